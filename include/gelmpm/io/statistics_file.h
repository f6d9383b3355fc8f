#ifndef gelmpm_io_statistics_file_h
#define gelmpm_io_statistics_file_h

#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief statistics.csv: one row per converged step, one column per quantity.
   *
   * The columns are fixed when the file is opened (a header row names them); each row is
   * written in one piece and flushed as soon as it is complete, so that a run that stops early
   * keeps every row it had; a row that a full disk cuts short is removed again.
   * Numbers are written with 10 significant digits.
   */
  class StatisticsFile
  {
  public:
    /**
     * Whether this process writes the file (default). On several MPI ranks only rank 0 does;
     * the others keep the same rows and byte count in memory, so that every rank's state (and
     * checkpoint) is the same.
     */
    void
    write_here(const bool writes);

    /** Create (truncate) @p file_name and write the header row. */
    void
    open(const std::string &file_name, const std::vector<std::string> &columns);

    /**
     * Continue @p file_name, written by an earlier run with the same @p columns, after its first
     * @p size bytes (a checkpoint's bytes(); the rows after them are cut off). Throws
     * std::runtime_error if the file is shorter or has other columns.
     */
    void
    resume(const std::string              &file_name,
           const std::vector<std::string> &columns,
           const std::uintmax_t            size);

    /** The bytes of the complete rows written so far, header included. */
    std::uintmax_t
    bytes() const;

    /** Set the value of @p column for the current row. */
    void
    set(const std::string &column, const double value);

    /** Set a text field (a name, e.g. the event of events.csv; no commas) of the current row. */
    void
    set(const std::string &column, const std::string &text);

    /** Write the current row (columns not set are written as empty fields) and start a new one. */
    void
    write_row();

    /** The column names. */
    const std::vector<std::string> &
    columns() const;

    /** The rows written so far (for the test-mode echo of the log). */
    const std::vector<std::vector<std::string>> &
    rows() const;

  private:
    /** Name the file and its @p columns; no file is opened. */
    void
    set_columns(const std::string &file_name, const std::vector<std::string> &columns);

    /**
     * Write @p fields as one line and flush; if that fails, cut the file back to its last
     * complete line and throw std::runtime_error (write_failure()).
     */
    void
    append_line(const std::vector<std::string> &fields);

    std::string                           name;
    std::uintmax_t                        complete = 0; // bytes of complete lines
    bool                                  writes   = true;
    std::ofstream                         file;
    std::vector<std::string>              columns_;
    std::map<std::string, unsigned int>   index;
    std::vector<std::string>              current;
    std::vector<std::vector<std::string>> rows_;
  };

  /**
   * Read a statistics.csv written by StatisticsFile back, column by column (empty and text
   * fields become NaN). For tests and tools that compare a run with a reference. Throws
   * std::runtime_error if the file cannot be read.
   */
  std::map<std::string, std::vector<double>>
  read_statistics(const std::string &file_name);
} // namespace GelMPM

#endif

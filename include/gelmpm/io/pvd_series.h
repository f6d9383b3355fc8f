#ifndef gelmpm_io_pvd_series_h
#define gelmpm_io_pvd_series_h

#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A ParaView time series in an output directory: the files `<name>-NNNNN.vtu`, numbered
   * from 0 in the order they are written, and the series file `<name>.pvd` that lists them with
   * their simulated times (deal.II DataOutBase::write_pvd_record).
   *
   * The .pvd file is rewritten after every addition, atomically (written to a temporary file,
   * then renamed), so that it only ever lists complete files, also when a run stops early.
   */
  class PvdSeries
  {
  public:
    /** A series `<name>.pvd` in @p directory, which must exist. */
    PvdSeries(const std::string &directory, const std::string &name);

    /** The file name (without directory) of the next output: `<name>-NNNNN.vtu`. */
    std::string
    next_file_name() const;

    /** The path of next_file_name() in the directory. */
    std::string
    next_path() const;

    /** Record that next_file_name() has been written for @p time and rewrite the .pvd file. */
    void
    add(const double time);

    /** (time, file name) of every output so far. */
    const std::vector<std::pair<double, std::string>> &
    times_and_names() const;

  private:
    std::string                                 directory;
    std::string                                 name;
    std::vector<std::pair<double, std::string>> series;
  };
} // namespace GelMPM

#endif

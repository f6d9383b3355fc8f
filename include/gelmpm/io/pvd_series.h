#ifndef gelmpm_io_pvd_series_h
#define gelmpm_io_pvd_series_h

#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <functional>
#include <ostream>
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
   * Each .vtu file and the .pvd file are written under a temporary name and renamed when
   * complete, and a file joins the .pvd only after that: the series only ever lists complete
   * files, also when a run stops early or the disk is full.
   *
   * On several MPI ranks an output is a `<name>-NNNNN.pvtu` record, written by rank 0, of the
   * pieces `<name>-NNNNN.RRRR.vtu` that each rank writes of its own part; the .pvd lists the
   * .pvtu files, and every rank keeps the same list.
   */
  class PvdSeries
  {
  public:
    /**
     * A series `<name>.pvd` in @p directory, which must exist, written by the ranks of
     * @p communicator.
     */
    PvdSeries(const std::string &directory,
              const std::string &name,
              const MPI_Comm     communicator = MPI_COMM_SELF);

    /** The file name (without directory) of the next output: `<name>-NNNNN.vtu`. */
    std::string
    next_file_name() const;

    /** The path of next_file_name() in the directory. */
    std::string
    next_path() const;

    /**
     * Write next_file_name() for @p time with @p writer, under a temporary name renamed when
     * complete, then add it to the series. Throws std::runtime_error (saying "disk full" when it
     * is) if writing fails; the series then lists only the files written before.
     */
    void
    write(const double time, const std::function<void(std::ostream &)> &writer);

    /**
     * As write(), on several ranks: each rank writes its piece with @p writer, then rank 0 the
     * .pvtu record with @p record_writer(out, piece file names). Collective. On one rank the
     * same as write().
     */
    void
    write(
      const double                                                                 time,
      const std::function<void(std::ostream &)>                                   &writer,
      const std::function<void(std::ostream &, const std::vector<std::string> &)> &record_writer);

    /** Record that next_file_name() has been written for @p time and rewrite the .pvd file. */
    void
    add(const double time);

    /** (time, file name) of every output so far. */
    const std::vector<std::pair<double, std::string>> &
    times_and_names() const;

    /** The outputs so far, for a checkpoint (boost serialization). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &series;
    }

    /**
     * After the outputs were read back from a checkpoint: rewrite the .pvd file with them and
     * remove this series' files that a run wrote after the checkpoint (numbered from their count
     * on, and temporary files).
     */
    void
    restore_files() const;

  private:
    /** Write @p path with @p writer under a temporary name and rename it when complete. */
    void
    write_file(const std::string &path, const std::function<void(std::ostream &)> &writer) const;

    /** Whether this series is written by several ranks (as pieces and .pvtu records). */
    bool
    parallel() const;

    std::string                                 directory;
    std::string                                 name;
    MPI_Comm                                    communicator;
    std::vector<std::pair<double, std::string>> series;
  };
} // namespace GelMPM

#endif

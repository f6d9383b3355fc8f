#ifndef gelmpm_io_checkpoint_h
#define gelmpm_io_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Checkpoint" section: how often a run writes the checkpoint from which
   * `gelmpm --resume` continues it. Off by default, so that a scene that does not ask for
   * checkpoints does no work for them.
   */
  struct CheckpointSettings
  {
    /** Write a checkpoint every this many converged steps (0: off). */
    unsigned int interval_steps = 0;
    /** Write a checkpoint after a step when this many minutes of wall time have passed since the
     * last one (or the start; 0: off). */
    double interval_minutes = 0.;

    /** Whether checkpoints are written at all. */
    bool
    enabled() const;

    /** Declare the section "Checkpoint". */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section "Checkpoint" (its patterns admit only valid values). */
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };


  /**
   * @brief What a checkpoint says about itself, read and checked before the state is: the
   * parameters it was written for, where the run was, and how long the run's .csv files were.
   */
  struct CheckpointHeader
  {
    /** checkpoint_parameters() of the run that wrote it. */
    std::string parameters;
    /** Converged steps and time (tau_d) at the checkpoint. */
    unsigned int step = 0;
    double       time = 0.;
    /** Bytes of each .csv file (by file name in the output directory) at the checkpoint: a
     * resumed run cuts off the rows written after it; and of each file that a .pvd series
     * lists, which a resumed run needs as it was. */
    std::map<std::string, std::uint64_t> file_sizes;

    /** Boost serialization. */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &parameters &step &time &file_sizes;
    }
  };


  /** The checkpoint file of an output directory: `<directory>/checkpoint.bin`. */
  std::string
  checkpoint_path(const std::string &directory);

  /**
   * The parameters a checkpoint is written for: @p parameters (the scene's parameters as used,
   * deal.II's ShortPRM format) without those that do not change the computation at all: the
   * section Checkpoint and 'Output/Directory' (a result may be moved).
   */
  std::string
  checkpoint_parameters(const std::string &parameters);

  /**
   * Whether the entry @p path ("Section/Entry") may differ between a checkpoint and the scene
   * that resumes it: it chooses the steps ahead or the output times ('End time', 'Tolerance' and
   * the rest of the step control in "Time stepping" except 'Characteristic length', 'Initial step'
   * and 'End at equilibrium'; 'Output/Interval steps' and 'Interval time'), but neither the
   * physics, the discretisation nor the state the checkpoint holds.
   */
  bool
  adjustable_on_resume(const std::string &path);

  /**
   * The entries adjustable_on_resume() whose values differ between the parameter texts
   * @p checkpoint and @p scene (both checkpoint_parameters()), each as "'Section/Entry' is 'b'
   * (was 'a')", for the log of the resumed run.
   */
  std::vector<std::string>
  adjusted_parameters(const std::string &checkpoint, const std::string &scene);

  /**
   * The first entry, not adjustable_on_resume(), in which the parameter texts @p checkpoint and
   * @p scene (both checkpoint_parameters()) differ, as "'Section/Entry' is 'a' in the checkpoint
   * and 'b' in the scene"; empty if they agree.
   */
  std::string
  parameter_difference(const std::string &checkpoint, const std::string &scene);

  /**
   * Write the checkpoint of @p directory: @p header, then what @p state writes into the archive.
   * The file is written under a temporary name, synchronised to the disk and renamed over the
   * previous checkpoint, so that a run killed at any moment leaves the previous or the new
   * checkpoint complete. A checksum over the contents lets CheckpointReader refuse a damaged
   * file. Returns the size of the file in bytes; throws std::runtime_error (write_failure()) if
   * it cannot be written.
   */
  std::uintmax_t
  write_checkpoint(const std::string                                            &directory,
                   const CheckpointHeader                                       &header,
                   const std::function<void(boost::archive::binary_oarchive &)> &state);

  /**
   * @brief The checkpoint of an output directory, read and checked for `gelmpm --resume`.
   *
   * The constructor throws InputError, naming the problem and the fix, if there is no
   * checkpoint, if it is damaged (truncated, altered), or if it was written by another GelMPM
   * version or for other parameters. The state then follows header() in archive().
   */
  class CheckpointReader
  {
  public:
    /**
     * Read the checkpoint of @p directory and check it against @p parameters, the
     * checkpoint_parameters() of the scene that resumes it.
     */
    CheckpointReader(const std::string &directory, const std::string &parameters);

    const CheckpointHeader &
    header() const;

    /** The archive, positioned at the state that follows the header. */
    boost::archive::binary_iarchive &
    archive();

  private:
    std::istringstream                               payload;
    std::unique_ptr<boost::archive::binary_iarchive> archive_;
    CheckpointHeader                                 header_;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_io_output_directory_h
#define gelmpm_io_output_directory_h

#include <regex>
#include <string>

namespace GelMPM
{
  /**
   * The names of the files a gelmpm run writes into its output directory (all but the lock file
   * DirectoryLock::file_name): a new run removes them first, so that no file of an earlier run
   * sits beside its own.
   */
  const std::regex &
  run_output_names();

  /**
   * Throw InputError naming @p entry (the entry that gives @p directory, e.g. 'Output/Directory')
   * if writing a run's output into @p directory would fail only once the run has started, or
   * destroy what the run is started from: @p directory is the directory of @p scene_file (a
   * result's parameters.prm run again), a symbolic link to nothing, a file, a directory this user
   * cannot write into, or it holds under one of run_output_names() a directory or, under a
   * sticky bit, another user's file (with @p resume, checkpoint.bin is read, not replaced). A
   * directory that does not exist yet passes (the run creates it). Used by gelmpm and by the
   * body-fitted peer tools, whose output directories are claimed the same way (with
   * DirectoryLock).
   */
  void
  check_output_directory(const std::string &directory,
                         const std::string &entry,
                         const std::string &scene_file,
                         const bool         resume);
} // namespace GelMPM

#endif

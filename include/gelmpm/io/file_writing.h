#ifndef gelmpm_io_file_writing_h
#define gelmpm_io_file_writing_h

#include <fstream>
#include <string>

namespace GelMPM
{
  /**
   * What went wrong writing @p file, from the errno value @p error: "disk full while writing
   * '<file>'" for ENOSPC, the file-size limit for EFBIG, else the system's text.
   */
  std::string
  write_failure(const std::string &file, const int error);

  /**
   * Open @p partial for writing the contents of the file @p path (written under the temporary
   * name @p partial and renamed by commit_file(), so that @p path is never a torn file). Throws
   * std::runtime_error (write_failure()) if it cannot be opened.
   */
  std::ofstream
  open_partial(const std::string &partial, const std::string &path);

  /**
   * Close @p out, written as @p partial, and rename it to @p path. If writing failed, remove
   * @p partial and throw std::runtime_error (write_failure() of @p path with @p error, or with
   * errno if @p error is 0). With @p synchronise, the file is on the disk before it is renamed and
   * the rename before this returns (sync_to_disk()): what must survive a crash of the machine, not
   * only of the run.
   */
  void
  commit_file(std::ofstream     &out,
              const std::string &partial,
              const std::string &path,
              const int          error       = 0,
              const bool         synchronise = false);

  /**
   * Wait until the file or directory @p path is on the disk (fsync). Throws std::runtime_error
   * (write_failure()) if that fails.
   */
  void
  sync_to_disk(const std::string &path);
} // namespace GelMPM

#endif

#ifndef gelmpm_io_directory_lock_h
#define gelmpm_io_directory_lock_h

#include <string>

namespace GelMPM
{
  /**
   * @brief The claim of one run on its output directory: an exclusive flock(2) on the file
   * `gelmpm.lock` in it, held from construction to destruction.
   *
   * Two runs writing into one directory would interleave their rows and series; the second
   * one is refused instead. gelmpm and the body-fitted peer tools take the same lock, so that
   * neither writes into a directory the other is writing into. The kernel releases the lock when
   * the process ends, however it ends (also by `kill -9`), so a lock is never stale; the file
   * itself stays and is reused. Under MPI one rank (rank 0, which prepares the directory) holds it.
   */
  class DirectoryLock
  {
  public:
    /**
     * Lock @p directory (which must exist). Throws InputError naming @p entry (the entry that
     * gives the directory: gelmpm's 'Output/Directory', a peer tool's 'FE peer/Output
     * directory') if another process holds the lock or the lock file cannot be created.
     */
    explicit DirectoryLock(const std::string &directory,
                           const std::string &entry = "Output/Directory");

    /** Release the lock. */
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

    /** The name of the lock file in a locked directory. */
    static constexpr const char *file_name = "gelmpm.lock";

  private:
    int descriptor = -1;
  };
} // namespace GelMPM

#endif

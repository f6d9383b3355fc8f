#include <gelmpm/core/input_error.h>
#include <gelmpm/io/directory_lock.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <unistd.h>

namespace GelMPM
{
  DirectoryLock::DirectoryLock(const std::string &directory, const std::string &entry)
  {
    const std::string path = directory + "/" + file_name;
    descriptor             = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor < 0)
      throw InputError(entry,
                       "is '" + directory + "', which cannot hold the run's lock file '" +
                         file_name + "' (" + std::strerror(errno) + ")",
                       "choose a directory you can write to");
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        const int error = errno;
        // The holder wrote its process id into the file.
        char          text[32] = {};
        const ssize_t n        = ::pread(descriptor, text, sizeof(text) - 1, 0);
        ::close(descriptor);
        descriptor              = -1;
        const std::string owner = n > 0 ? std::string(text, n) : std::string();
        if (error == EWOULDBLOCK)
          throw InputError(entry,
                           "is '" + directory + "', the output directory of another GelMPM run" +
                             (owner.empty() ? std::string() : " (process " + owner + ")") +
                             " that has not ended; both would write the same files",
                           "wait for that run to end, or give this run another directory, e.g. "
                           "--set \"" +
                             entry + "=rerun\"");
        throw InputError(entry,
                         "is '" + directory + "', whose lock file '" + file_name +
                           "' cannot be locked (" + std::strerror(error) + ")",
                         "choose a directory on a file system that supports flock(2)");
      }
    // The process id, for the message of a refused run (nothing depends on it being written).
    const std::string           pid = std::to_string(::getpid());
    [[maybe_unused]] const bool written =
      ::ftruncate(descriptor, 0) == 0 && ::pwrite(descriptor, pid.data(), pid.size(), 0) > 0;
  }


  DirectoryLock::~DirectoryLock()
  {
    if (descriptor >= 0)
      ::close(descriptor);
  }
} // namespace GelMPM

#include <gelmpm/io/file_writing.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace GelMPM
{
  std::string
  write_failure(const std::string &file, const int error)
  {
    switch (error)
      {
        case ENOSPC:
          return "disk full while writing '" + file + "' (no space left on the device)";
        case EDQUOT:
          return "disk quota exceeded while writing '" + file + "'";
        case EFBIG:
          return "'" + file + "' reached the file-size limit (see 'ulimit -f')";
        case 0:
          return "cannot write '" + file + "'";
        default:
          return "cannot write '" + file + "' (" + std::strerror(error) + ")";
      }
  }


  std::ofstream
  open_partial(const std::string &partial, const std::string &path)
  {
    errno = 0;
    std::ofstream out(partial, std::ios::binary);
    if (!out)
      throw std::runtime_error(write_failure(path, errno));
    return out;
  }


  void
  commit_file(std::ofstream     &out,
              const std::string &partial,
              const std::string &path,
              const int          error,
              const bool         synchronise)
  {
    if (out)
      out.flush();
    const int  failure = error != 0 ? error : (out ? 0 : errno);
    const bool failed  = error != 0 || !out;
    out.close();
    if (failed || out.fail())
      {
        const int reason = failed ? failure : errno;
        std::remove(partial.c_str());
        throw std::runtime_error(write_failure(path, reason));
      }
    if (synchronise)
      try
        {
          sync_to_disk(partial);
        }
      catch (const std::runtime_error &)
        {
          std::remove(partial.c_str());
          throw;
        }
    if (std::rename(partial.c_str(), path.c_str()) != 0)
      {
        const int reason = errno;
        std::remove(partial.c_str());
        throw std::runtime_error(write_failure(path, reason));
      }
    if (synchronise)
      sync_to_disk(std::filesystem::path(path).parent_path().empty()
                     ? std::string(".")
                     : std::filesystem::path(path).parent_path().string());
  }


  void
  sync_to_disk(const std::string &path)
  {
    // A descriptor opened for reading is enough for fsync, also for a directory.
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0 || ::fsync(fd) != 0)
      {
        const int reason = errno;
        if (fd >= 0)
          ::close(fd);
        throw std::runtime_error(write_failure(path, reason));
      }
    ::close(fd);
  }
} // namespace GelMPM

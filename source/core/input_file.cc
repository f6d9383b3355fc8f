#include <gelmpm/core/input_error.h>
#include <gelmpm/core/input_file.h>

#include <filesystem>
#include <sstream>

namespace GelMPM
{
  void
  require_bounded_file(const std::string   &path,
                       const std::string   &entry,
                       const std::string   &what,
                       const std::uintmax_t largest_bytes,
                       const std::string   &fix)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const auto      status = fs::status(path, error);
    if (error || !fs::exists(status) || fs::is_directory(status))
      return; // missing, unreadable or a directory: the caller's own message says so
    require(fs::is_regular_file(status),
            entry,
            "'" + path + "' is a device, pipe or socket, not " + what +
              ": it has no end that would bound its reading",
            fix);
    const std::uintmax_t bytes = fs::file_size(path, error);
    if (error)
      return;
    const auto megabytes = [](const std::uintmax_t n) {
      std::ostringstream text;
      text.precision(3);
      text << n / 1048576. << " MB";
      return text.str();
    };
    require(bytes <= largest_bytes,
            entry,
            "'" + path + "' holds " + megabytes(bytes) + ", more than the " +
              megabytes(largest_bytes) + " that " + what + " is read up to",
            fix);
  }
} // namespace GelMPM

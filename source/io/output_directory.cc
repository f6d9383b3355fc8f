#include <gelmpm/core/input_error.h>
#include <gelmpm/io/output_directory.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace GelMPM
{
  const std::regex &
  run_output_names()
  {
    static const std::regex names(
      "(particles|grid|mode)(-[0-9]{5}(\\.[0-9]{4})?\\.p?vtu|\\.pvd)(\\.tmp)?|"
      "(statistics|statistics_units|stability|events)\\.csv(\\.tmp)?|parameters\\.prm|original\\.prm|"
      "checkpoint\\.bin(\\.tmp)?|surface_.+-[0-9]{5}\\.csv(\\.tmp)?");
    return names;
  }


  void
  check_output_directory(const std::string &directory,
                         const std::string &entry,
                         const std::string &scene_file,
                         const bool         resume)
  {
    namespace fs = std::filesystem;
    std::error_code   error;
    const fs::path    scene_directory = fs::absolute(scene_file, error).parent_path();
    const std::string elsewhere       = "--set \"" + entry + "=rerun\"";
    // A run removes an earlier run's files from its directory and rewrites original.prm: run in
    // a result's directory, it would destroy the result it was started from.
    require(!fs::exists(directory, error) || !fs::equivalent(directory, scene_directory, error),
            entry,
            "'" + directory + "' is the directory of the scene file '" + scene_file +
              "', whose results (parameters.prm, original.prm, statistics.csv, "
              ".vtu files) the run would overwrite",
            "give the run another directory, e.g. " + elsewhere);
    // What creating or writing into it would fail on only once the run starts.
    if (fs::is_symlink(fs::symlink_status(directory, error)) && !fs::exists(directory, error))
      throw InputError(entry,
                       "is '" + directory + "', a symbolic link to '" +
                         fs::read_symlink(directory, error).string() + "', which does not exist",
                       "create the directory the link points to, or give another directory");
    require(!fs::exists(directory, error) || fs::is_directory(directory, error),
            entry,
            "is '" + directory + "', which is a file, not a directory",
            "move that file away, or give the run another directory, e.g. " + elsewhere);
    if (fs::is_directory(directory, error) && ::access(directory.c_str(), W_OK | X_OK) != 0)
      throw InputError(entry,
                       "is '" + directory + "', which this user cannot write into (" +
                         std::strerror(errno) + ")",
                       "give the directory write permission, or give another directory");
    // An earlier run's file that the run removes or replaces, but cannot: a directory in its
    // place (a device or a link is replaced; as checkpoint.bin --resume refuses it by name), or a
    // file of another user where the sticky bit (/tmp) lets only its owner remove or rename it. The
    // run would stop at its first write with exit status 1.
    if (!fs::is_directory(directory, error))
      return;
    struct stat directory_status;
    const bool  sticky = ::stat(directory.c_str(), &directory_status) == 0 &&
                        (directory_status.st_mode & S_ISVTX) != 0 && ::geteuid() != 0 &&
                        directory_status.st_uid != ::geteuid();
    for (const auto &file : fs::directory_iterator(directory, error))
      {
        const std::string name = file.path().filename().string();
        // --resume reads checkpoint.bin, and refuses what is not one by name.
        if (!std::regex_match(name, run_output_names()) || (resume && name == "checkpoint.bin"))
          continue;
        const std::string path = file.path().string();
        if (file.is_directory(error))
          throw InputError(entry,
                           "is '" + directory + "', which holds '" + name +
                             "' that is a directory: the run cannot write its own '" + name +
                             "' there",
                           "remove '" + path + "', or give the run another directory");
        struct stat file_status;
        if (sticky && ::stat(path.c_str(), &file_status) == 0 && file_status.st_uid != ::geteuid())
          throw InputError(entry,
                           "is '" + directory + "', which holds '" + name +
                             "' of another user, and its sticky bit lets only that user remove "
                             "or replace it",
                           "have '" + path + "' removed, or give the run another directory");
      }
  }
} // namespace GelMPM

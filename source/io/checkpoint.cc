#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/version.h>
#include <gelmpm/io/checkpoint.h>
#include <gelmpm/io/file_writing.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>
#include <vector>

namespace GelMPM
{
  namespace
  {
    /**
     * The first line of a checkpoint. Its format number changes with what a checkpoint holds;
     * a checkpoint also holds the GelMPM version, since another version may compute the next
     * step differently (the resumed run would no longer be the run that was checkpointed).
     */
    constexpr unsigned int checkpoint_format = 2;

    std::string
    first_line()
    {
      return "GelMPM checkpoint, format " + std::to_string(checkpoint_format) + ", GelMPM " +
             GELMPM_VERSION + "\n";
    }

    /** FNV-1a, 64 bit: the same on every platform and run, unlike std::hash. */
    std::uint64_t
    checksum(const std::string &bytes)
    {
      std::uint64_t hash = 14695981039346656037ull;
      for (const unsigned char c : bytes)
        hash = (hash ^ c) * 1099511628211ull;
      return hash;
    }

    InputError
    refusal(const std::string &problem, const std::string &fix)
    {
      return InputError("", "cannot resume: " + problem, fix);
    }

    const std::string start_afresh = "or run the scene from the start (without --resume)";
  } // namespace


  bool
  CheckpointSettings::enabled() const
  {
    return interval_steps > 0 || interval_minutes > 0.;
  }


  void
  CheckpointSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval steps",
                      "0",
                      dealii::Patterns::Integer(0),
                      "Write a checkpoint (checkpoint.bin in the output directory) every this "
                      "many converged steps, from which 'gelmpm --resume scene.prm' continues a "
                      "killed run exactly as if it had not stopped. 0: off. A run with "
                      "checkpoints also writes one at its end and before it stops on SIGTERM or "
                      "SIGINT.");
    prm.declare_entry("Interval minutes",
                      "0",
                      dealii::Patterns::Double(0.),
                      "Also write a checkpoint after the first step that ends this many minutes "
                      "of wall time after the last checkpoint (or the start). 0: off.");
    prm.leave_subsection();
  }


  void
  CheckpointSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    interval_steps   = prm.get_integer("Interval steps");
    interval_minutes = prm.get_double("Interval minutes");
    prm.leave_subsection();
  }


  std::string
  checkpoint_path(const std::string &directory)
  {
    return directory + "/checkpoint.bin";
  }


  std::string
  checkpoint_parameters(const std::string &parameters)
  {
    std::string result;
    for (const auto &[path, value] : parameter_entries(parameters))
      if (path.rfind("Checkpoint/", 0) != 0 && path != "Output/Directory")
        result += path + " = " + value + "\n";
    return result;
  }


  bool
  adjustable_on_resume(const std::string &path)
  {
    // How the steps ahead are chosen and when output is written: none of them enters the state
    // (the points, the fields, the step control's memory), which a resumed run takes as it was.
    // 'Initial step' only sets the first step, 'End at equilibrium' has judged the steps up to
    // the checkpoint, 'Characteristic length' is the unit of every time: they stay fixed.
    static const std::set<std::string> adjustable = {"Time stepping/End time",
                                                     "Time stepping/Tolerance",
                                                     "Time stepping/Tolerance until",
                                                     "Time stepping/Error norm",
                                                     "Time stepping/Displacement tolerance",
                                                     "Time stepping/Step caps",
                                                     "Time stepping/Stop at times",
                                                     "Time stepping/Growth factor",
                                                     "Time stepping/Growth below iterations",
                                                     "Time stepping/Cut factor",
                                                     "Time stepping/Minimum step",
                                                     "Time stepping/Maximum steps",
                                                     "Time stepping/Largest increment",
                                                     "Output/Interval steps",
                                                     "Output/Interval time"};
    return adjustable.count(path) > 0;
  }


  namespace
  {
    /** The entries of a checkpoint_parameters() text, which has one "path = value" per line. */
    std::map<std::string, std::string>
    split_parameters(const std::string &text)
    {
      std::map<std::string, std::string> values;
      std::istringstream                 in(text);
      for (std::string line; std::getline(in, line);)
        {
          const auto equals = line.find(" = ");
          values[line.substr(0, equals)] =
            equals == std::string::npos ? std::string() : line.substr(equals + 3);
        }
      return values;
    }
  } // namespace


  std::vector<std::string>
  adjusted_parameters(const std::string &checkpoint, const std::string &scene)
  {
    std::vector<std::string> changes;
    const auto old_values = split_parameters(checkpoint), new_values = split_parameters(scene);
    for (const auto &[path, value] : new_values)
      {
        const auto it = old_values.find(path);
        if (adjustable_on_resume(path) && it != old_values.end() && it->second != value)
          changes.push_back("'" + path + "' is '" + value + "' (was '" + it->second + "')");
      }
    return changes;
  }


  std::string
  parameter_difference(const std::string &checkpoint, const std::string &scene)
  {
    const auto old_values = split_parameters(checkpoint), new_values = split_parameters(scene);
    for (const auto &[path, value] : old_values)
      {
        if (adjustable_on_resume(path))
          continue;
        const auto it = new_values.find(path);
        if (it == new_values.end())
          return "'" + path + "' is '" + value + "' in the checkpoint and absent from the scene";
        if (it->second != value)
          return "'" + path + "' is '" + value + "' in the checkpoint and '" + it->second +
                 "' in the scene";
      }
    for (const auto &[path, value] : new_values)
      if (old_values.count(path) == 0 && !adjustable_on_resume(path))
        return "'" + path + "' is '" + value + "' in the scene and absent from the checkpoint";
    return "";
  }


  std::uintmax_t
  write_checkpoint(const std::string                                            &directory,
                   const CheckpointHeader                                       &header,
                   const std::function<void(boost::archive::binary_oarchive &)> &state)
  {
    std::ostringstream payload;
    {
      boost::archive::binary_oarchive archive(payload);
      archive << header;
      state(archive);
    }
    const std::string   bytes = payload.str();
    const std::uint64_t size = bytes.size(), sum = checksum(bytes);

    const std::string path    = checkpoint_path(directory);
    const std::string partial = path + ".tmp";
    std::ofstream     out     = open_partial(partial, path);
    const std::string line    = first_line();
    out.write(line.data(), line.size());
    out.write(reinterpret_cast<const char *>(&size), sizeof(size));
    out.write(reinterpret_cast<const char *>(&sum), sizeof(sum));
    out.write(bytes.data(), bytes.size());
    commit_file(out, partial, path, 0, true);
    return line.size() + sizeof(size) + sizeof(sum) + bytes.size();
  }


  CheckpointReader::CheckpointReader(const std::string &directory, const std::string &parameters)
  {
    namespace fs           = std::filesystem;
    const std::string path = checkpoint_path(directory);
    std::error_code   error;
    if (!fs::exists(path, error))
      throw refusal("found no checkpoint in '" + directory + "' (no file checkpoint.bin)",
                    "resume the scene whose 'Output/Directory' holds the checkpoint, " +
                      start_afresh +
                      " with 'Checkpoint/Interval steps' or 'Interval minutes' set so that it "
                      "writes checkpoints");
    // Read no more than the file holds: a directory, a device such as /dev/zero or a pipe has
    // no size to bound the read by.
    if (!fs::is_regular_file(path, error))
      throw refusal("'" + path + "' is not a checkpoint file but a " +
                      (fs::is_directory(path, error) ? "directory" : "device, pipe or socket"),
                    "restore the checkpoint that the run wrote, " + start_afresh);
    const std::uintmax_t file_size = fs::file_size(path, error);
    std::ifstream        in(path, std::ios::binary);
    if (error || !in)
      throw refusal("'" + path + "' cannot be read" +
                      (error ? " (" + error.message() + ")" : std::string()),
                    "give the file read permission, " + start_afresh);

    // The first line, of at most a few hundred bytes.
    std::string head(std::min<std::uintmax_t>(file_size, 256), '\0');
    in.read(head.data(), head.size());
    head.resize(in.gcount());
    const auto        newline = head.find('\n');
    const std::string line    = head.substr(0, newline == std::string::npos ? 0 : newline + 1);
    if (line.rfind("GelMPM checkpoint", 0) != 0)
      throw refusal("'" + path + "' is not a GelMPM checkpoint",
                    "restore the checkpoint that the run wrote, " + start_afresh);
    if (line != first_line())
      throw refusal("'" + path + "' was written by another GelMPM version (its first line reads '" +
                      line.substr(0, line.size() - 1) + "', this is GelMPM " + GELMPM_VERSION +
                      " with checkpoint format " + std::to_string(checkpoint_format) + ")",
                    "resume it with the GelMPM version that wrote it, " + start_afresh);

    std::uint64_t size = 0, sum = 0;
    const auto    expected = line.size() + sizeof(size) + sizeof(sum);
    in.clear();
    in.seekg(line.size());
    if (file_size >= expected)
      {
        in.read(reinterpret_cast<char *>(&size), sizeof(size));
        in.read(reinterpret_cast<char *>(&sum), sizeof(sum));
      }
    const std::string damaged = "'" + path + "' is damaged: ";
    const std::string restore = "restore the checkpoint that the run wrote, " + start_afresh;
    if (file_size < expected || file_size - expected != size)
      throw refusal(damaged + "it has " + std::to_string(file_size) +
                      " bytes where it was "
                      "written with " +
                      (file_size < expected ? std::string("more")
                                            : std::to_string(expected + size)) +
                      " (truncated or appended to)",
                    restore);
    std::string bytes(size, '\0');
    in.read(bytes.data(), size);
    if (static_cast<std::uint64_t>(in.gcount()) != size)
      throw refusal(damaged + "it ended while it was read (changed meanwhile?)", restore);
    if (checksum(bytes) != sum)
      throw refusal(damaged + "its contents do not match the checksum written with them", restore);

    payload.str(bytes);
    try
      {
        archive_ = std::make_unique<boost::archive::binary_iarchive>(payload);
        *archive_ >> header_;
      }
    catch (const std::exception &e)
      {
        throw refusal(damaged + "its header cannot be read (" + std::string(e.what()) + ")",
                      restore);
      }
    const std::string difference = parameter_difference(header_.parameters, parameters);
    if (!difference.empty())
      throw refusal("the checkpoint in '" + directory +
                      "' was written for other parameters: " + difference,
                    "resume it with the scene file and --set overrides of the run that wrote "
                    "it (its parameters.prm), " +
                      start_afresh + " with another 'Output/Directory'");
  }


  const CheckpointHeader &
  CheckpointReader::header() const
  {
    return header_;
  }


  boost::archive::binary_iarchive &
  CheckpointReader::archive()
  {
    return *archive_;
  }
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/core/input_file.h>
#include <gelmpm/core/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    const std::string list_hint =
      "'gelmpm --print-parameters' lists every section and entry with its pattern and documentation";

    // Editors on Windows start UTF-8 files with one; deal.II would see it as part of line 1.
    const std::string byte_order_mark = "\xEF\xBB\xBF";

    /** The file named by an 'include' line of a parameter file (as deal.II reads it), or "". */
    std::string
    included_file(std::string line)
    {
      line = dealii::Utilities::trim(line.substr(0, line.find('#')));
      if (line.rfind(byte_order_mark, 0) == 0)
        line.erase(0, byte_order_mark.size());
      if (line.rfind("include ", 0) != 0 && line.rfind("INCLUDE ", 0) != 0)
        return "";
      return dealii::Utilities::trim(line.substr(8));
    }

    /**
     * deal.II follows 'include' lines without a limit: a file that includes itself, directly or
     * through others, recurses until the stack overflows.
     */
    void
    check_includes(const std::string &file_name, std::vector<std::string> &chain)
    {
      std::error_code   error;
      const std::string path = std::filesystem::weakly_canonical(file_name, error).string();
      for (const auto &outer : chain)
        if (outer == path)
          throw InputError("",
                           "the scene file includes '" + file_name +
                             "' inside itself (an 'include' cycle)",
                           "remove the 'include " + file_name + "' line that closes the cycle");
      if (chain.size() >= 32)
        throw InputError("",
                         "the scene file nests 'include' lines more than 32 deep",
                         "include fewer files");
      if (!chain.empty())
        require_bounded_file(file_name,
                             "",
                             "a parameter file ('include " + file_name + "' in '" + chain.back() +
                               "')",
                             largest_scene_file_bytes,
                             "include a parameter file, or remove the line");
      std::ifstream in(file_name);
      if (!in || std::filesystem::is_directory(file_name))
        return; // deal.II reports a missing include file with its line number
      chain.push_back(path);
      for (std::string line; std::getline(in, line);)
        if (const auto included = included_file(line); !included.empty())
          check_includes(included, chain);
      chain.pop_back();
    }

    /** The names of all sections (@p sections) or all entries of @p prm. */
    std::vector<std::string>
    declared_names(const dealii::ParameterHandler &prm, const bool sections)
    {
      std::ostringstream text;
      prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
      const std::string        keyword = sections ? "subsection " : "set ";
      std::vector<std::string> names;
      std::istringstream       lines(text.str());
      for (std::string line; std::getline(lines, line);)
        {
          line = dealii::Utilities::trim(line);
          if (line.rfind(keyword, 0) != 0)
            continue;
          const auto name =
            dealii::Utilities::trim(line.substr(keyword.size(), line.find('=') - keyword.size()));
          if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
        }
      return names;
    }

    /** Edit distance of @p a and @p b, ignoring case. */
    unsigned int
    distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int above = row[j];
              const bool         same  = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                std::tolower(static_cast<unsigned char>(b[j - 1]));
              row[j]   = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
              diagonal = above;
            }
        }
      return row[b.size()];
    }

    /** "write 'X'" for the declared name nearest to the misspelt @p name, else the list hint. */
    std::string
    nearest_name_fix(const dealii::ParameterHandler &prm,
                     const std::string              &name,
                     const bool                      section)
    {
      std::string  best;
      unsigned int best_distance = std::max<unsigned int>(2, name.size() / 3) + 1;
      for (const auto &candidate : declared_names(prm, section))
        if (const unsigned int d = distance(name, candidate); d < best_distance)
          {
            best          = candidate;
            best_distance = d;
          }
      if (best.empty())
        return list_hint;
      return "write '" + best + "', the nearest " + (section ? "section" : "entry") + " name (" +
             list_hint + ")";
    }

    /** The first of @p sections (a path) that @p prm does not declare. */
    std::string
    first_missing_section(const dealii::ParameterHandler &prm,
                          const std::vector<std::string> &sections)
    {
      std::vector<std::string> path;
      for (const auto &s : sections)
        {
          path.push_back(s);
          if (!prm.subsection_path_exists(path))
            return s;
        }
      return sections.empty() ? "" : sections.back();
    }

    /** The text between @p open and @p close after @p marker in @p message, or "". */
    std::string
    quoted_after(const std::string &message,
                 const std::string &marker,
                 const char         open,
                 const char         close)
    {
      const auto at = message.find(marker);
      if (at == std::string::npos)
        return "";
      const auto begin = message.find(open, at + marker.size());
      const auto end   = message.find(close, begin + 1);
      if (begin == std::string::npos || end == std::string::npos)
        return "";
      return message.substr(begin + 1, end - begin - 1);
    }

    /** Leave @p n subsections of @p prm (the sections an override entered). */
    void
    leave_sections(dealii::ParameterHandler &prm, const std::size_t n)
    {
      for (std::size_t i = 0; i < n; ++i)
        prm.leave_subsection();
    }

    /** A fix for what deal.II reported in @p message, as specific as the message allows. */
    std::string
    fix_for(const dealii::ParameterHandler &prm, const std::string &message)
    {
      if (const auto name = quoted_after(message, "No entry with name", '<', '>'); !name.empty())
        return nearest_name_fix(prm, name, false);
      if (const auto at = message.find("no such subsection to be entered: ");
          at != std::string::npos)
        {
          // "Section.Subsection." (deal.II separates the path by dots and ends with one).
          std::string path = dealii::Utilities::trim(message.substr(at + 34));
          if (!path.empty() && path.back() == '.')
            path.pop_back();
          const auto        dot    = path.rfind('.');
          const std::string name   = path.substr(dot == std::string::npos ? 0 : dot + 1);
          const std::string parent = dot == std::string::npos ? "" : path.substr(0, dot);
          const std::string fix    = nearest_name_fix(prm, name, true);
          // A piece or region left out of its list (e.g. by --set) keeps its subsection.
          for (const auto &[section, list] :
               {std::make_pair("Boundary conditions", "Boundary conditions/Pieces"),
                std::make_pair("Material", "Material/Regions")})
            if (fix == list_hint && parent == section)
              return "add '" + name + "' to '" + list +
                     "', or remove its subsection from the "
                     "scene file";
          return fix;
        }
      if (message.find("does not match the given pattern") != std::string::npos)
        return "give a value of the pattern in brackets (the entry's documentation: 'gelmpm "
               "--print-parameters')";
      if (message.find("unequal numbers of 'subsection' and 'end'") != std::string::npos)
        return "close every 'subsection' with one 'end'";
      if (message.find("include") != std::string::npos)
        return "check the path after 'include' (relative paths are taken from the current "
               "directory)";
      return list_hint;
    }
  } // namespace


  std::string
  describe(const dealii::ExceptionBase &exception)
  {
    std::ostringstream out;
    exception.print_info(out);
    // One line: deal.II spreads some of its messages over several indented lines.
    std::string text;
    for (const char c : out.str())
      if (!std::isspace(static_cast<unsigned char>(c)))
        text += c;
      else if (!text.empty() && text.back() != ' ')
        text += ' ';
    while (!text.empty() && text.back() == ' ')
      text.pop_back();
    return text;
  }


  std::string
  ParameterOverride::path() const
  {
    std::string p;
    for (const auto &s : sections)
      p += s + "/";
    return p + entry;
  }


  ParameterOverride
  ParameterOverride::parse(const std::string &text)
  {
    const auto equal = text.find('=');
    require(equal != std::string::npos,
            "--set " + text,
            "has no '='",
            "write --set \"Section/Entry=value\"");
    ParameterOverride result;
    result.text  = text;
    result.value = dealii::Utilities::trim(text.substr(equal + 1));
    auto parts   = dealii::Utilities::split_string_list(text.substr(0, equal), '/');
    require(!parts.empty() && !parts.back().empty(),
            "--set " + text,
            "names no entry",
            "write --set \"Section/Entry=value\"");
    result.entry = parts.back();
    parts.pop_back();
    result.sections = parts;
    return result;
  }


  CommandLine
  CommandLine::parse(const int argc, const char *const *argv)
  {
    CommandLine cl;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          cl.help = true;
        else if (arg == "--print-parameters")
          cl.print_parameters = true;
        else if (arg == "--check")
          cl.check_only = true;
        else if (arg == "--resume")
          cl.resume = true;
        else if (arg == "--set")
          {
            require(i + 1 < argc,
                    "--set",
                    "is missing its argument",
                    "write --set \"Section/Entry=value\"");
            cl.overrides.push_back(ParameterOverride::parse(argv[++i]));
          }
        else if (arg.rfind("--set=", 0) == 0)
          cl.overrides.push_back(ParameterOverride::parse(arg.substr(6)));
        else if (!arg.empty() && arg[0] == '-')
          throw InputError("", "unknown option '" + arg + "'", "see 'gelmpm --help'");
        else
          {
            require(cl.scene_file.empty(),
                    "",
                    "more than one scene file given ('" + cl.scene_file + "' and '" + arg + "')",
                    "give exactly one scene file");
            cl.scene_file = arg;
          }
      }
    if (!cl.help && !cl.print_parameters)
      require(!cl.scene_file.empty(), "", "no scene file given", "run 'gelmpm scene.prm'");
    return cl;
  }


  std::string
  CommandLine::usage()
  {
    return "Usage: gelmpm [options] scene.prm\n"
           "\n"
           "Runs the hydrogel scene described by the parameter file scene.prm.\n"
           "\n"
           "Options:\n"
           "  --set \"Section/Entry=value\"  override one entry of the scene file (repeatable;\n"
           "                               nested sections are separated by '/')\n"
           "  --check                      read and validate the scene, write nothing, exit\n"
           "  --resume                     continue the run from the checkpoint in the scene's\n"
           "                               output directory (section Checkpoint)\n"
           "  --print-parameters           print every entry with its documentation, pattern and\n"
           "                               default (with a scene file: with that scene's values)\n"
           "  --help                       this text\n"
           "\n"
           "Exit status: 0 success, 1 the run failed (e.g. no convergence, disk full), 2 bad\n"
           "input or a checkpoint that cannot be resumed (nothing is written), 130/143 stopped\n"
           "by SIGINT/SIGTERM after a step.\n";
  }


  void
  apply_overrides(dealii::ParameterHandler             &prm,
                  const std::vector<ParameterOverride> &overrides,
                  const bool                            skip_undefined)
  {
    for (const auto &o : overrides)
      {
        if (!prm.subsection_path_exists(o.sections))
          {
            if (skip_undefined)
              continue;
            throw InputError("--set " + o.text,
                             "names a section that does not exist",
                             nearest_name_fix(prm, first_missing_section(prm, o.sections), true));
          }
        for (const auto &s : o.sections)
          prm.enter_subsection(s);
        try
          {
            prm.set(o.entry, o.value);
          }
        catch (const dealii::ParameterHandler::ExcEntryUndeclared &)
          {
            leave_sections(prm, o.sections.size());
            if (skip_undefined)
              continue;
            throw InputError("--set " + o.text,
                             "names an entry that does not exist",
                             nearest_name_fix(prm, o.entry, false));
          }
        catch (const dealii::ExceptionBase &e)
          {
            leave_sections(prm, o.sections.size());
            if (skip_undefined)
              continue;
            throw InputError(o.path(), "(from --set): " + describe(e), fix_for(prm, describe(e)));
          }
        leave_sections(prm, o.sections.size());
      }
  }


  void
  read_scene_file(dealii::ParameterHandler             &prm,
                  const std::string                    &file_name,
                  const std::vector<ParameterOverride> &overrides,
                  const bool                            skip_undefined)
  {
    {
      // Before it is opened: opening a pipe waits for a writer.
      require_bounded_file(file_name,
                           "",
                           "a scene file",
                           largest_scene_file_bytes,
                           "give a scene file, e.g. prm/constrained_swelling.prm");
      std::ifstream probe(file_name);
      require(static_cast<bool>(probe),
              "",
              "the scene file '" + file_name + "' cannot be opened",
              "check the path (relative paths are taken from the current directory)");
      // A directory opens as a stream on Linux and reads as an empty scene of defaults.
      require(!std::filesystem::is_directory(file_name),
              "",
              "'" + file_name + "' is a directory, not a scene file",
              "give a scene file, e.g. prm/constrained_swelling.prm");
    }
    std::vector<std::string> chain;
    check_includes(file_name, chain);
    try
      {
        std::ifstream     file(file_name);
        std::stringstream in;
        in << file.rdbuf();
        std::string text = in.str();
        if (text.rfind(byte_order_mark, 0) == 0)
          text.erase(0, byte_order_mark.size());
        std::istringstream stripped(text);
        prm.parse_input(stripped, file_name, "", skip_undefined);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("", "in scene file: " + describe(e), fix_for(prm, describe(e)));
      }
    apply_overrides(prm, overrides, skip_undefined);
    check_numbers_representable(prm);
  }


  std::vector<double>
  get_double_list(const dealii::ParameterHandler &prm,
                  const std::string              &entry,
                  const std::string              &entry_path,
                  const unsigned int              n)
  {
    const auto parts = dealii::Utilities::split_string_list(prm.get(entry), ',');
    require(parts.size() == n,
            entry_path,
            "has " + std::to_string(parts.size()) + " components but needs " + std::to_string(n),
            "give " + std::to_string(n) + " comma-separated numbers");
    std::vector<double> values;
    for (const auto &p : parts)
      {
        try
          {
            values.push_back(dealii::Utilities::string_to_double(p));
          }
        catch (...)
          {
            throw InputError(entry_path, "has the non-number '" + p + "'", "give numbers only");
          }
      }
    return values;
  }


  std::vector<std::pair<std::string, std::string>>
  parameter_entries(const std::string &short_prm)
  {
    std::vector<std::pair<std::string, std::string>> result;
    std::vector<std::string>                         sections;
    std::istringstream                               in(short_prm);
    for (std::string line; std::getline(in, line);)
      {
        const auto first = line.find_first_not_of(' ');
        if (first == std::string::npos)
          continue;
        line = line.substr(first);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(line.substr(11));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto  equals = line.find('=');
            std::string name =
              line.substr(4, equals == std::string::npos ? std::string::npos : equals - 4);
            name.erase(name.find_last_not_of(' ') + 1);
            std::string value =
              equals == std::string::npos ? std::string() : line.substr(equals + 1);
            value.erase(0, value.find_first_not_of(' '));
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            result.emplace_back(path + name, value);
          }
      }
    return result;
  }


  void
  require_new_subsection_names(const dealii::ParameterHandler &prm,
                               const std::string              &section,
                               const std::vector<std::string> &names,
                               const std::string              &list_entry,
                               const std::string              &what)
  {
    if (names.empty())
      return;
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    const std::string prefix = section + "/";
    for (const auto &[path, value] : parameter_entries(text.str()))
      {
        if (path.rfind(prefix, 0) != 0)
          continue;
        const std::string rest  = path.substr(prefix.size());
        const auto        slash = rest.find('/');
        const std::string child = rest.substr(0, slash);
        const bool        entry = slash == std::string::npos;
        require(std::find(names.begin(), names.end(), child) == names.end(),
                list_entry,
                "names the " + what + " '" + child + "', which is also the name of " +
                  (entry ? "an entry" : "a subsection") + " of the section '" + section +
                  "': its subsection '" + section + "/" + child +
                  "' would be taken for that one, and parameters.prm would leave the " + what +
                  " out",
                "rename the " + what + ", e.g. '" + child + " " + what + "'");
      }
  }


  void
  check_numbers_representable(const dealii::ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    for (const auto &[path, value] : parameter_entries(text.str()))
      {
        // The numbers of an entry: those of lists ('1, 0'), step caps ('5: 0.0125') and
        // expressions that are a number alone; a number inside an expression ('2*x') is left
        // to the expression's own checks.
        std::string token;
        for (std::size_t k = 0; k <= value.size(); ++k)
          {
            const char c = k < value.size() ? value[k] : ' ';
            if (c != ',' && c != ':' && c != ';' && !std::isspace(static_cast<unsigned char>(c)))
              {
                token += c;
                continue;
              }
            if (token.empty())
              continue;
            char *end              = nullptr;
            errno                  = 0;
            const double x         = std::strtod(token.c_str(), &end);
            const bool   number    = end == token.c_str() + token.size();
            const bool   too_big   = errno == ERANGE && std::abs(x) >= 1.;
            const bool   too_small = (errno == ERANGE && std::abs(x) < 1.) ||
                                   (x != 0. && std::abs(x) < std::numeric_limits<double>::min());
            const std::string what =
              (token == value ? "is " + value + ","
                              : "is '" + value + "', whose number " + token + " is");
            if (number && too_big)
              throw InputError(path,
                               what + " beyond the largest double (about 1.8e308)",
                               "give a number of magnitude below 1e308");
            if (number && too_small)
              throw InputError(path,
                               what + " below the smallest normal double (about 2.2e-308), "
                                      "where arithmetic loses its precision",
                               "give 0 or a number of magnitude at least 1e-300");
            token.clear();
          }
      }
  }


  void
  print_parameters_with_patterns(const dealii::ParameterHandler &prm, std::ostream &out)
  {
    // The patterns, from deal.II's JSON listing, whose names are mangled ("_20" for a space).
    const auto demangle = [](const std::string &name) {
      std::string result;
      for (std::size_t k = 0; k < name.size(); ++k)
        if (name[k] == '_' && k + 2 < name.size() &&
            std::isxdigit(static_cast<unsigned char>(name[k + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[k + 2])))
          {
            result += static_cast<char>(std::stoi(name.substr(k + 1, 2), nullptr, 16));
            k += 2;
          }
        else
          result += name[k];
      return result;
    };
    std::map<std::string, std::string> patterns;
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      const std::function<void(const boost::property_tree::ptree &, const std::string &)> walk =
        [&](const boost::property_tree::ptree &node, const std::string &path) {
          for (const auto &[name, child] : node)
            {
              const std::string child_path = path + demangle(name);
              if (const auto pattern = child.get_optional<std::string>("pattern_description"))
                patterns[child_path] = *pattern;
              else
                walk(child, child_path + "/");
            }
        };
      walk(tree, "");
    }

    std::stringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::PRM);
    std::vector<std::string> sections;
    for (std::string line; std::getline(text, line);)
      {
        const auto        first   = line.find_first_not_of(' ');
        const std::string trimmed = first == std::string::npos ? "" : line.substr(first);
        if (trimmed.rfind("subsection ", 0) == 0)
          sections.push_back(dealii::Utilities::trim(trimmed.substr(11)));
        else if (trimmed == "end" && !sections.empty())
          sections.pop_back();
        else if (trimmed.rfind("set ", 0) == 0)
          {
            std::string path;
            for (const auto &section : sections)
              path += section + "/";
            path += dealii::Utilities::trim(trimmed.substr(4, trimmed.find('=') - 4));
            if (const auto pattern = patterns.find(path); pattern != patterns.end())
              out << line.substr(0, first) << "# Pattern: " << pattern->second << '\n';
          }
        out << line << '\n';
      }
  }


  std::string
  entry_value(const double x)
  {
    std::ostringstream text;
    text.precision(17);
    text << x;
    return text.str();
  }
} // namespace GelMPM

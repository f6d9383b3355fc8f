#ifndef gelmpm_core_parameters_h
#define gelmpm_core_parameters_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * deal.II's own description of an exception on one line, without its file/line boilerplate,
   * for messages to the user.
   */
  std::string
  describe(const dealii::ExceptionBase &exception);


  /**
   * @brief One `--set "Section/Subsection/Entry=value"` given on the command line.
   *
   * Applied after the scene file is read, so that it wins over the file.
   */
  struct ParameterOverride
  {
    /** The subsections leading to the entry, outermost first. */
    std::vector<std::string> sections;
    /** The entry's name. */
    std::string entry;
    /** The new value, as text (checked against the entry's pattern when applied). */
    std::string value;
    /** The argument as the user typed it, for messages. */
    std::string text;

    /** The entry's full path "Section/Subsection/Entry". */
    std::string
    path() const;

    /**
     * Parse "Section/Subsection/Entry=value". Throws InputError on text without '=' or without
     * an entry name.
     */
    static ParameterOverride
    parse(const std::string &text);
  };

  /**
   * @brief What the gelmpm command line asks for.
   */
  struct CommandLine
  {
    /** The scene file (empty with --help or --print-parameters without a scene). */
    std::string scene_file;
    /** The --set overrides, in the order given. */
    std::vector<ParameterOverride> overrides;
    /** --help: print usage and exit. */
    bool help = false;
    /** --print-parameters: print every entry with documentation, pattern and default. */
    bool print_parameters = false;
    /** --check: read and validate the scene, then exit without writing anything. */
    bool check_only = false;
    /** --resume: continue the run from the checkpoint in the scene's output directory. */
    bool resume = false;

    /** Parse argv. Throws InputError on unknown options or a missing scene file argument. */
    static CommandLine
    parse(const int argc, const char *const *argv);

    /** Usage text for --help. */
    static std::string
    usage();
  };

  /**
   * @brief Read a scene file into @p prm, then apply @p overrides.
   *
   * Every failure (missing file, unknown subsection or entry, a value that does not match its
   * pattern, unbalanced subsection/end, an override naming no entry) is turned into one
   * InputError that names the line or entry and says how to fix it.
   *
   * @param skip_undefined Ignore entries and overrides that @p prm does not declare. Used for a
   *   first pass that reads only what decides the structure of the rest (the dimension, the names
   *   of boundary pieces).
   */
  void
  read_scene_file(dealii::ParameterHandler             &prm,
                  const std::string                    &file_name,
                  const std::vector<ParameterOverride> &overrides,
                  const bool                            skip_undefined = false);

  /**
   * Apply @p overrides to @p prm (see read_scene_file()). With @p skip_undefined, overrides of
   * entries that @p prm does not declare are ignored.
   */
  void
  apply_overrides(dealii::ParameterHandler             &prm,
                  const std::vector<ParameterOverride> &overrides,
                  const bool                            skip_undefined = false);

  /**
   * Parse a list of @p n comma-separated doubles from entry @p entry of @p prm (the current
   * subsection); @p entry_path is used in the error message. Throws InputError on a wrong count.
   */
  std::vector<double>
  get_double_list(const dealii::ParameterHandler &prm,
                  const std::string              &entry,
                  const std::string              &entry_path,
                  const unsigned int              n);

  /**
   * The entries of a parameter text in deal.II's ShortPRM format (ParameterHandler::
   * print_parameters()) as ("Section/Subsection/Entry", value), in the order printed.
   */
  std::vector<std::pair<std::string, std::string>>
  parameter_entries(const std::string &short_prm);

  /**
   * Throw InputError naming @p list_entry (e.g. "Material/Regions") if one of @p names, each to
   * become a subsection of the top-level @p section of @p prm, is the name of an entry or a
   * subsection already declared there: deal.II would take the two for one, so that the
   * subsection's entries are printed nowhere and parameters.prm would lose them. @p what names
   * one of @p names ("region").
   */
  void
  require_new_subsection_names(const dealii::ParameterHandler &prm,
                               const std::string              &section,
                               const std::vector<std::string> &names,
                               const std::string              &list_entry,
                               const std::string              &what);

  /**
   * Throw an InputError for the first entry of @p prm whose value holds a number that a double
   * cannot carry: one below the smallest normal double (a denormal such as 1e-320, or one that
   * underflows to 0 such as 1e-400) or beyond the largest. deal.II's patterns accept such a
   * number, and ParameterHandler::get_double() then fails an assertion that names no entry.
   * read_scene_file() calls it once the file and the overrides are read, so every numeric entry
   * (lists and function expressions included) is checked in this one place.
   */
  void
  check_numbers_representable(const dealii::ParameterHandler &prm);

  /**
   * Write @p prm as a parameter file (deal.II's PRM format: every entry with its documentation
   * and value) in which each entry's documentation ends with the pattern its values must match
   * ("# Pattern: [Double 0...MAX_DOUBLE (inclusive)]"): what `gelmpm --print-parameters` shows.
   */
  void
  print_parameters_with_patterns(const dealii::ParameterHandler &prm, std::ostream &out);

  /** @p x as the text of a parameter entry, with all its digits (round-trips exactly). */
  std::string
  entry_value(const double x);
} // namespace GelMPM

#endif

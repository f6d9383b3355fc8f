#ifndef gelmpm_core_input_error_h
#define gelmpm_core_input_error_h

#include <stdexcept>
#include <string>

namespace GelMPM
{
  /**
   * @brief An error in what the user gave: a parameter file, a `--set` override, or a value that is
   * inconsistent with another.
   *
   * It names the parameter entry ("Section/Subsection/Entry"), says what is wrong and how to fix
   * it. The gelmpm application prints it as one message and exits with status 2 before writing any
   * output; library code throws it wherever it checks input, so that the check stays next to the
   * parameter it guards.
   */
  class InputError : public std::runtime_error
  {
  public:
    /**
     * @param entry Full path of the offending entry, e.g. "Material/Diffusivity"; may be empty
     *   when the error concerns a file as a whole.
     * @param problem What is wrong, e.g. "must be positive, but is -1".
     * @param fix What the user should do, e.g. "give the solvent diffusivity D > 0".
     */
    InputError(const std::string &entry, const std::string &problem, const std::string &fix = "");

    /** The entry path given to the constructor. */
    const std::string &
    entry() const;

    /** What is wrong. */
    const std::string &
    problem() const;

    /** How to fix it (may be empty). */
    const std::string &
    fix() const;

  private:
    std::string entry_;
    std::string problem_;
    std::string fix_;
  };

  /**
   * Throw an InputError for @p entry unless @p condition holds. Keeps validation one line long
   * next to the parse_parameters() code that reads the entry.
   */
  inline void
  require(const bool         condition,
          const std::string &entry,
          const std::string &problem,
          const std::string &fix = "")
  {
    if (!condition)
      throw InputError(entry, problem, fix);
  }
} // namespace GelMPM

#endif

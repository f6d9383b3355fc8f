#ifndef gelmpm_scene_expression_h
#define gelmpm_scene_expression_h

#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace GelMPM
{
  /**
   * @brief Keeps std::cerr quiet while alive: deal.II's expression parser writes its own
   * diagnostics there before throwing, and the InputError that follows says it once, in the
   * user's terms.
   */
  class QuietCerr
  {
  public:
    QuietCerr()
      : saved(std::cerr.rdbuf(sink.rdbuf()))
    {}
    ~QuietCerr()
    {
      std::cerr.rdbuf(saved);
    }
    QuietCerr(const QuietCerr &) = delete;
    QuietCerr &
    operator=(const QuietCerr &) = delete;

  private:
    std::ostringstream sink;
    std::streambuf    *saved;
  };

  /**
   * The constants 'name=value, ...' of @p text for an expression in @p variable_names
   * (comma-separated). Checked here because deal.II's expression parser aborts the program on a
   * name that is not an identifier or that shadows a variable. Throws InputError naming @p entry.
   */
  std::map<std::string, double>
  parse_expression_constants(const std::string &text,
                             const std::string &variable_names,
                             const std::string &entry);
} // namespace GelMPM

#endif

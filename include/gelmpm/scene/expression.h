#ifndef gelmpm_scene_expression_h
#define gelmpm_scene_expression_h

#include <array>
#include <iostream>
#include <map>
#include <memory>
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

  /**
   * @brief An expression in a point and a unit normal, x, y[, z], nx, ny[, nz]: the selector of
   * a boundary piece; or in the point alone, x, y[, z]: the selector of a material region.
   *
   * deal.II's FunctionParser takes at most three space variables and time, one too few for a
   * point and a normal in 3D, so this class drives muParser (the parser FunctionParser wraps)
   * directly, with the functions FunctionParser adds to it (if, int, ceil, floor, pow, log, cot,
   * csc, sec, erfc): an expression means the same in 2D and 3D, and the same as in the other
   * entries of a scene file.
   */
  class PointNormalExpression
  {
  public:
    /**
     * Parse @p expression in the variables of variable_names(@p dim, @p with_normal) and
     * @p constants, and evaluate it once (muParser compiles lazily). Throws
     * std::invalid_argument with muParser's message if it cannot be parsed.
     */
    PointNormalExpression(const unsigned int                   dim,
                          const std::string                   &expression,
                          const std::map<std::string, double> &constants,
                          const bool                           with_normal = true);
    ~PointNormalExpression();

    /** "x,y,nx,ny" in 2D, "x,y,z,nx,ny,nz" in 3D; without the normal "x,y" and "x,y,z". */
    static std::string
    variable_names(const unsigned int dim, const bool with_normal = true);

    /**
     * The value at the point @p x with normal @p normal (dim entries each; @p normal is not read
     * for an expression in the point alone); NaN where muParser fails.
     */
    double
    value(const double *x, const double *normal) const;

  private:
    struct Parser;
    // Not copied or moved: the parser refers to the addresses of its variables.
    std::unique_ptr<Parser> parser;
  };
} // namespace GelMPM

#endif

#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <muParser.h>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    bool
    is_name(const std::string &name)
    {
      if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
        return false;
      for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
          return false;
      return true;
    }
  } // namespace


  std::map<std::string, double>
  parse_expression_constants(const std::string &text,
                             const std::string &variable_names,
                             const std::string &entry)
  {
    const auto                    variables = dealii::Utilities::split_string_list(variable_names);
    std::map<std::string, double> constants;
    for (const auto &item : dealii::Utilities::split_string_list(text, ','))
      {
        const auto kv = dealii::Utilities::split_string_list(item, '=');
        require(kv.size() == 2,
                entry,
                "has the item '" + item + "' that is not 'name=value'",
                "write e.g. 'H=1, tol=1e-9'");
        require(is_name(kv[0]),
                entry,
                "has the constant name '" + kv[0] + "', which is not a name",
                "start the name with a letter and use letters, digits and '_' only");
        require(std::find(variables.begin(), variables.end(), kv[0]) == variables.end(),
                entry,
                "has the constant '" + kv[0] + "', which is also a variable (" + variable_names +
                  ")",
                "rename the constant");
        require(constants.count(kv[0]) == 0,
                entry,
                "gives the constant '" + kv[0] + "' twice",
                "give each constant once");
        double value;
        try
          {
            value = dealii::Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            throw InputError(entry, "has a non-number in '" + item + "'", "give numbers");
          }
        require(std::isfinite(value),
                entry,
                "has the value '" + kv[1] + "', which is not finite, in '" + item + "'",
                "give a finite number");
        constants[kv[0]] = value;
      }
    return constants;
  }


  struct PointNormalExpression::Parser
  {
    mu::Parser            parser;
    std::array<double, 6> variables   = {};
    unsigned int          dim         = 2;
    bool                  with_normal = true;
  };


  PointNormalExpression::PointNormalExpression(const unsigned int                   dim,
                                               const std::string                   &expression,
                                               const std::map<std::string, double> &constants,
                                               const bool                           with_normal)
    : parser(std::make_unique<Parser>())
  {
    parser->dim         = dim;
    parser->with_normal = with_normal;
    auto      &p        = parser->parser;
    const auto names    = dealii::Utilities::split_string_list(variable_names(dim, with_normal));
    try
      {
        for (unsigned int i = 0; i < names.size(); ++i)
          p.DefineVar(names[i], &parser->variables[i]);
        for (const auto &[name, value] : constants)
          p.DefineConst(name, value);
        // The functions deal.II's FunctionParser adds to muParser, with the same meaning.
        p.DefineFun("if", [](double c, double a, double b) {
          return c != 0. ? a : b;
        });
        p.DefineFun("int", [](double x) {
          return static_cast<double>(static_cast<long>(x));
        });
        p.DefineFun("ceil", [](double x) {
          return std::ceil(x);
        });
        p.DefineFun("floor", [](double x) {
          return std::floor(x);
        });
        p.DefineFun("cot", [](double x) {
          return 1. / std::tan(x);
        });
        p.DefineFun("csc", [](double x) {
          return 1. / std::sin(x);
        });
        p.DefineFun("sec", [](double x) {
          return 1. / std::cos(x);
        });
        p.DefineFun("log", [](double x) {
          return std::log(x);
        });
        p.DefineFun("pow", [](double x, double y) {
          return std::pow(x, y);
        });
        p.DefineFun("erfc", [](double x) {
          return std::erfc(x);
        });
        p.SetExpr(expression);
        // muParser compiles lazily: evaluate once so that syntax errors surface here.
        (void)p.Eval();
      }
    catch (const mu::Parser::exception_type &e)
      {
        // Without muParser's closing full stop: the InputError adds its own punctuation.
        std::string message = e.GetMsg();
        while (!message.empty() && (message.back() == '.' || message.back() == ' '))
          message.pop_back();
        throw std::invalid_argument(message);
      }
  }


  PointNormalExpression::~PointNormalExpression() = default;


  std::string
  PointNormalExpression::variable_names(const unsigned int dim, const bool with_normal)
  {
    if (!with_normal)
      return dim == 3 ? "x,y,z" : "x,y";
    return dim == 3 ? "x,y,z,nx,ny,nz" : "x,y,nx,ny";
  }


  double
  PointNormalExpression::value(const double *x, const double *normal) const
  {
    for (unsigned int d = 0; d < parser->dim; ++d)
      {
        parser->variables[d] = x[d];
        if (parser->with_normal)
          parser->variables[parser->dim + d] = normal[d];
      }
    try
      {
        return parser->parser.Eval();
      }
    catch (const mu::Parser::exception_type &)
      {
        return std::numeric_limits<double>::quiet_NaN();
      }
  }
} // namespace GelMPM

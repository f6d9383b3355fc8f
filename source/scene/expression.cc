#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>

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
} // namespace GelMPM

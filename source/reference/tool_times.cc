#include <gelmpm/reference/tool_times.h>

#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  std::vector<double>
  parse_positive_times(const std::string &text)
  {
    std::vector<double> times;
    std::stringstream   in(text);
    std::string         item;
    while (std::getline(in, item, ','))
      {
        std::size_t  used  = 0;
        const double value = std::stod(item, &used);
        if (value <= 0. || item.find_first_not_of(" \t", used) != std::string::npos)
          throw std::invalid_argument("--times: '" + item + "' is not a positive number");
        times.push_back(value);
      }
    return times;
  }
} // namespace GelMPM

#ifndef gelmpm_reference_tool_times_h
#define gelmpm_reference_tool_times_h

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The `--times` option of the reference tools (gelmpm-swelling-1d,
   * gelmpm-swelling-sphere-1d): a comma-separated list of positive times.
   *
   * Throws std::invalid_argument naming the first item that is not a positive number.
   */
  std::vector<double>
  parse_positive_times(const std::string &text);
} // namespace GelMPM

#endif

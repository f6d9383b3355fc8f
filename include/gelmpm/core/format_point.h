#ifndef gelmpm_core_format_point_h
#define gelmpm_core_format_point_h

#include <deal.II/base/tensor.h>

#include <sstream>
#include <string>

namespace GelMPM
{
  /**
   * A point (or a vector) as messages write it: its coordinates in deal.II's notation in
   * parentheses, "(0.5 1)". The one way of writing a position, so that the messages of every
   * module read alike.
   */
  template <int dim>
  std::string
  format_point(const dealii::Tensor<1, dim> &p)
  {
    std::ostringstream out;
    out << "(" << p << ")";
    return out.str();
  }
} // namespace GelMPM

#endif

#include <gelmpm/core/input_error.h>
#include <gelmpm/solvers/newton.h>

#include <cmath>

namespace GelMPM
{
  void
  NewtonSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations",
                      "15",
                      dealii::Patterns::Integer(1),
                      "Newton iterations before a step counts as failed (and is retried with a "
                      "smaller step).");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      dealii::Patterns::Double(0.),
                      "Both residual blocks must fall below this, relative to their natural "
                      "scales: G |Omega_0|^((dim-1)/dim) for the displacement block and "
                      "(k_BT/nu) |Omega_0| for the chemical-potential block.");
    prm.leave_subsection();
  }


  void
  NewtonSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    maximum_iterations = prm.get_integer("Maximum iterations");
    tolerance          = prm.get_double("Tolerance");
    prm.leave_subsection();
    require(tolerance > 0. && tolerance < 1.,
            "Newton/Tolerance",
            "must lie strictly between 0 and 1",
            "use e.g. 1e-10");
  }
} // namespace GelMPM

#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/core/input_error.h>

#include <sstream>
#include <tuple>

namespace GelMPM
{
  void
  NitscheSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Nitsche");
    prm.declare_entry("Displacement penalty",
                      "1000",
                      Patterns::Double(0.),
                      "gamma_u: the displacement penalty is beta_u = gamma_u G / h_u (paper "
                      "eq. (32), Table 1: 1000). Must be positive; too small a value makes the "
                      "symmetric variant lose coercivity; at most 1e8 (the tangent's condition "
                      "number grows in proportion to it).");
    prm.declare_entry("Chemical potential penalty",
                      "25",
                      Patterns::Double(0.),
                      "gamma_mu: the chemical-potential penalty is beta_mu = gamma_mu m_n / h_mu "
                      "(paper eq. (32), Table 1: 25). At most 1e8.");
    prm.declare_entry("Variant",
                      "symmetric",
                      Patterns::Selection("symmetric|skew-symmetric"),
                      "symmetric (s = 1): symmetric tangent, needed by the stability analysis. "
                      "skew-symmetric (s = -1): coercive for any penalty, unsymmetric tangent.");
    prm.leave_subsection();
  }


  void
  NitscheSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Nitsche");
    displacement_penalty       = prm.get_double("Displacement penalty");
    chemical_potential_penalty = prm.get_double("Chemical potential penalty");
    symmetry                   = (prm.get("Variant") == "symmetric") ? 1. : -1.;
    prm.leave_subsection();
    require(displacement_penalty > 0.,
            "Nitsche/Displacement penalty",
            "must be positive",
            "give gamma_u > 0 (Table 1: 1000)");
    require(chemical_potential_penalty > 0.,
            "Nitsche/Chemical potential penalty",
            "must be positive",
            "give gamma_mu > 0 (Table 1: 25)");
    for (const auto &[value, entry, fix] :
         {std::make_tuple(displacement_penalty,
                          "Nitsche/Displacement penalty",
                          "give gamma_u between 1e3 and 1e6 (Table 1: 1000; doc/extremes.md)"),
          std::make_tuple(chemical_potential_penalty,
                          "Nitsche/Chemical potential penalty",
                          "give gamma_mu between 10 and 1e6 (Table 1: 25; doc/extremes.md)")})
      if (value > largest_penalty)
        {
          std::ostringstream problem;
          problem << "is " << value
                  << ", above 1e8: the condition number of the tangent grows in proportion to it "
                     "and the linear solves would keep no digit";
          throw InputError(entry, problem.str(), fix);
        }
  }
} // namespace GelMPM

// FloryRehnerGel::largest_swelling_chemical_potential() against the Flory-Rehner law in closed
// form (tests/flory_rehner_closed_form.h, written without FloryRehnerGel): for three gels and each
// kinematics (plane strain with F_33 = lambda_0; isotropic, as in 3D and in the body of revolution
// of an axisymmetric scene) a walk of the stretch s from the dry state (factors 1.001, up to
// J = 1e12) looks for a stress-free state, P_11 F_11 = 0, at 0.999 and at 1.001 times the limit:
// there must be one below and none above. In plane strain the limit is N nu/lambda_0 (the
// asymptote of mu(s) = N nu (s^2 - 1)/J + ln(1 - 1/J) + 1/J + chi/J^2, J = lambda_0 s^2), to a
// relative 1e-9; GelReferences::free_swelling() finds the state just below the limit; the 2D gel
// of an axisymmetric scene, whose body of revolution swells in 3D, has the 3D limit. The limits
// are printed to 3 digits, none of them near a rounding boundary.
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/material/gel_references.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "../flory_rehner_closed_form.h"

using GelMPM::FloryRehnerGel;

namespace
{
  bool all_ok = true;

  void
  report(const std::string &what, const bool ok)
  {
    all_ok &= ok;
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
  }

  /**
   * Whether the closed-form law has a stress-free state at @p mu, in plane strain (J = lambda_0
   * s^2) or isotropic (J = s^3): the first sign change of P_11 F_11 on the walk up from the dry
   * state.
   */
  bool
  has_swollen_state(const double mu,
                    const bool   plane_strain,
                    const double lambda_0,
                    const double chi,
                    const double N_nu)
  {
    const double dry = plane_strain ? 1. / std::sqrt(lambda_0) : 1.;
    for (double s = dry * 1.001;; s *= 1.001)
      {
        const double J = plane_strain ? lambda_0 * s * s : s * s * s;
        if (J > 1e12)
          return false;
        if (GelMPMTests::stress_times_stretch(s, J, mu, 1., chi, N_nu) >= 0.)
          return true;
      }
  }

  void
  check_limit(const std::string &kinematics,
              const double       limit,
              const bool         plane_strain,
              const double       lambda_0,
              const double       chi,
              const double       N_nu)
  {
    std::ostringstream text;
    text << std::setprecision(3) << "  " << kinematics << ": largest mu = " << limit;
    std::cout << text.str() << std::endl;
    report("stress-free state at 0.999 x the limit",
           has_swollen_state(0.999 * limit, plane_strain, lambda_0, chi, N_nu));
    report("none at 1.001 x the limit",
           !has_swollen_state(1.001 * limit, plane_strain, lambda_0, chi, N_nu));
  }
} // namespace


int
main()
{
  const double N_nu = 7.299e-3;
  for (const auto &[lambda_0, chi] :
       {std::pair{1.2801, 0.1}, std::pair{2.3489, 0.1}, std::pair{1.5, 0.3}})
    {
      std::cout << "lambda_0 = " << lambda_0 << ", chi = " << chi << ", N nu = " << N_nu << ":"
                << std::endl;
      const FloryRehnerGel<2> gel_2d(1., chi, N_nu, 1., lambda_0);
      const FloryRehnerGel<3> gel_3d(1., chi, N_nu, 1., lambda_0);
      const double            plane_strain = gel_2d.largest_swelling_chemical_potential();
      check_limit("plane strain", plane_strain, true, lambda_0, chi, N_nu);
      report("equal to N nu/lambda_0 (relative 1e-9)",
             std::abs(plane_strain * lambda_0 / N_nu - 1.) < 1e-9);
      bool found = true;
      try
        {
          GelMPM::GelReferences(gel_2d).free_swelling(0.999 * plane_strain,
                                                      GelMPM::SwellingKinematics::plane_strain);
        }
      catch (const std::domain_error &)
        {
          found = false;
        }
      report("GelReferences finds the plane-strain state at 0.999 x the limit", found);
      const double isotropic = gel_3d.largest_swelling_chemical_potential();
      check_limit("3D", isotropic, false, lambda_0, chi, N_nu);
      report("the 2D gel of an axisymmetric scene has the 3D limit",
             gel_2d.largest_swelling_chemical_potential(true) == isotropic);
    }
  std::cout << (all_ok ? "all swelling-limit checks passed" : "SOME SWELLING-LIMIT CHECKS FAILED")
            << std::endl;
  return all_ok ? 0 : 1;
}

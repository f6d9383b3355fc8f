// Shared by the tests that check a run against the Flory-Rehner law in closed form, computed
// independently of the solver and of the material class (paper eq. (19), the units of
// doc/method.md).
#ifndef gelmpm_tests_flory_rehner_closed_form_h
#define gelmpm_tests_flory_rehner_closed_form_h

#include <cmath>
#include <functional>

namespace GelMPMTests
{
  /**
   * P_ii F_ii of a gel with shear modulus @p G, @p chi and @p N_nu at a diagonal F whose
   * component i is @p stretch (from the dry state), J = det F, at mu/kT = @p mu:
   *   G (F_ii^2 - 1) + (G / N nu) J [ln(1 - 1/J) + 1/J + chi/J^2 - mu].
   * Zero for every i at a stress-free state: eq. (22) with all stretches equal.
   */
  inline double
  stress_times_stretch(const double stretch,
                       const double J,
                       const double mu,
                       const double G,
                       const double chi,
                       const double N_nu)
  {
    return G * (stretch * stretch - 1.) +
           G / N_nu * J * (std::log(1. - 1. / J) + 1. / J + chi / (J * J) - mu);
  }

  /** A root of @p f in [a, b], where f changes sign, by 200 bisections. */
  inline double
  bisect(const std::function<double(double)> &f, double a, double b)
  {
    for (int i = 0; i < 200; ++i)
      {
        const double m              = 0.5 * (a + b);
        (f(a) * f(m) <= 0. ? b : a) = m;
      }
    return 0.5 * (a + b);
  }
} // namespace GelMPMTests

#endif

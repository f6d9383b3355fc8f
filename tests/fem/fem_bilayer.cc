// The body-fitted peer with two materials (FemMixedSystem, one gel per cell material_id) on the
// bilayer actuator of prm/bilayer_actuator.prm (FemBilayer), against Timoshenko's bimetal formula
// at a small mismatch, computed here from the Flory-Rehner law in closed form (independent of the
// material class; the reference of contrib/benchmarks/bilayer_reference.py):
// - the passive layer with chi = 0.15, the bath from mu_0 to -0.04 over 1 tau_d, held to
//   10 tau_d: a mismatch strain of 0.65 %;
// - on 40 x 4 Q2-Q1 cells (two through each layer) the curvature of the lower surface (circle
//   fit) lies within 1 % of Timoshenko's (measured: +0.10 %; the MPM on 8 and 16
//   cells through the thickness: +0.39 % and +0.05 %, doc/own_scenes.md);
// - each layer starts stress-free at the one mu_0 with its own lambda_0 (eq. (22)): the lambda_0
//   of the passive gel equals the closed form's to 1e-8.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_bilayer.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../flory_rehner_closed_form.h"

namespace
{
  constexpr double G = 1., chi_active = 0.1, N_nu = 7.299e-3, lambda_0 = 1.2801;

  double
  p11(const double stretch, const double J, const double mu, const double chi)
  {
    return GelMPMTests::stress_times_stretch(stretch, J, mu, G, chi, N_nu);
  }

  /** The Table 1 mu_0/k_BT (eq. (22) at lambda_0 = 1.2801). */
  double
  table_1_mu_0()
  {
    return p11(lambda_0, std::pow(lambda_0, 3), 0., chi_active) / (std::pow(lambda_0, 3) / N_nu);
  }

  /** lambda_0 of the gel with @p chi, stress-free at the Table 1 mu_0. */
  double
  stress_free_stretch(const double chi)
  {
    const double mu_0 = table_1_mu_0();
    return GelMPMTests::bisect(
      [&](double s) {
        return p11(s, s * s * s, mu_0, chi);
      },
      1. + 1e-12,
      10.);
  }

  /** The in-plane free-swelling stretch a (relative to the initial state) and the drained
   * plane-strain uniaxial modulus E' of the gel with @p chi, initially stress-free at the Table 1
   * mu_0, in a bath of @p mu_b (out of plane F_33 = lambda_0r). */
  std::pair<double, double>
  layer(const double chi, const double mu_b)
  {
    const double l0 = stress_free_stretch(chi);
    const double a  = GelMPMTests::bisect(
      [&](double t) {
        return p11(l0 * t, l0 * l0 * l0 * t * t, mu_b, chi);
      },
      (1. + 1e-12) / std::pow(l0, 1.5),
      10.);
    const auto cauchy_11 = [&](const double delta) {
      const double F11 = l0 * a * (1. + delta);
      const double b   = GelMPMTests::bisect(
        [&](double u) {
          return p11(l0 * a * u, F11 * l0 * a * u * l0, mu_b, chi);
        },
        0.5,
        1.5);
      const double J = F11 * l0 * a * b * l0;
      return p11(F11, J, mu_b, chi) / J;
    };
    const double d = 1e-6;
    return {a, (cauchy_11(d) - cauchy_11(-d)) / (2. * d)};
  }

  /** Timoshenko's curvature of two layers of initial thickness @p h0 each (J. Opt. Soc. Am. 11,
   * 1925), the upper one Table 1, the lower one with @p chi_bottom. */
  double
  timoshenko(const double chi_bottom, const double mu_b, const double h0)
  {
    const auto [a1, E1] = layer(chi_active, mu_b);
    const auto [a2, E2] = layer(chi_bottom, mu_b);
    const double eps = a1 / a2 - 1., h1 = h0 * a1, h2 = h0 * a2;
    const double m = h1 / h2, n = E1 / E2, h = h1 + h2;
    return 6. * eps * (1. + m) * (1. + m) /
           (h * (3. * (1. + m) * (1. + m) + (1. + m * n) * (m * m + 1. / (m * n))));
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  GelMPM::FemBilayer::Parameters parameters;
  parameters.cells            = 4;
  parameters.chi_passive      = 0.15;
  const auto         settings = GelMPM::fem_run_settings({{"Characteristic length", "0.2"},
                                                          {"Initial step", "1e-3"},
                                                          {"End time", "10"},
                                                          {"Step caps", "1: 0.05, 10: 0.5"}},
                                                 {});
  GelMPM::FemBilayer bilayer(parameters);

  // The initial state: each layer stress-free at the common mu_0.
  const double passive_lambda_0 = bilayer.materials()[1].lambda_0();
  std::cout << "lambda_0 of the layers: " << std::setprecision(5)
            << bilayer.materials()[0].lambda_0() << ", " << passive_lambda_0
            << "; the passive one equals the closed form's to 1e-8: "
            << (std::abs(passive_lambda_0 - stress_free_stretch(parameters.chi_passive)) < 1e-8)
            << std::endl;

  double       curvature = 0.;
  const auto   result    = bilayer.run(settings.time_stepping,
                                  settings.newton,
                                  GelMPM::LinearSolver(),
                                  [&](const GelMPM::FemBilayer::Step &s) {
                                    curvature = s.curvature;
                                  });
  const double reference = timoshenko(parameters.chi_passive, parameters.mu_bath, 0.1);
  const double deviation = curvature / reference - 1.;
  std::cout << "run completed: " << result.completed << std::endl;
  std::cout << "Timoshenko curvature " << std::setprecision(4) << reference
            << "; FE 40 x 4 within 1 %: " << (std::abs(deviation) < 0.01) << " (" << std::fixed
            << std::setprecision(1) << 100. * deviation << " %)" << std::endl;
  return 0;
}

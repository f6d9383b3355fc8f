// Material regions: a laterally constrained stack of two different gels swelling from the top
// (two_gel_stack_scene.prm) reaches the closed-form equilibrium
//   Delta h / h_0 = sum_k h_k (lambda_k - 1) / sum_k h_k,
// each lambda_k the one-dimensional constrained equilibrium of its own gel: F = diag(lambda_0k,
// lambda_0k lambda_k, lambda_0k) with P_22 = 0 at the bath's mu, lambda_0k the region's initial
// stretch at the common mu_0 (eq. (22)). Computed here from the Flory-Rehner law by bisection,
// independently of the solver and of the material class:
//   P_ii F_ii = G (F_ii^2 - 1) + (G / N nu) J [ln(1 - 1/J) + 1/J + chi/J^2 - mu/kT].
// Asserted within 1e-3 of Delta h / h_0 at 150 tau_d (8e-5 measured); also that the two
// regions' gels differ enough to matter (their lambda_k differ by more than 5%).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "../flory_rehner_closed_form.h"
#include "../scene_run.h"

using GelMPMTests::bisect;
using GelMPMTests::stress_times_stretch;


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  // The Table 1 gel fixes mu_0 and k_BT/nu = G/(N nu) = 1/7.299e-3.
  const double lambda_0 = 1.2801, kT_over_nu = 1. / 7.299e-3;
  const double mu_0 = stress_times_stretch(lambda_0, std::pow(lambda_0, 3), 0., 1., 0.1, 7.299e-3) /
                      (kT_over_nu * std::pow(lambda_0, 3));
  const double mu_bath = -0.05;
  struct Layer
  {
    double h, chi, N_nu;
  };
  const Layer layers[] = {{0.25, 0.3, 2. * 7.299e-3}, {0.25, 0.1, 7.299e-3}};
  double      change = 0., height = 0.;
  double      stretches[2];
  for (unsigned int k = 0; k < 2; ++k)
    {
      const auto  &l  = layers[k];
      const double G  = l.N_nu * kT_over_nu;
      const double L0 = bisect(
        [&](const double s) {
          return stress_times_stretch(s, s * s * s, mu_0, G, l.chi, l.N_nu);
        },
        1. + 1e-9,
        5.);
      const double stretch = bisect(
        [&](const double s) {
          return stress_times_stretch(L0 * s, L0 * L0 * L0 * s, mu_bath, G, l.chi, l.N_nu);
        },
        (1. + 1e-9) / (L0 * L0 * L0),
        10.);
      stretches[k] = stretch;
      change += l.h * (stretch - 1.);
      height += l.h;
    }
  const double expected = change / height;

  const auto run = GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/two_gel_stack_scene.prm",
                                          "two_gel_stack",
                                          {});
  std::cout << "run completed: " << (run.status == 0) << std::endl;
  std::cout << "the layers' constrained stretches differ by more than 5%: "
            << (std::abs(stretches[1] / stretches[0] - 1.) > 0.05) << std::endl;
  const double found = run.statistics.at("delta_h_over_h0").back();
  std::cout << "Delta h / h_0 within 1e-3 of the closed form: "
            << (std::abs(found - expected) <= 1e-3 * expected) << std::endl;
  if (!(std::abs(found - expected) <= 1e-3 * expected))
    std::cout << "  (" << found << " against " << expected << ")" << std::endl;
  return 0;
}

// Going through the loss of stability of the §4.3 column (doc/method.md, "Going through an
// instability"): prm/column_buckling.prm on a coarse grid (h_u = H/8, 3 x 3 points per cell) to
// t = 0.32 tau_d with the scene's stability settings: the onset bracketed by the drained criterion
// (K_uu indefinite) to 1e-3 tau_d, the perturbation of 1e-2 H along the critical mode towards +x,
// signature step control and the error control of the steps (a predictor-corrector difference of at
// most 0.01 H per step). Asserted from stability.csv and statistics.csv:
// - exactly one onset is bracketed, at most 1e-3 tau_d wide, between 0.2 and 0.3 tau_d, where K_uu
//   gains one negative eigenvalue (n_neg_uu: 0 before, >= 1 after);
// - the column sways towards +x, the side the perturbation chose: centre_offset_x exceeds 0.1 H
//   at the end and grows over the last ten steps;
// - the run completes, and after the sway has set in the tangent's signature is (n_dofs_u,
//   n_dofs_mu, 0) again (the last step).
#include <gelmpm/io/statistics_file.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/column_buckling.prm",
                           "results",
                           {"Background grid/Cells=140, 80",
                            "Material points/Points per cell=3",
                            "Time stepping/End time=0.32",
                            "Time stepping/Stop at times=",
                            "Stability/Schur eigenvalues=1"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  const auto [t_stable, t_unstable] = GelMPMTests::single_bracket("results", 1e-3);
  if (t_stable < 0.)
    return 0;
  std::cout << "onset between 0.2 and 0.3 tau_d: " << (t_stable > 0.2 && t_unstable < 0.3)
            << std::endl;

  const auto &s               = run.statistics;
  const auto &t               = s.at("t_over_tau_d");
  const auto &neg             = s.at("n_neg_uu");
  bool        definite_before = true, indefinite_at = false;
  for (unsigned int i = 1; i < t.size(); ++i)
    {
      if (t[i] <= t_stable * (1. + 1e-12))
        definite_before = definite_before && neg[i] == 0.;
      if (std::abs(t[i] - t_unstable) < 1e-9)
        indefinite_at = neg[i] >= 1.;
    }
  std::cout << "K_uu positive definite before the onset, indefinite at its end: "
            << (definite_before && indefinite_at) << std::endl;

  const auto        &offset  = s.at("centre_offset_x");
  const unsigned int n       = offset.size();
  bool               growing = n > 11;
  for (unsigned int i = n - 10; growing && i < n; ++i)
    growing = offset[i] > offset[i - 1];
  std::cout << "the column sways towards +x by more than 0.1 H: " << (offset.back() > 0.1)
            << std::endl;
  std::cout << "and the sway grows over the last ten steps: " << growing << std::endl;
  if (!(offset.back() > 0.1 && growing))
    std::cout << "  (centre_offset_x at the end " << offset.back() << ")" << std::endl;
  std::cout << "the signature is (n_dofs_u, n_dofs_mu, 0) again at the end: "
            << (s.at("n_pos").back() == s.at("n_dofs_u").back() &&
                s.at("n_neg").back() == s.at("n_dofs_mu").back() && s.at("n_zero").back() == 0.)
            << std::endl;
  return 0;
}

// Bracketing the loss of stability (paper §3.6, §4.3): the swelling column of
// prm/column_buckling.prm on a coarse grid (h = H/8, 3 x 3 points per cell, steps of at most
// 0.02 tau_d) with the inertia, one Schur eigenvalue, the drained onset criterion (K_uu turns
// indefinite, as in the scenes) and 'Stability/Bisection tolerance = 1e-3', no perturbation.
// Asserted from stability.csv and statistics.csv: exactly one loss of stability is reported before
// t = 0.3 tau_d, its bracket is at most 1e-3 tau_d wide, K_uu has no negative eigenvalue at its
// stable end and one at its unstable end, and it lies within 20% of the paper's onset
// t_onset = 0.28 tau_d (Fig. 10; measured here: 0.233125 to 0.23375 tau_d, 17% below; the onset
// rises under refinement to 0.2509 tau_d on the scene's grid, doc/column_buckling.md). With
// 'Stability/Write mode', the critical mode written at the end (mode.pvd, read back with VTK) is
// the sway of the column: its lateral displacement exceeds the vertical one fivefold, and it grows
// from the pinned bottom to the top (which only the normal condition holds).
#include <gelmpm/io/statistics_file.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../scene_run.h"
#include "../vtu_reader.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/column_buckling.prm",
                           "results",
                           {"Background grid/Cells=140, 80",
                            "Material points/Points per cell=3",
                            "Time stepping/Initial step=0.02",
                            "Time stepping/Step caps=2: 0.02",
                            "Time stepping/End time=0.3",
                            "Time stepping/Stop at times=",
                            "Stability/Inertia=true",
                            "Stability/Schur eigenvalues=1",
                            "Stability/Bisection tolerance=1e-3",
                            "Stability/Write mode=true",
                            "Newton/Initial chemical potential=grid",
                            "Stability/Onset criterion=drained",
                            "Stability/Perturbation amplitude=0",
                            "Stability/Signature step control=false",
                            "Time stepping/Largest increment=0",
                            "Time stepping/Displacement tolerance=0",
                            "Newton/Initial displacement=zero"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  const auto brackets = GelMPM::read_statistics("results/stability.csv");
  const bool one      = brackets.count("t_stable") && brackets.at("t_stable").size() == 1;
  std::cout << "one loss of stability reported: " << one << std::endl;
  if (!one)
    return 0;
  const double t_stable = brackets.at("t_stable")[0], t_unstable = brackets.at("t_unstable")[0];
  std::cout << "bracket at most 1e-3 tau_d wide: " << (t_unstable - t_stable <= 1e-3 + 1e-12)
            << std::endl;
  // K_uu's negative eigenvalues at the bracket's two ends, from the steps that landed on them.
  const auto  steps     = GelMPM::read_statistics("results/statistics.csv");
  const auto &t         = steps.at("t_over_tau_d");
  const auto &n_neg     = steps.at("n_neg_uu");
  double      at_stable = -1., at_unstable = -1.;
  for (unsigned int i = 0; i < t.size(); ++i)
    {
      if (std::abs(t[i] - t_stable) < 1e-9)
        at_stable = n_neg[i];
      if (std::abs(t[i] - t_unstable) < 1e-9)
        at_unstable = n_neg[i];
    }
  std::cout << "K_uu positive definite at the stable end, one negative eigenvalue at the other: "
            << (at_stable == 0. && at_unstable == 1.) << std::endl;
  std::cout << "onset within 20% of the paper's 0.28 tau_d: "
            << (std::abs(0.5 * (t_stable + t_unstable) / 0.28 - 1.) < 0.2) << std::endl;

  // The last entry of mode.pvd: the mode of the last converged step.
  std::ifstream pvd("results/mode.pvd");
  std::string   line, last_file;
  while (std::getline(pvd, line))
    if (const auto at = line.find("file=\""); at != std::string::npos)
      last_file = line.substr(at + 6, line.find('"', at + 6) - at - 6);
  std::cout << "mode.pvd lists the mode: " << !last_file.empty() << std::endl;
  if (last_file.empty())
    return 0;
  const auto  mode   = GelMPMTests::read_vtu("results/" + last_file);
  const auto *field  = mode.array("displacement_increment");
  double      ux_max = 0., uy_max = 0., ux_bottom = 0., ux_top = 0.;
  for (std::size_t k = 0; field != nullptr && k < mode.points.size(); ++k)
    {
      const double u[2] = {(*field)(k, 0), (*field)(k, 1)};
      const auto  &x    = mode.points[k];
      if (!std::isfinite(u[0]))
        continue;
      ux_max = std::max(ux_max, std::abs(u[0]));
      uy_max = std::max(uy_max, std::abs(u[1]));
      if (x[1] < 1.5)
        ux_bottom = std::max(ux_bottom, std::abs(u[0]));
      if (x[1] > 8.5)
        ux_top = std::max(ux_top, std::abs(u[0]));
    }
  std::cout << "the mode is lateral (max |u_x| > 5 max |u_y|): " << (ux_max > 5. * uy_max)
            << std::endl;
  std::cout << "the mode sways: |u_x| at the top above 10 x at the bottom: "
            << (ux_top > 10. * ux_bottom) << std::endl;
  return 0;
}

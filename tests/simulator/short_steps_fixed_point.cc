// A step of vanishing length leaves a converged state as it is.
//
// (i) Nitsche's adjoint term in time (doc/method.md): the flat punch of prm/flat_punch.prm on
// 30 x 30 cells (3 x 3 points per cell) is run to t = 0.01 tau_d with growing steps, then five
// steps of 1e-11 tau_d. The first of them relaxes what the last real step's motion left in the
// quadrature; from then on the state must stay: over each of the last two, J_min and J_max of the
// volume points change by at most 1e-5 and J_mean by at most 1e-6 (measured: 1.2e-6, 3e-6 and
// below 1e-8; with the symmetric Nitsche term counted afresh at every step they rose by 2.4e-3,
// 6.5e-3 and 1.4e-5 at every step).
//
// (ii) Points held on a grid edge (doc/method.md, "Points held on a grid edge"): the constrained
// swelling of prm/constrained_swelling.prm (3 x 3 points per cell) is run to t = 20 tau_d, where
// the roller at x = 0, the grid's edge, is pressed by the swollen layer, then six steps of
// 1e-11 tau_d. The last three must need no Newton iteration (the state is a fixed point) and
// leave Delta h / h_0 unchanged to 1e-10. With the violation of the roller dropped at every step
// (points put back on the edge without their offset), every short step needed an iteration, and
// over thousands of short steps the layer crept through the edge and its thickness fell by up to
// 2.3e-5 per step (doc/performance.md, "What held 10^-4 back").
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "../scene_run.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/flat_punch.prm",
                           "punch",
                           {"Background grid/Cells=30, 30",
                            "Material points/Points per cell=3",
                            "Observables/Volume ratio range=true",
                            "Time stepping/Step caps=3.125e-6: 3.125e-7, 0.01: 1e9, 1: 1e-11",
                            "Time stepping/Stop at times=3.125e-6, 0.01",
                            "Time stepping/End time=0.01000000005"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;
  const auto        &t     = run.statistics.at("t_over_tau_d");
  const unsigned int first = std::find_if(t.begin(),
                                          t.end(),
                                          [](const double time) {
                                            return time >= 0.01 * (1. - 1e-12);
                                          }) -
                             t.begin();
  std::cout << "five short steps after t = 0.01: " << (t.size() - 1 - first == 5) << std::endl;
  for (const auto &[name, bound] : std::vector<std::pair<std::string, double>>{{"J_min", 1e-5},
                                                                               {"J_mean", 1e-6},
                                                                               {"J_max", 1e-5}})
    {
      const auto &J      = run.statistics.at(name);
      double      change = 0.;
      for (unsigned int i = J.size() - 2; i < J.size(); ++i)
        change = std::max(change, std::abs(J[i] - J[i - 1]));
      std::cout << name << " steady over the last two short steps (change at most " << bound
                << "): " << (change <= bound) << std::endl;
      if (change > bound)
        std::cout << "  (changed by " << change << ")" << std::endl;
    }
  const auto layer =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/constrained_swelling.prm",
                           "layer",
                           {"Material points/Points per cell=3",
                            "Time stepping/Step caps=5: 0.05, 20: 0.2, 20.00000000008: 1e-11",
                            "Time stepping/Stop at times=20",
                            "Time stepping/End time=20.00000000008"});
  std::cout << "layer run completed: " << (layer.status == 0) << std::endl;
  const auto &layer_t = layer.statistics.at("t_over_tau_d");
  const auto  n_short = std::count_if(layer_t.begin(), layer_t.end(), [](const double time) {
    return time >= 20. * (1. - 1e-12);
  });
  std::cout << "seven steps end at t = 20 (one landing, six short): " << (n_short == 7)
            << std::endl;
  const auto &iterations = layer.statistics.at("newton_iterations");
  const auto &thickness  = layer.statistics.at("delta_h_over_h0");
  if (iterations.size() < 4)
    return 0;
  double most   = 0.;
  double change = 0.;
  for (unsigned int i = iterations.size() - 3; i < iterations.size(); ++i)
    {
      most   = std::max(most, iterations[i]);
      change = std::max(change, std::abs(thickness[i] - thickness[i - 1]));
    }
  std::cout << "no Newton iteration in the last three short steps: " << (most == 0.) << std::endl;
  std::cout << "Delta h / h_0 steady over them (change at most 1e-10): " << (change <= 1e-10)
            << std::endl;
  if (most != 0. || change > 1e-10)
    std::cout << "  (at most " << most << " iterations, change " << change << ")" << std::endl;
  return 0;
}

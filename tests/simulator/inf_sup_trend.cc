// The discrete inf-sup constant of the undrained problem under refinement (doc/inf_sup.md): the
// H x H gel of prm/flat_punch.prm with a free, impermeable top, rollers elsewhere, at its initial
// state (one step of 3.125e-7 tau_d), on grids with h = 0.125H and 0.0625H (body aligned with the
// grid, 3 x 3 points per cell). Asserted:
// - Q2-Q2SD: beta_h changes by less than 5% from one grid to the next (bounded below);
// - Q2-Q2 and Q3-Q2 (maximally smooth, one grid): beta_h drops by more than 20% per halving of h
//   (measured 0.70 and 0.63; 0.70 and 0.55 on the next halving);
// - on the finer grid the SD pair's beta_h exceeds Q2-Q2's by more than a factor 10.
#include <deal.II/base/mpi.h>

#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  /** beta_h of the pair set by @p pair on a grid of @p cells x @p cells over 1.5H x 1.5H. */
  double
  inf_sup_constant(const std::vector<std::string> &pair, const unsigned int cells)
  {
    std::vector<std::string> overrides = {"Background grid/Cells=" + std::to_string(cells) + ", " +
                                            std::to_string(cells),
                                          "Material points/Points per cell=3",
                                          "Boundary conditions/punch/Displacement=free",
                                          "Time stepping/End time=3.125e-7",
                                          "Stability/Inf-sup constant=true"};
    overrides.insert(overrides.end(), pair.begin(), pair.end());
    return GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/flat_punch.prm",
                                  "results",
                                  overrides)
      .statistics.at("inf_sup")
      .back();
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize              mpi(argc, argv, 1);
  const std::map<std::string, std::vector<std::string>> pairs = {
    {"Q2-Q2", {"Discretisation/Chemical potential grid=same"}},
    {"Q3-Q2",
     {"Discretisation/Chemical potential grid=same", "Discretisation/Displacement degree=3"}},
    {"Q2-Q2SD", {}}};
  std::map<std::string, std::pair<double, double>> beta;
  for (const auto &[name, overrides] : pairs)
    beta[name] = {inf_sup_constant(overrides, 12), inf_sup_constant(overrides, 24)};

  std::cout << std::boolalpha;
  const auto ratio = [&](const std::string &name) {
    return beta[name].second / beta[name].first;
  };
  std::cout << "Q2-Q2SD: beta_h changes by less than 5% on refinement: "
            << (std::abs(ratio("Q2-Q2SD") - 1.) < 0.05) << std::endl;
  std::cout << "Q2-Q2: beta_h drops by more than 20%: " << (ratio("Q2-Q2") < 0.8) << std::endl;
  std::cout << "Q3-Q2: beta_h drops by more than 20%: " << (ratio("Q3-Q2") < 0.8) << std::endl;
  std::cout << "fine grid: Q2-Q2SD beta_h above 10 x Q2-Q2: "
            << (beta["Q2-Q2SD"].second > 10. * beta["Q2-Q2"].second) << std::endl;
  for (const auto &[name, b] : beta)
    if (!(std::abs(ratio("Q2-Q2SD") - 1.) < 0.05 && ratio("Q2-Q2") < 0.8 && ratio("Q3-Q2") < 0.8))
      std::cout << "  " << name << ": " << b.first << " -> " << b.second << std::endl;
  return 0;
}

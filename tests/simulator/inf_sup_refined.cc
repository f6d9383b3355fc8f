// The discrete inf-sup constant of Q2-Q2SD on locally refined grids (doc/inf_sup.md, "On a
// refined grid"): the gel of tests/simulator/inf_sup_trend (prm/flat_punch.prm with a free,
// impermeable top, rollers elsewhere, one step of 3.125e-7 tau_d) on 12 x 12 cells with the box
// 0.25 <= x <= 0.75, y >= 0.75 (the body's top left, cut by its top) refined 2 and 3 times, mu one
// level coarser than u everywhere. Asserted:
// - beta_h stays bounded as a level is added: the third level changes it by less than 2 %
//   (measured 111.92 -> 111.50), and it stays above 0.85 times the uniform grid's (120.54);
// - the tangent's signature is that of a stable saddle point, (n_dofs_u, n_dofs_mu, 0), with
//   n_dofs_u and n_dofs_mu those of the hierarchical spaces (more than the uniform grid's).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  struct Analysis
  {
    double beta, n_u, n_mu, n_pos, n_neg, n_zero;
  };

  /** The last step's analysis with 'Refinement levels' @p levels (0: the uniform grid). */
  Analysis
  analyse(const unsigned int levels)
  {
    std::vector<std::string> overrides = {"Background grid/Cells=12, 12",
                                          "Material points/Points per cell=3",
                                          "Boundary conditions/punch/Displacement=free",
                                          "Time stepping/End time=3.125e-7",
                                          "Stability/Inf-sup constant=true",
                                          "Stability/Inertia=true",
                                          "Output/Write particles=false"};
    if (levels > 0)
      {
        overrides.push_back("Background grid/Refinement boxes=0.25, 0.75 : 0.75, 1.5");
        overrides.push_back("Background grid/Refinement levels=" + std::to_string(levels));
      }
    const auto run  = GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/flat_punch.prm",
                                            "results",
                                            overrides);
    const auto last = [&](const std::string &column) {
      return run.statistics.at(column).back();
    };
    return {last("inf_sup"),
            last("n_dofs_u"),
            last("n_dofs_mu"),
            last("n_pos"),
            last("n_neg"),
            last("n_zero")};
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Analysis uniform = analyse(0), two = analyse(2), three = analyse(3);
  std::cout << std::boolalpha;
  std::cout << "the refined spaces have more unknowns: "
            << (two.n_u > uniform.n_u && three.n_u > two.n_u && three.n_mu > two.n_mu) << std::endl;
  std::cout << "beta_h changes by less than 2 % from 2 to 3 levels: "
            << (std::abs(three.beta / two.beta - 1.) < 0.02) << std::endl;
  std::cout << "beta_h above 0.85 times the uniform grid's: "
            << (two.beta > 0.85 * uniform.beta && three.beta > 0.85 * uniform.beta) << std::endl;
  for (const auto &[name, a] : {std::make_pair("2 levels", two), std::make_pair("3 levels", three)})
    std::cout << name << ": signature (n_dofs_u, n_dofs_mu, 0): "
              << (a.n_pos == a.n_u && a.n_neg == a.n_mu && a.n_zero == 0.) << std::endl;
  if (!(std::abs(three.beta / two.beta - 1.) < 0.02 && two.beta > 0.85 * uniform.beta))
    std::cout << "  beta_h: uniform " << uniform.beta << ", 2 levels " << two.beta << ", 3 levels "
              << three.beta << std::endl;
  return 0;
}

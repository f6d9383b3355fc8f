// A locally refined grid against the finite-difference reference:
// prm/constrained_swelling_refined.prm (paper §4.1 with the cell pairs of 0.9 <= y <= 1.2, across
// the top, halved once: truncated hierarchical B-splines, extended at both levels; steps growing
// by 1.08), up to t = 0.0013 tau_d (11 steps), with the solvent balance. Asserted:
// - Delta h within 1 % of the 1D reference at every step from 1e-3 tau_d on (measured +0.20 % at
//   1.09e-3, -0.05 % at 1.197e-3 and -0.23 % at 1.3e-3 tau_d; the paper's 20 x 160 grid +10.3 %
//   at 1.197e-3);
// - the solvent mass balance on the refined grid: |solvent_imbalance| <= 1e-8 at every step
//   (measured 7e-12);
// - the refined grid has more unknowns than the uniform one (926 + 129 against 738 + 105 at the
//   first step), and fewer than the uniform 40 x 320 grid that is as accurate (2754 + 369).
// The same with the box replaced by refinement where the points' mu (and the bath's) span more
// than 0.01 k_BT ('Background grid/Refinement mu range', marked anew every step with a buffer of
// q + 2 cells), and that its refined region moves: the unknowns change from step to step and
// points are split during the run, the solvent balance holding on a grid that changes. And the
// same with refinement round the material that starts at y >= 0.9 ('Refinement material
// region = 0.9 - y').
#include <gelmpm/reference/constrained_swelling_1d.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "../scene_run.h"


namespace
{
  /**
   * Run the refined scene to 0.0013 tau_d with @p overrides and print the assertions above;
   * returns the run's statistics.
   */
  std::map<std::string, std::vector<double>>
  run_and_check(const std::string &directory, std::vector<std::string> overrides)
  {
    overrides.insert(overrides.end(),
                     {"Observables/Forces and fluxes=all",
                      "Time stepping/End time=0.0013",
                      "Time stepping/Stop at times=0.001197",
                      "Output/Write particles=false"});
    const auto run = GelMPMTests::run_scene(std::string(SOURCE_DIR) +
                                              "/../../prm/constrained_swelling_refined.prm",
                                            directory,
                                            overrides);
    std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

    auto        mpm       = run.statistics;
    const auto &t         = mpm["t_over_tau_d"];
    const auto &dh        = mpm["delta_h_over_h0"];
    const auto &imbalance = mpm["solvent_imbalance"];
    const auto &n_u       = mpm["n_dofs_u"];
    const auto &n_mu      = mpm["n_dofs_mu"];

    GelMPM::ConstrainedSwelling1D reference(GelMPM::ConstrainedSwelling1D::Parameters{});
    double                        worst_error = 0., worst_imbalance = 0.;
    unsigned int                  compared = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
      {
        worst_imbalance = std::max(worst_imbalance, std::abs(imbalance[i]));
        if (t[i] >= 1e-3)
          {
            reference.advance_to(t[i]);
            worst_error =
              std::max(worst_error, std::abs(dh[i] / reference.thickness_change() - 1.));
            ++compared;
          }
      }
    std::cout << "steps from 1e-3 tau_d on compared: " << (compared >= 3) << std::endl;
    std::cout << "Delta h within 1 % of the reference at each of them: " << (worst_error < 0.01)
              << std::endl;
    if (worst_error >= 0.01)
      std::cout << "  (" << 100. * worst_error << " %)" << std::endl;
    std::cout << "|solvent_imbalance| <= 1e-8 at every step: " << (worst_imbalance <= 1e-8)
              << std::endl;
    std::cout << "unknowns between the uniform grid's 843 and the uniform 40 x 320 grid's 3123: "
              << (t.size() > 1 && n_u[1] + n_mu[1] > 843 && n_u[1] + n_mu[1] < 3123) << std::endl;
    return mpm;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << "The box 0.9 <= y <= 1.2:" << std::endl;
  run_and_check("results", {});
  std::cout << "Refined where the points' mu spans more than 0.01 (marked every step):"
            << std::endl;
  auto        front  = run_and_check("front",
                             {"Background grid/Refinement boxes=",
                                      "Background grid/Refinement mu range=0.01"});
  const auto &n_u    = front["n_dofs_u"];
  const auto &points = front["n_particles"];
  std::cout << "the unknowns change as the front moves: "
            << (*std::max_element(n_u.begin() + 1, n_u.end()) >
                *std::min_element(n_u.begin() + 1, n_u.end()))
            << std::endl;
  std::cout << "points split during the run: " << (points.back() > points[1]) << std::endl;

  std::cout << "Refined round the material that starts at y >= 0.9 (marked every step):"
            << std::endl;
  auto        material        = run_and_check("material",
                                {"Background grid/Refinement boxes=",
                                               "Background grid/Refinement material region=0.9 - y"});
  const auto &material_points = material["n_particles"];
  std::cout << "the material's points split (more than the unrefined grid's 12,768): "
            << (material_points[0] > 12768.) << std::endl;
  return 0;
}

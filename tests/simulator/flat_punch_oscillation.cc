// Inf-sup stability seen in the solution (paper §4.2, Fig. 7b and 8a-d): the flat punch of
// prm/flat_punch.prm at the end of its ramp (t_inc = 3.125e-6 tau_d, the undrained limit) on the
// coarse grid (h_u = 0.05H, 3 x 3 points per cell), with three u-mu pairs: (i) Q2-Q2, (ii) Q3-Q2
// (both on one grid; not inf-sup stable with maximally smooth B-splines) and (iv) Q2-Q2SD (mu on
// the 2h grid). The measure mu_oscillation (mean over rows of volume points of the summed
// |second differences| of mu, over the range of mu; Observables/Chemical potential oscillation)
// is asserted to order the pairs:
// - Q2-Q2 carries the checkerboard mode of an unstable pair: more than 10 times the SD value
//   (68 times here);
// - Q3-Q2 lies above the SD value (the measured ratio is 2.4 here, and 3.5 with 5 x 5 points on
//   the fine grids of doc/flat_punch.md);
// - Q2-Q2SD stays below 0.1.
#include <deal.II/base/mpi.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  /** mu_oscillation at the end of the punch ramp for the pair set by @p overrides. */
  double
  oscillation_at_end_of_ramp(const std::string &directory, const std::vector<std::string> &pair)
  {
    std::vector<std::string> overrides = {"Background grid/Cells=30, 30",
                                          "Material points/Points per cell=3",
                                          "Time stepping/End time=3.125e-6",
                                          "Observables/Chemical potential oscillation=true"};
    overrides.insert(overrides.end(), pair.begin(), pair.end());
    const auto run = GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/flat_punch.prm",
                                            directory,
                                            overrides);
    std::cout << std::boolalpha << directory << ": run completed: " << (run.status == 0)
              << std::endl;
    return run.statistics.at("mu_oscillation").back();
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             q2_q2 =
    oscillation_at_end_of_ramp("q2_q2", {"Discretisation/Chemical potential grid=same"});
  const double q3_q2   = oscillation_at_end_of_ramp("q3_q2",
                                                  {"Discretisation/Chemical potential grid=same",
                                                     "Discretisation/Displacement degree=3"});
  const double q2_q2sd = oscillation_at_end_of_ramp("q2_q2sd", {});

  std::cout << std::boolalpha << "Q2-Q2 oscillation above 10 x Q2-Q2SD: " << (q2_q2 > 10. * q2_q2sd)
            << std::endl;
  std::cout << "Q3-Q2 oscillation above Q2-Q2SD: " << (q3_q2 > q2_q2sd) << std::endl;
  std::cout << "Q2-Q2SD oscillation below 0.1: " << (q2_q2sd < 0.1) << std::endl;
  if (!(q2_q2 > 10. * q2_q2sd && q3_q2 > q2_q2sd && q2_q2sd < 0.1))
    std::cout << "  (Q2-Q2 " << q2_q2 << ", Q3-Q2 " << q3_q2 << ", Q2-Q2SD " << q2_q2sd << ")"
              << std::endl;
  return 0;
}

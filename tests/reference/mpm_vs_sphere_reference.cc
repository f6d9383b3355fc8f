// Verification of the axisymmetric MPM against the spherical finite-volume reference: the scene
// prm/swelling_sphere.prm (a gel sphere swelling freely, its bath going from mu_0 to 0 over
// 4 tau_d, modelled in its meridian plane) against FreeSwellingSphere1D with the same ramp.
// Asserted:
// - |r_MPM - r_ref| / R_0 <= 0.5 % of the equilibrium change (r_eq - R_0)/R_0 at every step with
//   t >= 1 tau_d (after the early boundary layer, which the reference resolves on graded nodes
//   and the MPM grid does not);
// - at 1200 tau_d, |r/R_0 - 1.834936| <= 1e-3, 1.834936 the closed-form free-swelling stretch
//   (the reference's own stretch_at(0), bisection on eq. (22)).
#include <gelmpm/reference/free_swelling_sphere_1d.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../scene_run.h"
#include "sphere_radius_error.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/swelling_sphere.prm",
                           "results",
                           {"Time stepping/Stop at times="});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  const double equilibrium = GelMPMTests::report_sphere_radius_error(run.statistics);
  const auto  &t           = run.statistics.at("t_over_tau_d");
  const auto  &radius      = run.statistics.at("radius_over_R0");
  std::cout << "run reaches 1200 tau_d: " << (std::abs(t.back() - 1200.) < 1e-9) << std::endl;
  std::cout << "|r/R_0 - r_eq/R_0| at the end below 1e-3: "
            << (std::abs(radius.back() - equilibrium) <= 1e-3) << std::endl;
  std::cout << "r_eq/R_0 (closed form): " << std::fixed << std::setprecision(6) << equilibrium
            << std::endl;
  return 0;
}

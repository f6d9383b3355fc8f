// The axisymmetric MPM on a locally refined grid against the spherical finite-volume reference:
// prm/swelling_sphere.prm (a gel sphere of radius 0.5 swelling freely, its bath going from mu_0 to
// 0 over 4 tau_d, in its meridian plane) with the cells of x >= 0.1875 halved once: a shell round
// a coarse core, cut by the sphere's surface at both levels and swept by it as it swells from 0.5
// to 0.92 (extended B-splines at both levels), to 10 tau_d (r/R_0 from 1 to 1.47).
// Asserted, as for the uniform grid (mpm_vs_sphere_reference):
// - |r_MPM - r_ref| / R_0 <= 0.5 % of the equilibrium change (r_eq - R_0)/R_0 at every step with
//   t >= 1 tau_d;
#include <gelmpm/reference/free_swelling_sphere_1d.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../scene_run.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/swelling_sphere.prm",
                           "results",
                           {"Time stepping/Stop at times=",
                            "Time stepping/End time=10",
                            "Background grid/Refinement boxes=0.1875, -0.1875 : 1.125, 1.0625",
                            "Background grid/Refinement levels=1",
                            "Output/Write particles=false"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  GelMPM::FreeSwellingSphere1D::Parameters parameters;
  parameters.ramp = 4.;
  GelMPM::FreeSwellingSphere1D reference(parameters);
  const double                 equilibrium = reference.stretch_at(0.);
  const auto                  &t           = run.statistics.at("t_over_tau_d");
  const auto                  &radius      = run.statistics.at("radius_over_R0");
  double                       worst = 0., worst_time = 0.;
  for (unsigned int i = 0; i < t.size(); ++i)
    if (t[i] >= 1.)
      {
        reference.advance_to(t[i]);
        const double error = std::abs(radius[i] - reference.outer_radius()) / (equilibrium - 1.);
        if (error > worst)
          worst = error, worst_time = t[i];
      }
  std::cout << "max |r - r_ref| / (r_eq - R_0) for t >= 1 tau_d below 0.005: " << (worst <= 0.005)
            << std::endl;
  if (worst > 0.005)
    std::cout << "  (" << worst << " at t = " << worst_time << ")" << std::endl;
  std::cout << "run reaches 10 tau_d: " << (std::abs(t.back() - 10.) < 1e-9) << std::endl;
  return 0;
}

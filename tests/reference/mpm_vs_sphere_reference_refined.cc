// The axisymmetric MPM on a locally refined grid against the spherical finite-volume reference:
// prm/swelling_sphere.prm (a gel sphere of radius 0.5 swelling freely, its bath going from mu_0 to
// 0 over 4 tau_d, in its meridian plane) with the cells of x >= 0.1875 halved once: a shell round
// a coarse core, cut by the sphere's surface at both levels and swept by it as it swells from 0.5
// to 0.92 (extended B-splines at both levels), to 10 tau_d (r/R_0 from 1 to 1.47).
// Asserted, as for the uniform grid (mpm_vs_sphere_reference):
// - |r_MPM - r_ref| / R_0 <= 0.5 % of the equilibrium change (r_eq - R_0)/R_0 at every step with
//   t >= 1 tau_d;
// with 'Time stepping/Tolerance = 2e-3' instead of the scene's 1e-3: from about 3 tau_d the
// points' integration noise holds the steps of 1e-3 to 0.01-0.1 tau_d (384 steps, 17 s; the
// uniform grid's too, 327 steps), 2e-3 takes 119 steps with the largest error 0.17 % (1e-3:
// 0.085 %; 1e-2: 0.75 %, which fails).
// And the same to 10 tau_d with a band that follows the surface instead ('Background
// grid/Refinement band = 0.15', the scene's grid refined once within 0.15 of the current surface,
// marked anew every step, points split as the band reaches them), asserted alike, and that the
// band moved with the surface: its unknowns change, and points are split and merged during the
// run. (A fixed
// band |r - 0.5| <= 0.15 stops at 4.06 tau_d as the surface nears its outer edge,
// doc/architecture.md.)
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
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
                           {"Time stepping/Stop at times=",
                            "Time stepping/End time=10",
                            "Background grid/Refinement boxes=0.1875, -0.1875 : 1.125, 1.0625",
                            "Background grid/Refinement levels=1",
                            "Time stepping/Tolerance=2e-3",
                            "Output/Write particles=false"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  GelMPMTests::report_sphere_radius_error(run.statistics);
  const auto &t = run.statistics.at("t_over_tau_d");
  std::cout << "run reaches 10 tau_d: " << (std::abs(t.back() - 10.) < 1e-9) << std::endl;

  std::cout << "A band that follows the surface:" << std::endl;
  const auto band =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/swelling_sphere.prm",
                           "band",
                           {"Time stepping/Stop at times=",
                            "Time stepping/End time=10",
                            "Background grid/Refinement band=0.15",
                            "Time stepping/Tolerance=2e-3",
                            "Output/Write particles=false"});
  std::cout << "run completed: " << (band.status == 0) << std::endl;
  GelMPMTests::report_sphere_radius_error(band.statistics);
  const auto &band_t = band.statistics.at("t_over_tau_d");
  std::cout << "run reaches 10 tau_d: " << (std::abs(band_t.back() - 10.) < 1e-9) << std::endl;
  const auto &n_u    = band.statistics.at("n_dofs_u");
  const auto &points = band.statistics.at("n_particles");
  std::cout << "displacement unknowns change with the band: "
            << (*std::max_element(n_u.begin() + 1, n_u.end()) >
                *std::min_element(n_u.begin() + 1, n_u.end()))
            << std::endl;
  std::cout << "points split and merged during the run (their number changes): "
            << (*std::max_element(points.begin(), points.end()) >
                *std::min_element(points.begin(), points.end()))
            << std::endl;
  return 0;
}

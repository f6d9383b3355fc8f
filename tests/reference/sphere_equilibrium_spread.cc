// The point-to-point spread of J at the equilibrium of a freely swelling sphere
// (doc/own_scenes.md, "The spread of J at equilibrium"): prm/swelling_sphere.prm (Table 1 gel,
// radius 0.5, axisymmetric, J from 2.098 to the closed-form 12.95969) at Tolerance 1e-2.
//
// 1. The bath ramped so that its free-swelling stretch grows linearly from lambda_0 to lambda_eq
//    over 400 tau_d (mu_b(t) = eq. (22) at that stretch), held to 2400 tau_d: every volume point's
//    J lies within 1 % of the closed form (measured -0.41 % and +0.27 %, in 58 steps).
// 2. The scene's own bath, mu linear from mu_0 to 0 over 4 tau_d, held to 1200 tau_d: the same
//    mean J, but the points keep a spread beyond 1 % (measured -2.31 % and +3.41 %, in the cells
//    cut by the surface): the residual strain that a fast swelling locks in (doc/method.md,
//    "Residual strain after large swelling"). A bath linear in mu puts 71 % of the volume change
//    in the ramp's last tenth (eq. (22) is steep near mu = 0), where the skin swells ahead of the
//    core.
// In both, the V_0-weighted mean J equals the closed form to 1e-4 (solvent uptake is exact).
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "../flory_rehner_closed_form.h"
#include "../scene_run.h"

namespace
{
  const double G = 1., chi = 0.1, N_nu = 7.299e-3, lambda_0 = 1.2801;

  /** The stretch from dry of the stress-free state at mu = 0: eq. (22) (Table 1). */
  double
  free_swelling_stretch()
  {
    return GelMPMTests::bisect(
      [](const double l) {
        return GelMPMTests::stress_times_stretch(l, l * l * l, 0., G, chi, N_nu);
      },
      1.5,
      4.);
  }

  /**
   * The bath mu_b(t) whose free-swelling stretch (eq. (22)) grows linearly from lambda_0 at t = 0
   * to @p lambda_eq at t = @p ramp, then stays: a 'Chemical potential value' expression.
   */
  std::string
  stretch_ramp(const double lambda_eq, const double ramp)
  {
    std::ostringstream l;
    l << std::setprecision(12) << "(" << lambda_0 << " + " << lambda_eq - lambda_0 << " * min(t / "
      << ramp << ", 1))";
    const std::string  L = l.str();
    std::ostringstream mu;
    mu << std::setprecision(12) << "min(" << N_nu << " * (1 / " << L << " - 1 / " << L
       << "^3) + log(1 - 1 / " << L << "^3) + 1 / " << L << "^3 + " << chi << " / " << L
       << "^6, 0)";
    return mu.str();
  }

  /** Prints whether the run's last J_min, J_mean, J_max lie as asserted about @p J_eq. */
  void
  report(const std::string           &name,
         const GelMPMTests::SceneRun &run,
         const double                 J_eq,
         const bool                   within_one_percent)
  {
    const double low  = run.statistics.at("J_min").back() / J_eq - 1.;
    const double mean = run.statistics.at("J_mean").back() / J_eq - 1.;
    const double high = run.statistics.at("J_max").back() / J_eq - 1.;
    std::cout << name << ": run completed: " << (run.status == 0) << std::endl;
    std::cout << name << ": mean J equals the closed form to 1e-4: " << (std::abs(mean) < 1e-4)
              << std::endl;
    const bool within = std::max(-low, high) < 0.01;
    std::cout << name << ": every volume point's J within 1 % of the closed form: " << within
              << std::endl;
    // The figures, on demand or when the assertion fails (they hinge on round-off).
    if (std::getenv("SPHERE_SPREAD_PRINT") || within != within_one_percent)
      std::cout << name << ": J_min, J_mean, J_max relative to " << J_eq << ": " << low << ", "
                << mean << ", " << high << " after " << run.statistics.at("t_over_tau_d").size() - 1
                << " steps" << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;
  const std::string scene     = std::string(SOURCE_DIR) + "/../../prm/swelling_sphere.prm";
  const double      lambda_eq = free_swelling_stretch();
  const double      J_eq      = lambda_eq * lambda_eq * lambda_eq;
  const std::string bath =
    "Boundary conditions/sphere/Chemical potential value/Function expression";

  const auto slow = GelMPMTests::run_scene(scene,
                                           "stretch_ramp",
                                           {"Time stepping/Stop at times=",
                                            "Time stepping/Tolerance=1e-2",
                                            "Time stepping/End time=2400",
                                            bath + "=" + stretch_ramp(lambda_eq, 400.)});
  report("stretch ramp over 400 tau_d", slow, J_eq, true);

  const auto fast =
    GelMPMTests::run_scene(scene,
                           "mu_ramp",
                           {"Time stepping/Stop at times=", "Time stepping/Tolerance=1e-2"});
  report("mu ramp over 4 tau_d (the scene's)", fast, J_eq, false);
  return 0;
}

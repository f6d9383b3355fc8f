// Numerical stability at the extremes (doc/extremes.md), each against what the method promises:
// 1. Undrained limit: the flat punch of prm/flat_punch.prm (coarse grid, 3 x 3 points per cell)
//    ramped over 10 steps of dt = 1e-10 tau_d. Q2-Q2SD: every step converges with the stable
//    signature (n_dofs_u, n_dofs_mu, 0) and mu stays smooth (mu_oscillation below 0.1, within 1%
//    of its value at dt = 1e-6 tau_d); Q2-Q2 at the same dt carries the checkerboard mode
//    (mu_oscillation above 1).
// 2. Nitsche penalties on §4.1 (coarse grid, to t = 0.01 tau_d): with gamma_u = 1e6 every step is
//    stable and the displacement conditions hold to 1e-12; with gamma_u = 100 the symmetric
//    variant is not coercive and the inertia says so (more negative eigenvalues than mu unknowns);
//    the skew-symmetric variant converges with gamma_u = 1 and holds the conditions to 1e-8.
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  using Statistics = std::map<std::string, std::vector<double>>;

  /** Run @p scene (relative to prm/) into @p directory with @p overrides; its statistics. */
  Statistics
  run(const std::string              &scene,
      const std::string              &directory,
      const std::vector<std::string> &overrides)
  {
    const auto result =
      GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/" + scene, directory, overrides);
    std::cout << std::boolalpha << directory << ": run completed: " << (result.status == 0)
              << std::endl;
    return result.statistics;
  }

  /** Whether every converged step had the signature (n_dofs_u, n_dofs_mu, 0). */
  bool
  stable_signature(const Statistics &s)
  {
    for (unsigned int i = 1; i < s.at("step").size(); ++i)
      if (s.at("n_pos")[i] != s.at("n_dofs_u")[i] || s.at("n_neg")[i] != s.at("n_dofs_mu")[i] ||
          s.at("n_zero")[i] != 0.)
        return false;
    return true;
  }

  /** Largest value of @p column over the converged steps. */
  double
  largest(const Statistics &s, const std::string &column)
  {
    double value = 0.;
    for (unsigned int i = 1; i < s.at(column).size(); ++i)
      value = std::max(value, s.at(column)[i]);
    return value;
  }

  /** The flat punch ramped over 10 steps of @p dt, with @p pair overrides. */
  Statistics
  punch(const std::string &directory, const double dt, const std::vector<std::string> &pair)
  {
    const auto text = [](const double x) {
      std::ostringstream out;
      out << std::setprecision(17) << x;
      return out.str();
    };
    const std::string        dt_text = text(dt), ramp = text(10. * dt);
    std::vector<std::string> overrides = {
      "Background grid/Cells=30, 30",
      "Material points/Points per cell=3",
      "Time stepping/Initial step=" + dt_text,
      "Time stepping/Step caps=" + ramp + ": " + dt_text,
      "Time stepping/End time=" + ramp,
      "Time stepping/Stop at times=",
      "Boundary conditions/punch/Displacement value/Function expression=0; -0.09 * min(t / " +
        ramp + ", 1)",
      "Observables/Chemical potential oscillation=true",
      "Stability/Inertia=true"};
    overrides.insert(overrides.end(), pair.begin(), pair.end());
    return run("flat_punch.prm", directory, overrides);
  }

  /** §4.1 on the coarse grid to t = 0.01 tau_d with Nitsche @p settings. */
  Statistics
  swelling(const std::string &directory, const std::vector<std::string> &settings)
  {
    std::vector<std::string> overrides = {"Background grid/Upper corner=0.5, 1.5",
                                          "Background grid/Cells=20, 60",
                                          "Material points/Points per cell=3",
                                          "Time stepping/End time=0.01",
                                          "Time stepping/Stop at times=",
                                          "Observables/Boundary condition error=true"};
    overrides.insert(overrides.end(), settings.begin(), settings.end());
    return run("constrained_swelling.prm", directory, overrides);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  const auto   sd     = punch("sd_1e-10", 1e-10, {});
  const auto   sd_6   = punch("sd_1e-6", 1e-6, {});
  const auto   q2_q2  = punch("q2q2_1e-10", 1e-10, {"Discretisation/Chemical potential grid=same"});
  const double o_sd   = sd.at("mu_oscillation").back();
  const double o_sd_6 = sd_6.at("mu_oscillation").back();
  const double o_q2_q2 = q2_q2.at("mu_oscillation").back();
  std::cout << "dt = 1e-10: Q2-Q2SD reached the end of the ramp with the stable signature: "
            << (sd.at("step").back() == 10 && stable_signature(sd)) << std::endl;
  std::cout << "dt = 1e-10: Q2-Q2SD mu_oscillation below 0.1 and within 1% of dt = 1e-6: "
            << (o_sd < 0.1 && std::abs(o_sd / o_sd_6 - 1.) < 0.01) << std::endl;
  std::cout << "dt = 1e-10: Q2-Q2 mu_oscillation above 1: " << (o_q2_q2 > 1.) << std::endl;
  if (!(o_sd < 0.1 && std::abs(o_sd / o_sd_6 - 1.) < 0.01 && o_q2_q2 > 1.))
    std::cout << "  (" << o_sd << ", " << o_sd_6 << ", " << o_q2_q2 << ")" << std::endl;

  const auto large =
    swelling("gamma_1e6", {"Nitsche/Displacement penalty=1e6", "Stability/Inertia=true"});
  std::cout << "gamma_u = 1e6: stable signature at every step: " << stable_signature(large)
            << std::endl;
  std::cout << "gamma_u = 1e6: displacement conditions hold to 1e-12: "
            << (largest(large, "u_bc_error") < 1e-12) << std::endl;
  const auto small =
    swelling("gamma_100", {"Nitsche/Displacement penalty=100", "Stability/Inertia=true"});
  std::cout << "gamma_u = 100, symmetric: the inertia shows the loss of coercivity: "
            << (small.at("n_neg").back() > small.at("n_dofs_mu").back()) << std::endl;
  const auto skew =
    swelling("skew_gamma_1", {"Nitsche/Displacement penalty=1", "Nitsche/Variant=skew-symmetric"});
  std::cout << "gamma_u = 1, skew-symmetric: reached t = 0.01 tau_d: "
            << (std::abs(skew.at("t_over_tau_d").back() - 0.01) < 1e-12) << std::endl;
  std::cout << "gamma_u = 1, skew-symmetric: displacement conditions hold to 1e-8: "
            << (largest(skew, "u_bc_error") < 1e-8) << std::endl;
  return 0;
}

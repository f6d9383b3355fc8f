// Patch tests of the coupled solver in plane strain, on the scene free_swelling_scene.prm (a
// quarter square on rollers, exposed top and right sides, Table 1 material).
//
// 1. At rest: with mu = mu_0 held on the exposed sides the initial state is the exact discrete
//    solution, so after 10 tau_d every volume point still has J = lambda_0^3 (to the 10 digits
//    that statistics.csv keeps, 1e-9 relative): the
//    Nitsche terms, the rollers and the extended bases at cut cells are consistent.
// 2. Free swelling towards mu = 0 (ramped over 50 tau_d, held to 1000 tau_d): the exact equilibrium
//    is homogeneous with in-plane stretch a solving P_11 = 0 at mu = 0 with F_33 = lambda_0, here
//    computed from the closed-form Flory-Rehner equation by bisection, independently of the solver
//    and of the material class:
//
//      N nu (a^2 - 1)/J + ln(1 - 1/J) + 1/J + chi/J^2 = mu/kT,   J = lambda_0 a^2.
//
//    Asserted: the V_0-weighted mean of J equals that J to 1e-4 (solvent uptake), and the spread
//    (J_max - J_min)/J stays below 1.5%. The spread does not vanish: after a 4.5-fold volume
//    change the material points keep a residual point-to-point variation of J (0.73% measured on
//    this scene) that the weak equilibrium on the B-spline space does not see; it changes little
//    with more points per cell or a finer grid (doc/method.md, "Residual strain after large
//    swelling").
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
  /** J of the plane-strain stress-free state at mu/kT = 0 for Table 1 (bisection on a). */
  double
  plane_strain_equilibrium_J()
  {
    const double N_nu = 7.299e-3, chi = 0.1, lambda_0 = 1.2801;
    const auto   f = [&](const double a) {
      const double J = lambda_0 * a * a;
      return N_nu * (a * a - 1.) / J + std::log(1. - 1. / J) + 1. / J + chi / (J * J);
    };
    // f < 0 in the stretched-too-little state (mu below 0), f > 0 when over-swollen.
    double lo = lambda_0, hi = 20.;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid        = 0.5 * (lo + hi);
        (f(mid) < 0. ? lo : hi) = mid;
      }
    const double a = 0.5 * (lo + hi);
    return lambda_0 * a * a;
  }
} // namespace


namespace
{
  /** Run the scene into @p directory with @p overrides; its statistics (the log is not compared).
   */
  std::map<std::string, std::vector<double>>
  run(const std::string &directory, const std::vector<std::string> &overrides)
  {
    const auto run = GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/free_swelling_scene.prm",
                                            directory,
                                            overrides);
    std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;
    return run.statistics;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const double J_0  = std::pow(1.2801, 3);
  const auto   rest = run("rest",
                        {"Boundary conditions/exposed/Chemical potential value/Function "
                             "expression=-0.145974528563566",
                           "Time stepping/End time=10"});
  std::cout << "at rest: every J equals lambda_0^3 to 1e-9 after 10 tau_d: "
            << (std::abs(rest.at("J_min").back() / J_0 - 1.) < 1e-9 &&
                std::abs(rest.at("J_max").back() / J_0 - 1.) < 1e-9)
            << std::endl;

  const auto   swelling = run("swelling", {});
  const double J_exact  = plane_strain_equilibrium_J();
  const double J_mean   = swelling.at("J_mean").back();
  const double spread   = (swelling.at("J_max").back() - swelling.at("J_min").back()) / J_exact;
  std::cout << std::setprecision(6) << "closed-form plane-strain equilibrium J = " << J_exact
            << std::endl;
  std::cout << "swelling: mean J equals it to 1e-4: " << (std::abs(J_mean / J_exact - 1.) < 1e-4)
            << std::endl;
  std::cout << "swelling: spread (J_max - J_min)/J below 1.5%: " << (spread < 0.015) << std::endl;
  if (std::abs(J_mean / J_exact - 1.) >= 1e-4 || spread >= 0.015)
    std::cout << "  (mean J = " << J_mean << ", spread = " << spread << ")" << std::endl;
  return 0;
}

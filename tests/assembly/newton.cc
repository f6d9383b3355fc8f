// Newton's method on the scene of scene_fixture.h converges quadratically: once the relative
// residual r_k is below 1e-3, r_{k+1} <= C r_k^2 with C < 1e3 (C ~ 1e2 is observed).
#include <gelmpm/solvers/linear_solver.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "scene_fixture.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  SceneFixture                     scene;
  auto                            &system = *scene.system;
  const auto                      &spaces = system.spaces();
  GelMPM::LinearSolver             solver;

  // Start from the initial state: du = 0, mu = mu_0; the boundary values pull it away.
  Vector<double> x(spaces.n_dofs()), dx(spaces.n_dofs());
  for (unsigned int i = spaces.n_u_dofs(); i < spaces.n_dofs(); ++i)
    x(i) = scene.material.mu_0();
  system.set_boundary_values(0.05, 0.);
  const Vector<double> x_0 = x;
  const double         dt  = 1e-3;
  std::vector<double>  history;
  for (unsigned int k = 0; k < 12; ++k)
    {
      system.assemble(x, dt, true);
      const double r = std::hypot(system.residual_norm_u(), system.residual_norm_mu() / 137.);
      history.push_back(r);
      if (r < 1e-12)
        break;
      solver.solve(system.matrix(), dx, system.residual());
      x -= dx;
    }
  const double r0 = history[0];
  std::cout << "Newton residual history (relative to the first):" << std::endl;
  for (unsigned int k = 0; k < history.size(); ++k)
    std::cout << "  " << k << "  below " << (history[k] / r0 < 1e-10 ? "1e-10" : "--") << std::endl;

  // Quadratic convergence: r_{k+1} <= C r_k^2 with a bounded C once r_k is small (linear
  // convergence would make r_{k+1} / r_k^2 grow without bound). Observed here: C of 1e2.
  double       worst_constant = 0.;
  unsigned int n_checked      = 0;
  for (unsigned int k = 1; k < history.size(); ++k)
    // Below 1e-13 the residual is rounding: no order of convergence shows there.
    if (history[k - 1] / r0 < 1e-3 && history[k] / r0 > 1e-13)
      {
        worst_constant =
          std::max(worst_constant, (history[k] / r0) / std::pow(history[k - 1] / r0, 2));
        ++n_checked;
      }
  const bool converged = history.back() / r0 < 1e-10;
  const bool quadratic = n_checked >= 2 && worst_constant < 1e3;
  std::cout << "converged below 1e-10: " << (converged ? "yes" : "no  FAIL") << std::endl;
  std::cout << "r_{k+1} <= 1e3 r_k^2 below r_k = 1e-3 (" << n_checked
            << " iterations checked): " << (quadratic ? "yes" : "no  FAIL") << std::endl;

  // The linear solver kept one symbolic factorisation over the iterations (one pattern), and a
  // solve with a fresh solver (analysing the pattern anew) gives the same first increment.
  system.assemble(x_0, dt, true);
  Vector<double> kept(spaces.n_dofs()), fresh(spaces.n_dofs());
  solver.solve(system.matrix(), kept, system.residual());
  GelMPM::LinearSolver().solve(system.matrix(), fresh, system.residual());
  fresh -= kept;
  const bool one_analysis = solver.n_symbolic_factorisations() == 1;
  const bool same         = fresh.l2_norm() <= 1e-12 * std::max(kept.l2_norm(), 1e-300);
  std::cout << "one symbolic factorisation for all solves: " << (one_analysis ? "yes" : "no  FAIL")
            << std::endl;
  std::cout << "a fresh factorisation gives the same increment to 1e-12: "
            << (same ? "yes" : "no  FAIL") << std::endl;
  return (converged && quadratic && one_analysis && same) ? 0 : 1;
}

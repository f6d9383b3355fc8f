// The modified Newton of solve_newton() ('Newton/Reuse contraction') against Newton's method on
// the scene of scene_fixture.h, two steps on one sparsity pattern (so the second starts from the
// first's factorisation):
// - both converge to the tolerance (1e-10 relative), to the same state within 1e-7 of the
//   step's change of the unknowns;
// - the modified iteration factorises fewer tangents than it takes iterations, and its second
//   step starts from the kept factorisation;
// - a factorisation from a state far off is replaced, and the step converges.
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iostream>
#include <string>

#include "scene_fixture.h"

using namespace dealii;

namespace
{
  /** The verdict of one check as the output file has it. */
  std::string
  yes_or_fail(const bool ok)
  {
    return ok ? "yes" : "no  FAIL";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TimerOutput                      timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
  // Two steps on one pattern: the fixture's system, set up once.
  SceneFixture scene;
  auto        &system = *scene.system;
  const auto  &spaces = system.spaces();

  Vector<double> x_0(spaces.n_dofs());
  for (unsigned int i = spaces.n_u_dofs(); i < spaces.n_dofs(); ++i)
    x_0(i) = scene.material.mu_0();
  const double dt       = 1e-3;
  const double scale_u  = std::sqrt(1.3 * 1.1);
  const double scale_mu = scene.material.kT_over_nu() * 1.3 * 1.1;

  GelMPM::NewtonSettings newton, modified;
  newton.maximum_iterations = modified.maximum_iterations = 30;
  newton.reuse_contraction                                = 0.;
  modified.reuse_contraction                              = 1e-3;
  GelMPM::LinearSolver fresh_solver, kept_solver;
  fresh_solver.set_symmetric(true);
  kept_solver.set_symmetric(true);

  bool ok = true;
  // Two steps: boundary values at t = 0.05, then at t = 0.1 from the first step's state.
  Vector<double> x_newton = x_0, x_modified = x_0;
  for (const double t : {0.05, 0.1})
    {
      system.set_boundary_values(t, 0.); // the points stay at the start
      const Vector<double> start = x_newton;
      const auto           full =
        GelMPM::solve_newton(system, x_newton, dt, newton, fresh_solver, scale_u, scale_mu, timer);
      const bool     started_factorised = kept_solver.has_factorization();
      const auto     reused             = GelMPM::solve_newton(system,
                                               x_modified,
                                               dt,
                                               modified,
                                               kept_solver,
                                               scale_u,
                                               scale_mu,
                                               timer);
      Vector<double> change = x_newton, difference = x_modified;
      change -= start;
      difference -= x_newton;
      std::cout << "step to t = " << t << ":" << std::endl;
      std::cout << "  both converge: " << yes_or_fail(full.converged && reused.converged)
                << std::endl;
      std::cout << "  same state within 1e-7 of the change: "
                << yes_or_fail(difference.l2_norm() <= 1e-7 * change.l2_norm()) << std::endl;
      std::cout << "  Newton factorises at every iteration: "
                << yes_or_fail(full.factorizations == full.iterations) << std::endl;
      std::cout << "  the modified iteration factorises less often: "
                << yes_or_fail(reused.factorizations < reused.iterations) << std::endl;
      ok &= full.converged && reused.converged && difference.l2_norm() <= 1e-7 * change.l2_norm() &&
            full.factorizations == full.iterations && reused.factorizations < reused.iterations;
      if (t > 0.05)
        {
          std::cout << "  the second step starts from the kept factorisation: "
                    << yes_or_fail(started_factorised) << std::endl;
          ok &= started_factorised;
        }
    }

  // From the initial state with the factorisation of the converged second step: the old tangent
  // does not contract the residual enough, and a fresh one is taken.
  system.set_boundary_values(0.05, 0.);
  x_modified = x_0;
  const auto restart =
    GelMPM::solve_newton(system, x_modified, dt, modified, kept_solver, scale_u, scale_mu, timer);
  std::cout << "a stale factorisation is replaced and the step converges: "
            << yes_or_fail(restart.converged && restart.factorizations >= 1) << std::endl;
  ok &= restart.converged && restart.factorizations >= 1;

  fresh_solver.new_pattern();
  kept_solver.new_pattern();
  return ok ? 0 : 1;
}

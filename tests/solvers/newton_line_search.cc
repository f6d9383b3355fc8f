// The damped Newton of solve_newton() on a scalar problem whose full Newton update leaves the
// physical range: R(x) = log(x - 1) with the physical states x > 1 (the assembly throws
// NonPhysicalState for x <= 1, as the gel does for J <= 1) and the root x = 2. From x_0 = 5 the
// full update lands at x = 5 - 4 log 4 = -0.545, outside the range:
// - 'none' (full updates) fails the attempt at iteration 1 with the non-physical state named;
// - 'physical' halves the update once (x = 2.227) and converges to x = 2 within 1e-12;
// - 'merit' converges too, with the residual decreasing at every iteration.
#include <gelmpm/core/non_physical_state.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>

#include "scalar_system.h"

namespace
{
  /** R(x) = log(x - 1) on one unknown, with the interface solve_newton() needs. */
  class LogarithmSystem : public GelMPMTests::ScalarSystem
  {
  public:
    void
    assemble(const dealii::Vector<double> &x, const double, const bool with_matrix) override
    {
      if (!(x(0) > 1.))
        throw GelMPM::NonPhysicalState("the state x = " + std::to_string(x(0)) +
                                       " is outside the physical range x > 1");
      set(std::log(x(0) - 1.), 1. / (x(0) - 1.), with_matrix);
    }
  };

  GelMPM::NewtonReport
  solve(const GelMPM::NewtonSettings::LineSearch line_search, double &x)
  {
    dealii::ParameterHandler prm;
    GelMPM::LinearSolver::declare_parameters(prm);
    GelMPM::LinearSolver linear_solver;
    linear_solver.parse_parameters(prm);
    GelMPM::NewtonSettings settings;
    settings.line_search        = line_search;
    settings.maximum_iterations = 30;
    settings.tolerance          = 1e-13;
    LogarithmSystem        system;
    dealii::Vector<double> solution(1);
    solution(0) = 5.;
    dealii::TimerOutput timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    const auto          report =
      GelMPM::solve_newton(system, solution, 1., settings, linear_solver, 1., 1., timer);
    linear_solver.new_pattern();
    x = solution(0);
    return report;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;
  using LineSearch = GelMPM::NewtonSettings::LineSearch;
  double     x     = 0.;
  const auto full  = solve(LineSearch::none, x);
  std::cout << "full Newton fails: " << !full.converged << std::endl;
  std::cout << "at iteration 1 on the non-physical state: "
            << (full.failure.find("Newton iteration 1") != std::string::npos &&
                full.failure.find("outside the physical range") != std::string::npos)
            << std::endl;
  const auto damped = solve(LineSearch::physical, x);
  std::cout << "damped Newton ('physical') converges: " << damped.converged << std::endl;
  std::cout << "to the root x = 2 within 1e-12: " << (std::abs(x - 2.) < 1e-12) << std::endl;
  std::cout << "the first update was damped by 1/2: "
            << (!damped.history.empty() && damped.history[0][2] == 0.5) << std::endl;
  const auto merit      = solve(LineSearch::merit, x);
  bool       decreasing = true;
  for (unsigned int k = 1; k < merit.history.size(); ++k)
    decreasing = decreasing && merit.history[k][0] < merit.history[k - 1][0];
  std::cout << "damped Newton ('merit') converges with a decreasing residual: "
            << (merit.converged && std::abs(x - 2.) < 1e-12 && decreasing) << std::endl;
  return 0;
}

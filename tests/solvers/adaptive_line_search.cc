// 'Newton/Line search = adaptive' in the time loop: an attempt that fails is retried at the same
// step with Armijo's rule before the step is cut (and Armijo's rule kept for its retakes). A
// scalar model R(x) = atan(x - 3 t) whose root moves by 3 per unit time, each step starting from
// the last root (no predictor), one step of 1 to t = 1, at most 6 Newton iterations per attempt.
// Full Newton on atan diverges from farther than 1.39 from the root (from 3: -9.5, 124, -2.4e4,
// ...), Armijo's damping converges from anywhere (the first update is damped to 1/4, then Newton
// converges quadratically):
// - 'physical' (full updates here, every state being physical) fails the step of 1 and of 1/2
//   and reaches t = 1 with a first step of 1/4, no attempt retried;
// - 'adaptive' retries the failed attempt of 1 with Armijo's rule, which converges: t = 1 in one
//   step, one retry counted and one step accepted with Armijo's rule, the root within 1e-12;
// - 'merit' takes the step of 1 at once, no retry counted.
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/time_loop.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "scalar_system.h"

namespace
{
  /** R(x) = atan(x - c) on one unknown. */
  class ArctanSystem : public GelMPMTests::ScalarSystem
  {
  public:
    void
    assemble(const dealii::Vector<double> &x, const double, const bool with_matrix) override
    {
      const double y = x(0) - root;
      set(std::atan(y), 1. / (1. + y * y), with_matrix);
    }

    double root = 0.;
  };


  /** The root moves by 3 per unit time; a step starts from the last root. */
  class MovingRoot : public GelMPM::SteppedModel
  {
  public:
    GelMPM::NewtonSystem &
    system() override
    {
      return arctan;
    }

    void
    prepare_attempt(const double t_begin,
                    const double dt,
                    const double,
                    dealii::Vector<double> &solution) override
    {
      arctan.root = 3. * (t_begin + dt);
      solution.reinit(1);
      solution(0) = x;
    }

    void
    update(const dealii::Vector<double> &solution, const double) override
    {
      x = solution(0);
      steps.push_back(solution(0));
    }

    ArctanSystem        arctan;
    double              x = 0.;
    std::vector<double> steps;
  };


  struct Run
  {
    bool                                    finished   = false;
    unsigned int                            steps      = 0;
    double                                  first_step = 0., x = 0.;
    std::pair<unsigned long, unsigned long> retries;
  };


  Run
  run(const GelMPM::NewtonSettings::LineSearch line_search)
  {
    dealii::ParameterHandler prm;
    GelMPM::LinearSolver::declare_parameters(prm);
    GelMPM::LinearSolver linear_solver;
    linear_solver.parse_parameters(prm);
    GelMPM::NewtonSettings newton;
    newton.line_search        = line_search;
    newton.maximum_iterations = 6;
    newton.tolerance          = 1e-12;
    GelMPM::TimeStepping stepping;
    stepping.initial_step      = 1.;
    stepping.end_time          = 1.;
    stepping.minimum_step      = 1e-3;
    stepping.largest_increment = 0.;
    MovingRoot                 model;
    std::ostringstream         log_text;
    dealii::ConditionalOStream log(log_text, true);
    dealii::TimerOutput        timer(log_text,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    GelMPM::TimeLoop loop(model, stepping, newton, linear_solver, GelMPM::RunScales(), log, timer);
    Run              result;
    result.finished = loop.run() == GelMPM::TimeLoop::Outcome::finished;
    result.steps    = loop.control().step();
    result.retries  = loop.armijo_retries();
    result.x        = model.x;
    // The first step's length from its root: x = 3 t at its end.
    result.first_step = model.steps.empty() ? 0. : model.steps.front() / 3.;
    // The factorisation refers to the model's matrix: released before the model is.
    linear_solver.new_pattern();
    return result;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;
  using LineSearch    = GelMPM::NewtonSettings::LineSearch;
  const auto physical = run(LineSearch::physical);
  std::cout << "physical: reaches t = 1: " << physical.finished
            << "; first step 1/4 after two cuts: " << (std::abs(physical.first_step - 0.25) < 1e-9)
            << "; no retry: " << (physical.retries.first == 0) << std::endl;
  const auto adaptive = run(LineSearch::adaptive);
  std::cout << "adaptive: reaches t = 1 in one step: " << (adaptive.finished && adaptive.steps == 1)
            << "; one retry, one step accepted with it: "
            << (adaptive.retries.first == 1 && adaptive.retries.second == 1)
            << "; at the root within 1e-12: " << (std::abs(adaptive.x - 3.) < 1e-12) << std::endl;
  const auto merit = run(LineSearch::merit);
  std::cout << "merit: reaches t = 1 in one step without a retry: "
            << (merit.finished && merit.steps == 1 && merit.retries.first == 0) << std::endl;
  return 0;
}

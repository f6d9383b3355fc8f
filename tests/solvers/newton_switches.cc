// Switches that make the residual jump, held by solve_newton() (NewtonSystem::freeze_switches()),
// on a scalar problem R(x) = x - 1 + c s with the switch s = [x > a], the model of an
// impermeable obstacle that seals the bath condition where a point touches it:
// - c = 0.5, a = 0.75: neither branch's root is consistent with its switch (s = 0 gives x = 1,
//   where s = 1; s = 1 gives x = 0.5, where s = 0), the point on a contact edge whose seal flips
//   with each solution. Following the iterate, Newton alternates between 1 and 0.5 and fails;
//   with the switch held it converges on its branch, updates the switch the allowed number of
//   times and takes the state, saying that the switch is unsettled.
// - c = 0.5, a = 0.25: one consistent root, x = 0.5 with s = 1; held or followed, Newton finds
//   it, and holding it there needs no update.
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <iostream>

namespace
{
  /** R(x) = x - 1 + c s, s = [x > a] or held, with the interface solve_newton() needs. */
  class SwitchSystem : public GelMPM::NewtonSystem
  {
  public:
    SwitchSystem(const double c, const double a)
      : c(c)
      , a(a)
    {
      dealii::DynamicSparsityPattern pattern(1, 1);
      pattern.add(0, 0);
      matrix_.reinit(pattern);
      residual_.reinit(1);
    }

    void
    assemble(const dealii::Vector<double> &x, const double, const bool with_matrix) override
    {
      const bool s = held >= 0 ? held == 1 : live(x);
      residual_(0) = x(0) - 1. + (s ? c : 0.);
      if (with_matrix)
        matrix_.set(0, 0, 1.);
      matrix_.compress(dealii::VectorOperation::insert);
    }

    unsigned int
    n_u_dofs() const override
    {
      return 1;
    }

    unsigned int
    freeze_switches(const dealii::Vector<double> &x) override
    {
      const int  s       = live(x) ? 1 : 0;
      const bool changed = held >= 0 && held != s;
      held               = s;
      ++freezes;
      return changed ? 1 : 0;
    }

    void
    release_switches() override
    {
      held = -1;
    }

    /** The root of the branch of the switch it was solved with is reached: R = 0 with it. */
    bool
    on_held_branch(const double x) const
    {
      return std::abs(x - 1. + (solved_with == 1 ? c : 0.)) < 1e-12;
    }

    int          held        = -1;
    int          solved_with = -1;
    unsigned int freezes     = 0;

  private:
    bool
    live(const dealii::Vector<double> &x) const
    {
      return x(0) > a;
    }

    const double c, a;
  };

  struct Outcome
  {
    GelMPM::NewtonReport report;
    double               x;
    bool                 released;
    bool                 on_held_branch;
  };

  Outcome
  solve(const double c, const double a, const unsigned int freeze_after)
  {
    dealii::ParameterHandler prm;
    GelMPM::LinearSolver::declare_parameters(prm);
    GelMPM::LinearSolver linear_solver;
    linear_solver.parse_parameters(prm);
    GelMPM::NewtonSettings settings;
    settings.maximum_iterations    = 15;
    settings.tolerance             = 1e-13;
    settings.reuse_contraction     = 0.;
    settings.freeze_switches_after = freeze_after;
    // The switch the state was solved with is the one held before the last check, which
    // freezes it anew at the state (and solve_newton() releases it after).
    struct Recording : SwitchSystem
    {
      using SwitchSystem::SwitchSystem;
      unsigned int
      freeze_switches(const dealii::Vector<double> &x) override
      {
        solved_with = held;
        return SwitchSystem::freeze_switches(x);
      }
    } system(c, a);
    dealii::Vector<double> solution(1);
    dealii::TimerOutput    timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    Outcome                outcome;
    outcome.report =
      GelMPM::solve_newton(system, solution, 1., settings, linear_solver, 1., 1., timer);
    linear_solver.new_pattern();
    outcome.x              = solution(0);
    outcome.released       = system.held == -1;
    outcome.on_held_branch = system.on_held_branch(outcome.x);
    return outcome;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  const auto followed = solve(0.5, 0.75, 0);
  std::cout << "no consistent root, switch following the iterate: fails after 15 iterations: "
            << (!followed.report.converged && followed.report.iterations == 15) << std::endl;

  const auto held = solve(0.5, 0.75, 4);
  std::cout << "held after 4 iterations: converged: " << held.report.converged << std::endl;
  std::cout << "  after " << held.report.switch_updates << " updates of the switch (the most "
            << "allowed: "
            << (held.report.switch_updates == GelMPM::NewtonSettings::maximum_switch_updates)
            << "), said unsettled: " << held.report.switches_unsettled << std::endl;
  std::cout << "  the state a root of its held branch: " << held.on_held_branch
            << ", x = 1 or 0.5: "
            << (std::abs(held.x - 1.) < 1e-12 || std::abs(held.x - 0.5) < 1e-12) << std::endl;
  std::cout << "  released at the end: " << held.released << std::endl;

  const auto consistent_followed = solve(0.5, 0.25, 0);
  const auto consistent_held     = solve(0.5, 0.25, 1);
  std::cout << "one consistent root: followed finds x = 0.5: "
            << (consistent_followed.report.converged &&
                std::abs(consistent_followed.x - 0.5) < 1e-12)
            << std::endl;
  std::cout << "  held after 1 iteration finds x = 0.5: "
            << (consistent_held.report.converged && std::abs(consistent_held.x - 0.5) < 1e-12)
            << ", with no update: " << (consistent_held.report.switch_updates == 0)
            << ", settled: " << !consistent_held.report.switches_unsettled
            << ", released: " << consistent_held.released << std::endl;
  return 0;
}

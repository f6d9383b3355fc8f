// Switches that make the residual jump, held by solve_newton() (NewtonSystem::freeze_switches()),
// on a scalar problem R(x) = x - 1 + c s with the switch s = [x > a], the model of an
// impermeable obstacle that seals the bath condition where a point touches it:
// - c = 0.5, a = 0.75: neither branch's root is consistent with its switch (s = 0 gives x = 1,
//   where s = 1; s = 1 gives x = 0.5, where s = 0), the point on a contact edge whose seal flips
//   with each solution. Following the iterate, Newton alternates between 1 and 0.5 and fails;
//   with the switch held it converges on its branch, updates the switch the allowed number of
//   times and takes the state, saying that the switch is unsettled; the switch stays held at
//   the value the state was solved with (what the observables of the state then see).
// - c = 0.5, a = 0.25: one consistent root, x = 0.5 with s = 1; held or followed, Newton finds
//   it, and holding it there needs no update. A second solve on the same system, with a wrong
//   switch left held, starts by releasing it and finds the root again.
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>

#include "scalar_system.h"

namespace
{
  /** R(x) = x - 1 + c s, s = [x > a] or held, with the interface solve_newton() needs. */
  class SwitchSystem : public GelMPMTests::ScalarSystem
  {
  public:
    SwitchSystem(const double c, const double a)
      : c(c)
      , a(a)
    {}

    void
    assemble(const dealii::Vector<double> &x, const double, const bool with_matrix) override
    {
      const bool s = held >= 0 ? held == 1 : live(x);
      set(x(0) - 1. + (s ? c : 0.), 1., with_matrix);
    }

    unsigned int
    freeze_switches(const dealii::Vector<double> &x, const bool hold) override
    {
      const int  s       = live(x) ? 1 : 0;
      const bool changed = held >= 0 && held != s;
      if (hold)
        held = s;
      return changed ? 1 : 0;
    }

    void
    release_switches() override
    {
      held = -1;
    }

    /** The root of the branch of the held switch is reached: R = 0 with it. */
    bool
    on_held_branch(const double x) const
    {
      return held >= 0 && std::abs(x - 1. + (held == 1 ? c : 0.)) < 1e-12;
    }

    int held = -1;

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
    bool                 on_held_branch;
  };

  Outcome
  solve(SwitchSystem &system, const unsigned int freeze_after)
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
    dealii::Vector<double> solution(1);
    dealii::TimerOutput    timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    Outcome                outcome;
    outcome.report =
      GelMPM::solve_newton(system, solution, 1., settings, linear_solver, 1., 1., timer);
    linear_solver.new_pattern();
    outcome.x              = solution(0);
    outcome.on_held_branch = system.on_held_branch(outcome.x);
    return outcome;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  SwitchSystem no_root(0.5, 0.75);
  const auto   followed = solve(no_root, 0);
  std::cout << "no consistent root, switch following the iterate: fails after 15 iterations: "
            << (!followed.report.converged && followed.report.iterations == 15) << std::endl;

  const auto held = solve(no_root, 4);
  std::cout << "held after 4 iterations: converged: " << held.report.converged << std::endl;
  std::cout << "  after " << held.report.switch_updates << " updates of the switch (the most "
            << "allowed: "
            << (held.report.switch_updates == GelMPM::NewtonSettings::maximum_switch_updates)
            << "), said unsettled: " << held.report.switches_unsettled << std::endl;
  std::cout << "  x = 1 or 0.5: "
            << (std::abs(held.x - 1.) < 1e-12 || std::abs(held.x - 0.5) < 1e-12)
            << ", a root of the branch of the switch still held: " << held.on_held_branch
            << std::endl;

  SwitchSystem one_root(0.5, 0.25);
  const auto   consistent_followed = solve(one_root, 0);
  std::cout << "one consistent root: followed finds x = 0.5: "
            << (consistent_followed.report.converged &&
                std::abs(consistent_followed.x - 0.5) < 1e-12)
            << std::endl;
  const auto consistent_held = solve(one_root, 1);
  std::cout << "  held after 1 iteration finds x = 0.5: "
            << (consistent_held.report.converged && std::abs(consistent_held.x - 0.5) < 1e-12)
            << ", with no update: " << (consistent_held.report.switch_updates == 0)
            << ", settled: " << !consistent_held.report.switches_unsettled
            << ", held at s = 1: " << (one_root.held == 1) << std::endl;
  one_root.held    = 0;
  const auto again = solve(one_root, 0);
  std::cout << "  a wrong switch left held is released by the next solve, which finds x = 0.5: "
            << (again.report.converged && std::abs(again.x - 0.5) < 1e-12) << std::endl;
  return 0;
}

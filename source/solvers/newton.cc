#include <gelmpm/core/input_error.h>
#include <gelmpm/core/non_physical_state.h>
#include <gelmpm/solvers/newton.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace GelMPM
{
  void
  NewtonSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations",
                      "15",
                      dealii::Patterns::Integer(1),
                      "Newton iterations before a step counts as failed (and is retried with a "
                      "smaller step).");
    prm.declare_entry(
      "Tolerance",
      "1e-10",
      dealii::Patterns::Double(0.),
      "Both residual blocks must fall below this, relative to their natural "
      "scales: G |Omega_0|^((dim-1)/dim) for the displacement block and "
      "(k_BT/nu) |Omega_0| for the chemical-potential block. At least 1e-14 (below, "
      "the residuals stop on round-off).");
    prm.declare_entry(
      "Line search",
      "physical",
      dealii::Patterns::Selection("none|physical|merit|adaptive"),
      "How Newton updates are damped, by backtracking (1, 1/2, 1/4, ...): "
      "'physical' until the trial state is physical at every point (J > 1, a "
      "fraction-to-the-boundary rule); 'merit' in addition until the scaled "
      "residual norm decreases (Armijo's rule); 'adaptive': 'physical', and an "
      "attempt that fails to converge is retried at the same step with 'merit' "
      "(kept for the step's retakes) before the step is cut; 'none': full updates, and a trial "
      "state with J <= 1 fails the attempt (doc/method.md, 'Newton').");
    prm.declare_entry(
      "Initial chemical potential",
      "points",
      dealii::Patterns::Selection("grid|points"),
      "The first iterate of mu in a step (material point scenes): 'grid', the "
      "coefficients of the last step (for control points that held none, the "
      "projection below); 'points', the L2 projection of the material points' mu "
      "onto the step's basis. After a fast motion 'grid' shifts mu at every point by "
      "grad mu . du and the stress with it, a false residual the first Newton "
      "iterations must remove (doc/method.md). The converged step is the same.");
    prm.declare_entry(
      "Initial displacement",
      "zero",
      dealii::Patterns::Selection("zero|extrapolated"),
      "The first iterate of the displacement increment in a step (material point scenes): "
      "'zero'; 'extrapolated', the points' increments of the last accepted step scaled by "
      "dt / dt_last and projected onto the step's basis (L2 over the volume points), "
      "which continues a steady motion: fewer iterations, and near an instability the "
      "iterates start on the branch the gel is following. The converged step is the same.");
    prm.declare_entry("Log failures",
                      "false",
                      dealii::Patterns::Bool(),
                      "Print the scaled residuals and the damping of every iteration of a failed "
                      "attempt to the log, and the first residuals of every step (diagnosis of a "
                      "step that does not converge).");
    prm.declare_entry("Smallest damping",
                      "0.015625",
                      dealii::Patterns::Double(0., 1.),
                      "With 'Line search': the smallest damping factor tried; below it the "
                      "attempt fails and the step is cut.");
    prm.declare_entry(
      "Reuse contraction",
      "0.001",
      dealii::Patterns::Double(0., 1.),
      "Modified Newton: an iteration solves with the factorisation of the last tangent (of an "
      "earlier iterate, or of the last step while the cell classification stays) as long as "
      "each iteration reduces the scaled residual norm by at least this factor; otherwise the "
      "next iteration assembles and factorises a fresh tangent, and an update from an old "
      "factorisation that is not physical or does not reduce the residual is discarded. The "
      "converged state is the same to 'Tolerance'. 0: a fresh tangent at every iteration "
      "(Newton's method; doc/performance.md). With single-precision factors ('Linear "
      "solver/Precision') a solve with an old factorisation is refined only to a tenth of "
      "this factor.");
    prm.declare_entry(
      "Reuse step ratio",
      "0",
      dealii::Patterns::Double(0.),
      "With 'Reuse contraction' > 0: a step whose time step differs from that of the kept "
      "tangent by more than this factor (larger over smaller) starts with a fresh tangent "
      "instead of the kept factorisation. At least 1; 0: the kept factorisation whatever the "
      "time step (doc/performance.md, 'Fewer factorisations').");
    prm.declare_entry("Maximum reuses",
                      "0",
                      dealii::Patterns::Integer(0),
                      "With 'Reuse contraction' > 0: the solves one factorisation serves at "
                      "most, over iterations and steps, before a fresh tangent is factorised; "
                      "0: no limit.");
    prm.declare_entry(
      "Freeze switches after",
      "4",
      dealii::Patterns::Integer(0),
      "Iterations after which the switches that make the residual jump (an impermeable "
      "obstacle sealing the bath condition where it touches, the points in contact with a "
      "rigid obstacle, the self-contact's active pairs) are held at the iterate's values "
      "instead of following it, and updated only at a converged state until they settle: "
      "semi-smooth Newton can otherwise cycle without end at a point on the contact edge. The "
      "converged state is the same (its switches are its own); 0: always follow the iterate "
      "(doc/method.md, 'Contact with planes of symmetry and rigid obstacles', 'Permeability').");
    prm.leave_subsection();
  }


  void
  NewtonSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    maximum_iterations       = prm.get_integer("Maximum iterations");
    tolerance                = prm.get_double("Tolerance");
    const std::string search = prm.get("Line search");
    line_search              = (search == "none")       ? LineSearch::none
                               : (search == "physical") ? LineSearch::physical
                               : (search == "adaptive") ? LineSearch::adaptive
                                                        : LineSearch::merit;
    smallest_damping         = prm.get_double("Smallest damping");
    log_failures             = prm.get_bool("Log failures");
    mu_from_points           = prm.get("Initial chemical potential") == "points";
    extrapolate_displacement = prm.get("Initial displacement") == "extrapolated";
    reuse_contraction        = prm.get_double("Reuse contraction");
    reuse_step_ratio         = prm.get_double("Reuse step ratio");
    maximum_reuses           = prm.get_integer("Maximum reuses");
    freeze_switches_after    = prm.get_integer("Freeze switches after");
    prm.leave_subsection();
    require(reuse_step_ratio == 0. || reuse_step_ratio >= 1.,
            "Newton/Reuse step ratio",
            "must be 0 (no limit) or at least 1 (a ratio of time steps, the larger over the "
            "smaller)",
            "use e.g. 1.5, or 0");
    require(smallest_damping > 0. && smallest_damping <= 1.,
            "Newton/Smallest damping",
            "must lie in (0, 1]",
            "use e.g. 0.015625 (1/64)");
    require(reuse_contraction < 1.,
            "Newton/Reuse contraction",
            "must be below 1 (a factorisation kept while the residual does not decrease would "
            "never be replaced)",
            "use e.g. 0.001, or 0 for Newton's method");
    require(tolerance > 0. && tolerance < 1.,
            "Newton/Tolerance",
            "must lie strictly between 0 and 1",
            "use e.g. 1e-10");
    // The scaled residual sums thousands of point terms, each rounded to 2.2e-16 of its size:
    // converged states of the free-swelling test scene stop at 0.8-1.2e-14, and stiffer gels
    // (smaller N nu) far above.
    if (tolerance < smallest_tolerance)
      {
        std::ostringstream problem;
        problem << "is " << tolerance << ", below " << smallest_tolerance
                << " (45 times the double's precision 2.2e-16), where the scaled residuals stop "
                   "on round-off: no Newton iteration can meet it";
        throw InputError("Newton/Tolerance",
                         problem.str(),
                         "give at least 1e-14, e.g. the default 1e-10");
      }
  }


  std::string
  round_off_stall(const NewtonReport &report, const NewtonSettings &settings)
  {
    // The residuals at the start of the last iterations and at the end: a Newton iteration
    // that has reached the round-off of its residual moves it no more than by a factor of a few.
    constexpr unsigned int n_last = 4;
    if (report.converged || report.history.size() + 1 < n_last)
      return "";
    std::vector<double> last = {std::max(report.residual_u, report.residual_mu)};
    for (auto h = report.history.rbegin(); h != report.history.rend() && last.size() < n_last; ++h)
      last.push_back(std::max((*h)[0], (*h)[1]));
    const double lowest  = *std::min_element(last.begin(), last.end());
    const double highest = *std::max_element(last.begin(), last.end());
    if (!(lowest > settings.tolerance) || highest > 10. * lowest || highest > 1e-8)
      return "";
    std::ostringstream hint;
    hint.precision(2);
    hint << "Newton stalls at scaled residuals of " << report.residual_u << " (|R_u|) and "
         << report.residual_mu
         << " (|R_mu|), the round-off of this scene's residual, above 'Newton/Tolerance' = "
         << settings.tolerance << ": give 'Newton/Tolerance' at least " << 10. * highest;
    return hint.str();
  }

  namespace
  {
    /**
     * Whether a tangent factorised at the time step @p factorized_dt (0: unknown) is too far
     * from @p dt for 'Newton/Reuse step ratio'.
     */
    bool
    step_ratio_exceeded(const double factorized_dt, const double dt, const NewtonSettings &settings)
    {
      if (settings.reuse_step_ratio == 0. || !(factorized_dt > 0.) || !(dt > 0.))
        return false;
      return std::max(dt / factorized_dt, factorized_dt / dt) > settings.reuse_step_ratio;
    }
  } // namespace


  NewtonReport
  solve_newton(NewtonSystem           &system,
               dealii::Vector<double> &solution,
               const double            dt,
               const NewtonSettings   &settings,
               const LinearSolver     &linear_solver,
               const double            scale_u,
               const double            scale_mu,
               dealii::TimerOutput    &timer)
  {
    NewtonReport report;
    const bool   reuse = settings.reuse_contraction > 0.;
    // Every attempt starts with the switches following its iterate. They stay held after it,
    // so that what is measured on the state (the pieces' inflow) uses the switches it was
    // solved with.
    system.release_switches();
    bool         frozen = false;
    unsigned int limit  = settings.maximum_iterations;
    // Assemble at x; false (with the reason in report.failure) if x is not physical.
    const auto assemble_at = [&](const dealii::Vector<double> &x, const bool with_matrix) {
      try
        {
          dealii::TimerOutput::Scope scope(timer, "assembly");
          system.assemble(x, dt, with_matrix);
        }
      catch (const NonPhysicalState &e)
        {
          report.failure = e.what();
          return false;
        }
      report.tangent_at_solution = with_matrix;
      report.residual_u          = system.residual_norm_u() / scale_u;
      report.residual_mu         = system.residual_norm_mu() / scale_mu;
      return true;
    };
    // At a converged state with the switches held: hold them at its values; whether any
    // changed (and the iteration must go on). After the last update allowed the state is
    // taken.
    const auto switches_changed_at = [&](const dealii::Vector<double> &x) {
      if (report.switch_updates == NewtonSettings::maximum_switch_updates)
        {
          report.switches_unsettled = system.freeze_switches(x, false) > 0;
          return false;
        }
      if (system.freeze_switches(x) == 0)
        return false;
      ++report.switch_updates;
      return true;
    };
    const auto merit = [&]() {
      return report.residual_u * report.residual_u + report.residual_mu * report.residual_mu;
    };

    // After a failed linear solve (of an earlier attempt or step) a first iterate that meets the
    // tolerance proves nothing: the failures cut the step until the predictor's residual alone
    // fell below it, and such steps were accepted without a single solve (GMRES restarted after
    // every vector: steps of 1e-7 with no Newton iteration, the run crawling). One iteration,
    // whose solve must succeed, or the attempt fails and the step is cut again.
    const unsigned int minimum_iterations = linear_solver.last_call_failed()
                                              ? std::max(settings.minimum_iterations, 1u)
                                              : settings.minimum_iterations;
    // Whether the next iteration factorises the tangent at its iterate, and why. Without
    // reuse every assembly includes the tangent, which the next iteration then factorises.
    unsigned int *why_fresh = nullptr;
    if (!reuse || !linear_solver.has_factorization())
      why_fresh = &report.fresh_tangents.without_reuse;
    else if (step_ratio_exceeded(linear_solver.factorized_step(), dt, settings))
      why_fresh = &report.fresh_tangents.step_ratio;
    bool fresh = why_fresh != nullptr;
    if (!assemble_at(solution, fresh))
      return report;
    dealii::Vector<double> increment(solution.size()), trial(solution.size());
    for (unsigned int k = 0;; ++k)
      {
        if (!std::isfinite(report.residual_u) || !std::isfinite(report.residual_mu))
          {
            report.failure = "the residual is not finite";
            return report;
          }
        if (k >= minimum_iterations && report.residual_u <= settings.tolerance &&
            report.residual_mu <= settings.tolerance)
          {
            if (!frozen || !switches_changed_at(solution))
              {
                report.converged = true;
                report.failure.clear();
                return report;
              }
            // The residual jumped with the switches; the modified Newton iteration decides as
            // after any update whether the kept factorisation still serves.
            if (!assemble_at(solution, !reuse))
              return report;
            fresh     = !reuse;
            why_fresh = &report.fresh_tangents.without_reuse;
            limit     = k + settings.maximum_iterations;
          }
        if (!frozen && settings.freeze_switches_after > 0 && k == settings.freeze_switches_after)
          {
            system.freeze_switches(solution);
            frozen = true;
          }
        if (k == limit)
          {
            report.failure = "no convergence in " + std::to_string(k) + " Newton iterations";
            return report;
          }
        if (!fresh && settings.maximum_reuses > 0 &&
            linear_solver.solves_with_factorization() >= settings.maximum_reuses)
          {
            fresh     = true;
            why_fresh = &report.fresh_tangents.reuses;
          }
        // The state was physical when its residual was assembled: so is its tangent.
        if (fresh && !report.tangent_at_solution && !assemble_at(solution, true))
          return report;
        try
          {
            dealii::TimerOutput::Scope scope(timer, "solve");
            if (fresh)
              {
                linear_solver.factorize(system.matrix());
                linear_solver.note_factorized_step(dt);
                ++report.factorizations;
                ++*why_fresh;
              }
            // The kept factorisation is of another matrix: the true residual of the next
            // iterate corrects its solve, so refining it far below the contraction it is kept
            // for buys nothing.
            linear_solver.solve(increment,
                                system.residual(),
                                fresh ? SymmetricFactorization::refinement_tolerance
                                      : 0.1 * settings.reuse_contraction);
          }
        catch (const std::exception &e)
          {
            report.failure = e.what();
            return report;
          }
        report.iterations       = k + 1;
        report.last_solve_fresh = fresh;

        const double merit_0 = merit();
        const double r_u_0 = report.residual_u, r_mu_0 = report.residual_mu;
        double       alpha     = 1.;
        bool         discarded = false;
        for (;;)
          {
            trial = solution;
            trial.add(-alpha, increment);
            const bool physical = assemble_at(trial, !reuse);
            // Near the solution round-off decides whether the residual still decreases: there
            // any physical update is taken.
            const bool near_solution =
              std::max(report.residual_u, report.residual_mu) <= 1e3 * settings.tolerance;
            if (!fresh)
              {
                // An old tangent that leads astray is replaced, not damped.
                discarded = !physical || (!near_solution && merit() > (1. - 1e-4) * merit_0);
                break;
              }
            if (settings.line_search == NewtonSettings::LineSearch::none)
              {
                if (!physical)
                  {
                    report.failure =
                      "Newton iteration " + std::to_string(k + 1) + ": " + report.failure;
                    return report;
                  }
                break;
              }
            // 'adaptive' is 'physical' within one attempt (the time loop retries with 'merit').
            if (physical && (settings.line_search == NewtonSettings::LineSearch::physical ||
                             settings.line_search == NewtonSettings::LineSearch::adaptive ||
                             near_solution || merit() <= (1. - 1e-4 * alpha) * merit_0))
              break;
            const std::string why = physical ? "the residual does not decrease" : report.failure;
            alpha *= 0.5;
            if (alpha < settings.smallest_damping)
              {
                report.failure = "Newton iteration " + std::to_string(k + 1) +
                                 ": no damped update down to 'Newton/Smallest damping' = " +
                                 std::to_string(settings.smallest_damping) + " is acceptable (" +
                                 why + ")";
                return report;
              }
          }
        report.history.push_back({{r_u_0, r_mu_0, discarded ? 0. : alpha}});
        if (discarded)
          {
            // Back to the iterate, whose residual and (physical) tangent the next iteration
            // needs.
            fresh     = true;
            why_fresh = &report.fresh_tangents.discarded;
            if (!assemble_at(solution, true))
              return report;
            continue;
          }
        if (alpha < 1.)
          ++report.damped_iterations;
        solution.swap(trial);
        fresh =
          !reuse || merit() > settings.reuse_contraction * settings.reuse_contraction * merit_0;
        why_fresh =
          reuse ? &report.fresh_tangents.contraction : &report.fresh_tangents.without_reuse;
      }
  }
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/solvers/time_loop.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace GelMPM
{
  RunScales
  RunScales::of(const unsigned int dim,
                const double       length,
                const double       diffusivity,
                const double       shear_modulus,
                const double       kT_over_nu,
                const double       volume)
  {
    RunScales scales;
    scales.tau_d    = length * length / diffusivity;
    scales.scale_u  = shear_modulus * std::pow(volume, (dim - 1.) / dim);
    scales.scale_mu = kT_over_nu * volume;
    return scales;
  }


  void
  SteppedModel::begin_step(const double, const double)
  {}


  bool
  SteppedModel::estimates_errors() const
  {
    return false;
  }


  bool
  SteppedModel::measures_motion_in_cells() const
  {
    return estimates_errors();
  }


  SteppedModel::StepBound
  SteppedModel::bound_step(const double, const double dt) const
  {
    return {dt, ""};
  }


  bool
  SteppedModel::measures_rate_of_change() const
  {
    return false;
  }


  double
  SteppedModel::rate_of_change(const dealii::Vector<double> &, const double) const
  {
    return 0.;
  }


  double
  SteppedModel::largest_motion_in_cells(const dealii::Vector<double> &) const
  {
    return 0.;
  }


  std::string
  SteppedModel::refusal(const dealii::Vector<double> &) const
  {
    return {};
  }


  double
  SteppedModel::increment_deviation(const dealii::Vector<double> &, const double) const
  {
    return 0.;
  }


  double
  SteppedModel::local_error(const dealii::Vector<double> &, const double, const bool) const
  {
    return 0.;
  }


  int
  SteppedModel::stop_signal() const
  {
    return 0;
  }


  void
  StepObserver::step_begins()
  {}


  StepControl::Verdict
  StepObserver::judge_attempt(const dealii::Vector<double> &, const double, const NewtonReport &)
  {
    return StepControl::Verdict::accept;
  }


  void
  StepObserver::attempt_rejected()
  {}


  bool
  StepObserver::before_update(dealii::Vector<double> &, const double)
  {
    return false;
  }


  void
  StepObserver::accepted(const AcceptedStep &, const dealii::Vector<double> &)
  {}


  bool
  StepObserver::end_requested() const
  {
    return false;
  }


  void
  StepObserver::between_steps()
  {}


  TimeLoop::TimeLoop(SteppedModel               &model,
                     const TimeStepping         &time_stepping,
                     const NewtonSettings       &newton,
                     const LinearSolver         &linear_solver,
                     const RunScales            &scales,
                     dealii::ConditionalOStream &log,
                     dealii::TimerOutput        &timer,
                     const double                bisection_tolerance,
                     const double                unstable_step,
                     const bool                  signature_control,
                     const unsigned int          output_interval_steps,
                     const double                output_interval_time)
    : model(model)
    , time_stepping(time_stepping)
    , newton_settings(newton)
    , linear_solver(linear_solver)
    , run_scales(scales)
    , log(log)
    , timer(timer)
    , control_(time_stepping, bisection_tolerance, unstable_step, signature_control)
    , output_interval_steps(output_interval_steps)
    , output_interval_time(output_interval_time)
    , next_output_time(output_interval_time)
  {
    // The default bound is the material points'; a model without a grid ignores it.
    if (!model.measures_motion_in_cells() && time_stepping.largest_increment_default)
      this->time_stepping.largest_increment = 0.;
    require(!(this->time_stepping.largest_increment > 0.) || model.measures_motion_in_cells(),
            "Time stepping/Largest increment",
            "bounds a step's motion in cells of the background grid, which this model has not",
            std::string("leave it at its default (") +
              TimeStepping::default_largest_increment_text + ", ignored here) or set it to 0");
    for (const auto &[value, entry] :
         {std::make_pair(time_stepping.displacement_tolerance,
                         "Time stepping/Displacement tolerance"),
          std::make_pair(time_stepping.tolerance, "Time stepping/Tolerance")})
      if (value > 0. && !model.estimates_errors())
        throw InputError(entry,
                         "asks for an estimate of the step's motion or error, which this model "
                         "does not make",
                         "set it to 0 (its default)");
    require(!(time_stepping.end_at_equilibrium > 0.) || model.measures_rate_of_change(),
            "Time stepping/End at equilibrium",
            "asks for the rate of change of the state, which this model does not measure",
            "set it to 0 (its default) and give the 'End time' instead");
    // The tolerance rule compares the solution with the predictor, the first iterate: a step so
    // short that the predictor already meets Newton's tolerance would otherwise leave the
    // predictor as the solution, and the estimate would measure nothing.
    if (time_stepping.tolerance > 0.)
      newton_settings.minimum_iterations = std::max(newton_settings.minimum_iterations, 1u);
  }


  void
  TimeLoop::add_observer(StepObserver &observer)
  {
    observers.push_back(&observer);
  }


  TimeLoop::Outcome
  TimeLoop::run()
  {
    while (!control_.finished())
      {
        if ((signal_ = model.stop_signal()) != 0)
          return Outcome::interrupted;
        if (control_.out_of_steps())
          return Outcome::out_of_steps;
        switch (advance())
          {
            case StepOutcome::interrupted:
              return Outcome::interrupted_within_step;
            case StepOutcome::failed:
              return Outcome::failed;
            case StepOutcome::accepted:
              break;
          }
        for (const auto *observer : observers)
          if (observer->end_requested())
            return Outcome::ended_early;
        for (auto *observer : observers)
          observer->between_steps();
      }
    return control_.at_equilibrium() ? Outcome::equilibrium : Outcome::finished;
  }


  TimeLoop::StepOutcome
  TimeLoop::advance()
  {
    model.begin_step(last_dt, control_.time());
    for (auto *observer : observers)
      observer->step_begins();
    dealii::Vector<double> solution;
    // 'Line search = adaptive': whether the next attempt takes Armijo's rule.
    bool armijo_retry = false;
    for (unsigned int attempt = 1;; ++attempt)
      {
        // A step whose attempts keep failing can be stopped within one attempt.
        if ((signal_ = model.stop_signal()) != 0)
          return StepOutcome::interrupted;
        const double t_begin = control_.time();
        double       step_dt = control_.attempt();
        if (!bound_attempt(t_begin, step_dt))
          return StepOutcome::failed;
        model.prepare_attempt(t_begin, step_dt, last_dt, solution);
        // Armijo's rule after a failed attempt at this size, and for the retakes of a step it
        // took: near the same fold. A shorter step after its own failure tries 'physical' first.
        const bool     armijo_attempt   = armijo_retry;
        NewtonSettings attempt_settings = newton_settings;
        if (newton_settings.line_search == NewtonSettings::LineSearch::adaptive)
          attempt_settings.line_search = armijo_attempt ? NewtonSettings::LineSearch::merit
                                                        : NewtonSettings::LineSearch::physical;
        NewtonReport report = solve_newton(model.system(),
                                           solution,
                                           step_dt * run_scales.tau_d,
                                           attempt_settings,
                                           linear_solver,
                                           run_scales.scale_u,
                                           run_scales.scale_mu,
                                           timer);
        n_newton_iterations += report.iterations;
        n_factorizations += report.factorizations;
        fresh_tangents_ += report.fresh_tangents;
        n_switch_updates += report.switch_updates;
        n_unsettled_switches += report.converged && report.switches_unsettled;
        // Only Newton's own failures are retried: a motion or refusal is no matter of damping.
        if (!armijo_attempt && retry_with_armijo(report, t_begin, step_dt))
          {
            armijo_retry = true;
            continue;
          }
        if (report.converged && increment_bound_applies(step_dt))
          {
            const double moved = model.largest_motion_in_cells(solution);
            if (moved > time_stepping.largest_increment)
              {
                report.converged = false;
                std::ostringstream why;
                why << "a material point moves " << moved
                    << " cells, more than 'Time stepping/Largest increment' = "
                    << time_stepping.largest_increment;
                report.failure = why.str();
              }
          }
        if (report.converged && !error_acceptable(solution, step_dt, report.failure))
          {
            log << "    step " << control_.step() + 1 << " at t = " << t_begin
                << " with dt = " << step_dt << " retaken (" << report.failure
                << "); retrying with dt = " << control_.proposed_step() << std::endl;
            for (auto *observer : observers)
              observer->attempt_rejected();
            continue;
          }
        // Only a step that the error control accepts: one it retakes anyway is no state of
        // the run, and refusing it first would change the retaken step's size.
        if (report.converged)
          {
            const std::string refused = model.refusal(solution);
            if (!refused.empty())
              {
                report.converged = false;
                report.failure   = refused;
              }
          }
        if (!report.converged)
          {
            if (!attempt_failed(report, t_begin, step_dt))
              return StepOutcome::failed;
            armijo_retry = false;
            continue;
          }

        bool retake = false;
        for (auto *observer : observers)
          {
            const auto verdict = observer->judge_attempt(solution, step_dt, report);
            retake =
              verdict == StepControl::Verdict::retake || verdict == StepControl::Verdict::shorten;
            if (retake)
              break;
          }
        if (retake)
          continue;

        // Measured on the converged state, before a kick perturbs it and the points move.
        const double rate =
          time_stepping.end_at_equilibrium > 0. ? model.rate_of_change(solution, step_dt) : 0.;
        bool perturbed = false;
        for (auto *observer : observers)
          perturbed = observer->before_update(solution, step_dt) || perturbed;
        model.update(solution, t_begin + step_dt);
        control_.accept(report.iterations);
        n_armijo_converged += armijo_retry;
        // A kicked state is no rest, whatever its step's rate.
        if (time_stepping.end_at_equilibrium > 0.)
          control_.judge_equilibrium(perturbed ? std::numeric_limits<double>::infinity() : rate);
        // A perturbation is no motion to continue: the next step starts without a predictor.
        last_dt = perturbed ? 0. : step_dt;

        AcceptedStep accepted;
        accepted.number     = control_.step();
        accepted.t_begin    = t_begin;
        accepted.time       = control_.time();
        accepted.dt         = step_dt;
        accepted.attempts   = attempt;
        accepted.report     = report;
        accepted.output_due = output_due();
        for (auto *observer : observers)
          observer->accepted(accepted, solution);
        return StepOutcome::accepted;
      }
  }


  bool
  TimeLoop::bound_attempt(const double t_begin, double &step_dt)
  {
    const auto bound = model.bound_step(t_begin, step_dt);
    if (!(bound.dt < step_dt))
      return true;
    if (!(bound.dt >= time_stepping.minimum_step))
      {
        std::ostringstream why;
        why << "the step at t/tau_d = " << t_begin << " would have to be shorter than 'Time "
            << "stepping/Minimum step' = " << time_stepping.minimum_step << ": " << bound.reason;
        failure_ = why.str();
        log << "    " << failure_ << std::endl;
        return false;
      }
    if (!step_bound_said)
      log << "    step " << control_.step() + 1 << " at t = " << t_begin
          << " shortened from dt = " << step_dt << " to " << bound.dt << ": " << bound.reason
          << " (steps so shortened are not reported from here on)" << std::endl;
    step_bound_said = true;
    control_.limit_attempt(bound.dt);
    step_dt = bound.dt;
    return true;
  }


  bool
  TimeLoop::retry_with_armijo(const NewtonReport &report,
                              const double        t_begin,
                              const double        step_dt)
  {
    // Near a fold of the solution path the physical damping's full updates overshoot along the
    // soft mode; Armijo's rule follows the residual down.
    if (report.converged || newton_settings.line_search != NewtonSettings::LineSearch::adaptive)
      return false;
    log << "    step " << control_.step() + 1 << " at t = " << t_begin << " with dt = " << step_dt
        << " failed (" << report.failure
        << "); retrying with Armijo's line search ('Newton/Line search = adaptive')" << std::endl;
    for (auto *observer : observers)
      observer->attempt_rejected();
    ++n_armijo_retries;
    return true;
  }


  bool
  TimeLoop::attempt_failed(const NewtonReport &report, const double t_begin, const double step_dt)
  {
    round_off_hint_ = round_off_stall(report, newton_settings);
    log << "    step " << control_.step() + 1 << " at t = " << t_begin << " with dt = " << step_dt
        << " failed (" << report.failure << (round_off_hint_.empty() ? "" : "; " + round_off_hint_)
        << ")";
    if (newton_settings.log_failures)
      {
        log << "\n      Newton: scaled |R_u|, |R_mu| at the start of each iteration, "
               "damping taken:";
        for (const auto &h : report.history)
          log << "\n        " << h[0] << "  " << h[1] << "  " << h[2];
        log << "\n     ";
      }
    if (control_.bracketing())
      log << "; bracketing of the loss of stability abandoned";
    for (auto *observer : observers)
      observer->attempt_rejected();
    if (!control_.cut_step())
      {
        log << "; the step would fall below 'Time stepping/Minimum step' = "
            << time_stepping.minimum_step << std::endl;
        std::ostringstream why;
        why << "the step at t/tau_d = " << t_begin << " failed (" << report.failure
            << ") and would fall below 'Time stepping/Minimum step' = "
            << time_stepping.minimum_step;
        failure_ = why.str();
        return false;
      }
    log << "; retrying with dt = " << control_.proposed_step() << std::endl;
    return true;
  }


  bool
  TimeLoop::displacement_rule_judges() const
  {
    // The first step has no predictor: its estimate would be the whole motion.
    return time_stepping.displacement_tolerance > 0. && last_dt > 0.;
  }


  bool
  TimeLoop::tolerance_rule_judges(const double dt) const
  {
    // A step far longer than the last (after a landing on a stop time) would amplify the last
    // step's noise into its predictor: no estimate of the tolerance rule for it.
    return time_stepping.tolerance > 0. &&
           (time_stepping.tolerance_until_onset
              ? !control_.onset_seen()
              : (time_stepping.tolerance_until == 0. ||
                 control_.time() < time_stepping.tolerance_until)) &&
           last_dt > 0. && StepControl::estimate_applies(dt, last_dt);
  }


  bool
  TimeLoop::increment_bound_applies(const double dt) const
  {
    // Set by the scene, the bound holds for every step; at its default it guards the steps that
    // no error estimate judges (every step of a scene without one; else the first, the one after
    // a perturbation, one far longer than the last), where a step that converged to a wrong state
    // would pass unseen (doc/method.md, "Update after convergence").
    return time_stepping.largest_increment > 0. &&
           (!time_stepping.largest_increment_default ||
            !(displacement_rule_judges() || tolerance_rule_judges(dt)));
  }


  bool
  TimeLoop::error_acceptable(const dealii::Vector<double> &solution,
                             const double                  dt,
                             std::string                  &failure)
  {
    const bool displacement_rule = displacement_rule_judges();
    const bool tolerance_rule    = tolerance_rule_judges(dt);
    if (!(displacement_rule || tolerance_rule))
      return true;
    const double difference =
      displacement_rule ? model.increment_deviation(solution, dt / last_dt) : 0.;
    const double local_error =
      tolerance_rule ? model.local_error(solution, dt / last_dt, time_stepping.error_largest) : 0.;
    const auto excess = control_.error_excess(difference, local_error, dt);
    if (control_.judge_error(excess))
      {
        if (control_.error_uncontrolled() && n_uncontrolled_errors++ == 0)
          log << "    the step's error estimate exceeds its tolerance " << excess.factor
              << " times whatever the step: a jump in the last step (a perturbation) or the "
                 "points' integration noise, not an error of this one; accepted (such steps "
                 "are accepted without a word from here on and counted at the end)"
              << std::endl;
        return true;
      }
    std::ostringstream why;
    why << "the error estimate exceeds ";
    if (displacement_rule && difference > time_stepping.displacement_tolerance)
      why << "'Time stepping/Displacement tolerance' (a point's motion differs from the last "
             "step's by "
          << difference << ")";
    else
      why << "'Time stepping/Tolerance' (local error " << local_error << " against "
          << control_.tolerated_local_error(dt) << ")";
    failure = why.str();
    return false;
  }


  bool
  TimeLoop::output_due()
  {
    const double time = control_.time();
    const bool   interval_due =
      (output_interval_steps > 0 && control_.step() % output_interval_steps == 0) ||
      (output_interval_time > 0. && time >= next_output_time * (1. - relative_time_tolerance));
    // The next multiple of the interval after this time, in one step: a loop that adds the
    // interval would run for ever when it is tiny against the time.
    if (output_interval_time > 0. && next_output_time <= time * (1. + relative_time_tolerance))
      next_output_time =
        (std::floor(time * (1. + relative_time_tolerance) / output_interval_time) + 1.) *
        output_interval_time;
    return interval_due || control_.at_stop_time() || control_.finished();
  }


  const StepControl &
  TimeLoop::control() const
  {
    return control_;
  }


  StepControl &
  TimeLoop::control()
  {
    return control_;
  }


  double
  TimeLoop::time() const
  {
    return control_.time();
  }


  unsigned int
  TimeLoop::step() const
  {
    return control_.step();
  }


  const RunScales &
  TimeLoop::scales() const
  {
    return run_scales;
  }


  const NewtonSettings &
  TimeLoop::newton() const
  {
    return newton_settings;
  }


  const std::string &
  TimeLoop::failure() const
  {
    return failure_;
  }


  const std::string &
  TimeLoop::round_off_hint() const
  {
    return round_off_hint_;
  }


  int
  TimeLoop::signal() const
  {
    return signal_;
  }


  unsigned long
  TimeLoop::newton_iterations() const
  {
    return n_newton_iterations;
  }


  unsigned long
  TimeLoop::factorizations() const
  {
    return n_factorizations;
  }


  const FreshTangents &
  TimeLoop::fresh_tangents() const
  {
    return fresh_tangents_;
  }


  std::pair<unsigned long, unsigned long>
  TimeLoop::switch_updates() const
  {
    return {n_switch_updates, n_unsettled_switches};
  }


  std::pair<unsigned long, unsigned long>
  TimeLoop::armijo_retries() const
  {
    return {n_armijo_retries, n_armijo_converged};
  }


  unsigned long
  TimeLoop::uncontrolled_errors() const
  {
    return n_uncontrolled_errors;
  }


  void
  TimeLoop::count_factorization()
  {
    ++n_factorizations;
  }
} // namespace GelMPM

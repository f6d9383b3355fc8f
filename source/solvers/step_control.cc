#include <gelmpm/solvers/step_control.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace GelMPM
{
  StepControl::StepControl(const TimeStepping &settings,
                           const double        bisection_tolerance,
                           const double        unstable_step,
                           const bool          signature_control)
    : settings_(settings)
    , bisection_tolerance(bisection_tolerance)
    , unstable_step(unstable_step)
    , signature_control(signature_control)
    , proposed(settings.initial_step)
  {}


  double
  StepControl::time() const
  {
    return time_;
  }


  unsigned int
  StepControl::step() const
  {
    return step_;
  }


  bool
  StepControl::finished() const
  {
    return equilibrium || time_ >= settings_.end_time * (1. - relative_time_tolerance);
  }


  bool
  StepControl::out_of_steps() const
  {
    return step_ >= settings_.maximum_steps;
  }


  double
  StepControl::attempt()
  {
    if (bisecting)
      {
        // Half the bracket while it is wider than the tolerance; then the step onto its unstable
        // end. Such a step is shortened on purpose: it leaves the proposed step as it is.
        const double remaining = unstable_time - time_;
        current                = (remaining > bisection_tolerance) ? 0.5 * remaining : remaining;
        attempt_limit          = std::numeric_limits<double>::infinity();
        return current;
      }
    double limit = std::min(proposed, settings_.cap(time_));
    if (!stable_ && unstable_step > 0.)
      limit = std::min(limit, unstable_step);
    attempt_limit = limit;
    current       = settings_.next_step(time_, limit);
    return current;
  }


  void
  StepControl::limit_attempt(const double dt)
  {
    // A bracket's step forced to a shorter one no longer ends on the unstable time: bracketing
    // starts again from the state it reaches, as after a failed attempt.
    bisecting     = false;
    attempt_limit = dt;
    // Landing on a stop time or the end as attempt() does, rather than leaving a remainder.
    current = settings_.next_step(time_, dt);
  }


  double
  StepControl::attempt_size() const
  {
    return current;
  }


  bool
  StepControl::cut_step()
  {
    bisecting    = false;
    retaken_step = 0.;
    first_retake = 0.;
    proposed     = current * settings_.cut_factor;
    return proposed >= settings_.minimum_step;
  }


  bool
  StepControl::judge_error(const ErrorExcess &estimate)
  {
    error_limit         = 0.;
    uncontrolled        = false;
    const double excess = estimate.factor;
    if (!(excess > 0.))
      return true;
    const double factor = 0.9 / excess;
    if (excess <= 1.)
      {
        // A first attempt that meets the tolerance shows the estimate resolving the error
        // again; a retake that does may only have met the noise at a lucky moment.
        if (retaken_step == 0.)
          noise_rate = 0.;
        error_limit  = current * factor;
        retaken_step = 0.;
        first_retake = 0.;
        return true;
      }
    // A time-stepping error shrinks with the step (an excess in proportion to it). One that
    // shrinks by less than the fourth root of the step ratio (the displacement rule) or its
    // square root (the tolerance rule, whose excess is per unit time: the material point
    // method's integration noise, points crossing cell faces, is a constant rate there) is not
    // this step's.
    const double noise_exponent = estimate.per_unit_time ? 0.5 : 0.25;
    if (retaken_step > current &&
        excess > retaken_excess * std::pow(current / retaken_step, noise_exponent))
      return accept_as_noise(estimate.per_unit_time);
    double shorter = current * std::clamp(factor, 0.2, 0.9);
    // Below the relative step at which the estimate showed its noise it cannot tell an error
    // from noise: a retake goes no shorter, and an attempt at that size is accepted.
    if (estimate.per_unit_time && noise_rate > 0. && noise_rate < 1.)
      {
        const double floor = noise_rate * time_ / (1. - noise_rate);
        if (current <= floor * (1. + relative_time_tolerance))
          return accept_as_noise(true);
        shorter = std::max(shorter, floor);
      }
    if (shorter < settings_.minimum_step)
      return true;
    if (retaken_step == 0.)
      first_retake = current;
    retaken_step   = current;
    retaken_excess = excess;
    bisecting      = false;
    proposed       = shorter;
    return false;
  }


  bool
  StepControl::estimate_applies(const double dt, const double last_dt)
  {
    return last_dt > 0. && dt <= estimate_reach * last_dt * (1. + relative_time_tolerance);
  }


  bool
  StepControl::accept_as_noise(const bool per_unit_time)
  {
    uncontrolled = true;
    retaken_step = 0.;
    // The next step need not stay as short as the retakes made this one: shorter steps would
    // not meet the tolerance either.
    noise_step = per_unit_time ? first_retake : 0.;
    if (per_unit_time)
      noise_rate = current / (time_ + current);
    first_retake = 0.;
    return true;
  }


  StepControl::ErrorExcess
  StepControl::error_excess(const double displacement_difference,
                            const double local_error,
                            const double dt) const
  {
    ErrorExcess excess;
    // The difference goes as dt^2; the local error per unit relative time, (t + dt) / dt, as
    // dt: both give the step that meets their tolerance as dt / excess.
    if (settings_.displacement_tolerance > 0.)
      excess.factor = std::sqrt(displacement_difference / settings_.displacement_tolerance);
    // Where a step cap applies the scene sets the steps by hand (a loading ramp): the
    // tolerance does not overrule it there.
    if (settings_.tolerance > 0. && dt > 0. && std::isinf(settings_.cap(time_)))
      {
        const double per_unit_time = local_error * (time_ + dt) / (dt * settings_.tolerance);
        if (per_unit_time > excess.factor)
          excess = ErrorExcess{per_unit_time, true};
      }
    return excess;
  }


  double
  StepControl::tolerated_local_error(const double dt) const
  {
    return settings_.tolerance * dt / (time_ + dt);
  }


  bool
  StepControl::error_uncontrolled() const
  {
    return uncontrolled;
  }


  StepControl::Verdict
  StepControl::judge_signature(const bool stable)
  {
    if (stable && bisecting && time_ + current >= unstable_time * (1. - relative_time_tolerance))
      {
        bisecting = false;
        stable_   = true;
        return Verdict::step_dependent;
      }
    if (stable)
      {
        const bool was_stable = stable_;
        stable_               = true;
        return was_stable ? Verdict::accept : Verdict::regained;
      }
    if (onset_seen_ && signature_control &&
        current * settings_.cut_factor >= settings_.minimum_step)
      {
        proposed = current * settings_.cut_factor;
        return Verdict::shorten;
      }
    if (!stable_)
      return Verdict::accept;

    // The signature left (n_u, n_mu, 0) within this attempt: the critical time lies in
    // (time, time + current].
    const double t_unstable = time_ + current;
    if (bisection_tolerance > 0. && current > bisection_tolerance)
      {
        bisecting     = true;
        unstable_time = t_unstable;
        return Verdict::retake;
      }
    bisecting   = false;
    stable_     = false;
    bracket_    = Bracket{time_, t_unstable};
    onset_seen_ = true;
    // Going through: the mode grows from here on, so the steps start again from the bracket's
    // width rather than from the step that was being bisected.
    if (signature_control)
      proposed = current;
    return Verdict::onset;
  }


  void
  StepControl::accept(const unsigned int newton_iterations)
  {
    // A step shortened by a stop time or by bisection leaves the proposed step as it was; a
    // bisection step does not grow it either (its size was forced, not chosen by Newton).
    const bool bisection_step = std::isinf(attempt_limit);
    const bool full_step      = current >= attempt_limit * (1. - relative_time_tolerance);
    if (full_step)
      proposed = current;
    time_ += current;
    ++step_;
    if (newton_iterations < settings_.growth_below && !bisection_step)
      proposed *= settings_.growth_factor;
    // A step shortened by a stop time measures its error on a short interval, where the points'
    // integration noise weighs more: it does not shorten the next step either.
    if (error_limit > 0. && full_step)
      proposed = std::min(proposed, error_limit);
    if (noise_step > 0.)
      proposed = std::max(proposed, std::min(noise_step, estimate_reach * current));
    noise_step   = 0.;
    error_limit  = 0.;
    retaken_step = 0.;
  }


  bool
  StepControl::judge_equilibrium(const double step_rate)
  {
    rate                   = step_rate;
    const double last_stop = settings_.stop_times.empty() ? 0. : settings_.stop_times.back();
    const double t_begin   = time_ - current;
    const bool   calm      = settings_.end_at_equilibrium > 0. &&
                      step_rate < settings_.end_at_equilibrium &&
                      t_begin >= last_stop * (1. - relative_time_tolerance);
    calm_steps  = calm ? calm_steps + 1 : 0;
    equilibrium = calm_steps >= 2;
    return equilibrium;
  }


  bool
  StepControl::at_equilibrium() const
  {
    return equilibrium;
  }


  double
  StepControl::last_rate() const
  {
    return rate;
  }


  bool
  StepControl::at_stop_time() const
  {
    return std::any_of(settings_.stop_times.begin(),
                       settings_.stop_times.end(),
                       [this](const double s) {
                         return std::abs(s - time_) <= 1e-10 * s;
                       });
  }


  bool
  StepControl::stable() const
  {
    return stable_;
  }


  bool
  StepControl::onset_seen() const
  {
    return onset_seen_;
  }


  bool
  StepControl::bracketing() const
  {
    return bisecting;
  }


  const StepControl::Bracket &
  StepControl::bracket() const
  {
    return bracket_;
  }


  double
  StepControl::proposed_step() const
  {
    return proposed;
  }


  const TimeStepping &
  StepControl::settings() const
  {
    return settings_;
  }
} // namespace GelMPM

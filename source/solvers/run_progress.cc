#include <gelmpm/solvers/run_progress.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace GelMPM
{
  RunProgress::RunProgress(const TimeStepping &settings, const Clock::time_point start)
    : settings(settings)
    , start(start)
    , last(start)
  {}


  void
  RunProgress::begin_stepping(const Clock::time_point now)
  {
    last = now;
  }


  void
  RunProgress::step_accepted(const double t, const double dt, const Clock::time_point now)
  {
    const double cost = std::chrono::duration<double>(now - last).count();
    // The newest step weighs 1/4: the average follows a change of cost within a few steps and
    // does not jump with one slow step.
    seconds_per_step = seconds_per_step < 0. ? cost : 0.75 * seconds_per_step + 0.25 * cost;
    last             = now;
    time             = t;
    last_dt          = dt;
  }


  double
  RunProgress::elapsed(const Clock::time_point now) const
  {
    return std::chrono::duration<double>(now - start).count();
  }


  double
  RunProgress::remaining() const
  {
    if (seconds_per_step < 0.)
      return -1.;
    return seconds_per_step * remaining_steps(settings, time, last_dt, settings.end_time);
  }


  double
  RunProgress::remaining_steps(const TimeStepping &settings,
                               const double        t,
                               const double        dt,
                               const double        end_time)
  {
    if (t >= end_time * (1. - relative_time_tolerance) || dt <= 0.)
      return 0.;
    // The rate at which the step grows with the time; a step that is large against the time
    // (a run that began at t > 0) grows no faster than the step control lets it.
    const double rate  = t > 0. ? std::min(dt / t, settings.growth_factor - 1.) : 0.;
    double       steps = 0.;
    double       a     = t;
    auto         caps  = settings.caps;
    caps.emplace_back(std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity());
    for (const auto &[until, largest] : caps)
      {
        if (until <= a)
          continue;
        const double b = std::min(until, end_time);
        if (rate <= 0.)
          // Nothing to grow from: steps of dt, capped.
          steps += (b - a) / std::min(dt, largest);
        else
          {
            // Steps of rate s up to the cap, then of the cap.
            const double s_c = std::min(b, std::max(a, largest / rate));
            steps += std::log(s_c / a) / std::log1p(rate);
            if (s_c < b)
              steps += (b - s_c) / largest;
          }
        a = b;
        if (a >= end_time)
          break;
      }
    return std::max(steps, 1.);
  }


  std::string
  format_duration(const double seconds)
  {
    std::ostringstream out;
    if (seconds < 60.)
      out << std::fixed << std::setprecision(seconds < 10. ? 1 : 0) << seconds << " s";
    else if (seconds < 3600.)
      {
        const long s = std::lround(seconds);
        out << s / 60 << " min " << std::setw(2) << std::setfill('0') << s % 60 << " s";
      }
    else
      {
        const long m = std::lround(seconds / 60.);
        out << m / 60 << " h " << std::setw(2) << std::setfill('0') << m % 60 << " min";
      }
    return out.str();
  }
} // namespace GelMPM

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
    if (t > 0.)
      {
        recent_rates.push_back(dt / t);
        if (recent_rates.size() > 20)
          recent_rates.pop_front();
      }
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
    // Without an error tolerance nothing but the growth factor and the caps bounds the step.
    const double rate = assumed_rate();
    return seconds_per_step *
           remaining_steps(settings,
                           time,
                           last_dt,
                           settings.end_time,
                           rate > 0. ? rate : std::numeric_limits<double>::infinity());
  }


  double
  RunProgress::assumed_rate() const
  {
    if (recent_rates.empty() || (settings.tolerance <= 0. && settings.displacement_tolerance <= 0.))
      return 0.;
    // With an error tolerance the step tends to a share of the time: the largest of the last
    // steps (a step cut short for a contact or an onset grows back to it).
    return std::min(*std::max_element(recent_rates.begin(), recent_rates.end()),
                    settings.growth_factor - 1.);
  }


  double
  RunProgress::remaining_steps(const TimeStepping &settings,
                               const double        t,
                               const double        dt,
                               const double        end_time,
                               const double        rate)
  {
    const double end = end_time * (1. - relative_time_tolerance);
    if (t >= end || dt <= 0.)
      return 0.;
    const double g = settings.growth_factor;
    double       s = t, h = dt, steps = 0.;
    // Phases, each in closed form but the growth: growth by g per step (one step at a time: a
    // few dozen), steps of rate s (a geometric series of times), steps of the cap.
    for (unsigned int phase = 0; s < end && phase < 100000; ++phase)
      {
        const double cap = settings.cap(s);
        double       b   = end_time; // where the cap in force at s ends
        for (const auto &c : settings.caps)
          if (s < c.first * (1. - relative_time_tolerance))
            {
              b = std::min(b, c.first);
              break;
            }
        const double target = std::min(rate * s, cap);
        if (g > 1. && h * g < target)
          {
            h *= g;
            s += h;
            steps += 1.;
            continue;
          }
        if (rate * s < cap)
          {
            const double s_c = std::min(b, cap / rate);
            if (s_c > s * (1. + relative_time_tolerance))
              {
                steps += std::log(s_c / s) / std::log1p(rate);
                h = rate * s_c;
                s = s_c;
                continue;
              }
          }
        const double step = std::isfinite(cap) ? cap : h;
        steps += (b - s) / step;
        h = step;
        s = b;
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


  std::string
  format_percent(const double share)
  {
    const double       percent = 100. * share;
    std::ostringstream out;
    // Two significant digits without an exponent down to 10^-4 %: a crawl reads as one.
    const int decimals =
      percent > 0. ? std::max(0, 1 - static_cast<int>(std::floor(std::log10(percent)))) : 0;
    if (decimals > 6)
      out << std::setprecision(1) << std::scientific << percent;
    else
      out << std::fixed << std::setprecision(decimals) << percent;
    out << "%";
    return out.str();
  }
} // namespace GelMPM

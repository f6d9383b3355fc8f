// RunProgress, the wall time and the estimate of the time to the end in the step lines of the
// log (include/gelmpm/solvers/run_progress.h):
// 1. the number of steps still to take against an independent count, a step-by-step walk of
//    the rule it models (each step min(g h, r s, cap(s))): with r finite (error control: steps
//    in proportion to the time) and infinite (growth factor and caps alone), with and without
//    caps, from starts below and above a cap's time and from steps far below and at r s; within
//    one step, plus one per cap's end (the walk's last step before it may cross it); and the closed
//    form ln(50)/ln(1.1) of a run at r = 0.1 from t = 1;
// 2. the estimate is the average wall time per step times that count, the newest step weighing
//    1/4 (synthetic clock times), r being the largest dt/t of the last steps;
// 3. nothing is estimated before a step, and nothing remains at the end;
// 4. durations and shares read as the log writes them;
// 5. the dt/t the estimate assumes (printed beside it): none without an error tolerance, at most
//    'Growth factor' - 1 with one.
#include <gelmpm/solvers/run_progress.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

using GelMPM::RunProgress;

namespace
{
  /** The steps from t to the end, each min(g h, r s, cap(s)), walked one by one. */
  double
  walked_steps(const GelMPM::TimeStepping &settings,
               double                      s,
               double                      h,
               const double                r,
               const double                end)
  {
    unsigned int n = 0;
    while (s < end * (1. - 1e-12))
      {
        h = std::min({settings.growth_factor * h, r * s, settings.cap(s)});
        s += std::min(h, end - s);
        ++n;
      }
    return n;
  }
} // namespace


int
main()
{
  std::cout << std::boolalpha;
  GelMPM::TimeStepping settings;
  settings.end_time      = 50.;
  settings.growth_factor = 1.25;
  const double infinity  = std::numeric_limits<double>::infinity();

  // 1.
  std::cout << "proportional steps from t = 1 at r = 0.1: ln(50)/ln(1.1): "
            << (std::abs(RunProgress::remaining_steps(settings, 1., 0.1, 50., 0.1) -
                         std::log(50.) / std::log(1.1)) < 1e-9)
            << '\n';
  for (const bool capped : {false, true})
    {
      settings.caps      = capped ? std::vector<std::pair<double, double>>{{20., 0.5}, {1e9, 2.}}
                                  : std::vector<std::pair<double, double>>{};
      unsigned int cases = 0, within = 0;
      for (const double r : {0.1, 0.02, infinity})
        for (const double t : {1., 3., 25.})
          for (const double dt : {1e-4, 0.01, 0.1 * t, 3.})
            {
              const double h = std::min(dt, r * t);
              const double n = RunProgress::remaining_steps(settings, t, h, 50., r);
              const double w = walked_steps(settings, t, h, r, 50.);
              ++cases;
              // The walk's last step before a cap's end may cross it: one step per end.
              if (std::abs(n - w) <= (capped ? 2. : 1.))
                ++within;
              else
                std::cout << "  r = " << r << ", t = " << t << ", dt = " << h << ": " << n
                          << " steps against " << w << " walked\n";
            }
      std::cout << (capped ? "with two caps: within two steps" : "without caps: within one step")
                << " of the walk in " << within << " of " << cases << " cases\n";
    }

  // 2. Steps of 2 s and then 6 s of wall time, error control on (r from the steps).
  {
    settings.tolerance = 1e-2;
    using Clock        = RunProgress::Clock;
    const Clock::time_point start;
    RunProgress             progress(settings, start);
    std::cout << "no estimate before the first step: " << (progress.remaining() < 0.) << '\n';
    progress.begin_stepping(start + std::chrono::seconds(1));
    progress.step_accepted(1., 0.1, start + std::chrono::seconds(3));
    const double n = RunProgress::remaining_steps(settings, 1., 0.1, 50., 0.1);
    std::cout << "one step of 2 s: estimate 2 s per step: "
              << (std::abs(progress.remaining() - 2. * n) < 1e-9 * n) << '\n';
    // A step cut short (dt/t = 0.01): r stays the largest recent 0.1, the step grows back.
    progress.step_accepted(1.011, 0.011, start + std::chrono::seconds(9));
    const double n2 = RunProgress::remaining_steps(settings, 1.011, 0.011, 50., 0.1);
    std::cout << "then a short one of 6 s: 0.75 * 2 + 0.25 * 6 = 3 s per step, r = 0.1: "
              << (std::abs(progress.remaining() - 3. * n2) < 1e-9 * n2) << '\n';
    std::cout << "the estimate's assumption, the largest recent dt/t: "
              << (std::abs(progress.assumed_rate() - 0.1) < 1e-12) << '\n';
    std::cout << "wall time counts from the start of the run: "
              << (std::abs(progress.elapsed(start + std::chrono::seconds(9)) - 9.) < 1e-12) << '\n';
    progress.step_accepted(50., 1., start + std::chrono::seconds(10));
    std::cout << "nothing remains at the end: " << (progress.remaining() == 0.) << '\n';
  }

  // 5. Without an error tolerance no dt/t is assumed; with one it is at most 'Growth factor' - 1.
  {
    using Clock = RunProgress::Clock;
    const Clock::time_point start;
    settings.tolerance = 0.;
    RunProgress fixed(settings, start);
    fixed.step_accepted(1., 0.5, start + std::chrono::seconds(1));
    std::cout << "no dt/t assumed without a tolerance: " << (fixed.assumed_rate() == 0.) << '\n';
    settings.tolerance = 1e-2;
    RunProgress growing(settings, start);
    growing.step_accepted(1., 0.5, start + std::chrono::seconds(1));
    std::cout << "dt/t 0.5 assumed as the growth factor's 0.25: "
              << (std::abs(growing.assumed_rate() - 0.25) < 1e-12) << '\n';
  }

  // 4.
  std::cout << GelMPM::format_percent(1.) << " | " << GelMPM::format_percent(0.73) << " | "
            << GelMPM::format_percent(0.0137) << " | " << GelMPM::format_percent(2.2e-5) << " | "
            << GelMPM::format_percent(3e-9) << '\n';
  std::cout << GelMPM::format_duration(8.44) << " | " << GelMPM::format_duration(42.4) << " | "
            << GelMPM::format_duration(187.) << " | " << GelMPM::format_duration(7500.) << '\n';
  return 0;
}

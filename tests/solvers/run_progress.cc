// RunProgress, the wall time and the estimate of the time to the end in the step lines of the
// log (include/gelmpm/solvers/run_progress.h):
// 1. the number of steps still to take against an independent count: a step-by-step walk of
//    steps that grow in proportion to the time (h = c s) up to the caps, with and without caps,
//    from a start below and above a cap's time; within one step;
// 2. the estimate is the average wall time per step times that count, the newest step weighing
//    1/4 (synthetic clock times);
// 3. nothing is estimated before a step, and nothing remains at the end;
// 4. durations read as the log writes them.
#include <gelmpm/solvers/run_progress.h>

#include <chrono>
#include <cmath>
#include <iostream>

using GelMPM::RunProgress;

namespace
{
  /** The steps from t to the end, each c times the time it starts from, capped (walked). */
  double
  walked_steps(const GelMPM::TimeStepping &settings, double t, const double c, const double end)
  {
    unsigned int n = 0;
    while (t < end * (1. - 1e-12))
      {
        const double h = std::min(c * t, settings.cap(t));
        t += std::min(h, end - t);
        ++n;
      }
    return n;
  }
} // namespace


int
main()
{
  GelMPM::TimeStepping settings;
  settings.end_time      = 50.;
  settings.growth_factor = 1.25;

  // 1. Without caps, from t = 1 with dt = 0.1: ln(50)/ln(1.1) = 41.04 steps.
  {
    const double n = RunProgress::remaining_steps(settings, 1., 0.1, 50.);
    const double w = walked_steps(settings, 1., 0.1, 50.);
    std::cout << "uncapped growth: within one step of the walk: " << std::boolalpha
              << (std::abs(n - w) <= 1.) << '\n';
    std::cout << "uncapped growth: the closed form ln(50)/ln(1.1): "
              << (std::abs(n - std::log(50.) / std::log(1.1)) < 1e-9) << '\n';
  }
  // With a cap of 0.5 until 20 and 2 after.
  settings.caps = {{20., 0.5}, {1e9, 2.}};
  for (const double t : {1., 3., 25.})
    {
      const double c = 0.1;
      const double n = RunProgress::remaining_steps(settings, t, c * t, 50.);
      const double w = walked_steps(settings, t, c, 50.);
      std::cout << "capped growth from t = " << t << ": within one step of the walk: "
                << (std::abs(n - w) <= 1.) << '\n';
    }

  // 2. Steps of 2 s and then 6 s of wall time.
  {
    using Clock = RunProgress::Clock;
    const Clock::time_point start;
    RunProgress             progress(settings, start);
    std::cout << "no estimate before the first step: " << (progress.remaining() < 0.) << '\n';
    progress.begin_stepping(start + std::chrono::seconds(1));
    progress.step_accepted(1., 0.1, start + std::chrono::seconds(3));
    const double n = RunProgress::remaining_steps(settings, 1., 0.1, 50.);
    std::cout << "one step of 2 s: estimate 2 s per step: "
              << (std::abs(progress.remaining() - 2. * n) < 1e-9 * n) << '\n';
    progress.step_accepted(1.1, 0.11, start + std::chrono::seconds(9));
    const double n2 = RunProgress::remaining_steps(settings, 1.1, 0.11, 50.);
    std::cout << "then one of 6 s: 0.75 * 2 + 0.25 * 6 = 3 s per step: "
              << (std::abs(progress.remaining() - 3. * n2) < 1e-9 * n2) << '\n';
    std::cout << "wall time counts from the start of the run: "
              << (std::abs(progress.elapsed(start + std::chrono::seconds(9)) - 9.) < 1e-12)
              << '\n';
    progress.step_accepted(50., 1., start + std::chrono::seconds(10));
    std::cout << "nothing remains at the end: " << (progress.remaining() == 0.) << '\n';
  }

  // 4.
  std::cout << GelMPM::format_duration(8.44) << " | " << GelMPM::format_duration(42.4) << " | "
            << GelMPM::format_duration(187.) << " | " << GelMPM::format_duration(7500.) << '\n';
}

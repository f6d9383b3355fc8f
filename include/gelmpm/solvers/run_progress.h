#ifndef gelmpm_solvers_run_progress_h
#define gelmpm_solvers_run_progress_h

#include <gelmpm/solvers/time_stepping.h>

#include <chrono>
#include <deque>
#include <string>

namespace GelMPM
{
  /**
   * @brief How far a run has come and when it will end: the wall time since the start and an
   * estimate of the wall time to the end time, for the step lines of the log.
   *
   * The estimate is (steps still to take) x (wall time per step). The wall time per step is an
   * exponential average over the last steps (weight 1/4 for the newest, failed attempts
   * included): the cost of a step changes slowly with the body, abruptly when an attempt fails.
   * The steps still to take are counted as the step control would take them undisturbed: each
   * step 'Growth factor' times the last, up to the cap in force ('Step caps') and, with an error
   * tolerance ('Time stepping/Tolerance', 'Displacement tolerance'), up to a share r of the time,
   * as an error-controlled step in a diffusion problem grows in proportion to the time. r is the
   * largest dt/t of the last 20 accepted steps: a step cut short for a contact or an onset grows
   * back to where it was. In closed form but for the growth phase (remaining_steps()): steps of
   * r s from s_1 to s_2 number ln(s_2/s_1)/ln(1 + r). A run whose steps shrink (bracketing a
   * loss of stability, a contact) takes more than estimated; doc/output.md has the estimate's
   * error on the paper's scenes.
   */
  class RunProgress
  {
  public:
    using Clock = std::chrono::steady_clock;

    /** The run started at @p start (its set-up included); the steps' schedule is @p settings. */
    RunProgress(const TimeStepping &settings, const Clock::time_point start = Clock::now());

    /**
     * A step of @p dt was accepted at time @p t (both in tau_d) at the wall time @p now; the
     * wall time since the last accepted step (or since begin_stepping()) is its cost.
     */
    void
    step_accepted(const double t, const double dt, const Clock::time_point now = Clock::now());

    /** The time stepping begins now (after the set-up and the initial output). */
    void
    begin_stepping(const Clock::time_point now = Clock::now());

    /** Wall seconds since the start. */
    double
    elapsed(const Clock::time_point now = Clock::now()) const;

    /**
     * The estimated wall seconds to the end time; negative while no step has been taken (nothing
     * to estimate from).
     */
    double
    remaining() const;

    /**
     * The share of the time by which remaining() assumes the steps to go on: dt/t, the largest
     * of the last accepted steps (at most 'Growth factor' - 1); zero without an error tolerance,
     * where the growth factor and the caps alone set the steps. The log prints it beside the
     * estimate because the estimate is only as good as this assumption: in a diffusion run the
     * error-controlled dt/t falls and rises again by factors of 10 and more (doc/output.md).
     */
    double
    assumed_rate() const;

    /**
     * The number of steps from @p t to @p end_time, the last step having been @p dt: each step
     * grows by 'Growth factor' over the last, up to @p rate times the time (infinity: no such
     * bound) and up to the cap in force ('Step caps').
     */
    static double
    remaining_steps(const TimeStepping &settings,
                    const double        t,
                    const double        dt,
                    const double        end_time,
                    const double        rate);

  private:
    const TimeStepping &settings;
    Clock::time_point   start;
    Clock::time_point   last;
    double              seconds_per_step = -1.;
    double              time             = 0.;
    double              last_dt          = 0.;
    std::deque<double>  recent_rates; // dt/t of the last accepted steps
  };

  /** A wall time for the log: "8.4 s", "3 min 07 s", "2 h 05 min". */
  std::string
  format_duration(const double seconds);

  /** A share for the log, in percent with two significant digits: "100%", "1.4%", "0.0022%". */
  std::string
  format_percent(const double share);
} // namespace GelMPM

#endif

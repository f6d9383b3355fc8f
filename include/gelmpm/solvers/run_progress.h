#ifndef gelmpm_solvers_run_progress_h
#define gelmpm_solvers_run_progress_h

#include <gelmpm/solvers/time_stepping.h>

#include <chrono>
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
   * The steps still to take follow the way an error-controlled step grows in a diffusion
   * problem: in proportion to the time, dt(s) = (dt/t) s at the rate of the last accepted step
   * dt at time t, until it meets the cap of 'Time stepping/Maximum step' in force at s, and at
   * that cap from there on. Between the caps' times a_k < s < b_k with cap C_k this gives
   * ln(s_c / a_k) / ln(1 + dt/t) steps of geometric growth up to s_c = min(C_k t/dt, b_k) and
   * (b_k - s_c) / C_k capped steps. A run whose steps shrink (bracketing a loss of stability, a
   * contact) takes more than estimated; doc/output.md has the estimate's error on the paper's
   * scenes.
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
     * The number of steps from @p t to @p end_time whose size grows in proportion to the time,
     * from @p dt at @p t, up to the caps of @p settings (see the class documentation).
     */
    static double
    remaining_steps(const TimeStepping &settings,
                    const double        t,
                    const double        dt,
                    const double        end_time);

  private:
    const TimeStepping &settings;
    Clock::time_point   start;
    Clock::time_point   last;
    double              seconds_per_step = -1.;
    double              time             = 0.;
    double              last_dt          = 0.;
  };

  /** A wall time for the log: "8.4 s", "3 min 07 s", "2 h 05 min". */
  std::string
  format_duration(const double seconds);
} // namespace GelMPM

#endif

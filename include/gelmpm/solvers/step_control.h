#ifndef gelmpm_solvers_step_control_h
#define gelmpm_solvers_step_control_h

#include <gelmpm/solvers/time_stepping.h>

namespace GelMPM
{
  /**
   * @brief The time, the step size and every rule that chooses it, as one object that a time
   * loop drives: the material point Simulator and the body-fitted run_fem_time_loop() both use
   * it, so that the two models step identically.
   *
   * The rules (paper §4, §4.3):
   * - Newton: a failed attempt is retried with the step times 'Cut factor' (cut_step());
   *   convergence in fewer than 'Growth below iterations' iterations grows the next step by
   *   'Growth factor' (accept());
   * - caps: the piecewise 'Step caps' bound the step, and steps are shortened to land on the
   *   'Stop at times' and the end time (TimeStepping::next_step());
   * - signature ("adaptive time-stepping based on monitoring the signature", §4.3), when the loop
   *   reports it through judge_signature():
   *   - bracketing: when the signature leaves (n_u, n_mu, 0) within a step, the step is retaken
   *     from the last stable state with halved remaining intervals until the critical time is
   *     known to the bisection tolerance;
   *   - with signature control, the steps after an onset start from the bracket's width, and
   *     after the first bracketed loss of stability an unstable attempt
   *     is retaken shorter (by the cut factor) until its signature is (n_u, n_mu, 0) again or
   *     the minimum step is reached: the signature of K(dt) counts the modes that grow faster
   *     than 1/dt (doc/method.md), so this keeps sigma dt < 1 for every mode;
   * - error ('Displacement tolerance' and 'Tolerance', error_excess(), judge_error()): a
   *   converged attempt whose error estimate exceeds a tolerance is retaken shorter, and an
   *   accepted one bounds the next step by what the estimate allows (backward Euler's local
   *   error goes as dt^2);
   *   - while the accepted state is unstable, the step is at most 'unstable step': backward
   *     Euler multiplies a mode growing at rate sigma by 1/(1 - sigma dt) per step, which damps
   *     it once sigma dt > 2, so long steps would converge to the unstable symmetric state
   *     (doc/method.md, "Going through an instability").
   *
   * Usage, per step:
   * @code
   *   while (!control.finished())
   *     for (;;) {
   *       const double dt = control.attempt();      // size of this attempt
   *       ... solve from the last converged state to control.time() + dt ...
   *       if (!converged) { if (!control.cut_step()) stop; continue; }
   *       if (stability && control.judge_signature(stable) == StepControl::Verdict::retake)
   *         continue;
   *       control.accept(newton_iterations);
   *       break;
   *     }
   * @endcode
   */
  class StepControl
  {
  public:
    /**
     * The error estimates extrapolate the last step's motion to the current one (a predictor):
     * beyond this ratio of the steps the extrapolation amplifies the last step's noise more
     * than it measures this step's error, and a loop does not estimate (estimate_applies()).
     */
    static constexpr double estimate_reach = 10.;

    /** Whether a step @p dt after an accepted step @p last_dt is within estimate_reach of it. */
    static bool
    estimate_applies(const double dt, const double last_dt);

    /** What judge_signature() decided about a converged attempt. */
    enum class Verdict
    {
      /** Accept the attempt; nothing changed in the signature. */
      accept,
      /** The signature left (n_u, n_mu, 0) within a step longer than the bisection tolerance:
       * retake the step (shorter) from the last stable state. */
      retake,
      /** The attempt is the unstable end of a closed bracket of a loss of stability: accept it;
       * bracket() gives the bracket. */
      onset,
      /** The attempt onto the unstable end of a bracket was stable when taken shorter: the
       * signature depends on the step size (K_mumu ~ dt); bracketing ended, accept. */
      step_dependent,
      /** The signature is back at (n_u, n_mu, 0) after an unstable stretch: accept. */
      regained,
      /** After a bracketed loss of stability, with signature control: the attempt is unstable,
       * i.e. some mode grows faster than 1/dt; retake it with the step times the cut factor. */
      shorten
    };

    /** A loss of stability: the last stable and the first unstable time. */
    struct Bracket
    {
      double t_stable   = 0.;
      double t_unstable = 0.;

      /** Boost serialization (StepControl::serialize()). */
      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &t_stable &t_unstable;
      }
    };

    /**
     * @p settings: caps, stops, growth and cuts; @p bisection_tolerance (tau_d; 0: no
     * bisection) and @p unstable_step (largest step while unstable, tau_d; 0: no such cap) for
     * the signature rules.
     */
    explicit StepControl(const TimeStepping &settings,
                         const double        bisection_tolerance = 0.,
                         const double        unstable_step       = 0.,
                         const bool          signature_control   = false);

    /** Time of the last accepted state (tau_d). */
    double
    time() const;

    /** Number of accepted steps. */
    unsigned int
    step() const;

    /** Whether the end time or an equilibrium (judge_equilibrium()) is reached. */
    bool
    finished() const;

    /** Whether 'Maximum steps' steps have been taken. */
    bool
    out_of_steps() const;

    /** The size of the next attempt from time(), remembered for the calls that follow. */
    double
    attempt();

    /**
     * Shorten the current attempt to @p dt (below attempt_size()): a bound of the model's
     * (SteppedModel::bound_step()), which acts as a step cap does: a step accepted at it sets
     * the proposed step, from which the Newton rule grows the next.
     */
    void
    limit_attempt(const double dt);

    /** The size of the current attempt (the last attempt() returned). */
    double
    attempt_size() const;

    /**
     * The current attempt failed: the next one is shorter by the cut factor, and bracketing is
     * given up. Returns false if that would fall below the minimum step (the run must stop).
     */
    bool
    cut_step();

    /** How far an attempt exceeds the error rules (error_excess()). */
    struct ErrorExcess
    {
      /** The factor by which the step would have to shrink to meet the rules (at most 1:
       * within; 0: no rule on). */
      double factor = 0.;
      /** Whether 'Tolerance' decides (its estimate is a local error per unit time). */
      bool per_unit_time = false;
    };

    /**
     * How far the current attempt of size @p dt exceeds the error rules, the larger of:
     * - 'Displacement tolerance': sqrt(@p displacement_difference / tolerance), the largest
     *   predictor-corrector difference of a point's displacement;
     * - 'Tolerance': @p local_error (t + @p dt) / (@p dt Tolerance), the local error estimate
     *   normalised by L and k_BT (MixedSystem::local_error_estimate()) per unit relative time
     *   dt / (t + dt); not where a step cap applies (the scene sets the steps there by hand,
     *   e.g. over a loading ramp).
     */
    ErrorExcess
    error_excess(const double displacement_difference,
                 const double local_error,
                 const double dt) const;

    /** The local error 'Tolerance' allows a step of size @p dt from time(). */
    double
    tolerated_local_error(const double dt) const;

    /**
     * The current attempt converged with the error excess @p excess (error_excess()). Returns
     * false if the attempt must be retaken: the next attempt is shorter, by the factor
     * 0.9 / excess clamped to [0.2, 0.9]. Returns true if it may be accepted: always with no
     * rule on; when a shorter attempt would fall below the minimum step; and when the excess
     * did not shrink with the step (by at least the fourth root of the step ratio against the
     * last retaken attempt for the displacement rule, the square root for 'Tolerance'), so
     * that it is no time-stepping error but a jump in the last step's motion (a perturbation,
     * a change of branch) or the points' integration noise: error_uncontrolled() is then true,
     * and with 'Tolerance' the next step starts again from the first retaken attempt, but at
     * most estimate_reach times the accepted step, so that its error is estimated (an unchecked
     * long step would put its own error into the next step's predictor, which then looks like
     * noise again). From then on, until the first attempt of a step meets the tolerance, the
     * 'Tolerance' rule retakes no shorter than the relative step dt / (t + dt) of the attempt
     * accepted as noise and accepts an attempt of that size: below it the estimate cannot tell an
     * error from noise, and without that floor the retakes would ratchet the step down to the
     * minimum. An accepted estimate bounds the next step by dt 0.9 / excess.
     */
    bool
    judge_error(const ErrorExcess &excess);

    /**
     * The current attempt converged to a state whose signature is (n_u, n_mu, 0) if @p stable:
     * the signature rules above.
     */
    Verdict
    judge_signature(const bool stable);

    /**
     * Accept the current attempt, converged in @p newton_iterations iterations: advance the time,
     * and choose the next step.
     */
    void
    accept(const unsigned int newton_iterations);

    /**
     * 'End at equilibrium': the step just accepted changed the state at @p rate (per tau_d,
     * SteppedModel::rate_of_change()). Returns whether the run has reached equilibrium: the rate
     * below the tolerance on this step and on the one before, both beginning at or after the last
     * of the 'Stop at times' (where the scene's loading may still change). One step alone could
     * be a short step (landing on a stop time) or a moment of rest between two motions.
     */
    bool
    judge_equilibrium(const double rate);

    /** Whether judge_equilibrium() found the equilibrium (the run is finished). */
    bool
    at_equilibrium() const;

    /** The rate of the last step judge_equilibrium() saw. */
    double
    last_rate() const;

    /** Whether the last accepted step landed on one of the 'Stop at times'. */
    bool
    at_stop_time() const;

    /** Whether the last judge_error() accepted a difference above the tolerance because it did
     * not shrink with the step. */
    bool
    error_uncontrolled() const;

    /** Whether the last judged state was stable (true before any judgement). */
    bool
    stable() const;

    /** Whether a loss of stability has been bracketed (Verdict::onset) in this run. */
    bool
    onset_seen() const;

    /** Whether a critical time is being bracketed. */
    bool
    bracketing() const;

    /** The bracket of the last loss of stability (valid after a Verdict::onset). */
    const Bracket &
    bracket() const;

    /** The step the controller proposes next, before caps and stops. */
    double
    proposed_step() const;

    const TimeStepping &
    settings() const;

    /**
     * Write or read the state for a checkpoint (boost serialization): every member that a later
     * call reads, so that a resumed run steps exactly as the run that wrote the checkpoint; the
     * settings come from the scene. A new member of the state belongs here too.
     */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &onset_seen_ &time_ &step_ &proposed &current &attempt_limit &error_limit &retaken_step
        &retaken_excess &first_retake &noise_step &noise_rate &uncontrolled &stable_ &bisecting
          &unstable_time &bracket_ &calm_steps &equilibrium &rate;
    }

  private:
    /** Accept the current attempt as one whose excess is not a time-stepping error
     * (judge_error()). */
    bool
    accept_as_noise(const bool per_unit_time);

    TimeStepping settings_;
    double       bisection_tolerance;
    double       unstable_step;
    bool         signature_control;
    bool         onset_seen_ = false;

    double       time_          = 0.;
    unsigned int step_          = 0;
    double       proposed       = 0.; // the controller's step (Newton growth and cuts)
    double       current        = 0.; // the current attempt
    double       attempt_limit  = 0.; // what bounded it before stop times (infinite when bisecting)
    double       error_limit    = 0.; // the step the error estimate of the attempt allows (0: none)
    double       retaken_step   = 0.; // the last attempt retaken by the error control (0: none)
    double       retaken_excess = 0.;
    double       first_retake   = 0.; // the first attempt of the step the error retook
    double       noise_step     = 0.; // the next step after an uncontrolled excess
    double       noise_rate     = 0.; // dt / (t + dt) of the last attempt accepted as noise
    bool         uncontrolled   = false;
    bool         stable_        = true;
    bool         bisecting      = false;
    double       unstable_time  = 0.;
    Bracket      bracket_;
    unsigned int calm_steps  = 0; // consecutive steps below 'End at equilibrium'
    bool         equilibrium = false;
    double       rate        = 0.; // of the last step judged
  };
} // namespace GelMPM

#endif

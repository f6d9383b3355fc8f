#ifndef gelmpm_solvers_time_loop_h
#define gelmpm_solvers_time_loop_h

#include <gelmpm/core/newton_system.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/step_control.h>
#include <gelmpm/solvers/time_stepping.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The scales of a run: the diffusion time tau_d = L^2 / D, in which a loop counts
   * time, and Newton's residual scales G |Omega_0|^((dim-1)/dim) and (k_BT/nu) |Omega_0|
   * (NewtonSettings).
   */
  struct RunScales
  {
    double tau_d    = 1.;
    double scale_u  = 1.;
    double scale_mu = 1.;

    /**
     * The scales of a body of volume (area in 2D) @p volume in dimension @p dim, of a gel with
     * diffusivity @p diffusivity, shear modulus @p shear_modulus and k_BT/nu @p kT_over_nu, for
     * the characteristic length @p length ('Time stepping/Characteristic length').
     */
    static RunScales
    of(const unsigned int dim,
       const double       length,
       const double       diffusivity,
       const double       shear_modulus,
       const double       kT_over_nu,
       const double       volume);
  };


  /**
   * @brief The discretisation-specific part of a time step, which TimeLoop drives: the material
   * points on their background grid (MaterialPointModel) or the body-fitted mesh (the peer's
   * FemModel).
   *
   * Times are in tau_d. A model keeps the state of the last accepted step and the predictor
   * that the first Newton iterate is made of; the loop keeps the time, the step sizes and every
   * decision about them.
   */
  class SteppedModel
  {
  public:
    virtual ~SteppedModel() = default;

    /** The Newton system of the current step. */
    virtual NewtonSystem &
    system() = 0;

    /**
     * Once per step, before its attempts: whatever the attempts share (the grid reset of the
     * material points). @p last_dt is the last accepted step (0 before the first and after a
     * perturbation), @p t_begin the time the step starts at.
     */
    virtual void
    begin_step(const double last_dt, const double t_begin);

    /**
     * Before every attempt of the step [@p t_begin, @p t_begin + @p dt]: set that step's
     * boundary data and put the first Newton iterate into @p solution (with @p last_dt for a
     * predictor from the last step's motion).
     */
    virtual void
    prepare_attempt(const double            t_begin,
                    const double            dt,
                    const double            last_dt,
                    dealii::Vector<double> &solution) = 0;

    /**
     * Whether the model measures its steps' errors: increment_deviation() and local_error(). A
     * loop refuses 'Time stepping/Displacement tolerance' and 'Tolerance' for a model that does
     * not.
     */
    virtual bool
    estimates_errors() const;

    /**
     * Whether largest_motion_in_cells() is measured (by default: with the error estimates); a
     * loop refuses 'Time stepping/Largest increment' for a model that does not.
     */
    virtual bool
    measures_motion_in_cells() const;

    /** What bound_step() allows, and why. */
    struct StepBound
    {
      /** The longest step allowed (at most the step asked about). */
      double dt = 0.;
      /** What bounds it, for the log and a failure message (empty: nothing). */
      std::string reason;
    };

    /**
     * The longest step from @p t_begin, at most @p dt, that what the model prescribes itself
     * allows: the material points bound the travel of a rigid obstacle in one step
     * (Obstacle::largest_travel_in_cells). By default @p dt.
     */
    virtual StepBound
    bound_step(const double t_begin, const double dt) const;

    /**
     * Whether rate_of_change() is measured; a loop refuses 'Time stepping/End at equilibrium'
     * for a model that does not.
     */
    virtual bool
    measures_rate_of_change() const;

    /**
     * How fast the converged @p solution of a step of @p dt (tau_d) changes the state, per
     * tau_d and dimensionless, for 'Time stepping/End at equilibrium' (the material points: the
     * largest relative change of a volume point's J or of a point's position in units of the
     * 'Characteristic length', divided by @p dt).
     */
    virtual double
    rate_of_change(const dealii::Vector<double> &solution, const double dt) const;

    /** The largest displacement of the converged @p solution, in cells of the grid. */
    virtual double
    largest_motion_in_cells(const dealii::Vector<double> &solution) const;

    /**
     * Why the converged @p solution of a step is no state of the model, so that the step is
     * retaken shorter (a surface point that passed through the gel's own surface unseen by the
     * step's self-contact pairs); empty: accepted. By default empty.
     */
    virtual std::string
    refusal(const dealii::Vector<double> &solution) const;

    /**
     * The largest distance between the motion of @p solution and the last step's motion scaled
     * by @p ratio (the predictor), for 'Time stepping/Displacement tolerance'.
     */
    virtual double
    increment_deviation(const dealii::Vector<double> &solution, const double ratio) const;

    /**
     * The local error of @p solution against the predictor (last motion times @p ratio):
     * max(displacement error / 'Characteristic length', chemical-potential error in k_BT/nu),
     * as a root mean square or, with @p largest, the largest value.
     */
    virtual double
    local_error(const dealii::Vector<double> &solution,
                const double                  ratio,
                const bool                    largest) const;

    /** Apply the accepted @p solution of the step that ends at @p t_end. */
    virtual void
    update(const dealii::Vector<double> &solution, const double t_end) = 0;

    /** A stop signal that has arrived (0: none), the same on every rank. */
    virtual int
    stop_signal() const;
  };


  /** What the loop reports of an accepted step to its observers. */
  struct AcceptedStep
  {
    unsigned int number   = 0;  ///< steps accepted so far, this one included
    double       t_begin  = 0.; ///< at the step's start, tau_d
    double       time     = 0.; ///< at the step's end, tau_d
    double       dt       = 0.; ///< tau_d
    unsigned int attempts = 0;
    NewtonReport report;
    /** The output schedule ('Output/Interval'), a stop time or the end falls on this step. */
    bool output_due = false;
  };


  /**
   * @brief Something that watches the steps of a TimeLoop and may act on them: the stability
   * analysis (which may ask for a retake), the simulator's statistics, output and checkpoints,
   * the peer's callbacks. Every hook does nothing by default; observers are called in the order
   * they were added.
   */
  class StepObserver
  {
  public:
    virtual ~StepObserver() = default;

    /** Before the attempts of a step, after the model's begin_step(). */
    virtual void
    step_begins();

    /**
     * A converged attempt of @p dt, not yet accepted. Returns StepControl's verdict:
     * Verdict::retake or Verdict::shorten make the loop take the step again.
     */
    virtual StepControl::Verdict
    judge_attempt(const dealii::Vector<double> &solution,
                  const double                  dt,
                  const NewtonReport           &report);

    /** An attempt failed or was retaken by the error rules. */
    virtual void
    attempt_rejected();

    /**
     * The accepted @p solution, before the model applies it. Returns whether it changed
     * @p solution (a perturbation, after which the next step has no predictor).
     */
    virtual bool
    before_update(dealii::Vector<double> &solution, const double dt);

    /** The model has applied @p solution of the accepted @p step. */
    virtual void
    accepted(const AcceptedStep &step, const dealii::Vector<double> &solution);

    /** Whether the run is to end after the step just accepted. */
    virtual bool
    end_requested() const;

    /** Between two accepted steps (checkpoints). */
    virtual void
    between_steps();
  };


  /**
   * @brief The one adaptive time loop of every model: steps a SteppedModel from the start to
   * 'Time stepping/End time', owning the step control, the run's scales, the Newton settings as
   * used, the counters and the output schedule.
   *
   * Per step: the model's begin_step(), the observers' step_begins(); then attempts until one is
   * accepted: StepControl gives its size (shortened to what the model's bound_step() allows),
   * the model sets the boundary data and the first
   * iterate, solve_newton() solves, and the attempt is judged in turn by the rules of 'Time
   * stepping' ('Largest increment', 'Displacement tolerance', 'Tolerance': the model's
   * estimates against StepControl's bounds) and by the observers (the signature). A failed
   * attempt is cut by StepControl and retried until the minimum step; an attempt retaken by a
   * rule or an observer is retried at the size StepControl proposes. The accepted attempt goes
   * to the observers' before_update(), the model's update() and, once StepControl has accepted
   * it, to the observers' accepted().
   *
   * Retakes and failures are said in @p log (one line each), so that a long run shows why its
   * steps shrink.
   */
  class TimeLoop
  {
  public:
    /** How run() ended. */
    enum class Outcome
    {
      finished,     ///< the end time is reached
      equilibrium,  ///< 'Time stepping/End at equilibrium' found a steady state
      ended_early,  ///< an observer asked for the end (e.g. 'Stability/End at onset')
      out_of_steps, ///< 'Time stepping/Maximum steps' steps were taken
      failed,       ///< the step would fall below the minimum: failure() says why
      interrupted,  ///< a stop signal (signal()) arrived between steps
      /** A stop signal arrived between the attempts of a step: the last accepted state stands,
       * but the linear solver's factorisation is of a rejected attempt. */
      interrupted_within_step
    };

    /**
     * @p time_stepping and @p newton as parsed; @p bisection_tolerance, @p unstable_step and
     * @p signature_control are StepControl's signature rules; @p output_interval_steps and
     * @p output_interval_time the output schedule (0: none). Throws InputError if
     * @p time_stepping asks for an error rule that @p model cannot estimate.
     */
    TimeLoop(SteppedModel               &model,
             const TimeStepping         &time_stepping,
             const NewtonSettings       &newton,
             const LinearSolver         &linear_solver,
             const RunScales            &scales,
             dealii::ConditionalOStream &log,
             dealii::TimerOutput        &timer,
             const double                bisection_tolerance   = 0.,
             const double                unstable_step         = 0.,
             const bool                  signature_control     = false,
             const unsigned int          output_interval_steps = 0,
             const double                output_interval_time  = 0.);

    /** Add @p observer (kept by reference; it must outlive the loop's use). */
    void
    add_observer(StepObserver &observer);

    /** Take steps until the end time or until something stops the run. */
    Outcome
    run();

    /** The step control (time, step, stability bracket). */
    const StepControl &
    control() const;
    StepControl &
    control();

    /** Time of the last accepted state (tau_d) and the number of accepted steps. */
    double
    time() const;
    unsigned int
    step() const;

    const RunScales &
    scales() const;

    /** The Newton settings as used (at least one iteration under 'Time stepping/Tolerance'). */
    const NewtonSettings &
    newton() const;

    /** Why the run failed (Outcome::failed) and the signal that stopped it (interrupted). */
    const std::string &
    failure() const;
    /**
     * When the last failed attempt's Newton iteration stalled at round-off (round_off_stall()):
     * what to change, naming 'Newton/Tolerance'; otherwise empty.
     */
    const std::string &
    round_off_hint() const;
    int
    signal() const;

    /** Over all attempts of the run, for its summary. */
    unsigned long
    newton_iterations() const;
    unsigned long
    factorizations() const;
    /** Why Newton's factorisations were made (NewtonReport::fresh_tangents, summed). */
    const FreshTangents &
    fresh_tangents() const;
    /** Steps accepted although their error estimate exceeds its tolerance whatever the step. */
    unsigned long
    uncontrolled_errors() const;
    /** Updates of held switches (NewtonReport::switch_updates, summed), and the steps taken
     * with a switch that still flipped (NewtonReport::switches_unsettled). */
    std::pair<unsigned long, unsigned long>
    switch_updates() const;
    /** With 'Newton/Line search = adaptive': the failed attempts retried with Armijo's rule, and
     * the steps accepted with it. */
    std::pair<unsigned long, unsigned long>
    armijo_retries() const;

    /** Count a factorisation made outside Newton (the stability analysis's). */
    void
    count_factorization();

    /**
     * Boost serialization of the state the next step reads: the step control, the last step
     * (which scales the predictor) and the output schedule. Read back, the schedule follows the
     * 'Output/Interval time' of the resumed run, which may differ from the checkpoint's
     * (follow_output_interval()).
     */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &control_ &last_dt &next_output_time;
      if constexpr (Archive::is_loading::value)
        follow_output_interval();
    }

  private:
    /**
     * The next output time read from a checkpoint, made the next multiple of this run's
     * 'Output/Interval time' after the time unless it is that already (up to round-off), as it
     * is when the interval did not change: the resumed run then writes what the uninterrupted
     * one would have.
     */
    void
    follow_output_interval()
    {
      if (!(output_interval_time > 0.))
        return;
      const double time        = control_.time() * (1. + relative_time_tolerance);
      const double multiple    = next_output_time / output_interval_time;
      const bool   on_schedule = next_output_time > time &&
                               next_output_time <= time + output_interval_time * (1. + 1e-9) &&
                               std::abs(multiple - std::round(multiple)) <= 1e-9 * multiple;
      if (!on_schedule)
        next_output_time = (std::floor(time / output_interval_time) + 1.) * output_interval_time;
    }

    enum class StepOutcome
    {
      accepted,
      failed,
      interrupted
    };

    /** Take one accepted step. */
    StepOutcome
    advance();

    /** Whether 'Time stepping/Displacement tolerance' judges the current step. */
    bool
    displacement_rule_judges() const;

    /** Whether 'Time stepping/Tolerance' judges the current step, of size @p dt. */
    bool
    tolerance_rule_judges(const double dt) const;

    /**
     * Whether 'Time stepping/Largest increment' bounds the current step, of size @p dt: always
     * when the scene sets it, at its default only where no error estimate judges the step.
     */
    bool
    increment_bound_applies(const double dt) const;

    /**
     * Whether the converged @p solution of a step of @p dt may be accepted under the rules of
     * 'Time stepping' (else StepControl has proposed a shorter step and @p failure says why).
     */
    bool
    error_acceptable(const dealii::Vector<double> &solution, const double dt, std::string &failure);

    /**
     * Shorten the attempt @p step_dt from @p t_begin to what the model's bound_step() allows;
     * false (and failure() says why) if that is below the minimum step.
     */
    bool
    bound_attempt(const double t_begin, double &step_dt);

    /** Whether the output schedule falls on the step just accepted (and advance it). */
    bool
    output_due();

    /**
     * With 'Newton/Line search = adaptive', whether the attempt of @p report (of @p step_dt from
     * @p t_begin, damped as 'physical') failed and is retried at the same step with Armijo's
     * rule; logs and counts it.
     */
    bool
    retry_with_armijo(const NewtonReport &report, const double t_begin, const double step_dt);

    /** Log a failed attempt of @p step_dt from @p t_begin; false if the run cannot go on. */
    bool
    attempt_failed(const NewtonReport &report, const double t_begin, const double step_dt);

    SteppedModel               &model;
    TimeStepping                time_stepping;
    NewtonSettings              newton_settings;
    const LinearSolver         &linear_solver;
    RunScales                   run_scales;
    dealii::ConditionalOStream &log;
    dealii::TimerOutput        &timer;
    StepControl                 control_;
    std::vector<StepObserver *> observers;
    unsigned int                output_interval_steps;
    double                      output_interval_time;

    double        last_dt = 0.; // the last accepted step (0 before the first, after a kick)
    double        next_output_time = 0.;
    std::string   failure_;
    std::string   round_off_hint_;
    int           signal_             = 0;
    unsigned long n_newton_iterations = 0;
    unsigned long n_factorizations    = 0;
    FreshTangents fresh_tangents_;
    unsigned long n_uncontrolled_errors = 0;
    unsigned long n_switch_updates      = 0;
    unsigned long n_unsettled_switches  = 0;
    /** 'Line search = adaptive': failed attempts retried with Armijo's rule, and steps accepted
     * with it. */
    unsigned long n_armijo_retries   = 0;
    unsigned long n_armijo_converged = 0;
    /** Whether the log has said that the model bounds the steps (bound_step()). */
    bool step_bound_said = false;
  };
} // namespace GelMPM

#endif

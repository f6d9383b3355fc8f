#ifndef gelmpm_simulator_stability_monitor_h
#define gelmpm_simulator_stability_monitor_h

#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/time_loop.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>

namespace GelMPM
{
  /**
   * @brief The stability analysis of a material point run ('Stability' section), as an observer
   * of the TimeLoop's converged attempts.
   *
   * Each converged attempt's tangent is analysed (analyse_stability(): its signature from the
   * LDL^T that the next step's Newton starts from, the smallest Schur-complement eigenvalues, the
   * inf-sup constant, the condition number) and its signature handed to StepControl, which may
   * ask for a retake (bisection of a loss of stability, doc/method.md "Going through an
   * instability"). A bracketed onset goes to the log, `stability.csv` and `events.csv`; with
   * 'Perturbation amplitude' the accepted state is kicked along the critical mode before the
   * points move; with 'End at onset' the run ends there. The columns of the analysis go into the
   * step's row of `statistics.csv`.
   */
  template <int dim>
  class StabilityMonitor : public StepObserver
  {
  public:
    /**
     * Throw InputError where the 'Stability' section does not fit the rest of the scene: an
     * analysis of the inertia with the skew-symmetric Nitsche variant, a dense analysis on
     * several ranks, a perturbation direction without a component in the scene's @p dim
     * directions, or a bisection tolerance below what the step arithmetic of @p time_stepping
     * resolves. (The section's own values are checked by StabilitySettings.)
     */
    static void
    check_settings(const StabilitySettings &settings,
                   const Scene<dim>        &scene,
                   const TimeStepping      &time_stepping);

    /**
     * Watch the steps of @p loop on @p scene. @p statistics receives the step's columns,
     * @p stability_file one row per bracketed onset; @p write_event writes an events.csv row
     * (name, t/tau_d); @p record_mode keeps the critical mode of an accepted step for output
     * (empty: no mode output).
     */
    StabilityMonitor(const StabilitySettings                                   &settings,
                     Scene<dim>                                                &scene,
                     const LinearSolver                                        &linear_solver,
                     TimeLoop                                                  &loop,
                     StatisticsFile                                            &statistics,
                     StatisticsFile                                            &stability_file,
                     dealii::ConditionalOStream                                &log,
                     dealii::TimerOutput                                       &timer,
                     const std::function<void(const std::string &, double)>    &write_event,
                     const std::function<void(const dealii::Vector<double> &)> &record_mode);

    /** Analyse the converged attempt's tangent and judge its signature. */
    StepControl::Verdict
    judge_attempt(const dealii::Vector<double> &solution,
                  const double                  dt,
                  const NewtonReport           &report) override;

    void
    attempt_rejected() override;

    /** The kick along the critical mode after a bracketed onset ('Perturbation amplitude'). */
    bool
    before_update(dealii::Vector<double> &solution, const double dt) override;

    /** With 'End at onset', after the step that closed the first bracket. */
    bool
    end_requested() const override;

    /**
     * With 'Signature from = last Newton factorisation': how many signatures came from Newton's
     * last factorisation and how many from a factorisation of the converged tangent (Newton's
     * last iteration solved with a kept one, or made none), for the end of the run; else empty.
     */
    std::string
    signature_sources() const;

    /** Boost serialization of the bookkeeping the next step and stability.csv read. */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &announced_bracketing &last_eigenvalue;
      ar &last_stable_inertia.n_positive &last_stable_inertia.n_negative &last_stable_inertia
        .n_zero;
    }

  private:
    /**
     * With 'Signature from = last Newton factorisation': the LDL^T that the last iteration of
     * the Newton solve @p report made, of the tangent at the iterate before the converged
     * state; nullptr where that iteration solved with a factorisation kept from an earlier
     * iterate or step, none was made, or there is no double-precision LDL^T (the converged
     * tangent is then factorised).
     */
    const SymmetricFactorization *
    newton_factorization(const NewtonReport &report) const;

    /** Whether the analysis reads the tangent itself (K_uu, the dense estimates), not only its
     * factorisation. */
    bool
    reads_tangent() const;

    /** Hand the signature to the step control and log what it decided. */
    StepControl::Verdict
    judge_signature(const StabilityReport &result);
    /** A bracketed loss of stability: to the log, stability.csv and events.csv. */
    void
    report_onset(const StabilityReport &result);
    /** The stability columns of statistics.csv for a converged step. */
    void
    record_columns(const StabilityReport &result);
    /**
     * Add 'Perturbation amplitude' times @p mode (displacement unknowns, scaled and signed by
     * 'Perturbation direction') to @p solution.
     */
    void
    perturb_along_mode(const dealii::Vector<double> &mode, dealii::Vector<double> &solution) const;

    const StabilitySettings                            &settings;
    Scene<dim>                                         &scene;
    const LinearSolver                                 &linear_solver;
    TimeLoop                                           &loop;
    StatisticsFile                                     &statistics;
    StatisticsFile                                     &stability_file;
    dealii::ConditionalOStream                         &log;
    dealii::TimerOutput                                &timer;
    std::function<void(const std::string &, double)>    write_event;
    std::function<void(const dealii::Vector<double> &)> record_mode;

    bool            announced_bracketing = false;
    Inertia         last_stable_inertia;
    double          last_eigenvalue = 0.;
    bool            ended_at_onset  = false;
    bool            perturb         = false; // the accepted attempt is to be kicked
    StabilityReport last_result;

    /** Signatures taken from Newton's last factorisation, and from the converged tangent. */
    unsigned long n_signatures_reused = 0;
    unsigned long n_signatures_fresh  = 0;
  };
} // namespace GelMPM

#endif

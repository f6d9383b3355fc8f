#ifndef gelmpm_fem_fem_time_loop_h
#define gelmpm_fem_fem_time_loop_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/step_control.h>
#include <gelmpm/solvers/time_stepping.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace GelMPM
{
  /** What a converged step of a body-fitted run did (times in tau_d). */
  struct FemStep
  {
    unsigned int number            = 0;
    double       t_over_tau_d      = 0.;
    double       dt_over_tau_d     = 0.;
    unsigned int newton_iterations = 0;
    unsigned int attempts          = 0;
    double       residual_u = 0., residual_mu = 0.; // scaled, as NewtonReport
  };


  /** How a body-fitted run ended. */
  struct FemRunResult
  {
    bool completed = false;
    /** Why the run stopped early (empty if it completed). */
    std::string failure;
    /** Time reached (tau_d) and Newton iterations of the converged steps. */
    double       t_over_tau_d      = 0.;
    unsigned int newton_iterations = 0;
    /** The bracketed losses of stability (with FemSignatureControl). */
    std::vector<StepControl::Bracket> onsets;
  };


  /**
   * Stability-aware stepping of a body-fitted run (StepControl): @p stable() tells whether the
   * tangent of the converged attempt (the system's matrix() after Newton) has the signature
   * (n_u, n_mu, 0); a loss of stability is bracketed to @p bisection_tolerance (tau_d; 0: not
   * bracketed) and steps while unstable are at most @p unstable_step (0: no cap).
   */
  struct FemSignatureControl
  {
    std::function<bool()> stable;
    double                bisection_tolerance = 0.;
    double                unstable_step       = 0.;
    bool                  signature_control   = false;
  };


  /** The time stepping and Newton settings of a body-fitted run. */
  struct FemRunSettings
  {
    TimeStepping   time_stepping;
    NewtonSettings newton;
  };


  /**
   * Read FemRunSettings through gelmpm's own sections 'Time stepping' and 'Newton', so that they
   * are checked exactly as in a scene (InputError naming the entry); entries not given keep the
   * defaults of those sections. @p time_stepping and @p newton map entry names to values, e.g.
   * {{"Initial step", "8.75e-5"}, {"Step caps", "5: 0.0125"}}.
   */
  FemRunSettings
  fem_run_settings(const std::map<std::string, std::string> &time_stepping,
                   const std::map<std::string, std::string> &newton);


  /**
   * @brief The adaptive time loop of the material point simulator, for a FemMixedSystem: one
   * loop shared by the body-fitted scenes, so that the peer steps exactly as the MPM does.
   *
   * A failed Newton solve (solve_newton, residual scales G |Omega_0|^((dim-1)/dim) and
   * (k_BT/nu) |Omega_0| as in NewtonSettings) retries with the step times the cut factor and
   * stops the run below the minimum step; convergence in fewer than 'growth below' iterations
   * grows the next step; TimeStepping's caps and stop times bound and place the steps.
   *
   * With @p signature, the signature of every converged attempt is judged before the step is
   * accepted (a retake for the bisection restarts from the last converged state, since update()
   * comes only after acceptance), and FemRunResult::onsets lists the brackets.
   *
   * @p prescribe(t_begin, t_end) is called before every attempt of a step (times in tau_d) to set
   * the boundary data of that step on the system (e.g. FemMixedSystem::set_displacement_increment);
   * @p on_step after every converged step, after FemMixedSystem::update(). Time-dependent data
   * must therefore be functions of time, not of the number of attempts.
   */
  template <int dim>
  FemRunResult
  run_fem_time_loop(FemMixedSystem<dim>                        &system,
                    const FloryRehnerGel<dim>                  &material,
                    const TimeStepping                         &time_stepping,
                    const NewtonSettings                       &newton,
                    const LinearSolver                         &linear_solver,
                    const std::function<void(double, double)>  &prescribe,
                    const std::function<void(const FemStep &)> &on_step,
                    const FemSignatureControl                  &signature = FemSignatureControl());
} // namespace GelMPM

#endif

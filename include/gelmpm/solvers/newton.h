#ifndef gelmpm_solvers_newton_h
#define gelmpm_solvers_newton_h

#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/solvers/linear_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <string>

namespace GelMPM
{
  /**
   * @brief The "Newton" section: monolithic Newton–Raphson for one time step (paper eq. (35)–(40)).
   *
   * Convergence test, on both blocks: the step has converged when
   *   |R_u| <= tol * G |Omega_0|^((dim-1)/dim)   and   |R_mu| <= tol * (k_BT/nu) |Omega_0|,
   * i.e. when the Euclidean norms of the residual blocks are below the tolerance relative to the
   * natural force scale (shear modulus times a boundary measure) and the natural scale of the
   * solvent-volume balance. Both blocks must pass; a scene with a tiny body and a relative test
   * would otherwise stop on round-off.
   */
  struct NewtonSettings
  {
    unsigned int maximum_iterations = 15;
    double       tolerance          = 1e-10;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };


  /** What one Newton solve did. */
  struct NewtonReport
  {
    bool         converged   = false;
    unsigned int iterations  = 0;
    double       residual_u  = 0.; // scaled, see NewtonSettings
    double       residual_mu = 0.;
    std::string  failure;
  };


  /**
   * Solve one step of @p system by Newton's method, starting from @p solution (updated in
   * place). @p scale_u and @p scale_mu are the residual scales of NewtonSettings. Failures
   * (non-physical state, failing factorisation, too many iterations) are reported, not thrown.
   */
  template <int dim>
  NewtonReport
  solve_newton(MixedSystem<dim>       &system,
               dealii::Vector<double> &solution,
               const double            dt,
               const NewtonSettings   &settings,
               const LinearSolver     &linear_solver,
               const double            scale_u,
               const double            scale_mu,
               dealii::TimerOutput    &timer);
} // namespace GelMPM

#endif

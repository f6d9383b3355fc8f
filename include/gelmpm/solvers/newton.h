#ifndef gelmpm_solvers_newton_h
#define gelmpm_solvers_newton_h

#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/solvers/linear_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <exception>
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
   *
   * @p System is any discretisation of the mixed u–mu step with
   *   void assemble(const dealii::Vector<double> &solution, double dt, bool with_matrix)
   *     (throws NonPhysicalState when a state leaves the physical range),
   *   const dealii::TrilinosWrappers::SparseMatrix &matrix() const,
   *   const dealii::Vector<double> &residual() const,
   *   double residual_norm_u() const, double residual_norm_mu() const:
   * the material point system MixedSystem and the body-fitted FemMixedSystem.
   */
  template <typename System>
  NewtonReport
  solve_newton(System                 &system,
               dealii::Vector<double> &solution,
               const double            dt,
               const NewtonSettings   &settings,
               const LinearSolver     &linear_solver,
               const double            scale_u,
               const double            scale_mu,
               dealii::TimerOutput    &timer)
  {
    NewtonReport           report;
    dealii::Vector<double> increment(solution.size());
    for (unsigned int k = 0;; ++k)
      {
        try
          {
            dealii::TimerOutput::Scope scope(timer, "assembly");
            system.assemble(solution, dt, true);
          }
        catch (const NonPhysicalState &e)
          {
            report.failure = e.what();
            return report;
          }
        report.residual_u  = system.residual_norm_u() / scale_u;
        report.residual_mu = system.residual_norm_mu() / scale_mu;
        if (!std::isfinite(report.residual_u) || !std::isfinite(report.residual_mu))
          {
            report.failure = "the residual is not finite";
            return report;
          }
        if (report.residual_u <= settings.tolerance && report.residual_mu <= settings.tolerance)
          {
            report.converged = true;
            return report;
          }
        if (k == settings.maximum_iterations)
          {
            report.failure = "no convergence in " + std::to_string(k) + " Newton iterations";
            return report;
          }
        try
          {
            dealii::TimerOutput::Scope scope(timer, "solve");
            linear_solver.solve(system.matrix(), increment, system.residual());
          }
        catch (const std::exception &e)
          {
            report.failure = e.what();
            return report;
          }
        solution -= increment;
        report.iterations = k + 1;
      }
  }
} // namespace GelMPM

#endif

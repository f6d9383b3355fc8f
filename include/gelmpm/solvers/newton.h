#ifndef gelmpm_solvers_newton_h
#define gelmpm_solvers_newton_h

#include <gelmpm/core/newton_system.h>
#include <gelmpm/solvers/linear_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

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
    /** Iterations taken even when the initial guess already meets the tolerance (not a
     * parameter: the simulator sets 1 under 'Time stepping/Tolerance', whose error estimate
     * compares the solution with the predictor, the initial guess; on a step short enough that
     * the predictor's residual is below the tolerance, a step of none left the predictor as the
     * solution and the estimate measured nothing but the predictor's own extrapolation). */
    unsigned int minimum_iterations = 0;
    /** How the Newton update is damped (see solve_newton()). */
    enum class LineSearch
    {
      none,     ///< full updates; a non-physical trial state fails the attempt
      physical, ///< backtrack until every point of the trial state is physical (J > 1)
      merit,    ///< and until the scaled residual decreases (Armijo)
      adaptive  ///< physical; a failed attempt is retried with merit (TimeLoop::advance())
    };
    LineSearch line_search = LineSearch::physical;
    /** Start mu from the projection of the points' mu (Simulator), not the last coefficients. */
    bool mu_from_points = true;
    /** 'Initial displacement = extrapolated': Newton starts from the last step's motion. */
    bool extrapolate_displacement = false;
    /** Print the residual history of every failed attempt. */
    bool log_failures = false;
    /** The smallest damping factor tried before the iteration counts as failed. */
    double smallest_damping = 1. / 64.;
    /**
     * Modified Newton (see solve_newton()): keep the factorisation of a tangent while the scaled
     * residual contracts by at least 'Reuse contraction' per iteration. 0: off (a fresh tangent
     * at every iterate).
     */
    double reuse_contraction = 1e-3;
    /**
     * With reuse: the factorisation kept from an earlier step serves the step's first iteration
     * only while its tangent's time step lies within this factor of the step's (either way);
     * 0: whatever the time step (the modified Newton iteration before this entry).
     */
    double reuse_step_ratio = 0.;
    /** With reuse: the solves one factorisation serves at most (0: no limit). */
    unsigned int maximum_reuses = 0;
    /** Iterations after which the discontinuous switches are held (NewtonSystem::
     * freeze_switches()); 0: never. */
    unsigned int freeze_switches_after = 4;
    /** How often the held switches are updated to a converged state before it is taken. */
    static constexpr unsigned int maximum_switch_updates = 4;

    /** The smallest 'Tolerance' accepted: below it the scaled residuals stop on round-off. */
    static constexpr double smallest_tolerance = 1e-14;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };


  /**
   * Why the modified Newton iteration (NewtonSettings::reuse_contraction) factorised a fresh
   * tangent instead of solving with the kept factorisation, counted per reason.
   */
  struct FreshTangents
  {
    /** Newton's method (no reuse), or no factorisation of the current sparsity pattern. */
    unsigned int without_reuse = 0;
    /** The last iteration reduced the scaled residual norm by less than 'Reuse contraction'. */
    unsigned int contraction = 0;
    /** The kept tangent's time step differs from the step's by more than 'Reuse step ratio'. */
    unsigned int step_ratio = 0;
    /** The kept factorisation has served 'Maximum reuses' solves. */
    unsigned int reuses = 0;
    /** An update of the kept factorisation was not physical or did not reduce the residual. */
    unsigned int discarded = 0;

    FreshTangents &
    operator+=(const FreshTangents &other)
    {
      without_reuse += other.without_reuse;
      contraction += other.contraction;
      step_ratio += other.step_ratio;
      reuses += other.reuses;
      discarded += other.discarded;
      return *this;
    }
  };


  /** What one Newton solve did. */
  struct NewtonReport
  {
    bool         converged   = false;
    unsigned int iterations  = 0;
    double       residual_u  = 0.; // scaled, see NewtonSettings
    double       residual_mu = 0.;
    /** Iterations whose update the line search shortened. */
    unsigned int damped_iterations = 0;
    /** Numeric factorisations of a tangent (at most one per iteration). */
    unsigned int factorizations = 0;
    /** Why each fresh tangent was factorised (modified Newton; the counts sum to
     * 'factorizations' unless the last factorisation failed). */
    FreshTangents fresh_tangents;
    /** How often the held switches were updated to a converged state (NewtonSystem::
     * freeze_switches()), and whether the last one still changed some (a point at the edge of
     * a contact whose switch flips with each solution; the state is taken). */
    unsigned int switch_updates     = 0;
    bool         switches_unsettled = false;
    /** Whether the system's matrix() is the tangent at the returned state. */
    bool tangent_at_solution = false;
    /**
     * Whether the last iteration factorised the tangent at its own iterate (a fresh tangent, not
     * a factorisation kept from an earlier iterate or step): the linear solver then holds the
     * factorisation of the tangent at the state before the last update ('Stability/Signature
     * from').
     */
    bool last_solve_fresh = false;
    /**
     * Per iteration: the scaled residuals (u, mu) at its start and the damping taken (0: the
     * update of an old factorisation, discarded).
     */
    std::vector<std::array<double, 3>> history;
    std::string                        failure;
  };


  /**
   * When the failed Newton solve @p report stalled at the round-off of its residual (the last
   * iterations' scaled residuals within a factor of 10 of each other, below 1e-8 and above the
   * tolerance), a sentence that says so and names 'Newton/Tolerance' with a value that can be
   * met; otherwise empty.
   */
  std::string
  round_off_stall(const NewtonReport &report, const NewtonSettings &settings);


  /**
   * Solve one step of @p system by Newton's method, starting from @p solution (updated in
   * place). @p scale_u and @p scale_mu are the residual scales of NewtonSettings. Failures
   * (non-physical state, failing factorisation, too many iterations) are reported, not thrown.
   *
   * With a line search, every update is damped by backtracking: the trial state x - alpha dx is
   * tried for alpha = 1, 1/2, 1/4, ... down to 'smallest damping', and taken as soon as (a) every
   * point of it is physical (J > 1: the assembly does not throw NonPhysicalState, a
   * fraction-to-the-boundary rule) and, with LineSearch::merit, (b) it decreases the merit
   * function f = |R_u|^2 + |R_mu|^2 (scaled blocks) by Armijo's rule
   * f(alpha) <= (1 - 1e-4 alpha) f(0), or both scaled residuals of the trial state are within 1e3
   * times the tolerance (where round-off, not the update, decides whether f still decreases).
   * A physical full update is Newton's, quadratically convergent near the solution. Without a
   * line search a non-physical trial state ends the attempt. doc/method.md compares the rules.
   *
   * With 'Reuse contraction' c > 0 the iteration is a modified Newton method: an iteration
   * solves with the factorisation of the last tangent, possibly of an earlier iterate or step
   * (the linear solver keeps it while the sparsity pattern stays), and the iterates in between
   * assemble only the residual. A fresh tangent is assembled and factorised for the next
   * iteration when the last one reduced the scaled residual norm by less than the factor c, and
   * at once when an update from an old factorisation is not physical or does not decrease the
   * residual (it is then discarded, not damped). The convergence test is the same, so is the
   * converged state to the tolerance; near it an old tangent costs a few cheap iterations where
   * a fresh one costs an assembly of the tangent and a factorisation. Two more rules ask for a
   * fresh tangent: a step whose time step differs from the kept tangent's by more than 'Reuse
   * step ratio' starts with one (the μ block scales with the time step, so such a tangent's
   * first update mostly fails the contraction test and is paid for nothing), and so does an
   * iteration whose factorisation has served 'Maximum reuses' solves. A solve with the kept
   * factorisation of an earlier iterate or step is refined (single-precision factors) only to
   * a tenth of 'Reuse contraction': that factorisation is of another matrix, and the iteration
   * corrects what the solve leaves with the true residual. NewtonReport::fresh_tangents counts
   * why each tangent was factorised.
   *
   * A first iterate that meets the tolerance is the solution (no iteration), unless the linear
   * solver's last call failed (LinearSolver::last_call_failed()): then one iteration, whose solve
   * must succeed, is taken, so that cutting the step after a failing solve cannot end in a step
   * accepted without any solve.
   *
   * Switches that make the residual jump (NewtonSystem::freeze_switches(): an impermeable
   * obstacle's seal) follow the iterate for the first 'Freeze switches after' iterations; then
   * they are held at the iterate's values, and at a converged state updated to that state's: if
   * any changed, the iteration goes on from there with 'Maximum iterations' more, at most
   * maximum_switch_updates times, after which the state is taken with the switches it was
   * solved with (NewtonReport::switches_unsettled). A converged state is thus one whose switches
   * are its own, as before. The switches are released when the next solve starts: what is
   * measured on the state meanwhile (the inflow of the pieces) uses those it was solved with.
   *
   * @p system is any discretisation of the mixed u–mu step (NewtonSystem): the material point
   * system MixedSystem and the body-fitted FemMixedSystem.
   */
  NewtonReport
  solve_newton(NewtonSystem           &system,
               dealii::Vector<double> &solution,
               const double            dt,
               const NewtonSettings   &settings,
               const LinearSolver     &linear_solver,
               const double            scale_u,
               const double            scale_mu,
               dealii::TimerOutput    &timer);
} // namespace GelMPM

#endif

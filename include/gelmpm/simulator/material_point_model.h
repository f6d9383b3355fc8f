#ifndef gelmpm_simulator_material_point_model_h
#define gelmpm_simulator_material_point_model_h

#include <gelmpm/bspline/nested_grids.h>
#include <gelmpm/core/sparse_entries.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/time_loop.h>
#include <gelmpm/solvers/time_stepping.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The material point method as a SteppedModel of the TimeLoop: the grid reset of every
   * step (paper §3.2, Fig. 2b), the first Newton iterate, the error estimates of the points'
   * motion, and the update of the points after an accepted step.
   *
   * It keeps the state that carries over from one step to the next besides the points
   * themselves: the chemical-potential coefficients of the last step (the first iterate of mu
   * where a control point keeps its support) and, per step, the projections of the points' mu
   * and of their last motion onto the step's basis (the predictor of 'Newton/Initial
   * displacement = extrapolated'). The Simulator holds one, beside the scene it works on.
   */
  template <int dim>
  class MaterialPointModel : public SteppedModel
  {
  public:
    /**
     * The model of @p scene (after Scene::create_system()), solved with @p linear_solver, whose
     * factorisation it drops when a grid reset changes the sparsity pattern; the displacement
     * error is measured in @p characteristic_length ('Time stepping/Characteristic length').
     */
    MaterialPointModel(Scene<dim>           &scene,
                       LinearSolver         &linear_solver,
                       const NewtonSettings &newton,
                       const double          characteristic_length,
                       dealii::TimerOutput  &timer);

    NewtonSystem &
    system() override;

    /**
     * The grid reset: cells classified from the points, extended bases, per-point cache and
     * (when the classification changed) the sparsity pattern; the projections the attempts'
     * first iterates start from.
     */
    void
    begin_step(const double last_dt, const double t_begin) override;

    /** The step's boundary data, and the first iterate (initial_guess()). */
    void
    prepare_attempt(const double            t_begin,
                    const double            dt,
                    const double            last_dt,
                    dealii::Vector<double> &solution) override;

    bool
    estimates_errors() const override;

    double
    largest_motion_in_cells(const dealii::Vector<double> &solution) const override;
    /**
     * With 'Contact/Self contact/Retake unseen passes', a step that leaves surface points
     * through the gel's own surface unseen by its pairs is refused.
     */
    std::string
    refusal(const dealii::Vector<double> &solution) const override;

    bool
    measures_rate_of_change() const override;

    /**
     * max(largest |J_{n+1}/J_n - 1| of a volume point, largest displacement of a point /
     * 'Characteristic length') / @p dt.
     */
    double
    rate_of_change(const dealii::Vector<double> &solution, const double dt) const override;

    /** The longest step from @p t_begin, at most @p dt, in which no rigid obstacle travels
     * more than Obstacle::largest_travel_in_cells cells of the displacement grid. */
    StepBound
    bound_step(const double t_begin, const double dt) const override;

    double
    increment_deviation(const dealii::Vector<double> &solution, const double ratio) const override;

    double
    local_error(const dealii::Vector<double> &solution,
                const double                  ratio,
                const bool                    largest) const override;

    /**
     * Move the points by the accepted @p solution and update their state, put them into their
     * new cells (partitioning the grid anew on several ranks when the load has become uneven),
     * and keep the step's mu coefficients. Throws std::runtime_error when points left the grid.
     */
    void
    update(const dealii::Vector<double> &solution, const double t_end) override;

    /** A stop signal on any rank (all ranks stop together). */
    int
    stop_signal() const override;

    /**
     * The first Newton iterate of a step of @p dt after a step of @p last_dt: du = 0, or with
     * 'Newton/Initial displacement = extrapolated' the last step's motion scaled to @p dt; mu
     * from the points or from the last converged coefficients ('Newton/Initial chemical
     * potential'). Also the initial state of the grid output.
     */
    void
    initial_guess(dealii::Vector<double> &solution,
                  const double            dt      = 0.,
                  const double            last_dt = 0.) const;

    /**
     * A resumed run: refactorise @p tangent (all rows of the checkpoint's factorisation) at the
     * first grid reset if it gives @p classification again, so that the next Newton iteration
     * solves with what the interrupted run would have.
     */
    void
    restore_factorization(const std::vector<bool> &classification, const SparseEntries &tangent);

    /** Grid resets that gave a new sparsity pattern, and repartitions of the grid. */
    unsigned long
    new_patterns() const;
    /** Steps that kept the last step's moving refinement (Scene::keep_last_marking()). */
    unsigned long
    kept_markings() const;
    /** Steps whose moving refinement lost levels to 'Background grid/Refinement budget'. */
    unsigned long
    budget_limited_steps() const;
    /** Steps whose grid without moving refinement exceeded the budget (the body outgrew it). */
    unsigned long
    steps_over_budget() const;
    /**
     * Accepted steps in which surface points passed through the gel's own surface unseen by the
     * step's pairs, and those points (without 'Retake unseen passes').
     */
    std::pair<unsigned long, unsigned long>
    unseen_passes() const;
    unsigned long
    repartitions() const;

    /**
     * Boost serialization: the mu coefficients, which of them hold a value, the band's
     * marking they belong to, and the levels the budget left the moving refinement.
     */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &mu_coefficients &mu_known &mu_marking &scene.grid.moving_levels;
    }

  private:
    /**
     * The grid reset's first part with 'Background grid/Refinement band' or 'Refinement mu
     * range': the grid marked anew, the points split; the mu coefficients, which belong to the last
     * marking's control points, are forgotten when it changed (the step starts from the points'
     * mu).
     */
    void
    follow_surface(const double t_begin);

    /** Forget the mu coefficients when they belong to another marking than the grid's. */
    void
    forget_mu_of_other_marking();

    /**
     * The grid reset proper (MixedSystem::setup()); if the extension cannot be built on this
     * step's moving refinement, once more on the last step's. Returns whether the sparsity
     * pattern is new.
     */
    bool
    reset_grid();

    /**
     * Beyond 'Background grid/Refinement budget', drop the finest levels of the moving
     * refinement (Scene::coarsen_moving_refinement()) and set the grid up again until the
     * unknowns are within it or no moving level is left (the step then runs on the grid
     * without moving refinement). Returns whether it set the grid up again (dropped a level).
     */
    bool
    keep_within_budget();

    /** Count the points of the accepted @p solution that passed through a face unseen. */
    void
    count_unseen_passes(const dealii::Vector<double> &solution);

    /** Chemical-potential coefficients of every control point of the mu grid, from a solution. */
    void
    store_mu_coefficients(const dealii::Vector<double> &solution);

    Scene<dim>          &scene;
    LinearSolver        &linear_solver;
    NewtonSettings       newton;
    double               characteristic_length;
    dealii::TimerOutput &timer;

    std::vector<double>            mu_coefficients; // per mu control point
    std::vector<bool>              mu_known;        // coefficient holds a current value
    std::vector<std::vector<bool>> mu_marking;      // the band's marking of the coefficients
    std::vector<double>            mu_projection;   // points' mu on the step's basis
    std::vector<double> displacement_projection;    // last step's motion on the step's basis

    std::vector<bool> resumed_classification;
    SparseEntries     resumed_tangent;

    // The coarse grids of the geometric multigrid on the displacement block (built when first
    // wanted).
    std::unique_ptr<NestedBSplineGrids<dim>> nested_grids;

    // On several ranks: the ratio of the largest number of points on a rank to the mean above
    // which the grid is partitioned anew (a repartition costs about one grid reset).
    static constexpr double largest_imbalance         = 1.1;
    double                  imbalance_after_partition = 1.;
    unsigned long           n_new_patterns            = 0;
    unsigned long           n_kept_markings           = 0;
    unsigned long           n_budget_limited          = 0;
    unsigned long           n_over_budget             = 0;
    unsigned long           n_unseen_steps            = 0;
    unsigned long           n_unseen_points           = 0;
    unsigned long           n_repartitions            = 0;
  };
} // namespace GelMPM

#endif

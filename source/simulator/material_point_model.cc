#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/stop_request.h>
#include <gelmpm/particles/point_location.h>
#include <gelmpm/simulator/material_point_model.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  template <int dim>
  MaterialPointModel<dim>::MaterialPointModel(Scene<dim>           &scene,
                                              LinearSolver         &linear_solver,
                                              const NewtonSettings &newton,
                                              const double          characteristic_length,
                                              dealii::TimerOutput  &timer)
    : scene(scene)
    , linear_solver(linear_solver)
    , newton(newton)
    , characteristic_length(characteristic_length)
    , timer(timer)
    , mu_coefficients(scene.spaces->n_mu_control_points(), scene.material.mu_0())
    , mu_known(scene.spaces->n_mu_control_points(), true)
    , mu_marking(scene.grid.moving_marked)
  {}


  template <int dim>
  void
  MaterialPointModel<dim>::follow_surface(const double t_begin)
  {
    if (!scene.grid.moves())
      return;
    scene.update_moving_refinement(t_begin);
    forget_mu_of_other_marking();
  }


  template <int dim>
  void
  MaterialPointModel<dim>::forget_mu_of_other_marking()
  {
    if (scene.grid.moving_marked == mu_marking)
      return;
    mu_coefficients.assign(scene.spaces->n_mu_control_points(), scene.material.mu_0());
    mu_known.assign(mu_coefficients.size(), false);
    mu_marking = scene.grid.moving_marked;
  }


  template <int dim>
  bool
  MaterialPointModel<dim>::reset_grid()
  {
    const auto new_pattern = [this] {
      return scene.system->setup(scene.particles, [this] {
        linear_solver.new_pattern();
      });
    };
    bool changed = false;
    try
      {
        changed = new_pattern();
      }
    catch (const InputError &)
      {
        // A moving refinement can leave a refined region at the body's boundary thinner than
        // the extension needs (a front's last cells at a corner): the step keeps the marking of
        // the last one, which the extension accepted, and says so at the end of the run.
        if (!scene.keep_last_marking())
          throw;
        ++n_kept_markings;
        forget_mu_of_other_marking();
        changed = new_pattern();
      }
    return keep_within_budget() || changed;
  }


  template <int dim>
  bool
  MaterialPointModel<dim>::keep_within_budget()
  {
    const unsigned long budget = scene.grid.refinement_budget;
    if (budget == 0 || scene.spaces->n_dofs() <= budget)
      return false;
    // Coarser levels first dropped would leave finer marks without parents: the finest go.
    bool dropped = false;
    while (scene.spaces->n_dofs() > budget && scene.coarsen_moving_refinement())
      {
        dropped = true;
        forget_mu_of_other_marking();
        scene.system->setup(scene.particles, [this] {
          linear_solver.new_pattern();
        });
      }
    // A body that has grown beyond the budget on the grid without moving refinement goes on
    // there: the budget limits the refinement, not the run (counted at the end).
    n_budget_limited += dropped;
    n_over_budget += scene.spaces->n_dofs() > budget;
    return dropped;
  }


  template <int dim>
  NewtonSystem &
  MaterialPointModel<dim>::system()
  {
    return *scene.system;
  }


  template <int dim>
  void
  MaterialPointModel<dim>::begin_step(const double last_dt, const double t_begin)
  {
    dealii::TimerOutput::Scope scope(timer, "grid reset");
    follow_surface(t_begin);
    // A grid reset that changes the classification gives the tangent a new sparsity pattern;
    // the factorisation of the old one goes first, while the matrix it refers to still exists.
    // Otherwise it stays, and Newton may start from it (modified Newton).
    if (reset_grid())
      ++n_new_patterns;
    if (linear_solver.may_iterate())
      {
        std::vector<NestedBSplineLevel> levels;
        // On several ranks the iterative solver has the algebraic multigrid only; so has a step
        // whose faces have copies of functions, and a locally refined grid: the uniform grids'
        // levels know neither the copies nor the hierarchy's leaves.
        if (linear_solver.geometric_multigrid() && !Collective::is_parallel(scene.communicator) &&
            scene.spaces->u_copies().empty() && !scene.spaces->refined())
          {
            // The 1D refinement operators are fixed with the grid: computed once per space.
            if (!nested_grids || &nested_grids->fine_space() != &scene.spaces->u_space())
              nested_grids = std::make_unique<NestedBSplineGrids<dim>>(scene.spaces->u_space());
            levels = nested_grids->levels(scene.spaces->u());
          }
        linear_solver.set_block_structure(scene.spaces->n_u_dofs(),
                                          dim,
                                          scene.spaces->u_dof_greville_points(),
                                          levels);
      }
    if (!resumed_tangent.empty())
      {
        if (scene.system->restore_tangent(resumed_classification, resumed_tangent))
          linear_solver.factorize(scene.system->matrix());
        resumed_tangent.clear();
        resumed_classification.clear();
      }
    // The points and the basis are fixed for the attempts of the step: project mu once, and only
    // if some coefficient will start from it.
    bool needed = newton.mu_from_points;
    for (unsigned int i = 0; i < mu_known.size() && !needed; ++i)
      needed = !mu_known[i] &&
               scene.spaces->mu().dof_of_control_point(i) != dealii::numbers::invalid_unsigned_int;
    mu_projection           = needed ? scene.system->mu_from_points() : std::vector<double>();
    displacement_projection = (newton.extrapolate_displacement && last_dt > 0.)
                                ? scene.system->displacement_from_points(1.)
                                : std::vector<double>();
  }


  template <int dim>
  void
  MaterialPointModel<dim>::prepare_attempt(const double            t_begin,
                                           const double            dt,
                                           const double            last_dt,
                                           dealii::Vector<double> &solution)
  {
    scene.system->set_boundary_values(t_begin + dt, t_begin);
    initial_guess(solution, dt, last_dt);
  }


  template <int dim>
  void
  MaterialPointModel<dim>::initial_guess(dealii::Vector<double> &solution,
                                         const double            dt,
                                         const double            last_dt) const
  {
    solution.reinit(scene.spaces->n_dofs());
    if (!displacement_projection.empty() && last_dt > 0.)
      for (unsigned int i = 0; i < displacement_projection.size(); ++i)
        solution(i) = dt / last_dt * displacement_projection[i];
    const auto        &mu  = scene.spaces->mu();
    const unsigned int n_u = scene.spaces->n_u_dofs();
    // With 'Newton/Initial chemical potential = points' every coefficient starts from the
    // projection of the points' mu; otherwise only those that held no value in the last step
    // (newly covered by material), where a stale coefficient would put a stress jump into the
    // first residual that short (undrained) steps cannot absorb.
    const std::vector<double> &from_points     = mu_projection;
    const bool                 all_from_points = newton.mu_from_points && !from_points.empty();
    for (unsigned int i = 0; i < mu_coefficients.size(); ++i)
      {
        const unsigned int dof = mu.dof_of_control_point(i);
        if (dof != dealii::numbers::invalid_unsigned_int)
          solution(n_u + dof) = (all_from_points || (!mu_known[i] && !from_points.empty()))
                                  ? from_points[dof]
                                  : mu_coefficients[i];
      }
    scene.system->hold_axis(solution);
  }


  template <int dim>
  bool
  MaterialPointModel<dim>::estimates_errors() const
  {
    return true;
  }


  template <int dim>
  std::string
  MaterialPointModel<dim>::refusal(const dealii::Vector<double> &solution) const
  {
    if (!scene.contact.self_contact.retake_unseen_passes)
      return {};
    const unsigned int unseen = scene.system->unseen_self_contacts(solution);
    if (unseen == 0)
      return {};
    return std::to_string(unseen) +
           " surface point(s) passed through the gel's own surface where the step's "
           "self-contact pairs did not reach";
  }


  template <int dim>
  double
  MaterialPointModel<dim>::largest_motion_in_cells(const dealii::Vector<double> &solution) const
  {
    // In cells of the background grid as the scene gives it ('Background grid/Cells'), also on
    // a refined grid: refinement resolves the fields more finely, it does not shorten the steps
    // a body may take (in finest cells the self-contact blocks' step of 2.5 cells was 5.04 and
    // cut).
    return scene.system->largest_displacement_increment(solution) / scene.spaces->h_u(0);
  }


  template <int dim>
  bool
  MaterialPointModel<dim>::measures_rate_of_change() const
  {
    return true;
  }


  template <int dim>
  double
  MaterialPointModel<dim>::rate_of_change(const dealii::Vector<double> &solution,
                                          const double                  dt) const
  {
    // The volume ratio says how far the solvent is from its balance, the motion whether a body
    // at constant volume (a buckled column, a bending strip) still moves.
    const double volume_change = scene.system->largest_volume_change(solution);
    const double motion =
      scene.system->largest_displacement_increment(solution) / characteristic_length;
    return std::max(volume_change, motion) / dt;
  }


  template <int dim>
  typename MaterialPointModel<dim>::StepBound
  MaterialPointModel<dim>::bound_step(const double t_begin, const double dt) const
  {
    const double largest = Obstacle<dim>::largest_travel_in_cells * scene.spaces->h_u();
    StepBound    bound{dt, ""};
    for (const auto &obstacle : scene.obstacles)
      // A uniform motion meets the bound at once; a varying one within a few rounds, each
      // shortening the step by at least 1 %.
      for (double moved;
           (moved = obstacle.travel(t_begin, t_begin + bound.dt)) > largest * (1. + 1e-9);)
        {
          std::ostringstream reason;
          reason << "the obstacle '" << obstacle.name << "' would travel " << moved
                 << " in it, more than " << Obstacle<dim>::largest_travel_in_cells
                 << " cells of the grid (" << largest << "), where contact could miss it";
          bound.reason = reason.str();
          bound.dt *= std::clamp(largest / moved, 1e-3, 0.99);
          if (bound.dt < 1e-300)
            break;
        }
    return bound;
  }


  template <int dim>
  double
  MaterialPointModel<dim>::increment_deviation(const dealii::Vector<double> &solution,
                                               const double                  ratio) const
  {
    return scene.system->largest_increment_deviation(solution, ratio);
  }


  template <int dim>
  double
  MaterialPointModel<dim>::local_error(const dealii::Vector<double> &solution,
                                       const double                  ratio,
                                       const bool                    largest) const
  {
    const auto error = scene.system->local_error_estimate(solution, ratio, largest);
    return std::max(error.displacement / characteristic_length, error.chemical_potential);
  }


  template <int dim>
  void
  MaterialPointModel<dim>::update(const dealii::Vector<double> &solution, const double t_end)
  {
    dealii::TimerOutput::Scope scope(timer, "update");
    const auto                 n_before = scene.particles.n_global_particles();
    count_unseen_passes(solution);
    try
      {
        scene.system->update_particles(solution);
      }
    catch (const std::runtime_error &e)
      {
        std::ostringstream when;
        when << "at t/tau_d = " << t_end << ", " << e.what();
        throw std::runtime_error(when.str());
      }
    sort_into_cells(scene.particles, scene.grid, *scene.triangulation);
    // The body moves and changes the points per rank: partition the grid anew when the most
    // loaded rank holds much more than its share (its time sets the step's). The partition cannot
    // split a cell: where whole cells leave an imbalance, the run waits until the imbalance has
    // grown beyond what the last partition left.
    const double imbalance = scene.imbalance();
    if (imbalance > std::max(largest_imbalance, 1.05 * imbalance_after_partition))
      {
        scene.balance_partition();
        imbalance_after_partition = scene.imbalance();
        ++n_repartitions;
      }
    if (scene.particles.n_global_particles() != n_before)
      throw std::runtime_error(
        std::to_string(n_before - scene.particles.n_global_particles()) +
        " material point(s) left the background grid at t = " + std::to_string(t_end) +
        " tau_d; enlarge the grid ('Background grid/Upper corner')");
    store_mu_coefficients(solution);
  }


  template <int dim>
  void
  MaterialPointModel<dim>::store_mu_coefficients(const dealii::Vector<double> &solution)
  {
    const auto        &mu  = scene.spaces->mu();
    const unsigned int n_u = scene.spaces->n_u_dofs();
    for (unsigned int i = 0; i < mu_coefficients.size(); ++i)
      {
        const unsigned int dof = mu.dof_of_control_point(i);
        mu_known[i]            = true;
        if (dof != dealii::numbers::invalid_unsigned_int)
          mu_coefficients[i] = solution(n_u + dof);
        else if (mu.control_point_kind(i) == ControlPointKind::boundary)
          {
            double value = 0.;
            for (const auto &[interior, weight] : mu.extrapolation_weights(i))
              value += weight * solution(n_u + mu.dof_of_control_point(interior));
            mu_coefficients[i] = value;
          }
        else
          mu_known[i] = false;
      }
  }


  template <int dim>
  int
  MaterialPointModel<dim>::stop_signal() const
  {
    // A signal reaches the ranks at different moments: they stop together, at the first point
    // where any of them has it.
    return dealii::Utilities::MPI::max(GelMPM::stop_signal(), scene.communicator);
  }


  template <int dim>
  void
  MaterialPointModel<dim>::restore_factorization(const std::vector<bool> &classification,
                                                 const SparseEntries     &tangent)
  {
    resumed_classification = classification;
    resumed_tangent        = tangent;
  }


  template <int dim>
  unsigned long
  MaterialPointModel<dim>::kept_markings() const
  {
    return n_kept_markings;
  }


  template <int dim>
  unsigned long
  MaterialPointModel<dim>::budget_limited_steps() const
  {
    return n_budget_limited;
  }


  template <int dim>
  void
  MaterialPointModel<dim>::count_unseen_passes(const dealii::Vector<double> &solution)
  {
    if (!scene.contact.self_contact.enabled() || scene.contact.self_contact.retake_unseen_passes)
      return;
    const unsigned int unseen = scene.system->unseen_self_contacts(solution);
    n_unseen_steps += unseen > 0;
    n_unseen_points += unseen;
  }


  template <int dim>
  std::pair<unsigned long, unsigned long>
  MaterialPointModel<dim>::unseen_passes() const
  {
    return {n_unseen_steps, n_unseen_points};
  }


  template <int dim>
  unsigned long
  MaterialPointModel<dim>::steps_over_budget() const
  {
    return n_over_budget;
  }


  template <int dim>
  unsigned long
  MaterialPointModel<dim>::new_patterns() const
  {
    return n_new_patterns;
  }


  template <int dim>
  unsigned long
  MaterialPointModel<dim>::repartitions() const
  {
    return n_repartitions;
  }


  template class MaterialPointModel<2>;
  template class MaterialPointModel<3>;
} // namespace GelMPM

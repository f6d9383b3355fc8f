#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/core/input_error.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace GelMPM
{
  std::string
  DiscretisationSettings::name() const
  {
    return "Q" + std::to_string(displacement_degree) + "-Q" +
           std::to_string(chemical_potential_degree) + (subdivision ? "SD" : "");
  }


  void
  DiscretisationSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Discretisation");
    prm.declare_entry("Displacement degree",
                      "2",
                      Patterns::Integer(1, 6),
                      "Degree q_u of the maximally smooth B-splines for the displacement, on the "
                      "background grid (cell size h).");
    prm.declare_entry("Chemical potential degree",
                      "2",
                      Patterns::Integer(1, 6),
                      "Degree q_mu of the maximally smooth B-splines for the chemical potential.");
    prm.declare_entry("Chemical potential grid",
                      "coarse",
                      Patterns::Selection("coarse|same"),
                      "'coarse': mu on the grid of cell size 2h (subdivision stabilisation, the "
                      "paper's QiQjSD pairs, inf-sup stable; needs an even number of background "
                      "cells in every direction). 'same': mu on the background grid (Qi-Qj; Q2-Q2 "
                      "and Q3-Q2 are not inf-sup stable, kept for comparison).");
    prm.declare_entry("Extended B-splines",
                      "true",
                      Patterns::Bool(),
                      "Extrapolate the coefficients of boundary control points from interior ones "
                      "(paper eq. (50)-(54)) so that cut cells do not make the tangent "
                      "ill-conditioned. Switch off only to study the conditioning without it.");
    prm.leave_subsection();
  }


  void
  DiscretisationSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Discretisation");
    displacement_degree       = prm.get_integer("Displacement degree");
    chemical_potential_degree = prm.get_integer("Chemical potential degree");
    subdivision               = (prm.get("Chemical potential grid") == "coarse");
    extension                 = prm.get_bool("Extended B-splines");
    prm.leave_subsection();
  }


  unsigned int
  DiscretisationSettings::support_reach_in_pair_cells() const
  {
    const unsigned int u_reach = (displacement_degree + 1) / 2;
    const unsigned int mu_reach =
      subdivision ? chemical_potential_degree : (chemical_potential_degree + 1) / 2;
    return std::max(u_reach, mu_reach);
  }


  namespace
  {
    template <int dim>
    double
    smallest_cell_size(const BSplineSpace<dim> &space)
    {
      double h = space.cell_size(0);
      for (unsigned int d = 1; d < dim; ++d)
        h = std::min(h, space.cell_size(d));
      return h;
    }


    template <int dim>
    std::array<unsigned int, dim>
    mu_cells(const BackgroundGrid<dim> &grid, const bool subdivision)
    {
      std::array<unsigned int, dim> n = grid.n_cells;
      if (subdivision)
        for (unsigned int d = 0; d < dim; ++d)
          {
            require(n[d] % 2 == 0,
                    "Background grid/Cells",
                    "has an odd count (" + std::to_string(n[d]) + ") in direction " +
                      std::to_string(d) +
                      ", but 'Discretisation/Chemical potential grid = coarse' "
                      "puts mu on cells twice as large",
                    "use an even number of cells in every direction, or 'same'");
            n[d] /= 2;
          }
      return n;
    }
  } // namespace


  template <int dim>
  DiscreteSpaces<dim>::DiscreteSpaces(const BackgroundGrid<dim>    &grid,
                                      const DiscretisationSettings &settings)
    : settings_(settings)
    , u_space_(settings.displacement_degree, grid.lower, grid.upper, grid.n_cells)
    , mu_space_(settings.chemical_potential_degree,
                grid.lower,
                grid.upper,
                mu_cells(grid, settings.subdivision))
    , axisymmetric_(grid.axisymmetric)
  {
    // A body of revolution that reaches the axis is cut next to it, within the first q cells
    // of the grid, wherever its surface meets the axis (the poles of a sphere): there the
    // extrapolation of the extended B-splines is not exact (doc/axisymmetric.md).
    if (axisymmetric_)
      inexact_extrapolation_tolerated = true;
    if (grid.refined())
      {
        refinement_entry_ = grid.refinement_entry();
        graded_           = !grid.graded_marked.empty();
        build_hierarchies(grid);
      }
  }


  template <int dim>
  void
  DiscreteSpaces<dim>::build_hierarchies(const BackgroundGrid<dim> &grid)
  {
    // The marking is made on the grid of cell pairs (BackgroundGrid::refined_pair_cells()),
    // which is mu's grid with subdivision; u's refined cells are their halves.
    std::array<unsigned int, dim> pairs;
    for (unsigned int d = 0; d < dim; ++d)
      pairs[d] = grid.n_cells[d] / 2;
    const auto pair_cells = grid.refined_pair_cells();
    auto       pair_hierarchy =
      std::make_unique<HierarchicalBSplineSpace<dim>>(settings_.chemical_potential_degree,
                                                      grid.lower,
                                                      grid.upper,
                                                      pairs,
                                                      pair_cells);
    const auto u_cells = subdivision_refinement(*pair_hierarchy);
    u_hierarchy_ = std::make_unique<HierarchicalBSplineSpace<dim>>(settings_.displacement_degree,
                                                                   grid.lower,
                                                                   grid.upper,
                                                                   grid.n_cells,
                                                                   u_cells);
    if (settings_.subdivision)
      mu_hierarchy_ = std::move(pair_hierarchy);
    else
      mu_hierarchy_ =
        std::make_unique<HierarchicalBSplineSpace<dim>>(settings_.chemical_potential_degree,
                                                        grid.lower,
                                                        grid.upper,
                                                        grid.n_cells,
                                                        u_cells);
  }


  template <int dim>
  void
  DiscreteSpaces<dim>::rebuild_hierarchies(const BackgroundGrid<dim> &grid)
  {
    graded_ = !grid.graded_marked.empty();
    build_hierarchies(grid);
    // The extended spaces belong to the old hierarchies: the next reinit() builds them anew.
    u_.reset();
    mu_.reset();
    u_leaf_has_material_.clear();
  }


  template <int dim>
  bool
  DiscreteSpaces<dim>::refined() const
  {
    return u_hierarchy_ != nullptr;
  }


  template <int dim>
  const HierarchicalBSplineSpace<dim> &
  DiscreteSpaces<dim>::u_hierarchy() const
  {
    return *u_hierarchy_;
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::n_mu_control_points() const
  {
    return refined() ? mu_hierarchy_->n_active_functions() : mu_space_.n_functions();
  }


  template <int dim>
  bool
  DiscreteSpaces<dim>::axisymmetric() const
  {
    return axisymmetric_;
  }


  template <int dim>
  std::vector<dealii::types::global_dof_index>
  DiscreteSpaces<dim>::axis_unknowns() const
  {
    std::vector<dealii::types::global_dof_index> unknowns;
    if (!axisymmetric_)
      return unknowns;
    for_each_u_dof_function(
      [&](const unsigned int dof, const BSplineSpace<dim> &, const auto &index) {
        if (index[0] == 0)
          unknowns.push_back(dim * dof);
      });
    std::sort(unknowns.begin(), unknowns.end());
    return unknowns;
  }


  template <int dim>
  bool
  DiscreteSpaces<dim>::reinit(const std::vector<bool> &u_cell_has_material,
                              const std::vector<bool> &u_leaf_has_material)
  {
    if (!refined())
      return reinit(u_cell_has_material);
    if (u_ && mu_ && u_cell_has_material == u_cell_has_material_ &&
        u_leaf_has_material == u_leaf_has_material_)
      return false;
    u_cell_has_material_ = u_cell_has_material;
    u_leaf_has_material_ = u_leaf_has_material;
    std::vector<bool> mu_has_material(mu_space_.n_cells(), false);
    for (unsigned int c = 0; c < u_cell_has_material.size(); ++c)
      if (u_cell_has_material[c])
        mu_has_material[mu_cell_of(c)] = true;
    // A u leaf lies in the mu leaf of its centre (mu is one level coarser, or the same grid).
    std::vector<bool> mu_leaf_has_material(mu_hierarchy_->n_leaf_cells(), false);
    for (unsigned int leaf = 0; leaf < u_leaf_has_material.size(); ++leaf)
      if (u_leaf_has_material[leaf])
        {
          const auto &[level, cell] = u_hierarchy_->leaf_cell(leaf);
          const auto        &space  = u_hierarchy_->level_space(level);
          const auto         index  = space.cell_multi_index(cell);
          dealii::Point<dim> centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = space.basis_1d(d).x_min() + (index[d] + 0.5) * space.cell_size(d);
          mu_leaf_has_material[mu_hierarchy_->leaf_cell_containing(centre)] = true;
        }
    try
      {
        u_copies_.clear();
        u_  = std::make_unique<ExtendedBSplineSpace<dim>>(*u_hierarchy_,
                                                         u_cell_has_material,
                                                         u_leaf_has_material,
                                                         settings_.extension,
                                                         !inexact_extrapolation_tolerated);
        mu_ = std::make_unique<ExtendedBSplineSpace<dim>>(*mu_hierarchy_,
                                                          mu_has_material,
                                                          mu_leaf_has_material,
                                                          settings_.extension,
                                                          !inexact_extrapolation_tolerated);
      }
    catch (const std::runtime_error &e)
      {
        u_.reset();
        mu_.reset();
        const bool by_mu = refinement_entry_ == "Background grid/Refinement mu range" ||
                           refinement_entry_ == "Background grid/Refinement mu gradient jump";
        // Grading widens the coarser levels' domains, which may then leave too little of a
        // level inside the body: the user's own domains may be fine.
        const std::string ungraded =
          graded_ ? " (or set 'Background grid/Refinement grading = false': grading widened "
                    "the coarser levels)"
                  : "";
        throw InputError(refinement_entry_,
                         std::string("refines a region that the extended B-splines cannot "
                                     "extrapolate into (") +
                           e.what() + ")",
                         (refinement_entry_ == "Background grid/Refinement band"
                            ? "widen the band so that it reaches at least 2(q+1) cells of its "
                              "finest level into the body (the chemical potential's cells are "
                              "twice as large), or set 'Discretisation/Extended B-splines = "
                              "false'"
                          : by_mu
                            ? "refine the body's boundary there by a box or a band that reaches "
                              "2(q+1) cells of its finest level into the body as well, or set "
                              "'Discretisation/Extended B-splines = false'"
                            : "let a box (or 'Refinement region') that reaches the body's "
                              "boundary extend at least 2(q+1) cells of its finest level into "
                              "the body (also as it deforms; the chemical potential's cells are "
                              "twice as large), or set 'Discretisation/Extended B-splines = "
                              "false'") +
                           ungraded);
      }
    return true;
  }


  template <int dim>
  bool
  DiscreteSpaces<dim>::reinit(const std::vector<bool> &u_cell_has_material)
  {
    if (refined())
      {
        // Without the points' leaves (the grid output before the first step): a leaf holds
        // material when its base cell does.
        std::vector<bool> leaf_has_material(u_hierarchy_->n_leaf_cells());
        for (unsigned int leaf = 0; leaf < leaf_has_material.size(); ++leaf)
          {
            const auto &[level, cell] = u_hierarchy_->leaf_cell(leaf);
            auto index                = u_hierarchy_->level_space(level).cell_multi_index(cell);
            for (auto &i : index)
              i >>= level;
            leaf_has_material[leaf] = u_cell_has_material[u_space_.cell_index(index)];
          }
        return reinit(u_cell_has_material, leaf_has_material);
      }
    if (u_ && mu_ && u_cell_has_material == u_cell_has_material_ &&
        built_tolerating_inexact_extrapolation == inexact_extrapolation_tolerated)
      return false;
    u_cell_has_material_                   = u_cell_has_material;
    built_tolerating_inexact_extrapolation = inexact_extrapolation_tolerated;
    std::vector<bool> mu_has_material(mu_space_.n_cells(), false);
    for (unsigned int c = 0; c < u_cell_has_material.size(); ++c)
      if (u_cell_has_material[c])
        mu_has_material[mu_cell_of(c)] = true;
    u_copies_.clear();
    u_  = std::make_unique<ExtendedBSplineSpace<dim>>(u_space_,
                                                     u_cell_has_material,
                                                     settings_.extension,
                                                     !inexact_extrapolation_tolerated);
    mu_ = std::make_unique<ExtendedBSplineSpace<dim>>(mu_space_,
                                                      mu_has_material,
                                                      settings_.extension,
                                                      !inexact_extrapolation_tolerated);
    return true;
  }


  template <int dim>
  void
  DiscreteSpaces<dim>::tolerate_inexact_extrapolation()
  {
    inexact_extrapolation_tolerated = true;
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::n_inexact_extrapolations() const
  {
    return (u_ ? u_->n_inexact_extrapolations() : 0) + (mu_ ? mu_->n_inexact_extrapolations() : 0);
  }


  template <int dim>
  const BSplineSpace<dim> &
  DiscreteSpaces<dim>::u_space() const
  {
    return u_space_;
  }


  template <int dim>
  const BSplineSpace<dim> &
  DiscreteSpaces<dim>::mu_space() const
  {
    return mu_space_;
  }


  template <int dim>
  const ExtendedBSplineSpace<dim> &
  DiscreteSpaces<dim>::u() const
  {
    return *u_;
  }


  template <int dim>
  const ExtendedBSplineSpace<dim> &
  DiscreteSpaces<dim>::mu() const
  {
    return *mu_;
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::mu_cell_of(const unsigned int u_cell) const
  {
    if (!settings_.subdivision)
      return u_cell;
    // mu cells are numbered like u cells (x fastest), with half as many per direction.
    auto index = u_space_.cell_multi_index(u_cell);
    for (auto &i : index)
      i /= 2;
    return mu_space_.cell_index(index);
  }


  template <int dim>
  template <typename F>
  void
  DiscreteSpaces<dim>::for_each_u_dof_function(const F &f) const
  {
    const unsigned int n = refined() ? u_hierarchy_->n_active_functions() : u_space_.n_functions();
    // A copy of a function (set_u_copies()) is the same function for other points.
    std::vector<unsigned int> control_point_of(u_->n_dofs(), 0);
    const auto                call = [&](const unsigned int dof, const unsigned int i) {
      if (!refined())
        {
          f(dof, u_space_, u_space_.function_multi_index(i));
          return;
        }
      const auto &[level, function] = u_hierarchy_->active_function(i);
      const auto &space             = u_hierarchy_->level_space(level);
      f(dof, space, space.function_multi_index(function));
    };
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int dof = u_->dof_of_control_point(i);
        if (dof == dealii::numbers::invalid_unsigned_int)
          continue;
        control_point_of[dof] = i;
        call(dof, i);
      }
    for (unsigned int k = 0; k < u_copies_.size(); ++k)
      call(u_->n_dofs() + k, control_point_of[u_copies_[k]]);
  }


  template <int dim>
  bool
  DiscreteSpaces<dim>::set_u_copies(std::vector<unsigned int> copy_of)
  {
    const bool changed = copy_of != u_copies_;
    u_copies_          = std::move(copy_of);
    return changed;
  }


  template <int dim>
  const std::vector<unsigned int> &
  DiscreteSpaces<dim>::u_copies() const
  {
    return u_copies_;
  }


  template <int dim>
  std::vector<double>
  DiscreteSpaces<dim>::u_dof_greville_points() const
  {
    std::vector<double> points(n_u_dofs(), 0.);
    for_each_u_dof_function(
      [&](const unsigned int dof, const BSplineSpace<dim> &space, const auto &index) {
        for (unsigned int d = 0; d < dim; ++d)
          points[dim * dof + d] = space.basis_1d(d).greville(index[d]);
      });
    return points;
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::n_u_dofs() const
  {
    return dim * (u_->n_dofs() + u_copies_.size());
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::n_mu_dofs() const
  {
    return mu_->n_dofs();
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::n_dofs() const
  {
    return n_u_dofs() + n_mu_dofs();
  }


  template <int dim>
  double
  DiscreteSpaces<dim>::h_u() const
  {
    return h_u(refined() ? u_hierarchy_->n_levels() - 1 : 0);
  }


  template <int dim>
  double
  DiscreteSpaces<dim>::h_u(const unsigned int level) const
  {
    if (refined())
      return smallest_cell_size(u_hierarchy_->level_space(level));
    return smallest_cell_size(u_space_);
  }


  template <int dim>
  double
  DiscreteSpaces<dim>::h_mu(const unsigned int level) const
  {
    if (refined())
      return smallest_cell_size(mu_hierarchy_->level_space(level));
    return smallest_cell_size(mu_space_);
  }


  template <int dim>
  double
  DiscreteSpaces<dim>::h_mu() const
  {
    return h_mu(refined() ? mu_hierarchy_->n_levels() - 1 : 0);
  }


  template <int dim>
  unsigned int
  DiscreteSpaces<dim>::active_u_cell_containing(const dealii::Point<dim> &p) const
  {
    const unsigned int home = u_space_.cell_containing(p);
    if (u_cell_has_material_[home])
      return home;

    // Surface points lie on the boundary of the body, which may run along a face of, or
    // slightly outside, the cells that hold volume points (the body swells between
    // classifications). Evaluate them in the nearest neighbouring cell with material: its
    // polynomial pieces continue the (extended) field smoothly there.
    const auto   home_index = u_space_.cell_multi_index(home);
    unsigned int best       = dealii::numbers::invalid_unsigned_int;
    double       best_gap   = std::numeric_limits<double>::max();
    for (unsigned int neighbour = 0; neighbour < std::pow(3, dim); ++neighbour)
      {
        std::array<unsigned int, dim> index;
        bool                          valid = true;
        double                        gap   = 0.;
        unsigned int                  rest  = neighbour;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const int offset = static_cast<int>(rest % 3) - 1;
            rest /= 3;
            const int i = static_cast<int>(home_index[d]) + offset;
            if (i < 0 || i >= static_cast<int>(u_space_.n_cells_per_direction()[d]))
              {
                valid = false;
                break;
              }
            index[d]             = i;
            const auto  &basis   = u_space_.basis_1d(d);
            const double lower   = basis.x_min() + i * basis.cell_size();
            const double outside = std::max({0., lower - p[d], p[d] - (lower + basis.cell_size())});
            gap += outside * outside;
          }
        if (!valid)
          continue;
        const unsigned int cell = u_space_.cell_index(index);
        if (u_cell_has_material_[cell] && gap < best_gap)
          {
            best     = cell;
            best_gap = gap;
          }
      }
    return best;
  }


  template <int dim>
  const DiscretisationSettings &
  DiscreteSpaces<dim>::settings() const
  {
    return settings_;
  }


  template class DiscreteSpaces<2>;
  template class DiscreteSpaces<3>;
} // namespace GelMPM

#include <gelmpm/io/grid_output.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/numerics/data_out.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  GridOutput<dim>::GridOutput(const std::string                &directory,
                              const dealii::Triangulation<dim> &triangulation,
                              const std::string                &basename)
    : fe(dealii::FE_DGQ<dim>(1), dim + 1)
    , dof_handler(triangulation)
    , series(directory, basename, triangulation.get_communicator())
  {
    dof_handler.distribute_dofs(fe);
  }


  template <int dim>
  std::vector<unsigned int>
  GridOutput<dim>::count_volume_points(const dealii::Particles::ParticleHandler<dim> &particles,
                                       const BSplineSpace<dim>                       &space)
  {
    std::vector<unsigned int> count(space.n_cells(), 0);
    for (const auto &particle : particles)
      if (kind_of(particle.get_properties()) == PointKind::volume)
        ++count[space.cell_containing(particle.get_location())];
    return count;
  }


  template <int dim>
  void
  GridOutput<dim>::record(const ExtendedBSplineSpace<dim> &u,
                          const ExtendedBSplineSpace<dim> &mu,
                          const std::vector<unsigned int> &volume_points,
                          const dealii::Vector<double>    &solution)
  {
    const unsigned int n_cells = dof_handler.get_triangulation().n_active_cells();
    if (u.space().n_cells() != n_cells || volume_points.size() != n_cells ||
        solution.size() < dim * u.n_dofs() + mu.n_dofs())
      throw std::logic_error("GridOutput::record: the spaces, point counts and solution do not "
                             "match the background grid");

    u_cell_kind.reinit(n_cells);
    mu_cell_kind.reinit(n_cells);
    n_volume_points.reinit(n_cells);
    refinement_level.reinit(u.refined() ? n_cells : 0);
    vertex_values.reinit(dof_handler.n_dofs());
    vertex_values = std::numeric_limits<double>::quiet_NaN();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        // On several ranks each writes the cells it owns.
        if (!cell->is_locally_owned())
          continue;
        const unsigned int c    = cell->active_cell_index();
        const unsigned int mu_c = mu.space().cell_containing(cell->center());
        u_cell_kind(c)          = static_cast<double>(u.cell_kind(c));
        mu_cell_kind(c)         = static_cast<double>(mu.cell_kind(mu_c));
        n_volume_points(c)      = volume_points[c];
        if (u.refined())
          refinement_level(c) = u.finest_level(c);
        if (u.cell_kind(c) != CellKind::outer)
          evaluate_vertices(cell, u, mu, solution);
      }
    recorded = true;
  }


  template <int dim>
  void
  GridOutput<dim>::evaluate_vertices(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    const ExtendedBSplineSpace<dim>                              &u,
    const ExtendedBSplineSpace<dim>                              &mu,
    const dealii::Vector<double>                                 &solution)
  {
    const unsigned int c      = cell->active_cell_index();
    const unsigned int mu_c   = mu.space().cell_containing(cell->center());
    const bool         has_mu = mu.cell_kind(mu_c) != CellKind::outer;
    // Copies of u functions (DiscreteSpaces::set_u_copies()) lie between u's DoFs and mu's.
    const unsigned int n_u = solution.size() - mu.n_dofs();

    const auto         &u_dofs  = u.cell_dofs(c);
    const auto         &mu_dofs = has_mu ? mu.cell_dofs(mu_c) : std::vector<unsigned int>();
    std::vector<double> u_values(u_dofs.size()), mu_values(mu_dofs.size());
    std::vector<dealii::Tensor<1, dim>> u_gradients(u_dofs.size()), mu_gradients(mu_dofs.size());
    std::vector<double>                 u_scratch(u.space().functions_per_cell());
    std::vector<dealii::Tensor<1, dim>> u_scratch_gradients(u.space().functions_per_cell());
    std::vector<double>                 mu_scratch(mu.space().functions_per_cell());
    std::vector<dealii::Tensor<1, dim>> mu_scratch_gradients(mu.space().functions_per_cell());

    // The cells are axis-parallel boxes: vertex 0 is the lower corner, the last the upper one.
    const dealii::Point<dim> lower = cell->vertex(0);
    const dealii::Point<dim> upper = cell->vertex(dealii::GeometryInfo<dim>::vertices_per_cell - 1);
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(dofs);

    const auto &base = fe.base_element(0);
    for (unsigned int v = 0; v < base.n_dofs_per_cell(); ++v)
      {
        const dealii::Point<dim> unit = base.unit_support_point(v);
        dealii::Point<dim>       p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = lower[d] + unit[d] * (upper[d] - lower[d]);

        u.evaluate(p, c, u_values, u_gradients, u_scratch, u_scratch_gradients);
        for (unsigned int comp = 0; comp < dim; ++comp)
          {
            double value = 0.;
            for (unsigned int j = 0; j < u_dofs.size(); ++j)
              value += u_values[j] * solution(dim * u_dofs[j] + comp);
            vertex_values(dofs[fe.component_to_system_index(comp, v)]) = value;
          }
        if (has_mu)
          {
            mu.evaluate(p, mu_c, mu_values, mu_gradients, mu_scratch, mu_scratch_gradients);
            double value = 0.;
            for (unsigned int j = 0; j < mu_dofs.size(); ++j)
              value += mu_values[j] * solution(n_u + mu_dofs[j]);
            vertex_values(dofs[fe.component_to_system_index(dim, v)]) = value;
          }
      }
  }


  template <int dim>
  void
  GridOutput<dim>::write(const double time)
  {
    using namespace dealii;
    if (!recorded)
      throw std::logic_error("GridOutput::write: nothing recorded yet");

    std::vector<std::string> names(dim, "displacement_increment");
    names.emplace_back("mu_over_kT");
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim,
      DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(vertex_values, names, DataOut<dim>::type_dof_data, interpretation);
    data_out.add_data_vector(u_cell_kind, "u_cell_kind", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(mu_cell_kind, "mu_cell_kind", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(n_volume_points, "n_volume_points", DataOut<dim>::type_cell_data);
    if (refinement_level.size() == n_volume_points.size())
      data_out.add_data_vector(refinement_level, "refinement_level", DataOut<dim>::type_cell_data);
    data_out.build_patches();

    DataOutBase::VtkFlags flags;
    flags.time              = time;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    series.write(
      time,
      [&](std::ostream &out) {
        data_out.write_vtu(out);
      },
      [&](std::ostream &out, const std::vector<std::string> &pieces) {
        data_out.write_pvtu_record(out, pieces);
      });
  }


  template <int dim>
  const std::vector<std::pair<double, std::string>> &
  GridOutput<dim>::times_and_names() const
  {
    return series.times_and_names();
  }


  template class GridOutput<2>;
  template class GridOutput<3>;
} // namespace GelMPM

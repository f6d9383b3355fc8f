#include <gelmpm/fem/fem_mixed_system.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  using dealii::Tensor;

  namespace
  {
    template <int dim>
    const FloryRehnerGel<dim> &
    first_material(const std::vector<FloryRehnerGel<dim>> &materials)
    {
      if (materials.empty())
        throw std::invalid_argument("FemMixedSystem: no material given");
      return materials.front();
    }
  } // namespace

  template <int dim>
  FemMixedSystem<dim>::FemMixedSystem(const FloryRehnerGel<dim>        &material,
                                      const dealii::Triangulation<dim> &triangulation,
                                      const unsigned int                u_degree,
                                      const Formulation                 formulation)
    : materials{&material}
    , triangulation(triangulation)
    , formulation(formulation)
    , fe(dealii::FE_Q<dim>(u_degree < 2 ? 2 : u_degree),
         dim,
         dealii::FE_Q<dim>(u_degree < 2 ? 1 : u_degree - 1),
         1)
    , dof_handler_(triangulation)
  {
    if (u_degree < 2)
      throw std::invalid_argument("FemMixedSystem: the displacement degree must be at least 2 "
                                  "(Taylor-Hood Q_k^dim - Q_{k-1}), not " +
                                  std::to_string(u_degree));
  }


  template <int dim>
  FemMixedSystem<dim>::FemMixedSystem(const std::vector<FloryRehnerGel<dim>> &materials,
                                      const dealii::Triangulation<dim>       &triangulation,
                                      const unsigned int                      u_degree,
                                      const Formulation                       formulation)
    : FemMixedSystem(first_material(materials), triangulation, u_degree, formulation)
  {
    this->materials.clear();
    const FloryRehnerGel<dim> &first = materials.front();
    for (unsigned int id = 0; id < materials.size(); ++id)
      {
        const FloryRehnerGel<dim> &gel = materials[id];
        if (std::abs(gel.kT_over_nu() - first.kT_over_nu()) > 1e-12 * first.kT_over_nu())
          throw std::invalid_argument(
            "FemMixedSystem: the gel of material_id " + std::to_string(id) +
            " has k_BT/nu = " + std::to_string(gel.kT_over_nu()) + ", that of material_id 0 " +
            std::to_string(first.kT_over_nu()) + ": all gels share one solvent");
        if (std::abs(gel.mu_0() - first.mu_0()) > 1e-9 * std::max(1., std::abs(first.mu_0())))
          throw std::invalid_argument(
            "FemMixedSystem: the gel of material_id " + std::to_string(id) +
            " starts at mu_0 = " + std::to_string(gel.mu_0()) + ", that of material_id 0 at " +
            std::to_string(first.mu_0()) +
            ": all gels start in equilibrium with one chemical potential (give each its "
            "lambda_0 from eq. (22), FloryRehnerGel::lambda_0_from_mu_0)");
        this->materials.push_back(&gel);
      }
  }


  template <int dim>
  const FloryRehnerGel<dim> &
  FemMixedSystem<dim>::material_of(const dealii::CellAccessor<dim, dim> &cell) const
  {
    return *materials[materials.size() == 1 ? 0 : cell.material_id()];
  }


  template <int dim>
  void
  FemMixedSystem<dim>::constrain_displacement(const dealii::types::boundary_id id,
                                              const std::vector<unsigned int> &components)
  {
    auto &mask = displacement_constraints[id];
    mask.resize(dim + 1, false);
    for (const unsigned int c : components)
      {
        if (c >= dim)
          throw std::invalid_argument("FemMixedSystem: displacement component " +
                                      std::to_string(c) + " does not exist in " +
                                      std::to_string(dim) + "D");
        mask[c] = true;
      }
  }


  template <int dim>
  void
  FemMixedSystem<dim>::set_displacement_increment(const dealii::types::boundary_id id,
                                                  const unsigned int               component,
                                                  const double                     delta)
  {
    const auto entry = displacement_increments.find({id, component});
    if (entry == displacement_increments.end())
      throw std::invalid_argument("FemMixedSystem: displacement component " +
                                  std::to_string(component) + " of boundary " + std::to_string(id) +
                                  " is not held (constrain_displacement before setup)");
    entry->second.second = delta;
  }


  template <int dim>
  void
  FemMixedSystem<dim>::constrain_displacement_at_vertex(const dealii::Point<dim>        &vertex,
                                                        const std::vector<unsigned int> &components)
  {
    std::vector<bool> mask(dim + 1, false);
    for (const unsigned int c : components)
      {
        if (c >= dim)
          throw std::invalid_argument("FemMixedSystem: displacement component " +
                                      std::to_string(c) + " does not exist in " +
                                      std::to_string(dim) + "D");
        mask[c] = true;
      }
    vertex_constraints.emplace_back(vertex, mask);
  }


  template <int dim>
  void
  FemMixedSystem<dim>::prescribe_chemical_potential(const dealii::types::boundary_id id,
                                                    const double                     mu_bar)
  {
    mu_constraints[id] = mu_bar;
  }


  template <int dim>
  void
  FemMixedSystem<dim>::set_chemical_potential(const dealii::types::boundary_id id,
                                              const double                     mu_bar)
  {
    const auto entry = mu_constraints.find(id);
    if (entry == mu_constraints.end())
      throw std::invalid_argument("FemMixedSystem: boundary " + std::to_string(id) +
                                  " has no prescribed chemical potential "
                                  "(prescribe_chemical_potential before setup)");
    entry->second = mu_bar;
  }


  template <int dim>
  void
  FemMixedSystem<dim>::setup()
  {
    if (materials.size() > 1)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->material_id() >= materials.size())
          {
            std::ostringstream message;
            message << "FemMixedSystem: the cell at (" << cell->center() << ") has material_id "
                    << cell->material_id() << ", but only " << materials.size()
                    << " gels are given";
            throw std::invalid_argument(message.str());
          }
    const auto ids = triangulation.get_boundary_ids();
    for (const auto &c : displacement_constraints)
      if (std::find(ids.begin(), ids.end(), c.first) == ids.end())
        throw std::invalid_argument("FemMixedSystem: no boundary with id " +
                                    std::to_string(c.first) + " for a displacement condition");
    for (const auto &c : mu_constraints)
      if (std::find(ids.begin(), ids.end(), c.first) == ids.end())
        throw std::invalid_argument("FemMixedSystem: no boundary with id " +
                                    std::to_string(c.first) +
                                    " for a chemical-potential condition");

    dof_handler_.distribute_dofs(fe);
    std::vector<unsigned int> blocks(dim + 1, 0);
    blocks[dim] = 1;
    dealii::DoFRenumbering::component_wise(dof_handler_, blocks);
    const auto dofs_per_block = dealii::DoFTools::count_dofs_per_fe_block(dof_handler_, blocks);
    n_u_dofs_                 = dofs_per_block[0];

    zero_constraints.clear();
    constraints.clear();
    for (const auto &c : displacement_constraints)
      {
        const dealii::ComponentMask mask(c.second);
        dealii::VectorTools::interpolate_boundary_values(dof_handler_,
                                                         c.first,
                                                         dealii::Functions::ZeroFunction<dim>(dim +
                                                                                              1),
                                                         zero_constraints,
                                                         mask);
        dealii::VectorTools::interpolate_boundary_values(dof_handler_,
                                                         c.first,
                                                         dealii::Functions::ZeroFunction<dim>(dim +
                                                                                              1),
                                                         constraints,
                                                         mask);
      }
    std::vector<bool> mu_mask(dim + 1, false);
    mu_mask[dim] = true;
    for (const auto &c : mu_constraints)
      {
        dealii::VectorTools::interpolate_boundary_values(dof_handler_,
                                                         c.first,
                                                         dealii::Functions::ZeroFunction<dim>(dim +
                                                                                              1),
                                                         zero_constraints,
                                                         dealii::ComponentMask(mu_mask));
        dealii::VectorTools::interpolate_boundary_values(
          dof_handler_,
          c.first,
          dealii::Functions::ConstantFunction<dim>(c.second, dim + 1),
          constraints,
          dealii::ComponentMask(mu_mask));
      }
    // A held vertex may also lie on a held face: constrain each DoF once.
    const double tolerance = 1e-10 * dealii::GridTools::minimal_cell_diameter(triangulation);
    for (const auto &[vertex, mask] : vertex_constraints)
      {
        bool found = false;
        for (const auto &cell : dof_handler_.active_cell_iterators())
          for (const auto v : cell->vertex_indices())
            if (cell->vertex(v).distance(vertex) < tolerance)
              {
                found = true;
                // Vertex DoFs come first in a cell, fe.n_dofs_per_vertex() per vertex.
                for (unsigned int k = 0; k < fe.n_dofs_per_vertex(); ++k)
                  {
                    const unsigned int c =
                      fe.system_to_component_index(v * fe.n_dofs_per_vertex() + k).first;
                    const auto i = cell->vertex_dof_index(v, k);
                    if (mask[c] && !zero_constraints.is_constrained(i))
                      {
                        zero_constraints.add_line(i);
                        constraints.add_line(i);
                      }
                  }
              }
        if (!found)
          {
            std::ostringstream message;
            message << "FemMixedSystem: no mesh vertex at (" << vertex
                    << ") for a displacement condition";
            throw std::invalid_argument(message.str());
          }
      }
    zero_constraints.close();
    constraints.close();

    mu_dofs.clear();
    for (const auto &c : mu_constraints)
      {
        const dealii::IndexSet dofs =
          dealii::DoFTools::extract_boundary_dofs(dof_handler_,
                                                  dealii::ComponentMask(mu_mask),
                                                  {c.first});
        auto &indices = mu_dofs[c.first];
        for (const auto i : dofs)
          indices.push_back(i);
      }

    displacement_increments.clear();
    for (const auto &c : displacement_constraints)
      for (unsigned int component = 0; component < dim; ++component)
        if (c.second[component])
          {
            std::vector<bool> mask(dim + 1, false);
            mask[component] = true;
            const dealii::IndexSet dofs =
              dealii::DoFTools::extract_boundary_dofs(dof_handler_,
                                                      dealii::ComponentMask(mask),
                                                      {c.first});
            std::vector<dealii::types::global_dof_index> indices;
            for (const auto i : dofs)
              indices.push_back(i);
            displacement_increments[{c.first, component}] = {indices, 0.};
          }

    dealii::DynamicSparsityPattern dsp(dof_handler_.n_dofs());
    dealii::DoFTools::make_sparsity_pattern(dof_handler_, dsp, zero_constraints, false);
    dealii::SparsityPattern pattern;
    pattern.copy_from(dsp);
    matrix_.reinit(pattern);
    residual_.reinit(dof_handler_.n_dofs());
    unconstrained_residual_.reinit(dof_handler_.n_dofs());

    // One mu_0 for all gels (checked by the constructor).
    state_.reinit(dof_handler_.n_dofs());
    for (unsigned int i = n_u_dofs_; i < state_.size(); ++i)
      state_(i) = materials.front()->mu_0();
  }


  template <int dim>
  void
  FemMixedSystem<dim>::initial_guess(dealii::Vector<double> &solution) const
  {
    solution.reinit(dof_handler_.n_dofs());
    for (unsigned int i = n_u_dofs_; i < solution.size(); ++i)
      solution(i) = state_(i);
    constraints.distribute(solution);
    for (const auto &entry : displacement_increments)
      for (const auto i : entry.second.first)
        solution(i) = entry.second.second;
    // The prescribed mu of the coming step (set_chemical_potential), which may differ from the
    // value the constraints were built with.
    for (const auto &[id, indices] : mu_dofs)
      for (const auto i : indices)
        solution(i) = mu_constraints.at(id);
  }


  template <int dim>
  void
  FemMixedSystem<dim>::assemble(const dealii::Vector<double> &solution,
                                const double                  dt,
                                const bool                    with_matrix)
  {
    const dealii::QGauss<dim>                quadrature(fe.degree + 1);
    dealii::FEValues<dim>                    fe_values(fe,
                                    quadrature,
                                    dealii::update_values | dealii::update_gradients |
                                      dealii::update_JxW_values);
    const unsigned int                       n_q         = quadrature.size();
    const unsigned int                       n_dofs_cell = fe.n_dofs_per_cell();
    const dealii::FEValuesExtractors::Vector u_extractor(0);
    const dealii::FEValuesExtractors::Scalar mu_extractor(dim);

    std::vector<Tensor<2, dim>>                  grad_du(n_q), grad_u_n(n_q);
    std::vector<double>                          mu(n_q);
    std::vector<Tensor<1, dim>>                  grad_mu(n_q);
    dealii::FullMatrix<double>                   cell_matrix(n_dofs_cell, n_dofs_cell);
    dealii::Vector<double>                       cell_residual(n_dofs_cell);
    std::vector<dealii::types::global_dof_index> dofs(n_dofs_cell);
    // Per shape function: component, value and pulled-back gradient (grad_n or grad_0).
    std::vector<unsigned int>   component(n_dofs_cell);
    std::vector<double>         value(n_dofs_cell);
    std::vector<Tensor<1, dim>> gradient(n_dofs_cell);
    for (unsigned int i = 0; i < n_dofs_cell; ++i)
      component[i] = fe.system_to_component_index(i).first;

    const Tensor<2, dim> I = dealii::unit_symmetric_tensor<dim>();

    if (with_matrix)
      matrix_ = 0.;
    residual_               = 0.;
    unconstrained_residual_ = 0.;

    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        const FloryRehnerGel<dim> &material = material_of(*cell);
        const double               kTnu     = material.kT_over_nu();
        const Tensor<2, dim>       F_0      = material.lambda_0() * I;
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        fe_values[u_extractor].get_function_gradients(solution, grad_du);
        fe_values[u_extractor].get_function_gradients(state_, grad_u_n);
        fe_values[mu_extractor].get_function_values(solution, mu);
        fe_values[mu_extractor].get_function_gradients(solution, grad_mu);
        cell_matrix   = 0.;
        cell_residual = 0.;

        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Tensor<2, dim> F_n   = I + grad_u_n[q];
            const double         det_n = dealii::determinant(F_n);
            const Tensor<2, dim> F_p   = F_n * F_0;
            // m_n frozen at the converged state (§2.4), in the weak form's units.
            const double m_n = material.mobility(F_p);

            // The pull-back G of gradients (grad w -> grad w G, grad q -> G^T grad q), the volume
            // element, the mobility tensor, the state and the volume-change term.
            Tensor<2, dim>                            G, mobility;
            double                                    dV, volume_change;
            typename FloryRehnerGel<dim>::Incremental state;
            if (formulation == Formulation::previously_converged_lagrangian)
              {
                G                       = dealii::invert(F_n);
                dV                      = det_n * fe_values.JxW(q);
                mobility                = m_n * I;
                const Tensor<2, dim> dF = I + grad_du[q] * G;
                state                   = material.incremental(dF, mu[q], F_p);
                volume_change           = state.delta_J - 1.;
              }
            else
              {
                G                            = I;
                dV                           = fe_values.JxW(q);
                const Tensor<2, dim> F_n_inv = dealii::invert(F_n);
                mobility                     = m_n * det_n * F_n_inv * dealii::transpose(F_n_inv);
                const Tensor<2, dim> F_t     = F_n + grad_du[q];
                state                        = material.incremental(F_t, mu[q], F_0);
                volume_change                = state.delta_J - det_n;
              }
            const Tensor<1, dim> grad_mu_q = dealii::transpose(G) * grad_mu[q];
            const Tensor<1, dim> flux      = dt * (mobility * grad_mu_q);

            for (unsigned int i = 0; i < n_dofs_cell; ++i)
              {
                value[i]    = fe_values.shape_value(i, q);
                gradient[i] = dealii::transpose(G) * fe_values.shape_grad(i, q);
              }

            for (unsigned int i = 0; i < n_dofs_cell; ++i)
              {
                const unsigned int ci = component[i];
                if (ci < dim)
                  {
                    cell_residual(i) += (state.P_n * gradient[i])[ci] * dV;
                    if (!with_matrix)
                      continue;
                    for (unsigned int j = 0; j < n_dofs_cell; ++j)
                      {
                        const unsigned int cj = component[j];
                        if (cj < dim)
                          {
                            double k = 0.;
                            for (unsigned int J = 0; J < dim; ++J)
                              for (unsigned int L = 0; L < dim; ++L)
                                k += gradient[i][J] * state.A_n[ci][J][cj][L] * gradient[j][L];
                            cell_matrix(i, j) += k * dV;
                          }
                        else
                          cell_matrix(i, j) += (state.dP_n_dmu * gradient[i])[ci] * value[j] * dV;
                      }
                  }
                else
                  {
                    cell_residual(i) +=
                      (-kTnu * volume_change * value[i] - flux * gradient[i]) * dV;
                    if (!with_matrix)
                      continue;
                    for (unsigned int j = 0; j < n_dofs_cell; ++j)
                      {
                        const unsigned int cj = component[j];
                        if (cj < dim)
                          cell_matrix(i, j) += value[i] * (state.dP_n_dmu * gradient[j])[cj] * dV;
                        else
                          cell_matrix(i, j) -= dt * (gradient[i] * (mobility * gradient[j])) * dV;
                      }
                  }
              }
          }

        for (unsigned int i = 0; i < n_dofs_cell; ++i)
          unconstrained_residual_(dofs[i]) += cell_residual(i);
        if (with_matrix)
          zero_constraints.distribute_local_to_global(cell_matrix,
                                                      cell_residual,
                                                      dofs,
                                                      matrix_,
                                                      residual_);
        else
          zero_constraints.distribute_local_to_global(cell_residual, dofs, residual_);
      }
    if (with_matrix)
      matrix_.compress(dealii::VectorOperation::add);
  }


  template <int dim>
  void
  FemMixedSystem<dim>::update(const dealii::Vector<double> &solution)
  {
    for (unsigned int i = 0; i < n_u_dofs_; ++i)
      state_(i) += solution(i);
    for (unsigned int i = n_u_dofs_; i < state_.size(); ++i)
      state_(i) = solution(i);
  }


  template <int dim>
  Tensor<1, dim>
  FemMixedSystem<dim>::boundary_force(const dealii::types::boundary_id id) const
  {
    const auto ids = triangulation.get_boundary_ids();
    if (std::find(ids.begin(), ids.end(), id) == ids.end())
      throw std::invalid_argument("FemMixedSystem: no boundary with id " + std::to_string(id));
    Tensor<1, dim> force;
    const auto     held = displacement_constraints.find(id);
    if (held == displacement_constraints.end())
      return force;
    // Only the components this boundary holds: at a node it shares with another boundary, a
    // component the other one holds carries that boundary's reaction.
    for (unsigned int k = 0; k < dim; ++k)
      if (held->second[k])
        {
          std::vector<bool> mask(dim + 1, false);
          mask[k] = true;
          for (const auto i : dealii::DoFTools::extract_boundary_dofs(dof_handler_,
                                                                      dealii::ComponentMask(mask),
                                                                      {id}))
            force[k] += unconstrained_residual_(i);
        }
    return force;
  }


  template <int dim>
  double
  FemMixedSystem<dim>::mean_boundary_displacement(const dealii::types::boundary_id id,
                                                  const unsigned int               component) const
  {
    if (component >= dim)
      throw std::invalid_argument("FemMixedSystem: displacement component " +
                                  std::to_string(component) + " does not exist");
    const dealii::QGauss<dim - 1>            quadrature(fe.degree + 1);
    dealii::FEFaceValues<dim>                fe_face_values(fe,
                                             quadrature,
                                             dealii::update_values | dealii::update_JxW_values);
    const dealii::FEValuesExtractors::Scalar u_c(component);
    std::vector<double>                      values(quadrature.size());
    double                                   integral = 0., area = 0.;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == id)
          {
            fe_face_values.reinit(cell, face);
            fe_face_values[u_c].get_function_values(state_, values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                integral += values[q] * fe_face_values.JxW(q);
                area += fe_face_values.JxW(q);
              }
          }
    if (area == 0.)
      throw std::invalid_argument("FemMixedSystem: no boundary with id " + std::to_string(id));
    return integral / area;
  }


  template <int dim>
  typename FemMixedSystem<dim>::DeformationSummary
  FemMixedSystem<dim>::deformation_summary() const
  {
    const dealii::QGauss<dim>                quadrature(fe.degree + 1);
    dealii::FEValues<dim>                    fe_values(fe,
                                    quadrature,
                                    dealii::update_gradients | dealii::update_JxW_values);
    const dealii::FEValuesExtractors::Vector u_extractor(0);
    std::vector<Tensor<2, dim>>              grad_u(quadrature.size());
    DeformationSummary                       summary;
    summary.min_det_F         = std::numeric_limits<double>::max();
    summary.max_stretch_ratio = 1.;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[u_extractor].get_function_gradients(state_, grad_u);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const Tensor<2, dim> F     = dealii::unit_symmetric_tensor<dim>() + grad_u[q];
            const double         det_F = dealii::determinant(F);
            summary.deformed_volume += det_F * fe_values.JxW(q);
            summary.min_det_F  = std::min(summary.min_det_F, det_F);
            const auto squares = dealii::eigenvalues(dealii::symmetrize(dealii::transpose(F) * F));
            // Eigenvalues of C = F^T F, largest first; an inverted or collapsed point has an
            // unbounded distortion.
            summary.max_stretch_ratio =
              squares[dim - 1] > 0.
                ? std::max(summary.max_stretch_ratio, std::sqrt(squares[0] / squares[dim - 1]))
                : std::numeric_limits<double>::infinity();
          }
      }
    return summary;
  }


  template <int dim>
  std::vector<typename FemMixedSystem<dim>::BoundarySample>
  FemMixedSystem<dim>::boundary_samples(const dealii::types::boundary_id id,
                                        const unsigned int               per_face) const
  {
    const dealii::QIterated<dim - 1> quadrature(dealii::QTrapezoid<1>(), std::max(per_face, 1u));
    dealii::FEFaceValues<dim>        fe_face_values(fe,
                                             quadrature,
                                             dealii::update_values |
                                               dealii::update_quadrature_points);
    const dealii::FEValuesExtractors::Vector u_extractor(0);
    const dealii::FEValuesExtractors::Scalar mu_extractor(dim);
    std::vector<Tensor<1, dim>>              u(quadrature.size());
    std::vector<double>                      mu(quadrature.size());
    std::vector<BoundarySample>              samples;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto face : cell->face_indices())
        if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == id)
          {
            fe_face_values.reinit(cell, face);
            fe_face_values[u_extractor].get_function_values(state_, u);
            fe_face_values[mu_extractor].get_function_values(state_, mu);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              samples.push_back({fe_face_values.quadrature_point(q), u[q], mu[q]});
          }
    if (samples.empty())
      throw std::invalid_argument("FemMixedSystem: no boundary with id " + std::to_string(id));
    return samples;
  }


  template <int dim>
  double
  FemMixedSystem<dim>::volume() const
  {
    double v = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      v += cell->measure();
    return v;
  }


  template <int dim>
  unsigned int
  FemMixedSystem<dim>::n_dofs() const
  {
    return dof_handler_.n_dofs();
  }


  template <int dim>
  unsigned int
  FemMixedSystem<dim>::n_u_dofs() const
  {
    return n_u_dofs_;
  }


  template <int dim>
  unsigned int
  FemMixedSystem<dim>::n_mu_dofs() const
  {
    return dof_handler_.n_dofs() - n_u_dofs_;
  }


  template <int dim>
  const dealii::AffineConstraints<double> &
  FemMixedSystem<dim>::increment_constraints() const
  {
    return zero_constraints;
  }


  template <int dim>
  const dealii::Vector<double> &
  FemMixedSystem<dim>::state() const
  {
    return state_;
  }


  template <int dim>
  const dealii::DoFHandler<dim> &
  FemMixedSystem<dim>::dof_handler() const
  {
    return dof_handler_;
  }


  template class FemMixedSystem<2>;
  template class FemMixedSystem<3>;
} // namespace GelMPM

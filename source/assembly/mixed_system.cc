#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/core/collective.h>

#include <deal.II/base/parallel.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;

  namespace
  {
    template <int dim>
    Tensor<2, dim>
    outer(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    {
      Tensor<2, dim> t;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          t[i][j] = a[i] * b[j];
      return t;
    }

    /** The projector onto the displacement components a piece constrains. */
    template <int dim>
    Tensor<2, dim>
    constraint_projector(const typename BoundaryPiece<dim>::DisplacementCondition condition,
                         const Tensor<1, dim>                                    &normal)
    {
      using Condition = typename BoundaryPiece<dim>::DisplacementCondition;
      Tensor<2, dim> projector;
      switch (condition)
        {
          case Condition::free:
            break;
          case Condition::fixed:
            projector = dealii::unit_symmetric_tensor<dim>();
            break;
          case Condition::normal:
            projector = outer(normal, normal);
            break;
          case Condition::tangential:
            projector =
              dealii::Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()) - outer(normal, normal);
            break;
        }
      return projector;
    }

    template <int dim>
    std::string
    format_point(const Point<dim> &p)
    {
      std::ostringstream out;
      out << "(" << p << ")";
      return out.str();
    }
  } // namespace


  template <int dim>
  struct MixedSystem<dim>::ScratchData
  {
    // Local coefficients of the cell and the point state.
    std::vector<Tensor<1, dim>> du;
    std::vector<double>         mu;
    const double               *N   = nullptr;
    const Tensor<1, dim>       *G   = nullptr;
    const double               *M   = nullptr;
    const Tensor<1, dim>       *GM  = nullptr;
    unsigned int                n_u = 0, n_mu = 0;
    Tensor<2, dim>              delta_F;
    Tensor<1, dim>              du_at_point;
    double                      mu_at_point = 0.;
    Tensor<1, dim>              grad_mu;
    // Work arrays for the tangent.
    std::vector<Tensor<3, dim>> A_dot_G;      // [c][i][J][k] = sum_L A_iJkL G_c[L]
    dealii::FullMatrix<double>  volume_lower; // the volume points' sum, lower triangle
  };


  template <int dim>
  struct MixedSystem<dim>::CopyData
  {
    dealii::FullMatrix<double>                   matrix;
    dealii::Vector<double>                       residual;
    std::vector<dealii::types::global_dof_index> dofs;
    bool                                         failed = false;
    std::string                                  failure;
  };


  template <int dim>
  MixedSystem<dim>::MixedSystem(const MaterialRegions<dim> &materials,
                                BoundaryConditions<dim>    &boundary_conditions,
                                const NitscheSettings      &nitsche,
                                DiscreteSpaces<dim>        &spaces,
                                const MPI_Comm              communicator)
    : materials(materials)
    , boundary_conditions(boundary_conditions)
    , nitsche(nitsche)
    , spaces_(spaces)
    , communicator(communicator)
  {}


  template <int dim>
  bool
  MixedSystem<dim>::setup(dealii::Particles::ParticleHandler<dim> &particle_handler,
                          const std::function<void()>             &before_new_pattern)
  {
    bool new_pattern = classify_cells(particle_handler);

    std::vector<PointRecord>                                                         unsorted;
    std::vector<typename dealii::Particles::ParticleHandler<dim>::particle_iterator> its;
    std::vector<unsigned int>                                                        cells;
    unsorted.reserve(particle_handler.n_locally_owned_particles());
    std::string failure;
    try
      {
        for (auto particle = particle_handler.begin(); particle != particle_handler.end();
             ++particle)
          {
            unsorted.push_back(unpack_point(*particle));
            its.push_back(particle);
            cells.push_back(cell_of_point(unsorted.back()));
          }
      }
    catch (const std::runtime_error &e)
      {
        failure = e.what();
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
    group_points(unsorted, its, cells);
    evaluate_shape_functions();
    if (Collective::is_parallel(communicator))
      {
        // A rank writes the rows of the blocks its points join. A surface point joins the active
        // cell next to it, which another rank may hold, and moves between ranks with its cell:
        // the writable rows change although the classification and the holders do not.
        std::vector<unsigned int> block_cells;
        for (const Block &b : blocks)
          block_cells.push_back(b.u_cell);
        const bool blocks_changed = block_cells != pattern_block_cells;
        new_pattern =
          dealii::Utilities::MPI::logical_or(new_pattern || blocks_changed, communicator);
        if (new_pattern)
          pattern_block_cells = std::move(block_cells);
      }
    if (new_pattern)
      {
        before_new_pattern();
        build_sparsity_pattern();
        for (auto &pattern : projection_patterns)
          pattern.reset();
        // Only now: a setup that throws on the way leaves the next one to rebuild the pattern.
        pattern_classification = classification;
        pattern_holder         = cell_holder;
      }
    return new_pattern;
  }


  template <int dim>
  bool
  MixedSystem<dim>::classify_cells(const dealii::Particles::ParticleHandler<dim> &particle_handler)
  {
    // The cells that hold volume points decide the classification (§3.5).
    const auto         &u_space = spaces_.u_space();
    std::vector<double> holder(u_space.n_cells(), 0.);
    const double        this_rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    std::string         failure;
    for (const auto &particle : particle_handler)
      {
        const Point<dim> x = particle.get_location();
        unsigned int     cell;
        try
          {
            cell = u_space.cell_containing(x);
          }
        catch (const std::out_of_range &)
          {
            failure = "a material point at " + format_point(x) +
                      " has left the background grid; enlarge 'Background grid/Lower corner' "
                      "and 'Upper corner'";
            break;
          }
        if (kind_of(particle.get_properties()) == PointKind::volume)
          holder[cell] = this_rank + 1.;
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
    // The volume points of a cell are all on the rank that owns the cell: the sum over the ranks
    // is that rank + 1, and tells every rank the classification and who holds each active cell.
    Collective::sum_in_place(communicator, holder);
    std::vector<bool> has_material(u_space.n_cells(), false);
    cell_holder.assign(u_space.n_cells(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < holder.size(); ++c)
      if (holder[c] > 0.)
        {
          has_material[c] = true;
          cell_holder[c]  = static_cast<unsigned int>(holder[c]) - 1;
        }
    spaces_.reinit(has_material);
    n_active_cells_ = std::count(has_material.begin(), has_material.end(), true);
    classification  = std::move(has_material);
    // On several ranks the rows' owners follow the cells' holders too (a repartition).
    return classification != pattern_classification ||
           (Collective::is_parallel(communicator) && cell_holder != pattern_holder);
  }


  template <int dim>
  typename MixedSystem<dim>::PointRecord
  MixedSystem<dim>::unpack_point(const dealii::Particles::ParticleAccessor<dim> &particle) const
  {
    using Layout      = PropertyLayout<dim>;
    const auto  props = particle.get_properties();
    PointRecord r;
    r.kind    = kind_of(props);
    r.piece   = piece_of(props);
    r.measure = props[Layout::measure_n];
    r.x       = particle.get_location();
    for (unsigned int d = 0; d < dim; ++d)
      {
        r.edge_offset[d] = props[Layout::edge_offset + d];
        r.X0[d]          = props[Layout::position_0 + d];
        r.u_n[d]         = r.x[d] + r.edge_offset[d] - r.X0[d];
        r.du_last[d]     = props[Layout::increment + d];
      }
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        r.F_p[i][j] = props[Layout::F + i * dim + j];
    r.mu_n      = props[Layout::mu];
    r.dmu_last  = props[Layout::mu_increment];
    r.gel       = &materials[region_of_point<dim>(props)];
    r.mobility  = r.gel->mobility(r.F_p);
    r.assembled = (r.kind == PointKind::volume) || (r.piece >= 0);
    if (r.kind != PointKind::volume)
      {
        Tensor<1, dim> na;
        for (unsigned int d = 0; d < dim; ++d)
          na[d] = props[Layout::normal_area_n + d];
        r.measure = na.norm();
        r.normal  = na / r.measure;
        if (r.piece >= 0)
          {
            // A roller or a tangential constraint acts along the wall the surface started
            // on: the directions come from the reference normal N_0 and apply to the total
            // displacement. With the current normal N_n instead, a tilt of the surface by
            // round-off turns part of the accumulated displacement into a lateral gap, and
            // the correction tilts the surface further: a growing mode (doc/method.md).
            Tensor<1, dim> na0;
            for (unsigned int d = 0; d < dim; ++d)
              na0[d] = props[Layout::normal_area_0 + d];
            r.projector =
              constraint_projector<dim>(boundary_conditions.piece(r.piece).displacement_condition,
                                        na0 / na0.norm());
          }
      }
    return r;
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::cell_of_point(const PointRecord &r) const
  {
    // A surface point may sit in a cell without volume points; it belongs to the active cell
    // next to it, whose extended functions reach it.
    const unsigned int cell = (r.kind == PointKind::volume) ? spaces_.u_space().cell_containing(r.x)
                                                            : spaces_.active_u_cell_containing(r.x);
    if (cell == dealii::numbers::invalid_unsigned_int)
      throw std::runtime_error("the surface point at " + format_point(r.x) +
                               " lies in no background cell that holds volume points; the "
                               "surface has separated from the bulk");
    return cell;
  }


  template <int dim>
  void
  MixedSystem<dim>::group_points(
    const std::vector<PointRecord> &unsorted,
    const std::vector<typename dealii::Particles::ParticleHandler<dim>::particle_iterator> &its,
    const std::vector<unsigned int>                                                        &cells)
  {
    // Stable: within a cell the points keep the handler's order, so that sums over them (and
    // with them the results) do not depend on the sort.
    std::vector<unsigned int> order(unsorted.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return cells[a] < cells[b];
    });

    points.clear();
    particles.clear();
    blocks.clear();
    points.reserve(order.size());
    particles.reserve(order.size());
    unsigned int n_u_shapes = 0, n_mu_shapes = 0;
    for (const unsigned int i : order)
      {
        const unsigned int cell = cells[i];
        if (blocks.empty() || blocks.back().u_cell != cell)
          blocks.push_back(
            Block{cell, spaces_.mu_cell_of(cell), static_cast<unsigned int>(points.size()), 0});
        PointRecord r = unsorted[i];
        r.block       = blocks.size() - 1;
        r.u_offset    = n_u_shapes;
        r.mu_offset   = n_mu_shapes;
        n_u_shapes += spaces_.u().cell_dofs(cell).size();
        n_mu_shapes += spaces_.mu().cell_dofs(blocks.back().mu_cell).size();
        points.push_back(r);
        particles.push_back(its[i]);
        blocks.back().end = points.size();
      }
    u_values.resize(n_u_shapes);
    u_gradients.resize(n_u_shapes);
    mu_values.resize(n_mu_shapes);
    mu_gradients.resize(n_mu_shapes);
  }


  template <int dim>
  void
  MixedSystem<dim>::evaluate_shape_functions()
  {
    // Every point writes its own ranges of the arrays: evaluate them in parallel.
    dealii::parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(points.size()),
      [this](const unsigned int begin, const unsigned int end) {
        std::vector<double>         values, scratch_values;
        std::vector<Tensor<1, dim>> gradients, scratch_gradients;
        for (unsigned int p = begin; p < end; ++p)
          {
            const PointRecord &r = points[p];
            const Block       &b = blocks[r.block];
            for (const auto *space : {&spaces_.u(), &spaces_.mu()})
              {
                const bool         is_u = (space == &spaces_.u());
                const unsigned int cell = is_u ? b.u_cell : b.mu_cell;
                const unsigned int n    = space->cell_dofs(cell).size();
                values.resize(n);
                gradients.resize(n);
                scratch_values.resize(space->space().functions_per_cell());
                scratch_gradients.resize(space->space().functions_per_cell());
                space->evaluate(r.x, cell, values, gradients, scratch_values, scratch_gradients);
                const unsigned int offset = is_u ? r.u_offset : r.mu_offset;
                std::copy(values.begin(),
                          values.end(),
                          (is_u ? u_values : mu_values).begin() + offset);
                std::copy(gradients.begin(),
                          gradients.end(),
                          (is_u ? u_gradients : mu_gradients).begin() + offset);
              }
          }
      },
      256);
  }


  template <int dim>
  void
  MixedSystem<dim>::build_sparsity_pattern()
  {
    // Every unknown of a cell with points couples with every other one of that cell.
    dealii::DynamicSparsityPattern               pattern(spaces_.n_dofs(), spaces_.n_dofs());
    std::vector<dealii::types::global_dof_index> dofs;
    for (const Block &b : blocks)
      {
        unknowns_of_block(b, dofs);
        for (const auto row : dofs)
          pattern.add_entries(row, dofs.begin(), dofs.end(), true);
      }
    residual_.reinit(spaces_.n_dofs());
    rows_are_local_and_sorted = false;
    if (!Collective::is_parallel(communicator))
      {
        matrix_.reinit(pattern);
        const Epetra_CrsMatrix &A = matrix_.trilinos_matrix();
        rows_are_local_and_sorted =
          A.RowMap().LinearMap() && A.RowMap().MinMyGID() == 0 && A.ColMap().SameAs(A.RowMap());
        for (int row = 0; rows_are_local_and_sorted && row < A.NumMyRows(); ++row)
          {
            int     length;
            double *values;
            int    *columns;
            A.ExtractMyRowView(row, length, values, columns);
            rows_are_local_and_sorted = std::is_sorted(columns, columns + length);
          }
        return;
      }
    const auto [owned, relevant] = owned_and_relevant_dofs();
    dealii::TrilinosWrappers::SparsityPattern distributed(owned, owned, relevant, communicator);
    for (const auto row : relevant)
      {
        const auto begin = pattern.begin(row), end = pattern.end(row);
        for (auto entry = begin; entry != end; ++entry)
          distributed.add(row, entry->column());
      }
    distributed.compress();
    matrix_.reinit(distributed);
  }


  template <int dim>
  void
  MixedSystem<dim>::unknowns_of_block(const Block                                  &block,
                                      std::vector<dealii::types::global_dof_index> &dofs) const
  {
    const unsigned int n_u = spaces_.n_u_dofs();
    dofs.clear();
    for (const unsigned int i : spaces_.u().cell_dofs(block.u_cell))
      for (unsigned int c = 0; c < dim; ++c)
        dofs.push_back(dim * i + c);
    for (const unsigned int j : spaces_.mu().cell_dofs(block.mu_cell))
      dofs.push_back(n_u + j);
    std::sort(dofs.begin(), dofs.end());
  }


  template <int dim>
  std::pair<dealii::IndexSet, dealii::IndexSet>
  MixedSystem<dim>::owned_and_relevant_dofs() const
  {
    // A B-spline function spans q + 1 cells, more than a ghost layer: ownership is decided on
    // the replicated classification instead. Each unknown belongs to the rank that holds the
    // first active cell (in the grid's order) that its function reaches; every rank computes the
    // same map. The relevant unknowns of a rank are those of the cells its points are in.
    const unsigned int        n_u  = spaces_.n_u_dofs();
    const unsigned int        rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    std::vector<unsigned int> owner(spaces_.n_dofs(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < classification.size(); ++c)
      if (classification[c])
        {
          for (const unsigned int i : spaces_.u().cell_dofs(c))
            for (unsigned int d = 0; d < dim; ++d)
              if (owner[dim * i + d] == dealii::numbers::invalid_unsigned_int)
                owner[dim * i + d] = cell_holder[c];
          for (const unsigned int j : spaces_.mu().cell_dofs(spaces_.mu_cell_of(c)))
            if (owner[n_u + j] == dealii::numbers::invalid_unsigned_int)
              owner[n_u + j] = cell_holder[c];
        }
    dealii::IndexSet owned(spaces_.n_dofs()), relevant(spaces_.n_dofs());
    for (unsigned int i = 0; i < owner.size(); ++i)
      if (owner[i] == rank)
        owned.add_index(i);
    std::vector<dealii::types::global_dof_index> dofs;
    for (const Block &b : blocks)
      {
        unknowns_of_block(b, dofs);
        relevant.add_indices(dofs.begin(), dofs.end());
      }
    relevant.add_indices(owned);
    owned.compress();
    relevant.compress();
    return {owned, relevant};
  }


  template <int dim>
  void
  MixedSystem<dim>::set_boundary_values(const double t_over_tau_d, const double step_start)
  {
    // The symmetric Nitsche term of a prescribed displacement adds (g (x) N) : dP/dmu A to the
    // mu equation, a balance of the solvent gained over the step: like the volume points'
    // J_n, its value at the start of the step is subtracted, or the violation g left by
    // every step would add solvent again at the next, however short (doc/method.md).
    boundary_conditions.set_time(step_start);
    for (auto &r : points)
      {
        r.adjoint_solvent_n = 0.;
        if (r.kind == PointKind::volume || r.piece < 0 || nitsche.symmetry == 0.)
          continue;
        const auto &piece = boundary_conditions.piece(r.piece);
        if (!piece.displacement_prescribed())
          continue;
        const Point<dim> &X0 = r.X0;
        Tensor<1, dim>    u_bar_n;
        for (unsigned int d = 0; d < dim; ++d)
          u_bar_n[d] = piece.displacement_value().value(X0, d);
        const auto start = r.gel->incremental(dealii::unit_symmetric_tensor<dim>(), r.mu_n, r.F_p);
        r.adjoint_solvent_n =
          r.measure *
          dealii::scalar_product(outer(r.projector * (r.u_n - u_bar_n), r.normal), start.dP_n_dmu);
      }
    boundary_conditions.set_time(t_over_tau_d);
    for (auto &r : points)
      {
        if (r.kind == PointKind::volume || r.piece < 0)
          continue;
        const auto       &piece = boundary_conditions.piece(r.piece);
        const Point<dim> &X0    = r.X0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            r.u_bar[d]    = piece.displacement_value().value(X0, d);
            r.traction[d] = piece.traction().value(X0, d);
          }
        r.mu_bar = piece.chemical_potential_value().value(X0);
        r.flux   = piece.flux().value(X0);
      }
  }


  template <int dim>
  void
  MixedSystem<dim>::assemble(const dealii::Vector<double> &solution,
                             const double                  dt,
                             const bool                    with_matrix)
  {
    if (with_matrix)
      matrix_ = 0.;
    residual_ = 0.;

    std::vector<unsigned int> block_indices(blocks.size());
    std::iota(block_indices.begin(), block_indices.end(), 0u);

    bool        failed = false;
    std::string failure;
    dealii::WorkStream::run(
      block_indices.begin(),
      block_indices.end(),
      [&](const std::vector<unsigned int>::iterator &it, ScratchData &scratch, CopyData &copy) {
        assemble_block(blocks[*it], solution, dt, with_matrix, scratch, copy);
      },
      [&](const CopyData &copy) {
        if (copy.failed)
          {
            failed  = true;
            failure = copy.failure;
            return;
          }
        for (unsigned int i = 0; i < copy.dofs.size(); ++i)
          residual_(copy.dofs[i]) += copy.residual(i);
        if (with_matrix)
          add_to_matrix(copy);
      },
      ScratchData(),
      CopyData());
    if (with_matrix)
      matrix_.compress(dealii::VectorOperation::add);
    Collective::sum_in_place(communicator, residual_.begin(), residual_.size());
    // Collective: every rank learns of a failure on any, before the next collective call.
    Collective::agree_on_failure<NonPhysicalState>(communicator, failed ? failure : "");
  }


  template <int dim>
  void
  MixedSystem<dim>::add_to_matrix(const CopyData &copy)
  {
    if (!rows_are_local_and_sorted)
      {
        matrix_.add(copy.dofs, copy.matrix);
        return;
      }
    // One rank: local and global indices coincide and every row's columns are sorted, as are
    // the block's unknowns, so one merge per row finds the entries; the generic add searches
    // for each entry and was the largest serial part of the assembly.
    const Epetra_CrsMatrix &A = matrix_.trilinos_matrix();
    const unsigned int      n = copy.dofs.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        int     length;
        double *values;
        int    *columns;
        A.ExtractMyRowView(static_cast<int>(copy.dofs[i]), length, values, columns);
        int k = 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            const int column = static_cast<int>(copy.dofs[j]);
            while (columns[k] < column)
              ++k;
            Assert(k < length && columns[k] == column, dealii::ExcInternalError());
            values[k] += copy.matrix(i, j);
          }
      }
  }


  template <int dim>
  void
  MixedSystem<dim>::gather_block_coefficients(const Block                  &block,
                                              const dealii::Vector<double> &solution,
                                              ScratchData                  &scratch) const
  {
    const auto        &u_dofs     = spaces_.u().cell_dofs(block.u_cell);
    const auto        &mu_dofs    = spaces_.mu().cell_dofs(block.mu_cell);
    const unsigned int n_u_global = spaces_.n_u_dofs();
    scratch.n_u                   = u_dofs.size();
    scratch.n_mu                  = mu_dofs.size();
    scratch.du.resize(scratch.n_u);
    scratch.mu.resize(scratch.n_mu);
    for (unsigned int a = 0; a < scratch.n_u; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        scratch.du[a][c] = solution(dim * u_dofs[a] + c);
    for (unsigned int b = 0; b < scratch.n_mu; ++b)
      scratch.mu[b] = solution(n_u_global + mu_dofs[b]);
  }


  template <int dim>
  void
  MixedSystem<dim>::evaluate_point_fields(const PointRecord &point, ScratchData &scratch) const
  {
    scratch.N  = &u_values[point.u_offset];
    scratch.G  = &u_gradients[point.u_offset];
    scratch.M  = &mu_values[point.mu_offset];
    scratch.GM = &mu_gradients[point.mu_offset];

    scratch.delta_F     = dealii::unit_symmetric_tensor<dim>();
    scratch.du_at_point = 0;
    for (unsigned int a = 0; a < scratch.n_u; ++a)
      {
        scratch.delta_F += outer(scratch.du[a], scratch.G[a]);
        scratch.du_at_point += scratch.N[a] * scratch.du[a];
      }
    scratch.mu_at_point = 0.;
    scratch.grad_mu     = 0;
    for (unsigned int b = 0; b < scratch.n_mu; ++b)
      {
        scratch.mu_at_point += scratch.M[b] * scratch.mu[b];
        scratch.grad_mu += scratch.mu[b] * scratch.GM[b];
      }
  }


  template <int dim>
  std::vector<typename MixedSystem<dim>::PieceBalance>
  MixedSystem<dim>::boundary_balances(const dealii::Vector<double> &solution, const double dt) const
  {
    // The surface points' own residual terms, tested with w = e_k and q = 1: both lie in the
    // extended spaces (they reproduce constants), and the volume points' terms vanish for w =
    // e_k and are the change of solvent for q = 1. So the forces of all pieces balance and the
    // inflows add up to the body's change of solvent to the Newton tolerance
    // (doc/architecture.md).
    std::vector<PieceBalance> balances(boundary_conditions.n_pieces());
    ScratchData               scratch;
    CopyData                  copy;
    // One solvent: k_BT/nu is the same in every region (MaterialRegions).
    const double kTnu = materials[0].kT_over_nu();
    for (const auto &block : blocks)
      {
        bool has_surface_points = false;
        for (unsigned int p = block.first; p < block.end && !has_surface_points; ++p)
          has_surface_points = points[p].kind != PointKind::volume && points[p].assembled;
        if (!has_surface_points)
          continue;
        gather_block_coefficients(block, solution, scratch);
        const unsigned int mu0 = dim * scratch.n_u;
        for (unsigned int p = block.first; p < block.end; ++p)
          {
            const PointRecord &point = points[p];
            if (point.kind == PointKind::volume || !point.assembled)
              continue;
            evaluate_point_fields(point, scratch);
            copy.residual.reinit(mu0 + scratch.n_mu);
            add_surface_point(point, dt, false, scratch, copy);
            auto &balance = balances[point.piece];
            for (unsigned int a = 0; a < scratch.n_u; ++a)
              for (unsigned int k = 0; k < dim; ++k)
                balance.force[k] -= copy.residual(dim * a + k);
            for (unsigned int b = 0; b < scratch.n_mu; ++b)
              balance.solvent_in += copy.residual(mu0 + b) / kTnu;
          }
      }
    for (auto &balance : balances)
      {
        for (unsigned int k = 0; k < dim; ++k)
          balance.force[k] = dealii::Utilities::MPI::sum(balance.force[k], communicator);
        balance.solvent_in = dealii::Utilities::MPI::sum(balance.solvent_in, communicator);
      }
    return balances;
  }


  template <int dim>
  void
  MixedSystem<dim>::assemble_block(const Block                  &block,
                                   const dealii::Vector<double> &solution,
                                   const double                  dt,
                                   const bool                    with_matrix,
                                   ScratchData                  &scratch,
                                   CopyData                     &copy) const
  {
    const auto        &u_dofs  = spaces_.u().cell_dofs(block.u_cell);
    const auto        &mu_dofs = spaces_.mu().cell_dofs(block.mu_cell);
    const unsigned int n_u = u_dofs.size(), n_mu = mu_dofs.size();
    const unsigned int n          = dim * n_u + n_mu;
    const unsigned int n_u_global = spaces_.n_u_dofs();

    copy.failed = false;
    copy.dofs.resize(n);
    for (unsigned int a = 0; a < n_u; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        copy.dofs[dim * a + c] = dim * u_dofs[a] + c;
    for (unsigned int b = 0; b < n_mu; ++b)
      copy.dofs[dim * n_u + b] = n_u_global + mu_dofs[b];
    copy.residual.reinit(n);
    if (with_matrix)
      copy.matrix.reinit(n, n);

    gather_block_coefficients(block, solution, scratch);
    if (with_matrix && scratch.A_dot_G.size() < n_u)
      scratch.A_dot_G.resize(n_u);
    if (with_matrix)
      scratch.volume_lower.reinit(n, n);

    unsigned int failed_point = block.first;
    try
      {
        for (unsigned int p = block.first; p < block.end; ++p)
          {
            failed_point             = p;
            const PointRecord &point = points[p];
            if (!point.assembled)
              continue;
            evaluate_point_fields(point, scratch);

            if (point.kind == PointKind::volume)
              add_volume_point(point, dt, with_matrix, scratch, copy);
            else
              add_surface_point(point, dt, with_matrix, scratch, copy);
          }
        if (with_matrix)
          for (unsigned int r = 0; r < n; ++r)
            for (unsigned int c = 0; c <= r; ++c)
              {
                const double value = scratch.volume_lower(r, c);
                copy.matrix(r, c) += value;
                if (c != r)
                  copy.matrix(c, r) += value;
              }
      }
    catch (const NonPhysicalState &e)
      {
        copy.failed  = true;
        copy.failure = describe_failure(e, points[failed_point], scratch, block.u_cell);
      }
  }


  template <int dim>
  std::string
  MixedSystem<dim>::describe_failure(const NonPhysicalState &error,
                                     const PointRecord      &point,
                                     const ScratchData      &scratch,
                                     const unsigned int      u_cell) const
  {
    static const char *kinds[] = {"volume point",
                                  "surface point (u and mu prescribed)",
                                  "surface point (u prescribed, flux)",
                                  "surface point (traction, mu prescribed)",
                                  "surface point (traction, flux)"};
    std::ostringstream message;
    message << error.what() << " at the " << kinds[static_cast<unsigned int>(point.kind)];
    if (point.piece >= 0)
      message << " of piece '" << boundary_conditions.piece(point.piece).name << "'";
    message << " at x = " << format_point(Point<dim>(point.x + scratch.du_at_point))
            << " (x_n = " << format_point(point.x) << ", initially " << format_point(point.X0)
            << "), background cell " << u_cell;
    return message.str();
  }


  template <int dim>
  void
  MixedSystem<dim>::add_volume_point(const PointRecord &point,
                                     const double       dt,
                                     const bool         with_matrix,
                                     ScratchData       &s,
                                     CopyData          &copy) const
  {
    const auto   state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p, with_matrix);
    const double V     = point.measure;
    const double kTnu  = point.gel->kT_over_nu();
    const double m     = point.mobility;
    const unsigned int mu0 = dim * s.n_u;

    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> PG = state.P_n * s.G[a];
        for (unsigned int i = 0; i < dim; ++i)
          copy.residual(dim * a + i) += V * PG[i];
      }
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) +=
        V * (-kTnu * (state.delta_J - 1.) * s.M[b] - dt * m * (s.grad_mu * s.GM[b]));

    if (!with_matrix)
      return;

    // A volume point's tangent is symmetric (A has the major symmetry A_iJkL = A_kLiJ, and
    // K_mu,u = K_u,mu^T): only its lower triangle is summed here, and assemble_block() mirrors
    // the block's sum once.
    auto &L = s.volume_lower;
    for (unsigned int c = 0; c < s.n_u; ++c)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            s.A_dot_G[c][i][J][k] = state.A_n[i][J][k] * s.G[c];
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double *row = &L(dim * a + i, 0);
          for (unsigned int c = 0; c <= a; ++c)
            for (unsigned int k = 0; k < (c == a ? i + 1 : dim); ++k)
              {
                double value = 0.;
                for (unsigned int J = 0; J < dim; ++J)
                  value += s.G[a][J] * s.A_dot_G[c][i][J][k];
                row[dim * c + k] += V * value;
              }
        }
    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> Vq = V * (state.dP_n_dmu * s.G[a]);
        for (unsigned int b = 0; b < s.n_mu; ++b)
          {
            double *row = &L(mu0 + b, dim * a);
            for (unsigned int i = 0; i < dim; ++i)
              row[i] += Vq[i] * s.M[b];
          }
      }
    const double Vdtm = V * dt * m;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      {
        double *row = &L(mu0 + b, mu0);
        for (unsigned int d = 0; d <= b; ++d)
          row[d] -= Vdtm * (s.GM[b] * s.GM[d]);
      }
  }


  template <int dim>
  void
  MixedSystem<dim>::add_surface_point(const PointRecord &point,
                                      const double       dt,
                                      const bool         with_matrix,
                                      ScratchData       &s,
                                      CopyData          &copy) const
  {
    const auto        &piece = boundary_conditions.piece(point.piece);
    const double       area  = point.measure;
    const auto        &N     = point.normal;
    const double       sym   = nitsche.symmetry;
    const double       kTnu  = point.gel->kT_over_nu();
    const unsigned int mu0   = dim * s.n_u;
    auto              &K     = copy.matrix;
    auto              &r     = copy.residual;

    // Traction on the components the piece leaves free.
    if (piece.displacement_condition != BoundaryPiece<dim>::DisplacementCondition::fixed)
      {
        const Tensor<1, dim> t = point.traction - point.projector * point.traction;
        for (unsigned int a = 0; a < s.n_u; ++a)
          for (unsigned int i = 0; i < dim; ++i)
            r(dim * a + i) -= area * t[i] * s.N[a];
      }

    if (piece.displacement_prescribed())
      {
        add_displacement_nitsche(point,
                                 point.projector,
                                 point.projector * (point.u_n + s.du_at_point - point.u_bar),
                                 nitsche.displacement_penalty * point.gel->shear_modulus() /
                                   spaces_.h_u(),
                                 with_matrix,
                                 s,
                                 copy);
        for (unsigned int b = 0; b < s.n_mu; ++b)
          r(mu0 + b) += sym * point.adjoint_solvent_n * s.M[b];
      }
    else if (contact.enabled())
      add_plane_contact(point, with_matrix, s, copy);

    if (piece.chemical_potential_prescribed())
      {
        const double m       = point.mobility;
        const double beta_mu = nitsche.chemical_potential_penalty * m / spaces_.h_mu();
        const double diff    = s.mu_at_point - point.mu_bar;
        const double gN      = s.grad_mu * N;
        for (unsigned int b = 0; b < s.n_mu; ++b)
          r(mu0 + b) +=
            dt * area *
            (m * gN * s.M[b] + sym * m * (s.GM[b] * N) * diff - beta_mu * diff * s.M[b]);
        if (with_matrix)
          for (unsigned int b = 0; b < s.n_mu; ++b)
            for (unsigned int d = 0; d < s.n_mu; ++d)
              K(mu0 + b, mu0 + d) += dt * area *
                                     (m * (s.GM[d] * N) * s.M[b] +
                                      sym * m * (s.GM[b] * N) * s.M[d] - beta_mu * s.M[b] * s.M[d]);
      }
    else
      for (unsigned int b = 0; b < s.n_mu; ++b)
        r(mu0 + b) += dt * area * kTnu * point.flux * s.M[b];
  }


  template <int dim>
  void
  MixedSystem<dim>::add_displacement_nitsche(const PointRecord    &point,
                                             const Tensor<2, dim> &Pi,
                                             const Tensor<1, dim> &g,
                                             const double          beta,
                                             const bool            with_matrix,
                                             ScratchData          &s,
                                             CopyData             &copy) const
  {
    const double         area  = point.measure;
    const auto          &N     = point.normal;
    const double         sym   = nitsche.symmetry;
    const unsigned int   mu0   = dim * s.n_u;
    auto                &K     = copy.matrix;
    auto                &r     = copy.residual;
    const auto           state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p);
    const Tensor<2, dim> W     = outer(g, N);
    const Tensor<1, dim> Pi_PN = Pi * (state.P_n * N);
    Tensor<2, dim>       WA; // [k][L] = W_iJ A_iJkL
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int L = 0; L < dim; ++L)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            WA[k][L] += W[i][J] * state.A_n[i][J][k][L];
    const double W_dPdmu = dealii::scalar_product(W, state.dP_n_dmu);

    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> WAG = WA * s.G[a];
        for (unsigned int k = 0; k < dim; ++k)
          r(dim * a + k) += area * (beta * g[k] * s.N[a] - Pi_PN[k] * s.N[a] - sym * WAG[k]);
      }
    for (unsigned int b = 0; b < s.n_mu; ++b)
      r(mu0 + b) -= sym * area * W_dPdmu * s.M[b];

    if (with_matrix)
      {
        // C[k][m][L] = Pi_ki A_iJmL N_J: the consistency term's derivative.
        Tensor<3, dim> C;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int m = 0; m < dim; ++m)
            for (unsigned int L = 0; L < dim; ++L)
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int J = 0; J < dim; ++J)
                  C[k][m][L] += Pi[k][i] * state.A_n[i][J][m][L] * N[J];

        // Third derivative of the energy contracted with W, by a central difference of
        // the analytic tangent along W (second-order accurate, step 1e-5 relative).
        dealii::Tensor<4, dim> H;
        dealii::Tensor<2, dim> DW; // d(W : dP_n/dmu)/d(dF)
        const double           W_norm = W.norm();
        if (W_norm > 0.)
          {
            const double eps = 1e-5 / W_norm;
            const auto plus = point.gel->incremental(s.delta_F + eps * W, s.mu_at_point, point.F_p);
            const auto minus =
              point.gel->incremental(s.delta_F - eps * W, s.mu_at_point, point.F_p);
            H = (plus.A_n - minus.A_n) / (2. * eps);
            // The exact H has the major symmetry; the difference has it only to round-off
            // divided by eps, which would make the symmetric Nitsche tangent unsymmetric at
            // 1e-11.
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                for (unsigned int m = 0; m < dim; ++m)
                  for (unsigned int Q = 0; Q < dim; ++Q)
                    if (dim * m + Q > dim * k + L)
                      H[k][L][m][Q] = H[m][Q][k][L] = 0.5 * (H[k][L][m][Q] + H[m][Q][k][L]);
            // P_n is affine in mu, so this difference is exact.
            const auto mu_plus = point.gel->incremental(s.delta_F, s.mu_at_point + 1., point.F_p);
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int J = 0; J < dim; ++J)
                    DW[k][L] += W[i][J] * (mu_plus.A_n[i][J][k][L] - state.A_n[i][J][k][L]);
          }
        const Tensor<1, dim> Pi_dPdmu_N = Pi * (state.dP_n_dmu * N);

        for (unsigned int a = 0; a < s.n_u; ++a)
          for (unsigned int c = 0; c < s.n_u; ++c)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int m = 0; m < dim; ++m)
                {
                  double value = beta * Pi[k][m] * s.N[a] * s.N[c];
                  value -= s.N[a] * (C[k][m] * s.G[c]);
                  value -= sym * s.N[c] * (C[m][k] * s.G[a]);
                  if (W_norm > 0.)
                    for (unsigned int L = 0; L < dim; ++L)
                      for (unsigned int Q = 0; Q < dim; ++Q)
                        value -= sym * s.G[a][L] * H[k][L][m][Q] * s.G[c][Q];
                  K(dim * a + k, dim * c + m) += area * value;
                }
        for (unsigned int a = 0; a < s.n_u; ++a)
          {
            const Tensor<1, dim> DWG = DW * s.G[a];
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int b = 0; b < s.n_mu; ++b)
                {
                  K(dim * a + k, mu0 + b) -=
                    area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + sym * DWG[k]);
                  K(mu0 + b, dim * a + k) -=
                    sym * area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + DWG[k]);
                }
          }
      }
  }


  template <int dim>
  void
  MixedSystem<dim>::add_plane_contact(const PointRecord &point,
                                      const bool         with_matrix,
                                      ScratchData       &s,
                                      CopyData          &copy) const
  {
    const double beta = contact.penalty * point.gel->shear_modulus() / spaces_.h_u();
    // The traction P_n N, once per point for all planes (Nitsche only).
    Tensor<1, dim> traction;
    if (contact.method == ContactSettings::Method::nitsche)
      traction = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p).P_n * point.normal;
    for (const auto &plane : contact_planes)
      {
        const double   g = plane.sign * (point.x[plane.axis] + point.edge_offset[plane.axis] +
                                       s.du_at_point[plane.axis] - plane.value);
        Tensor<1, dim> n;
        n[plane.axis] = plane.sign;
        if (contact.method == ContactSettings::Method::nitsche)
          {
            // Nitsche's active set: the augmented normal traction sigma_n - beta g < 0.
            const double sigma_n = n * traction;
            if (beta * g - sigma_n > 0.)
              add_displacement_nitsche(point, outer(n, n), g * n, beta, with_matrix, s, copy);
            continue;
          }
        if (g <= 0.)
          continue;
        const unsigned int i    = plane.axis;
        const double       area = point.measure;
        for (unsigned int a = 0; a < s.n_u; ++a)
          copy.residual(dim * a + i) += area * beta * g * plane.sign * s.N[a];
        if (with_matrix)
          for (unsigned int a = 0; a < s.n_u; ++a)
            for (unsigned int c = 0; c < s.n_u; ++c)
              copy.matrix(dim * a + i, dim * c + i) += area * beta * s.N[a] * s.N[c];
      }
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::n_u_dofs() const
  {
    return spaces_.n_u_dofs();
  }


  template <int dim>
  void
  MixedSystem<dim>::fields_at_point(const PointRecord            &r,
                                    const dealii::Vector<double> &solution,
                                    Tensor<1, dim>               &du,
                                    Tensor<2, dim>               &delta_F,
                                    double                       &mu) const
  {
    const Block &b      = blocks[r.block];
    const auto  &u_dofs = spaces_.u().cell_dofs(b.u_cell);
    const auto  &m_dofs = spaces_.mu().cell_dofs(b.mu_cell);
    const auto   n_u    = spaces_.n_u_dofs();
    delta_F             = dealii::unit_symmetric_tensor<dim>();
    du                  = Tensor<1, dim>();
    for (unsigned int a = 0; a < u_dofs.size(); ++a)
      {
        Tensor<1, dim> coefficient;
        for (unsigned int c = 0; c < dim; ++c)
          coefficient[c] = solution(dim * u_dofs[a] + c);
        delta_F += outer(coefficient, u_gradients[r.u_offset + a]);
        du += u_values[r.u_offset + a] * coefficient;
      }
    mu = 0.;
    for (unsigned int j = 0; j < m_dofs.size(); ++j)
      mu += mu_values[r.mu_offset + j] * solution(n_u + m_dofs[j]);
  }


  template <int dim>
  std::pair<double, double>
  MixedSystem<dim>::dirichlet_errors(const dealii::Vector<double> &solution) const
  {
    double u_error = 0., mu_error = 0.;
    for (const auto &r : points)
      {
        if (r.kind == PointKind::volume || r.piece < 0)
          continue;
        Tensor<1, dim> du;
        Tensor<2, dim> delta_F;
        double         mu;
        fields_at_point(r, solution, du, delta_F, mu);
        if (r.projector.norm_square() > 0.)
          u_error = std::max(u_error, (r.projector * (r.u_n + du - r.u_bar)).norm());
        if (boundary_conditions.piece(r.piece).chemical_potential_prescribed())
          mu_error = std::max(mu_error, std::abs(mu - r.mu_bar));
      }
    return {dealii::Utilities::MPI::max(u_error, communicator),
            dealii::Utilities::MPI::max(mu_error, communicator)};
  }


  template <int dim>
  void
  MixedSystem<dim>::update_particles(const dealii::Vector<double> &solution)
  {
    using Layout = PropertyLayout<dim>;
    // Every point writes its own particle: update them in parallel. A point beyond the grid's
    // edge is marked and the first of them (in the serial order) reported below.
    std::vector<unsigned char> outside(points.size(), 0);
    std::vector<Point<dim>>    moved(points.size());
    const auto                 update_point = [&](const unsigned int p) {
      const PointRecord &r = points[p];
      Tensor<1, dim>     du;
      Tensor<2, dim>     delta_F;
      double             mu;
      fields_at_point(r, solution, du, delta_F, mu);

      const Tensor<2, dim> F_p = delta_F * r.F_p;
      // J_n relative to the initial configuration (the out-of-plane stretch stays lambda_0).
      const double lambda_0 = r.gel->lambda_0();
      const double J_n      = dealii::determinant(F_p) / std::pow(lambda_0, dim);

      auto props = particles[p]->get_properties();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          props[Layout::F + i * dim + j] = F_p[i][j];
      props[Layout::mu_increment] = mu - r.mu_n;
      props[Layout::mu]           = mu;
      for (unsigned int d = 0; d < dim; ++d)
        props[Layout::increment + d] = du[d];
      if (r.kind == PointKind::volume)
        props[Layout::measure_n] = J_n * props[Layout::measure_0];
      else
        {
          // eq. (34): N_n A_n = J_n F_n^{-T} N_0 A_0 with F_n = F_p / lambda_0.
          Tensor<1, dim> na0;
          for (unsigned int d = 0; d < dim; ++d)
            na0[d] = props[Layout::normal_area_0 + d];
          const Tensor<1, dim> na = J_n * (dealii::transpose(dealii::invert(F_p)) * na0) * lambda_0;
          for (unsigned int d = 0; d < dim; ++d)
            props[Layout::normal_area_n + d] = na[d];
          props[Layout::measure_n] = na.norm();
        }
      // A point held normal to a grid edge (a roller or a fixed piece on the edge, or a contact
      // plane there) crosses it by the small violation of the weakly imposed condition: its
      // particle stays on the edge and the edge offset keeps the rest of its displacement. So
      // do volume points next to such an edge; where the edge is a free face, its surface
      // points lie beyond the volume points and report the crossing. Any other point beyond
      // the edge is material the grid cannot carry.
      const Point<dim> x_next = r.x + r.edge_offset + du;
      Point<dim>       x      = x_next;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto  &basis     = spaces_.u_space().basis_1d(d);
          const double tolerance = 0.25 * basis.cell_size();
          const bool   held = r.kind == PointKind::volume || r.projector[d][d] > 0.5;
          if ((held || on_contact_plane(d, -1.)) && x[d] < basis.x_min() &&
              x[d] > basis.x_min() - tolerance)
            x[d] = basis.x_min();
          if ((held || on_contact_plane(d, 1.)) && x[d] > basis.x_max() &&
              x[d] < basis.x_max() + tolerance)
            x[d] = basis.x_max();
          if (x[d] < basis.x_min() || x[d] > basis.x_max())
            outside[p] = 1;
        }
      for (unsigned int d = 0; d < dim; ++d)
        props[Layout::edge_offset + d] = x_next[d] - x[d];
      moved[p] = x;
      if (!outside[p])
        particles[p]->set_location(x);
    };
    dealii::parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(points.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int p = begin; p < end; ++p)
          update_point(p);
      },
      256);

    std::string failure;
    const auto  first_outside = std::find(outside.begin(), outside.end(), 1);
    if (first_outside != outside.end())
      {
        const unsigned int p = first_outside - outside.begin();
        const PointRecord &r = points[p];
        failure              = std::string(
          "the material point at " + format_point(moved[p]) + " (initially at " +
          format_point(r.X0) + ", " +
          (r.kind == PointKind::volume ? std::string("inside the body")
                                                    : "on the boundary, free normal to the grid edge") +
          ") has crossed the edge of the background grid; enlarge the grid so that the body "
                       "stays inside it ('Background grid/Lower corner', 'Upper corner')");
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
  }


  template <int dim>
  std::vector<double>
  MixedSystem<dim>::project_point_values(
    const bool                                                      displacement,
    const unsigned int                                              n_components,
    const std::function<double(const PointRecord &, unsigned int)> &value) const
  {
    const auto &space   = displacement ? spaces_.u() : spaces_.mu();
    const auto  cell_of = [displacement](const Block &b) {
      return displacement ? b.u_cell : b.mu_cell;
    };
    const unsigned int n = displacement ? spaces_.n_u_dofs() / dim : spaces_.n_mu_dofs();
    // On several ranks the pattern is that of every active cell, the same on all ranks, so
    // that the ranks' sums of the mass matrix add entry by entry and each rank solves the whole
    // projection (it is small against the Newton system). On one rank the blocks are the
    // active cells anyway.
    // Both depend on the classification alone: the pattern is kept with the tangent's.
    auto &sparsity = projection_patterns[displacement ? 1 : 0];
    if (!sparsity)
      {
        dealii::DynamicSparsityPattern pattern(n, n);
        const auto                     add_cell = [&](const unsigned int cell) {
          const auto &dofs = space.cell_dofs(cell);
          for (const auto i : dofs)
            pattern.add_entries(i, dofs.begin(), dofs.end(), true);
        };
        if (Collective::is_parallel(communicator))
          {
            for (unsigned int c = 0; c < classification.size(); ++c)
              if (classification[c])
                add_cell(displacement ? c : spaces_.mu_cell_of(c));
          }
        else
          for (const Block &b : blocks)
            add_cell(cell_of(b));
        sparsity = std::make_unique<dealii::SparsityPattern>();
        sparsity->copy_from(pattern);
      }
    dealii::SparseMatrix<double>        mass(*sparsity);
    std::vector<dealii::Vector<double>> rhs(n_components, dealii::Vector<double>(n));
    // The points of a block share the functions of its cell: sum their contributions locally
    // and add each block once.
    dealii::FullMatrix<double> local_mass;
    dealii::FullMatrix<double> local_rhs;
    std::vector<double>        point_values(n_components);
    for (const Block &b : blocks)
      {
        const auto        &dofs = space.cell_dofs(cell_of(b));
        const unsigned int m    = dofs.size();
        local_mass.reinit(m, m);
        local_rhs.reinit(n_components, m);
        for (unsigned int p = b.first; p < b.end; ++p)
          {
            const PointRecord &r = points[p];
            if (r.kind != PointKind::volume)
              continue;
            const double *values = displacement ? &u_values[r.u_offset] : &mu_values[r.mu_offset];
            for (unsigned int c = 0; c < n_components; ++c)
              point_values[c] = value(r, c);
            for (unsigned int i = 0; i < m; ++i)
              {
                const double Vi = r.measure * values[i];
                for (unsigned int c = 0; c < n_components; ++c)
                  local_rhs(c, i) += Vi * point_values[c];
                for (unsigned int j = 0; j <= i; ++j)
                  local_mass(i, j) += Vi * values[j];
              }
          }
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < i; ++j)
            local_mass(j, i) = local_mass(i, j);
        for (unsigned int c = 0; c < n_components; ++c)
          for (unsigned int i = 0; i < m; ++i)
            rhs[c](dofs[i]) += local_rhs(c, i);
        mass.add(dofs, local_mass);
      }
    if (Collective::is_parallel(communicator))
      {
        std::vector<double> entries;
        entries.reserve(sparsity->n_nonzero_elements());
        for (const auto &entry : mass)
          entries.push_back(entry.value());
        Collective::sum_in_place(communicator, entries);
        std::size_t k = 0;
        for (auto entry = mass.begin(); entry != mass.end(); ++entry)
          entry->value() = entries[k++];
        for (auto &r : rhs)
          Collective::sum_in_place(communicator, r.begin(), r.size());
      }
    dealii::SparseDirectUMFPACK solver;
    solver.initialize(mass);
    std::vector<double>    interleaved(n * n_components);
    dealii::Vector<double> coefficients(n);
    for (unsigned int c = 0; c < n_components; ++c)
      {
        solver.vmult(coefficients, rhs[c]);
        for (unsigned int i = 0; i < n; ++i)
          interleaved[n_components * i + c] = coefficients(i);
      }
    return interleaved;
  }


  template <int dim>
  std::vector<double>
  MixedSystem<dim>::mu_from_points() const
  {
    return project_point_values(false, 1, [](const PointRecord &r, unsigned int) {
      return r.mu_n;
    });
  }


  template <int dim>
  std::vector<double>
  MixedSystem<dim>::displacement_from_points(const double ratio) const
  {
    return project_point_values(true, dim, [ratio](const PointRecord &r, const unsigned int c) {
      return ratio * r.du_last[c];
    });
  }


  template <int dim>
  double
  MixedSystem<dim>::largest_increment_deviation(const dealii::Vector<double> &solution,
                                                const double                  ratio) const
  {
    double largest = 0.;
    for (const auto &r : points)
      {
        Tensor<1, dim> du;
        Tensor<2, dim> delta_F;
        double         mu;
        fields_at_point(r, solution, du, delta_F, mu);
        largest = std::max(largest, (du - ratio * r.du_last).norm());
      }
    return dealii::Utilities::MPI::max(largest, communicator);
  }


  template <int dim>
  const std::vector<bool> &
  MixedSystem<dim>::classification_of_pattern() const
  {
    return pattern_classification;
  }


  template <int dim>
  bool
  MixedSystem<dim>::restore_tangent(const std::vector<bool> &classification,
                                    const SparseEntries     &entries)
  {
    if (classification != pattern_classification ||
        entries.size() != static_cast<std::size_t>(matrix_.n_nonzero_elements()))
      return false;
    const dealii::IndexSet owned = matrix_.locally_owned_range_indices();
    for (std::size_t k = 0; k < entries.size(); ++k)
      if (owned.is_element(entries.rows[k]))
        matrix_.set(entries.rows[k], entries.columns[k], entries.values[k]);
    matrix_.compress(dealii::VectorOperation::insert);
    return true;
  }


  template <int dim>
  typename MixedSystem<dim>::StepError
  MixedSystem<dim>::local_error_estimate(const dealii::Vector<double> &solution,
                                         const double                  ratio,
                                         const bool                    largest) const
  {
    // Milne's device for backward Euler after a step of ratio r = dt / dt_last: the corrector
    // misses x(t + dt) by dt^2 x''/2 and the linear predictor x_n + r (x_n - x_{n-1}) by
    // -dt (dt + dt_last) x''/2, so the local error is r / (2 r + 1) times their difference.
    const double weight = ratio / (2. * ratio + 1.);
    double       volume = 0., u_sum = 0., mu_sum = 0., u_max = 0., mu_max = 0.;
    for (const auto &r : points)
      if (r.kind == PointKind::volume)
        {
          Tensor<1, dim> du;
          Tensor<2, dim> delta_F;
          double         mu;
          fields_at_point(r, solution, du, delta_F, mu);
          const double mu_difference = (mu - r.mu_n) - ratio * r.dmu_last;
          const double u_square      = (du - ratio * r.du_last).norm_square();
          volume += r.measure;
          u_sum += r.measure * u_square;
          mu_sum += r.measure * mu_difference * mu_difference;
          u_max  = std::max(u_max, u_square);
          mu_max = std::max(mu_max, mu_difference * mu_difference);
        }
    if (largest)
      return {weight * std::sqrt(dealii::Utilities::MPI::max(u_max, communicator)),
              weight * std::sqrt(dealii::Utilities::MPI::max(mu_max, communicator))};
    double sums[3] = {volume, u_sum, mu_sum};
    Collective::sum_in_place(communicator, sums, 3);
    volume = sums[0];
    u_sum  = sums[1];
    mu_sum = sums[2];
    if (!(volume > 0.))
      return {0., 0.};
    return {weight * std::sqrt(u_sum / volume), weight * std::sqrt(mu_sum / volume)};
  }


  template <int dim>
  double
  MixedSystem<dim>::largest_displacement_increment(const dealii::Vector<double> &solution) const
  {
    double largest = 0.;
    for (const auto &r : points)
      {
        Tensor<1, dim> du;
        Tensor<2, dim> delta_F;
        double         mu;
        fields_at_point(r, solution, du, delta_F, mu);
        largest = std::max(largest, du.norm());
      }
    return dealii::Utilities::MPI::max(largest, communicator);
  }


  template <int dim>
  void
  MixedSystem<dim>::set_contact(const ContactSettings &settings)
  {
    contact = settings;
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = spaces_.u_space().basis_1d(d).x_min();
        upper[d] = spaces_.u_space().basis_1d(d).x_max();
      }
    contact_planes = settings.planes(lower, upper);
  }


  template <int dim>
  bool
  MixedSystem<dim>::on_contact_plane(const unsigned int axis, const double sign) const
  {
    return std::any_of(contact_planes.begin(), contact_planes.end(), [&](const auto &plane) {
      return plane.axis == axis && plane.sign == sign;
    });
  }


  template <int dim>
  std::pair<unsigned int, double>
  MixedSystem<dim>::contact_state(const dealii::Vector<double> &solution) const
  {
    unsigned int active      = 0;
    double       penetration = 0.;
    if (!contact.enabled())
      return {active, penetration};
    for (const auto &r : points)
      {
        if (r.kind == PointKind::volume || r.piece < 0 ||
            boundary_conditions.piece(r.piece).displacement_prescribed())
          continue;
        Tensor<1, dim> du;
        Tensor<2, dim> delta_F;
        double         mu;
        fields_at_point(r, solution, du, delta_F, mu);
        bool         is_active = false;
        const double beta      = contact.penalty * r.gel->shear_modulus() / spaces_.h_u();
        for (const auto &plane : contact_planes)
          {
            const double g = plane.sign * (r.x[plane.axis] + r.edge_offset[plane.axis] +
                                           du[plane.axis] - plane.value);
            penetration    = std::max(penetration, g);
            if (contact.method == ContactSettings::Method::nitsche)
              {
                Tensor<1, dim> n;
                n[plane.axis]    = plane.sign;
                const auto state = r.gel->incremental(delta_F, mu, r.F_p);
                is_active |= beta * g - n * (state.P_n * r.normal) > 0.;
              }
            else
              is_active |= g > 0.;
          }
        active += is_active;
      }
    return {dealii::Utilities::MPI::sum(active, communicator),
            dealii::Utilities::MPI::max(penetration, communicator)};
  }


  template <int dim>
  dealii::FullMatrix<double>
  MixedSystem<dim>::mu_mass_matrix() const
  {
    dealii::FullMatrix<double> mass(spaces_.n_mu_dofs(), spaces_.n_mu_dofs());
    for (const auto &r : points)
      if (r.kind == PointKind::volume)
        {
          const auto &dofs = spaces_.mu().cell_dofs(blocks[r.block].mu_cell);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            for (unsigned int j = 0; j < dofs.size(); ++j)
              mass(dofs[i], dofs[j]) +=
                r.measure * mu_values[r.mu_offset + i] * mu_values[r.mu_offset + j];
        }
    Collective::sum_in_place(communicator, &mass(0, 0), mass.n_elements());
    return mass;
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::n_points() const
  {
    return dealii::Utilities::MPI::sum(static_cast<unsigned int>(points.size()), communicator);
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::n_active_cells() const
  {
    return n_active_cells_;
  }


  template <int dim>
  const DiscreteSpaces<dim> &
  MixedSystem<dim>::spaces() const
  {
    return spaces_;
  }


  template class MixedSystem<2>;
  template class MixedSystem<3>;
} // namespace GelMPM

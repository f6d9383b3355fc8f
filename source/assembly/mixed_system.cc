#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/core/collective.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/non_physical_state.h>
#include <gelmpm/core/serial_blas.h>

#include <deal.II/base/work_stream.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


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
    , cache(materials, boundary_conditions, spaces, communicator)
    , projection(cache, spaces, communicator)
  {
    build_terms();
  }


  template <int dim>
  void
  MixedSystem<dim>::build_terms()
  {
    terms.build({boundary_conditions, nitsche, spaces_, tangent, contact_settings, obstacles});
    const auto &self_contact = contact_settings.self_contact;
    cache.separate_faces(self_contact.enabled() && self_contact.separate_faces
                           ? self_contact_pieces(self_contact, boundary_conditions)
                           : std::vector<bool>(),
                         self_contact.minimum_arc_length * spaces_.h_u(0));
  }


  template <int dim>
  void
  MixedSystem<dim>::add_term(std::unique_ptr<PointAssembler<dim>> term)
  {
    terms.add(std::move(term));
  }


  template <int dim>
  const std::vector<const PointAssembler<dim> *> &
  MixedSystem<dim>::assemblers() const
  {
    return terms.all();
  }


  template <int dim>
  bool
  MixedSystem<dim>::setup(dealii::Particles::ParticleHandler<dim> &particle_handler,
                          const std::function<void()>             &before_new_pattern)
  {
    cache.gather(particle_handler);
    on_axis.clear();
    if (spaces_.axisymmetric())
      {
        on_axis.assign(spaces_.n_dofs(), false);
        for (const auto i : spaces_.axis_unknowns())
          on_axis[i] = true;
      }
    // On several ranks the rows' owners follow the cells' holders too (a repartition).
    auto couplings = terms.cell_couplings(cache);
    bool new_pattern =
      cache.classification() != pattern_classification || cache.leaf_classification_changed() ||
      cache.separation_changed() || couplings != pattern_couplings ||
      (Collective::is_parallel(communicator) && cache.cell_holder() != pattern_holder);
    if (Collective::is_parallel(communicator))
      {
        // A rank writes the rows of the blocks its points join. A surface point joins the active
        // cell next to it, which another rank may hold, and moves between ranks with its cell:
        // the writable rows change although the classification and the holders do not.
        std::vector<unsigned int> block_cells;
        for (const PointBlock &b : cache.blocks())
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
        build_sparsity_pattern(couplings);
        projection.forget_patterns();
        // Only now: a setup that throws on the way leaves the next one to rebuild the pattern.
        pattern_classification = cache.classification();
        cache.pattern_follows_leaves();
        cache.pattern_follows_separation();
        pattern_holder    = cache.cell_holder();
        pattern_couplings = std::move(couplings);
      }
    return new_pattern;
  }


  template <int dim>
  void
  MixedSystem<dim>::unknowns_of_cell(const unsigned int                            u_cell,
                                     std::vector<dealii::types::global_dof_index> &dofs) const
  {
    cache.unknowns_of_cell(u_cell, dofs);
  }


  template <int dim>
  void
  MixedSystem<dim>::build_sparsity_pattern(
    const std::vector<std::pair<unsigned int, unsigned int>> &couplings)
  {
    // Every unknown of a cell with points couples with every other one of that cell, and with
    // every unknown of the cells the terms couple it with.
    dealii::DynamicSparsityPattern               pattern(spaces_.n_dofs(), spaces_.n_dofs());
    std::vector<dealii::types::global_dof_index> dofs, other;
    for (const PointBlock &b : cache.blocks())
      {
        cache.unknowns_of_block(b, dofs);
        for (const auto row : dofs)
          pattern.add_entries(row, dofs.begin(), dofs.end(), true);
      }
    // On a refined grid every piece of an active cell: a surface point can move into a piece
    // without volume points, and so form a block, while the classification (which decides when
    // the pattern is rebuilt) stays. Measured: the refined swelling sphere added entries outside
    // the pattern of its block-only version. Where faces are separated, a cell whose points all
    // use copies can be joined by a point that uses its own functions, the separation staying.
    if (spaces_.refined() || !spaces_.u_copies().empty())
      for (unsigned int c = 0; c < cache.classification().size(); ++c)
        if (cache.classification()[c])
          for (unsigned int p = 0; p < spaces_.u().n_pieces(c); ++p)
            {
              cache.unknowns_of_block(cache.block_for(c, p), dofs);
              for (const auto row : dofs)
                pattern.add_entries(row, dofs.begin(), dofs.end(), true);
            }
    for (const auto &[a, b] : couplings)
      {
        unknowns_of_cell(a, dofs);
        unknowns_of_cell(b, other);
        for (const auto row : dofs)
          pattern.add_entries(row, other.begin(), other.end(), true);
        for (const auto row : other)
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
    const auto [owned, relevant] = owned_and_relevant_dofs(couplings);
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
  std::pair<dealii::IndexSet, dealii::IndexSet>
  MixedSystem<dim>::owned_and_relevant_dofs(
    const std::vector<std::pair<unsigned int, unsigned int>> &couplings) const
  {
    // A B-spline function spans q + 1 cells, more than a ghost layer: ownership is decided on
    // the replicated classification instead. Each unknown belongs to the rank that holds the
    // first active cell (in the grid's order) that its function reaches; every rank computes the
    // same map. The relevant unknowns of a rank are those of the cells its points are in.
    const unsigned int        n_u  = spaces_.n_u_dofs();
    const unsigned int        rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    std::vector<unsigned int> owner(spaces_.n_dofs(), dealii::numbers::invalid_unsigned_int);
    const auto               &classification = cache.classification();
    const auto               &cell_holder    = cache.cell_holder();
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
    for (const PointBlock &b : cache.blocks())
      {
        cache.unknowns_of_block(b, dofs);
        relevant.add_indices(dofs.begin(), dofs.end());
      }
    for (const auto &pair : couplings)
      for (const unsigned int c : {pair.first, pair.second})
        {
          unknowns_of_cell(c, dofs);
          relevant.add_indices(dofs.begin(), dofs.end());
        }
    relevant.add_indices(owned);
    owned.compress();
    relevant.compress();
    return {owned, relevant};
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::freeze_switches(const dealii::Vector<double> &solution, const bool hold)
  {
    unsigned int changed = 0;
    // Only an impermeable obstacle switches a condition; otherwise nothing to evaluate.
    if (terms.contact() != nullptr && terms.contact()->seals_anywhere())
      for (auto &r : cache.points())
        {
          if (r.kind == PointKind::volume || r.piece < 0 ||
              !boundary_conditions.piece(r.piece).chemical_potential_prescribed())
            continue;
          const auto [du, delta_F, mu] = cache.fields_at(r, solution);
          const signed char seal       = terms.contact()->touches_impermeable(r, du, delta_F, mu);
          changed += r.seal >= 0 && r.seal != seal;
          if (hold)
            r.seal = seal;
        }
    // The rigid obstacles' active sets under Nitsche's method (a grid side's plane is not held;
    // the penalty follows the iterate: held, its sphere refined three times took states with a
    // point still flipping and an undrained force 10 % above the converged one).
    if (terms.contact() != nullptr && terms.contact()->holds_active_set())
      for (auto &r : cache.points())
        {
          if (r.kind == PointKind::volume || !terms.contact()->applies(r))
            continue;
          const auto [du, delta_F, mu] = cache.fields_at(r, solution);
          const auto active            = terms.contact()->active_rigid(r, du, delta_F, mu);
          changed += r.contact_held >= 0 && r.contact_held != active;
          if (hold)
            r.contact_held = active;
        }
    if (const auto *self = terms.self_contact())
      changed += self->hold_active_pairs(cache, solution, hold);
    return dealii::Utilities::MPI::sum(changed, communicator);
  }


  template <int dim>
  void
  MixedSystem<dim>::release_switches()
  {
    if (const auto *self = terms.self_contact())
      self->release_active_pairs();
    for (auto &r : cache.points())
      {
        r.seal         = -1;
        r.contact_held = -1;
      }
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
    for (auto &r : cache.points())
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
        const auto start = point_state(r,
                                       Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()),
                                       Tensor<1, dim>(),
                                       r.mu_n);
        r.adjoint_solvent_n =
          r.measure *
          dealii::scalar_product(outer(r.projector * (r.u_n - u_bar_n), r.normal), start.dP_n_dmu);
      }
    boundary_conditions.set_time(t_over_tau_d);
    if (obstacles != nullptr)
      for (auto &obstacle : *obstacles)
        obstacle.set_time(t_over_tau_d);
    for (auto &r : cache.points())
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
  std::vector<unsigned int>
  MixedSystem<dim>::assembly_order() const
  {
    const auto               &blocks = cache.blocks();
    std::vector<unsigned int> order(blocks.size());
    std::iota(order.begin(), order.end(), 0u);
    if (dim < 3)
      return order;
    // In 3D a block's rows of the tangent are long (about 400 entries) and the matrix far
    // exceeds the cache: in the cells' lexicographic order a row comes back only a plane of
    // cells later. The Z-order of the cells (their indices' bits interleaved) keeps the blocks
    // that share rows close in time; the copier adds in this order on any number of threads,
    // so the sums stay deterministic.
    const auto           &n_cells = spaces_.u_space().n_cells_per_direction();
    std::vector<uint64_t> key(blocks.size());
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        unsigned int c = blocks[b].u_cell;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int x = c % n_cells[d];
            c /= n_cells[d];
            for (unsigned int bit = 0; bit < 21; ++bit)
              key[b] |= uint64_t((x >> bit) & 1u) << (dim * bit + d);
          }
      }
    std::sort(order.begin(), order.end(), [&key](const unsigned int a, const unsigned int b) {
      return key[a] < key[b];
    });
    return order;
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

    const auto               &blocks        = cache.blocks();
    std::vector<unsigned int> block_indices = assembly_order();
    bool                      failed        = false;
    std::string               failure;
    const SerialBlasScope     serial_blas;
    dealii::WorkStream::run(
      block_indices.begin(),
      block_indices.end(),
      [&](const std::vector<unsigned int>::iterator &it,
          AssemblyScratch<dim>                      &scratch,
          AssemblyCopy                              &copy) {
        assemble_block(blocks[*it], solution, dt, with_matrix, scratch, copy);
      },
      [&](const AssemblyCopy &copy) {
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
      AssemblyScratch<dim>(),
      AssemblyCopy());
    if (!failed)
      add_beyond_blocks(solution, dt, with_matrix);
    if (with_matrix)
      matrix_.compress(dealii::VectorOperation::add);
    Collective::sum_in_place(communicator, residual_.begin(), residual_.size());
    // Collective: every rank learns of a failure on any, before the next collective call.
    Collective::agree_on_failure<NonPhysicalState>(communicator, failed ? failure : "");
  }


  template <int dim>
  void
  MixedSystem<dim>::add_beyond_blocks(const dealii::Vector<double> &solution,
                                      const double                  dt,
                                      const bool                    with_matrix)
  {
    std::vector<AssemblyCopy> copies;
    for (const auto *term : terms.all())
      term->assemble_beyond_blocks(cache, solution, dt, with_matrix, copies);
    for (auto &copy : copies)
      {
        // The axis unknowns keep only their blocks' diagonal entries.
        for (unsigned int i = 0; i < copy.dofs.size() && !on_axis.empty(); ++i)
          if (on_axis[copy.dofs[i]])
            {
              copy.residual(i) = 0.;
              for (unsigned int j = 0; j < copy.dofs.size() && with_matrix; ++j)
                copy.matrix(i, j) = copy.matrix(j, i) = 0.;
            }
        for (unsigned int i = 0; i < copy.dofs.size(); ++i)
          residual_(copy.dofs[i]) += copy.residual(i);
        if (with_matrix)
          add_to_matrix(copy);
      }
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::unseen_self_contacts(const dealii::Vector<double> &solution) const
  {
    if (const auto *self = terms.self_contact())
      return self->unseen_contacts(cache, solution);
    return 0;
  }


  template <int dim>
  typename MixedSystem<dim>::SelfContactState
  MixedSystem<dim>::self_contact_state(const dealii::Vector<double> &solution) const
  {
    SelfContactState state;
    if (const auto *self = terms.self_contact())
      {
        const auto s      = self->state(cache, solution);
        state.points      = s.points;
        state.force       = s.force;
        state.area        = s.area;
        state.penetration = s.penetration;
        state.deepest_X0  = s.deepest_X0;
      }
    return state;
  }


  template <int dim>
  void
  MixedSystem<dim>::hold_axis_in_block(AssemblyCopy &copy, const bool with_matrix) const
  {
    const unsigned int n = copy.dofs.size();
    for (unsigned int i = 0; i < n; ++i)
      if (on_axis[copy.dofs[i]])
        {
          copy.residual(i) = 0.;
          if (with_matrix)
            for (unsigned int j = 0; j < n; ++j)
              if (j != i)
                copy.matrix(i, j) = copy.matrix(j, i) = 0.;
        }
  }


  template <int dim>
  void
  MixedSystem<dim>::hold_axis(dealii::Vector<double> &solution) const
  {
    for (unsigned int i = 0; i < on_axis.size(); ++i)
      if (on_axis[i])
        solution(i) = 0.;
  }


  template <int dim>
  void
  MixedSystem<dim>::add_to_matrix(const AssemblyCopy &copy)
  {
    if (!rows_are_local_and_sorted)
      {
        matrix_.add(copy.dofs, copy.matrix);
        return;
      }
    // One rank: local and global indices coincide and every row's columns are sorted, as are
    // the block's unknowns (but where copies of functions replace some of them, PointCache::
    // separate_faces()), so one merge per row finds the entries; the generic add searches
    // for each entry and was the largest serial part of the assembly.
    const Epetra_CrsMatrix   &A = matrix_.trilinos_matrix();
    const unsigned int        n = copy.dofs.size();
    std::vector<unsigned int> order;
    if (!std::is_sorted(copy.dofs.begin(), copy.dofs.end()))
      {
        order.resize(n);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [&copy](const unsigned int a, const unsigned int b) {
          return copy.dofs[a] < copy.dofs[b];
        });
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        int     length;
        double *values;
        int    *columns;
        A.ExtractMyRowView(static_cast<int>(copy.dofs[i]), length, values, columns);
        int k = 0;
        for (unsigned int jj = 0; jj < n; ++jj)
          {
            const unsigned int j      = order.empty() ? jj : order[jj];
            const int          column = static_cast<int>(copy.dofs[j]);
            while (k < length && columns[k] < column)
              ++k;
            // Checked in every build: a coupling the pattern lacks would otherwise be added
            // to a neighbouring entry without a word.
            if (k == length || columns[k] != column)
              throw std::logic_error("MixedSystem: the tangent's entry (" +
                                     std::to_string(copy.dofs[i]) + ", " +
                                     std::to_string(copy.dofs[j]) +
                                     ") lies outside its sparsity pattern (an internal error: "
                                     "a term couples unknowns the pattern does not)");
            values[k] += copy.matrix(i, j);
          }
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
    AssemblyScratch<dim>      scratch;
    AssemblyCopy              copy;
    // One solvent: k_BT/nu is the same in every region (MaterialRegions).
    const double kTnu = materials[0].kT_over_nu();
    for (const auto &block : cache.blocks())
      {
        bool has_surface_points = false;
        for (unsigned int p = block.first; p < block.end && !has_surface_points; ++p)
          has_surface_points =
            cache.points()[p].kind != PointKind::volume && cache.points()[p].assembled;
        if (!has_surface_points)
          continue;
        scratch.gather_block_coefficients(block, cache, spaces_, solution);
        const unsigned int mu0 = dim * scratch.n_u;
        for (unsigned int p = block.first; p < block.end; ++p)
          {
            const PointRecord<dim> &point = cache.points()[p];
            if (point.kind == PointKind::volume || !point.assembled)
              continue;
            scratch.evaluate_point_fields(point, cache);
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
  std::vector<typename MixedSystem<dim>::ObstacleReaction>
  MixedSystem<dim>::obstacle_reactions(const dealii::Vector<double> &solution) const
  {
    // Each obstacle's own contact terms, tested with w = e_k as boundary_balances() tests the
    // pieces' terms: the force on the gel is minus their sum, the force on the obstacle their sum.
    const auto *contact = terms.contact();
    if (contact == nullptr)
      return {};
    std::vector<ObstacleReaction> reactions(contact->n_rigid_obstacles());
    AssemblyScratch<dim>          scratch;
    AssemblyCopy                  copy;
    for (const auto &block : cache.blocks())
      {
        bool has_contact_points = false;
        for (unsigned int p = block.first; p < block.end && !has_contact_points; ++p)
          has_contact_points = cache.points()[p].kind != PointKind::volume &&
                               cache.points()[p].assembled && contact->applies(cache.points()[p]);
        if (!has_contact_points)
          continue;
        scratch.gather_block_coefficients(block, cache, spaces_, solution);
        for (unsigned int p = block.first; p < block.end; ++p)
          {
            const PointRecord<dim> &point = cache.points()[p];
            if (point.kind == PointKind::volume || !point.assembled || !contact->applies(point))
              continue;
            scratch.evaluate_point_fields(point, cache);
            for (unsigned int k = 0; k < reactions.size(); ++k)
              {
                const unsigned int index = contact->index_of_rigid(k);
                const auto [active, g]   = contact->state(index,
                                                        point,
                                                        scratch.du_at_point,
                                                        scratch.delta_F,
                                                        scratch.mu_at_point);
                (void)g;
                if (!active)
                  continue;
                copy.residual.reinit(dim * scratch.n_u + scratch.n_mu);
                contact->assemble_obstacle(index, point, false, scratch, copy);
                auto &reaction = reactions[k];
                for (unsigned int a = 0; a < scratch.n_u; ++a)
                  for (unsigned int d = 0; d < dim; ++d)
                    reaction.force[d] += copy.residual(dim * a + d);
                reaction.area += point.measure;
                reaction.radius = std::max(reaction.radius,
                                           contact->rigid_obstacle(k).distance_from_axis(
                                             point.x + point.edge_offset + scratch.du_at_point));
              }
          }
      }
    for (auto &reaction : reactions)
      {
        for (unsigned int d = 0; d < dim; ++d)
          reaction.force[d] = dealii::Utilities::MPI::sum(reaction.force[d], communicator);
        reaction.area   = dealii::Utilities::MPI::sum(reaction.area, communicator);
        reaction.radius = dealii::Utilities::MPI::max(reaction.radius, communicator);
      }
    return reactions;
  }


  template <int dim>
  void
  MixedSystem<dim>::assemble_block(const PointBlock             &block,
                                   const dealii::Vector<double> &solution,
                                   const double                  dt,
                                   const bool                    with_matrix,
                                   AssemblyScratch<dim>         &scratch,
                                   AssemblyCopy                 &copy) const
  {
    const auto        &u_dofs  = cache.u_dofs(block);
    const auto        &mu_dofs = cache.mu_dofs(block);
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

    scratch.gather_block_coefficients(block, cache, spaces_, solution);
    for (const auto *term : terms.all())
      term->start_block(scratch, block.end - block.first, with_matrix);

    unsigned int failed_point = block.first;
    try
      {
        for (unsigned int p = block.first; p < block.end; ++p)
          {
            failed_point                  = p;
            const PointRecord<dim> &point = cache.points()[p];
            if (!point.assembled)
              continue;
            scratch.evaluate_point_fields(point, cache);

            if (point.kind == PointKind::volume)
              for (const auto *term : terms.at_volume_points())
                term->assemble(point, dt, with_matrix, scratch, copy);
            else
              add_surface_point(point, dt, with_matrix, scratch, copy);
          }
        for (const auto *term : terms.all())
          term->finish_block(scratch, copy, with_matrix);
        if (!on_axis.empty())
          hold_axis_in_block(copy, with_matrix);
      }
    catch (const NonPhysicalState &e)
      {
        copy.failed  = true;
        copy.failure = describe_failure(e, cache.points()[failed_point], scratch, block.u_cell);
      }
  }


  template <int dim>
  void
  MixedSystem<dim>::add_surface_point(const PointRecord<dim> &point,
                                      const double            dt,
                                      const bool              with_matrix,
                                      AssemblyScratch<dim>   &scratch,
                                      AssemblyCopy           &copy) const
  {
    for (const auto *term : terms.at_surface_points())
      term->assemble(point, dt, with_matrix, scratch, copy);
  }


  template <int dim>
  std::string
  MixedSystem<dim>::describe_failure(const NonPhysicalState     &error,
                                     const PointRecord<dim>     &point,
                                     const AssemblyScratch<dim> &scratch,
                                     const unsigned int          u_cell) const
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
  unsigned int
  MixedSystem<dim>::n_u_dofs() const
  {
    return spaces_.n_u_dofs();
  }


  template <int dim>
  std::vector<double>
  MixedSystem<dim>::mu_from_points() const
  {
    return projection.project(false, 1, [](const PointRecord<dim> &r, unsigned int) {
      return r.mu_n;
    });
  }


  template <int dim>
  std::vector<double>
  MixedSystem<dim>::displacement_from_points(const double ratio) const
  {
    return projection.project(true, dim, [ratio](const PointRecord<dim> &r, const unsigned int c) {
      return ratio * r.du_last[c];
    });
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
  void
  MixedSystem<dim>::set_contact(const ContactSettings &settings)
  {
    contact_settings = settings;
    obstacles        = nullptr;
    build_terms();
  }


  template <int dim>
  void
  MixedSystem<dim>::set_contact(const ContactSettings &settings, std::vector<Obstacle<dim>> &rigid)
  {
    contact_settings = settings;
    obstacles        = &rigid;
    build_terms();
  }


  template <int dim>
  std::pair<unsigned int, double>
  MixedSystem<dim>::contact_state(const dealii::Vector<double> &solution) const
  {
    unsigned int active      = 0;
    double       penetration = 0.;
    const auto  *contact     = terms.contact();
    if (contact == nullptr)
      return {active, penetration};
    for (const auto &r : cache.points())
      {
        if (r.kind == PointKind::volume || r.piece < 0 ||
            boundary_conditions.piece(r.piece).displacement_prescribed())
          continue;
        const auto [du, delta_F, mu] = cache.fields_at(r, solution);
        const auto [is_active, g]    = contact->state(r, du, delta_F, mu);
        penetration                  = std::max(penetration, g);
        active += is_active;
      }
    return {dealii::Utilities::MPI::sum(active, communicator),
            dealii::Utilities::MPI::max(penetration, communicator)};
  }


  template <int dim>
  dealii::FullMatrix<double>
  MixedSystem<dim>::mu_mass_matrix() const
  {
    return projection.mu_mass_matrix();
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::n_points() const
  {
    return dealii::Utilities::MPI::sum(static_cast<unsigned int>(cache.points().size()),
                                       communicator);
  }


  template <int dim>
  unsigned int
  MixedSystem<dim>::n_active_cells() const
  {
    return cache.n_active_cells();
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

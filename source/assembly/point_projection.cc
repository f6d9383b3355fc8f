#include <gelmpm/assembly/point_projection.h>
#include <gelmpm/core/collective.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>

namespace GelMPM
{
  template <int dim>
  PointProjection<dim>::PointProjection(const PointCache<dim>     &cache,
                                        const DiscreteSpaces<dim> &spaces,
                                        const MPI_Comm             communicator)
    : cache(cache)
    , spaces(spaces)
    , communicator(communicator)
  {}


  template <int dim>
  std::vector<double>
  PointProjection<dim>::project(
    const bool                                                           displacement,
    const unsigned int                                                   n_components,
    const std::function<double(const PointRecord<dim> &, unsigned int)> &value) const
  {
    const auto &space   = displacement ? spaces.u() : spaces.mu();
    const auto  dofs_of = [&](const PointBlock &b) -> const std::vector<unsigned int>  &{
      return displacement ? cache.u_dofs(b) : cache.mu_dofs(b);
    };
    const unsigned int n = displacement ? spaces.n_u_dofs() / dim : spaces.n_mu_dofs();
    // On several ranks the pattern is that of every active cell, the same on all ranks, so
    // that the ranks' sums of the mass matrix add entry by entry and each rank solves the whole
    // projection (it is small against the Newton system). On one rank the blocks are the
    // active cells anyway.
    // Both depend on the classification alone: the pattern is kept with the tangent's.
    auto &sparsity = patterns[displacement ? 1 : 0];
    if (!sparsity)
      {
        dealii::DynamicSparsityPattern pattern(n, n);
        // Sorted: a block's list of u DoFs is not where copies of functions replace some of its
        // cell's (PointCache::separate_faces()).
        const auto add_dofs = [&](std::vector<unsigned int> dofs) {
          std::sort(dofs.begin(), dofs.end());
          for (const auto i : dofs)
            pattern.add_entries(i, dofs.begin(), dofs.end(), true);
        };
        if (Collective::is_parallel(communicator))
          {
            for (unsigned int c = 0; c < cache.classification().size(); ++c)
              if (cache.classification()[c])
                add_dofs(space.cell_dofs(displacement ? c : spaces.mu_cell_of(c)));
          }
        else
          for (const PointBlock &b : cache.blocks())
            add_dofs(dofs_of(b));
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
    for (const PointBlock &b : cache.blocks())
      {
        const auto        &dofs = dofs_of(b);
        const unsigned int m    = dofs.size();
        local_mass.reinit(m, m);
        local_rhs.reinit(n_components, m);
        for (unsigned int p = b.first; p < b.end; ++p)
          {
            const PointRecord<dim> &r = cache.points()[p];
            if (r.kind != PointKind::volume)
              continue;
            const double *values = displacement ? cache.u_values_at(r) : cache.mu_values_at(r);
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
  dealii::FullMatrix<double>
  PointProjection<dim>::mu_mass_matrix() const
  {
    dealii::FullMatrix<double> mass(spaces.n_mu_dofs(), spaces.n_mu_dofs());
    for (const auto &r : cache.points())
      if (r.kind == PointKind::volume)
        {
          const auto &dofs = cache.mu_dofs(cache.blocks()[r.block]);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            for (unsigned int j = 0; j < dofs.size(); ++j)
              mass(dofs[i], dofs[j]) +=
                r.measure * cache.mu_values_at(r)[i] * cache.mu_values_at(r)[j];
        }
    Collective::sum_in_place(communicator, &mass(0, 0), mass.n_elements());
    return mass;
  }


  template <int dim>
  void
  PointProjection<dim>::forget_patterns()
  {
    for (auto &pattern : patterns)
      pattern.reset();
  }


  template class PointProjection<2>;
  template class PointProjection<3>;
} // namespace GelMPM

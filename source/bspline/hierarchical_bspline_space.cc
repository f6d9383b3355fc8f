#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  template <int dim>
  HierarchicalBSplineSpace<dim>::HierarchicalBSplineSpace(
    const unsigned int                            degree,
    const dealii::Point<dim>                     &lower,
    const dealii::Point<dim>                     &upper,
    const std::array<unsigned int, dim>          &n_cells,
    const std::vector<std::vector<unsigned int>> &refined_cells)
    : degree_(degree)
  {
    const unsigned int n_levels = refined_cells.size() + 1;
    for (unsigned int l = 0; l < n_levels; ++l)
      {
        std::array<unsigned int, dim> cells = n_cells;
        for (auto &n : cells)
          n <<= l;
        spaces.push_back(std::make_unique<BSplineSpace<dim>>(degree, lower, upper, cells));
      }
    for (unsigned int l = 0; l + 1 < n_levels; ++l)
      {
        children.emplace_back(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const dealii::FullMatrix<double> S =
              refinement_operator_1d(spaces[l]->basis_1d(d), spaces[l + 1]->basis_1d(d));
            auto &rows = children.back()[d];
            rows.resize(S.m());
            for (unsigned int I = 0; I < S.m(); ++I)
              for (unsigned int j = 0; j < S.n(); ++j)
                if (S(I, j) != 0.)
                  rows[I].emplace_back(j, S(I, j));
          }
      }
    mark_domains(refined_cells);
    select_active_functions();
    number_leaf_cells();
    build_leaf_coefficients();
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::degree() const
  {
    return degree_;
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::n_levels() const
  {
    return spaces.size();
  }


  template <int dim>
  const BSplineSpace<dim> &
  HierarchicalBSplineSpace<dim>::level_space(const unsigned int level) const
  {
    AssertIndexRange(level, spaces.size());
    return *spaces[level];
  }


  template <int dim>
  bool
  HierarchicalBSplineSpace<dim>::in_domain(const unsigned int level, const unsigned int cell) const
  {
    return domain[level][cell];
  }


  template <int dim>
  bool
  HierarchicalBSplineSpace<dim>::is_refined(const unsigned int level, const unsigned int cell) const
  {
    return refined[level][cell];
  }


  template <int dim>
  std::vector<std::vector<unsigned int>>
  HierarchicalBSplineSpace<dim>::refined_cells() const
  {
    std::vector<std::vector<unsigned int>> cells(spaces.size() - 1);
    for (unsigned int l = 0; l + 1 < spaces.size(); ++l)
      for (unsigned int c = 0; c < refined[l].size(); ++c)
        if (refined[l][c])
          cells[l].push_back(c);
    return cells;
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::n_active_functions() const
  {
    return active.size();
  }


  template <int dim>
  const typename HierarchicalBSplineSpace<dim>::LevelFunction &
  HierarchicalBSplineSpace<dim>::active_function(const unsigned int i) const
  {
    return active[i];
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::active_function_number(const unsigned int level,
                                                        const unsigned int index) const
  {
    return active_number[level][index];
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::n_leaf_cells() const
  {
    return leaves.size();
  }


  template <int dim>
  const typename HierarchicalBSplineSpace<dim>::LevelCell &
  HierarchicalBSplineSpace<dim>::leaf_cell(const unsigned int leaf) const
  {
    return leaves[leaf];
  }


  template <int dim>
  const std::vector<unsigned int> &
  HierarchicalBSplineSpace<dim>::leaf_functions(const unsigned int leaf) const
  {
    return functions_of_leaf[leaf];
  }


  template <int dim>
  const dealii::FullMatrix<double> &
  HierarchicalBSplineSpace<dim>::leaf_coefficients(const unsigned int leaf) const
  {
    return coefficients_of_leaf[leaf];
  }


  template <int dim>
  unsigned int
  HierarchicalBSplineSpace<dim>::leaf_cell_containing(const dealii::Point<dim> &p) const
  {
    unsigned int level = 0;
    unsigned int cell  = spaces[0]->cell_containing(p);
    // Down the levels through the refined cells. The child is clamped to the parent's two
    // halves per direction, so that a point on a face lands in a child of the cell its parent
    // level picked, whatever the round-off of the finer cell size.
    while (refined[level][cell])
      {
        const auto                    parent = spaces[level]->cell_multi_index(cell);
        const BSplineSpace<dim>      &fine   = *spaces[level + 1];
        std::array<unsigned int, dim> child;
        for (unsigned int d = 0; d < dim; ++d)
          child[d] = std::clamp(fine.basis_1d(d).cell_of(p[d]), 2 * parent[d], 2 * parent[d] + 1);
        ++level;
        cell = fine.cell_index(child);
      }
    return leaf_number[level][cell];
  }


  template <int dim>
  void
  HierarchicalBSplineSpace<dim>::evaluate(const dealii::Point<dim>            &p,
                                          const unsigned int                   leaf,
                                          std::vector<double>                 &values,
                                          std::vector<dealii::Tensor<1, dim>> &gradients) const
  {
    const LevelCell         &Q     = leaves[leaf];
    const BSplineSpace<dim> &space = *spaces[Q.level];
    const CompressedRows    &M     = compressed_coefficients[leaf];
    // The level's B-splines on the cell, in scratch space kept per thread: evaluate() is called
    // once per material point and step.
    thread_local std::vector<double>                 v;
    thread_local std::vector<dealii::Tensor<1, dim>> g;
    v.resize(space.functions_per_cell());
    g.resize(space.functions_per_cell());
    space.evaluate(p, Q.cell, v, g);
    const unsigned int n = M.row_start.size() - 1;
    values.resize(n);
    gradients.resize(n);
    for (unsigned int a = 0; a < n; ++a)
      {
        double                 value = 0.;
        dealii::Tensor<1, dim> gradient;
        for (unsigned int k = M.row_start[a]; k < M.row_start[a + 1]; ++k)
          {
            value += M.weight[k] * v[M.column[k]];
            gradient += M.weight[k] * g[M.column[k]];
          }
        values[a]    = value;
        gradients[a] = gradient;
      }
  }


  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  HierarchicalBSplineSpace<dim>::finest_level_coefficients(const unsigned int i) const
  {
    std::vector<std::pair<unsigned int, double>> c = {{active[i].index, 1.}};
    for (unsigned int k = active[i].level; k + 1 < spaces.size(); ++k)
      c = truncate_to_next_level(k, c);
    return c;
  }


  template <int dim>
  std::vector<unsigned int>
  HierarchicalBSplineSpace<dim>::support_cells(const unsigned int level,
                                               const unsigned int index) const
  {
    const BSplineSpace<dim> &space = *spaces[level];
    const auto               f     = space.function_multi_index(index);
    // Function j of a 1D basis is nonzero on cells j - q ... j (those in the grid).
    std::array<unsigned int, dim> first, count;
    unsigned int                  n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        first[d]               = f[d] >= degree_ ? f[d] - degree_ : 0;
        const unsigned int end = std::min(f[d], space.n_cells_per_direction()[d] - 1);
        count[d]               = end + 1 - first[d];
        n *= count[d];
      }
    std::vector<unsigned int> cells(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        std::array<unsigned int, dim> c;
        unsigned int                  rest = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            c[d] = first[d] + rest % count[d];
            rest /= count[d];
          }
        cells[k] = space.cell_index(c);
      }
    return cells;
  }


  template <int dim>
  bool
  HierarchicalBSplineSpace<dim>::all_flagged(const std::vector<std::vector<bool>> &flags,
                                             const unsigned int                    level,
                                             const std::vector<unsigned int>      &cells) const
  {
    return std::all_of(cells.begin(), cells.end(), [&](const unsigned int c) {
      return flags[level][c];
    });
  }


  template <int dim>
  bool
  HierarchicalBSplineSpace<dim>::reaches_refined_cell(const unsigned int level,
                                                      const unsigned int index) const
  {
    const auto cells = support_cells(level, index);
    return std::any_of(cells.begin(), cells.end(), [&](const unsigned int c) {
      return refined[level][c];
    });
  }


  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  HierarchicalBSplineSpace<dim>::truncate_to_next_level(
    const unsigned int                                  level,
    const std::vector<std::pair<unsigned int, double>> &coarse) const
  {
    const BSplineSpace<dim>       &coarse_space = *spaces[level];
    const BSplineSpace<dim>       &fine_space   = *spaces[level + 1];
    const auto                    &S            = children[level];
    std::map<unsigned int, double> fine;
    for (const auto &[I, c] : coarse)
      {
        const auto I_index = coarse_space.function_multi_index(I);
        // The tensor product of the directions' rows, odometer style.
        std::array<unsigned int, dim> position{};
        while (true)
          {
            std::array<unsigned int, dim> j;
            double                        value = c;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto &[jd, s] = S[d][I_index[d]][position[d]];
                j[d]                = jd;
                value *= s;
              }
            fine[fine_space.function_index(j)] += value;
            unsigned int d = 0;
            for (; d < dim; ++d)
              {
                if (++position[d] < S[d][I_index[d]].size())
                  break;
                position[d] = 0;
              }
            if (d == dim)
              break;
          }
      }
    std::vector<std::pair<unsigned int, double>> kept;
    for (const auto &[j, c] : fine)
      if (!all_flagged(domain, level + 1, support_cells(level + 1, j)))
        kept.emplace_back(j, c);
    return kept;
  }


  template <int dim>
  void
  HierarchicalBSplineSpace<dim>::mark_domains(
    const std::vector<std::vector<unsigned int>> &refined_cells)
  {
    const unsigned int L = spaces.size();
    domain.resize(L);
    refined.resize(L);
    for (unsigned int l = 0; l < L; ++l)
      {
        domain[l].assign(spaces[l]->n_cells(), l == 0);
        refined[l].assign(spaces[l]->n_cells(), false);
      }
    for (unsigned int l = 0; l + 1 < L; ++l)
      {
        for (const unsigned int c : refined_cells[l])
          {
            if (c >= spaces[l]->n_cells())
              throw std::invalid_argument("HierarchicalBSplineSpace: refined cell " +
                                          std::to_string(c) + " of level " + std::to_string(l) +
                                          " is not a cell of that level");
            if (!domain[l][c])
              throw std::invalid_argument("HierarchicalBSplineSpace: refined cell " +
                                          std::to_string(c) + " of level " + std::to_string(l) +
                                          " does not lie in the refined domain of that level " +
                                          "(its parent is not refined)");
            refined[l][c] = true;
          }
        // Omega^{l+1}: the children of the refined cells.
        for (unsigned int c = 0; c < spaces[l]->n_cells(); ++c)
          if (refined[l][c])
            {
              const auto parent = spaces[l]->cell_multi_index(c);
              for (unsigned int k = 0; k < (1u << dim); ++k)
                {
                  std::array<unsigned int, dim> child;
                  for (unsigned int d = 0; d < dim; ++d)
                    child[d] = 2 * parent[d] + ((k >> d) & 1u);
                  domain[l + 1][spaces[l + 1]->cell_index(child)] = true;
                }
            }
      }
  }


  template <int dim>
  void
  HierarchicalBSplineSpace<dim>::select_active_functions()
  {
    const unsigned int L = spaces.size();
    active_number.resize(L);
    std::vector<unsigned int> on_cell;
    for (unsigned int l = 0; l < L; ++l)
      {
        const BSplineSpace<dim> &space = *spaces[l];
        active_number[l].assign(space.n_functions(), dealii::numbers::invalid_unsigned_int);
        // Candidates: the B-splines nonzero on a cell of Omega^l.
        std::vector<bool> candidate(space.n_functions(), false);
        for (unsigned int c = 0; c < space.n_cells(); ++c)
          if (domain[l][c])
            {
              space.cell_functions(c, on_cell);
              for (const unsigned int i : on_cell)
                candidate[i] = true;
            }
        for (unsigned int i = 0; i < space.n_functions(); ++i)
          {
            if (!candidate[i])
              continue;
            const auto support = support_cells(l, i);
            if (all_flagged(domain, l, support) && !all_flagged(refined, l, support))
              {
                active_number[l][i] = active.size();
                active.push_back({l, i});
              }
          }
      }
  }


  template <int dim>
  void
  HierarchicalBSplineSpace<dim>::number_leaf_cells()
  {
    leaf_number.resize(spaces.size());
    for (unsigned int l = 0; l < spaces.size(); ++l)
      {
        leaf_number[l].assign(spaces[l]->n_cells(), dealii::numbers::invalid_unsigned_int);
        for (unsigned int c = 0; c < spaces[l]->n_cells(); ++c)
          if (domain[l][c] && !refined[l][c])
            {
              leaf_number[l][c] = leaves.size();
              leaves.push_back({l, c});
            }
      }
  }


  template <int dim>
  void
  HierarchicalBSplineSpace<dim>::build_leaf_coefficients()
  {
    const unsigned int n_local = spaces[0]->functions_per_cell();
    // Per leaf, its rows as (function, coefficients); functions are visited in increasing
    // number, so a leaf's rows come in increasing order.
    std::vector<std::vector<std::pair<unsigned int, std::vector<double>>>> rows(leaves.size());
    for (unsigned int i = 0; i < active.size(); ++i)
      {
        std::vector<std::pair<unsigned int, double>> c = {{active[i].index, 1.}};
        for (unsigned int k = active[i].level; k < spaces.size() && !c.empty(); ++k)
          {
            const BSplineSpace<dim> &space = *spaces[k];
            for (const auto &[tau, value] : c)
              {
                const auto t = space.function_multi_index(tau);
                for (const unsigned int cell : support_cells(k, tau))
                  {
                    const unsigned int leaf = leaf_number[k][cell];
                    if (leaf == dealii::numbers::invalid_unsigned_int)
                      continue;
                    const auto   q     = space.cell_multi_index(cell);
                    unsigned int local = 0, stride = 1;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        local += (t[d] - space.basis_1d(d).first_function(q[d])) * stride;
                        stride *= degree_ + 1;
                      }
                    if (rows[leaf].empty() || rows[leaf].back().first != i)
                      rows[leaf].emplace_back(i, std::vector<double>(n_local, 0.));
                    rows[leaf].back().second[local] += value;
                  }
              }
            if (k + 1 == spaces.size())
              break;
            // Only B-splines that reach a refined cell have a part on finer leaves.
            c.erase(std::remove_if(c.begin(),
                                   c.end(),
                                   [&](const std::pair<unsigned int, double> &entry) {
                                     return !reaches_refined_cell(k, entry.first);
                                   }),
                    c.end());
            c = truncate_to_next_level(k, c);
          }
      }
    functions_of_leaf.resize(leaves.size());
    coefficients_of_leaf.resize(leaves.size());
    compressed_coefficients.resize(leaves.size());
    for (unsigned int leaf = 0; leaf < leaves.size(); ++leaf)
      {
        auto           &M          = coefficients_of_leaf[leaf];
        CompressedRows &compressed = compressed_coefficients[leaf];
        M.reinit(rows[leaf].size(), n_local);
        compressed.row_start.push_back(0);
        for (unsigned int a = 0; a < rows[leaf].size(); ++a)
          {
            functions_of_leaf[leaf].push_back(rows[leaf][a].first);
            for (unsigned int b = 0; b < n_local; ++b)
              if (rows[leaf][a].second[b] != 0.)
                {
                  M(a, b) = rows[leaf][a].second[b];
                  compressed.column.push_back(b);
                  compressed.weight.push_back(rows[leaf][a].second[b]);
                }
            compressed.row_start.push_back(compressed.column.size());
          }
      }
  }


  template <int dim>
  std::vector<std::vector<unsigned int>>
  subdivision_refinement(const HierarchicalBSplineSpace<dim> &mu)
  {
    const auto                             mu_cells = mu.refined_cells();
    std::vector<std::vector<unsigned int>> u_cells(mu_cells.size());
    for (unsigned int l = 0; l < mu_cells.size(); ++l)
      {
        const BSplineSpace<dim>      &coarse = mu.level_space(l);
        std::array<unsigned int, dim> n_fine = coarse.n_cells_per_direction();
        dealii::Point<dim>            lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n_fine[d] *= 2;
            lower[d] = coarse.basis_1d(d).x_min();
            upper[d] = coarse.basis_1d(d).x_max();
          }
        // u's grid of level l, for its cell numbering.
        const BSplineSpace<dim> fine(1, lower, upper, n_fine);
        for (const unsigned int c : mu_cells[l])
          {
            const auto parent = coarse.cell_multi_index(c);
            for (unsigned int k = 0; k < (1u << dim); ++k)
              {
                std::array<unsigned int, dim> child;
                for (unsigned int d = 0; d < dim; ++d)
                  child[d] = 2 * parent[d] + ((k >> d) & 1u);
                u_cells[l].push_back(fine.cell_index(child));
              }
          }
        std::sort(u_cells[l].begin(), u_cells[l].end());
      }
    return u_cells;
  }


  template class HierarchicalBSplineSpace<1>;
  template class HierarchicalBSplineSpace<2>;
  template class HierarchicalBSplineSpace<3>;
  template std::vector<std::vector<unsigned int>>
  subdivision_refinement(const HierarchicalBSplineSpace<1> &);
  template std::vector<std::vector<unsigned int>>
  subdivision_refinement(const HierarchicalBSplineSpace<2> &);
  template std::vector<std::vector<unsigned int>>
  subdivision_refinement(const HierarchicalBSplineSpace<3> &);
} // namespace GelMPM

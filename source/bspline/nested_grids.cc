#include <gelmpm/bspline/nested_grids.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  NestedBSplineGrids<dim>::NestedBSplineGrids(const BSplineSpace<dim> &space,
                                              const unsigned int       max_levels)
    : finest(space)
  {
    const unsigned int q = space.degree();
    dealii::Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = space.basis_1d(d).x_min();
        upper[d] = space.basis_1d(d).x_max();
      }
    const BSplineSpace<dim> *fine = &space;
    while (spaces.size() < max_levels)
      {
        std::array<unsigned int, dim> n_cells = fine->n_cells_per_direction();
        bool                          even    = true;
        for (auto &n : n_cells)
          {
            even = even && n % 2 == 0 && n / 2 >= q + 1;
            n /= 2;
          }
        if (!even)
          break;
        spaces.push_back(std::make_unique<BSplineSpace<dim>>(q, lower, upper, n_cells));
        const BSplineSpace<dim> &coarse = *spaces.back();
        parents.emplace_back(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const dealii::FullMatrix<double> S =
              refinement_operator_1d(coarse.basis_1d(d), fine->basis_1d(d));
            auto &columns = parents.back()[d];
            columns.resize(S.n());
            for (unsigned int I = 0; I < S.m(); ++I)
              for (unsigned int i = 0; i < S.n(); ++i)
                if (S(I, i) != 0.)
                  columns[i].emplace_back(I, S(I, i));
          }
        fine = &coarse;
      }
  }


  template <int dim>
  const BSplineSpace<dim> &
  NestedBSplineGrids<dim>::fine_space() const
  {
    return finest;
  }


  template <int dim>
  unsigned int
  NestedBSplineGrids<dim>::n_levels() const
  {
    return spaces.size();
  }


  template <int dim>
  const BSplineSpace<dim> &
  NestedBSplineGrids<dim>::space(const unsigned int level) const
  {
    AssertIndexRange(level - 1, spaces.size());
    return *spaces[level - 1];
  }


  template <int dim>
  std::vector<NestedBSplineLevel>
  NestedBSplineGrids<dim>::levels(const ExtendedBSplineSpace<dim> &u) const
  {
    if (&u.space() != &finest)
      throw std::logic_error("NestedBSplineGrids: an extended space of another B-spline space");
    // The DoFs are the interior control points in increasing index: row i of the first
    // prolongation is DoF i.
    std::vector<unsigned int> functions;
    functions.reserve(u.n_dofs());
    for (unsigned int i = 0; i < finest.n_functions(); ++i)
      if (u.dof_of_control_point(i) != dealii::numbers::invalid_unsigned_int)
        functions.push_back(i);
    // The cells with material, level by level: a coarse cell holds material when one of the
    // cells it covers does.
    // The cells with material, grid by grid: a coarse cell holds material when one of the
    // cells it covers does.
    std::vector<unsigned int> cells;
    for (unsigned int c = 0; c < finest.n_cells(); ++c)
      if (u.cell_kind(c) != CellKind::outer)
        cells.push_back(c);
    // On the finest grid the blocks hold the DoFs among each cell's B-splines. Adding per
    // boundary control point the DoFs it is extrapolated from (the other couplings of a boundary
    // cell) changed the iterations by less than 4 % (cube at 20^3: 26.3 against 27.3 per solve;
    // §4.1 at 80 x 640: 17.3 against 17.6) at up to twice the smoothing work.
    const std::vector<std::vector<unsigned int>> fine_blocks = cell_blocks(0, cells, functions);

    std::vector<NestedBSplineLevel> result;
    for (unsigned int level = 1; level <= spaces.size(); ++level)
      {
        NestedBSplineLevel coarse = coarsen(level, functions);
        if (coarse.control_points.size() >= functions.size())
          break;
        coarse.row_blocks = level == 1 ? fine_blocks : cell_blocks(level - 1, cells, functions);
        const BSplineSpace<dim>  &fine_space = level == 1 ? finest : *spaces[level - 2];
        std::vector<unsigned int> coarse_cells;
        for (const unsigned int c : cells)
          {
            auto index = fine_space.cell_multi_index(c);
            for (auto &i : index)
              i /= 2;
            coarse_cells.push_back(spaces[level - 1]->cell_index(index));
          }
        std::sort(coarse_cells.begin(), coarse_cells.end());
        coarse_cells.erase(std::unique(coarse_cells.begin(), coarse_cells.end()),
                           coarse_cells.end());
        cells     = coarse_cells;
        functions = coarse.control_points;
        result.push_back(std::move(coarse));
      }
    return result;
  }


  template <int dim>
  std::vector<std::vector<unsigned int>>
  NestedBSplineGrids<dim>::cell_blocks(const unsigned int               level,
                                       const std::vector<unsigned int> &cells,
                                       const std::vector<unsigned int> &functions) const
  {
    const BSplineSpace<dim>  &space = level == 0 ? finest : *spaces[level - 1];
    std::vector<unsigned int> position(space.n_functions(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < functions.size(); ++k)
      position[functions[k]] = k;
    // The cells with even indices first: their blocks overlap by one function per direction
    // and cover all but the functions next to the edge of the material; then the other cells
    // whose block holds a function not yet covered.
    std::vector<std::vector<unsigned int>> blocks;
    std::vector<bool>                      covered(functions.size(), false);
    std::vector<unsigned int>              on_cell;
    for (const bool even_pass : {true, false})
      for (const unsigned int c : cells)
        {
          const auto index = space.cell_multi_index(c);
          const bool even  = std::all_of(index.begin(), index.end(), [](const unsigned int i) {
            return i % 2 == 0;
          });
          if (even != even_pass)
            continue;
          space.cell_functions(c, on_cell);
          std::vector<unsigned int> block;
          bool                      new_function = even;
          for (const unsigned int i : on_cell)
            if (position[i] != dealii::numbers::invalid_unsigned_int)
              {
                block.push_back(position[i]);
                new_function = new_function || !covered[position[i]];
              }
          if (block.empty() || !new_function)
            continue;
          for (const unsigned int k : block)
            covered[k] = true;
          std::sort(block.begin(), block.end());
          blocks.push_back(std::move(block));
        }
    return blocks;
  }


  template <int dim>
  NestedBSplineLevel
  NestedBSplineGrids<dim>::coarsen(const unsigned int               level,
                                   const std::vector<unsigned int> &fine_functions) const
  {
    const BSplineSpace<dim> &fine   = level == 1 ? finest : *spaces[level - 2];
    const BSplineSpace<dim> &coarse = *spaces[level - 1];
    const auto              &S      = parents[level - 1];

    // Entries with coarse control-point indices first; the columns are renumbered once the
    // functions that take part are known.
    NestedBSplineLevel result;
    result.n_rows = fine_functions.size();
    for (unsigned int d = 0; d < dim; ++d)
      result.n_cells.push_back(coarse.n_cells_per_direction()[d]);
    std::vector<bool> takes_part(coarse.n_functions(), false);
    for (unsigned int row = 0; row < fine_functions.size(); ++row)
      {
        const auto fine_index = fine.function_multi_index(fine_functions[row]);
        // The tensor product of the directions' columns, odometer style.
        std::array<unsigned int, dim> position{};
        while (true)
          {
            std::array<unsigned int, dim> coarse_index;
            double                        value = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto &[I, s] = S[d][fine_index[d]][position[d]];
                coarse_index[d]    = I;
                value *= s;
              }
            const unsigned int column = coarse.function_index(coarse_index);
            takes_part[column]        = true;
            result.prolongation.rows.push_back(row);
            result.prolongation.columns.push_back(column);
            result.prolongation.values.push_back(value);
            unsigned int d = 0;
            for (; d < dim; ++d)
              {
                if (++position[d] < S[d][fine_index[d]].size())
                  break;
                position[d] = 0;
              }
            if (d == dim)
              break;
          }
      }

    std::vector<unsigned int> number(coarse.n_functions(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int I = 0; I < coarse.n_functions(); ++I)
      if (takes_part[I])
        {
          number[I] = result.control_points.size();
          result.control_points.push_back(I);
          const auto index = coarse.function_multi_index(I);
          for (unsigned int d = 0; d < dim; ++d)
            result.greville_points.push_back(coarse.basis_1d(d).greville(index[d]));
        }
    for (auto &column : result.prolongation.columns)
      column = number[column];
    return result;
  }


  template class NestedBSplineGrids<1>;
  template class NestedBSplineGrids<2>;
  template class NestedBSplineGrids<3>;
} // namespace GelMPM

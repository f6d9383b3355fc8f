#include <gelmpm/bspline/extended_bspline_space.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  namespace
  {
    /** Calls f(multi_index) for every multi-index in the box [lo, hi] (inclusive). */
    template <int dim, typename F>
    void
    for_each_in_box(const std::array<int, dim> &lo, const std::array<int, dim> &hi, const F &f)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (lo[d] > hi[d])
          return;
      std::array<int, dim> i = lo;
      while (true)
        {
          f(i);
          unsigned int d = 0;
          for (; d < dim; ++d)
            {
              if (++i[d] <= hi[d])
                break;
              i[d] = lo[d];
            }
          if (d == dim)
            return;
        }
    }

    template <int dim>
    std::array<unsigned int, dim>
    to_unsigned(const std::array<int, dim> &i)
    {
      std::array<unsigned int, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = i[d];
      return u;
    }
  } // namespace


  template <int dim>
  ExtendedBSplineSpace<dim>::ExtendedBSplineSpace(const BSplineSpace<dim> &space,
                                                  const std::vector<bool> &cell_has_material,
                                                  const bool               use_extension,
                                                  const bool exact_extrapolation_required)
    : space_(space)
    , use_extension(use_extension)
    , exact_extrapolation_required(exact_extrapolation_required)
  {
    if (cell_has_material.size() != space.n_cells())
      throw std::invalid_argument("ExtendedBSplineSpace: one material flag per cell expected");
    classify_cells(cell_has_material);
    classify_control_points();
    if (use_extension)
      compute_extrapolation_weights();
    build_cell_matrices();
  }


  template <int dim>
  ExtendedBSplineSpace<dim>::ExtendedBSplineSpace(const HierarchicalBSplineSpace<dim> &hierarchy,
                                                  const std::vector<bool> &cell_has_material,
                                                  const std::vector<bool> &leaf_has_material,
                                                  const bool               use_extension,
                                                  const bool exact_extrapolation_required)
    : space_(hierarchy.level_space(0))
    , use_extension(use_extension)
    , exact_extrapolation_required(exact_extrapolation_required)
    , hierarchy(&hierarchy)
  {
    if (cell_has_material.size() != space_.n_cells() ||
        leaf_has_material.size() != hierarchy.n_leaf_cells())
      throw std::invalid_argument("ExtendedBSplineSpace: one material flag per cell expected");
    classify_cells(cell_has_material);
    classify_active_functions(leaf_has_material);
    number_hierarchical_dofs();
    build_leaf_matrices();
  }


  template <int dim>
  std::vector<std::vector<bool>>
  ExtendedBSplineSpace<dim>::material_per_level(const std::vector<bool> &leaf_has_material) const
  {
    const unsigned int             L = hierarchy->n_levels();
    std::vector<std::vector<bool>> material(L);
    for (unsigned int l = 0; l < L; ++l)
      material[l].assign(hierarchy->level_space(l).n_cells(), false);
    for (unsigned int leaf = 0; leaf < hierarchy->n_leaf_cells(); ++leaf)
      {
        const auto &[level, cell] = hierarchy->leaf_cell(leaf);
        material[level][cell]     = leaf_has_material[leaf];
      }
    const auto parent = [&](const unsigned int level, const unsigned int cell) {
      auto index = hierarchy->level_space(level).cell_multi_index(cell);
      for (auto &i : index)
        i >>= 1;
      return hierarchy->level_space(level - 1).cell_index(index);
    };
    // A refined cell holds material when one of its leaves does ...
    for (unsigned int l = L - 1; l > 0; --l)
      for (unsigned int c = 0; c < material[l].size(); ++c)
        if (hierarchy->in_domain(l, c) && material[l][c])
          material[l - 1][parent(l, c)] = true;
    // ... and a cell of a level outside that level's domain is part of a coarser leaf: it holds
    // material when that leaf does, which is what its neighbours of the level see.
    for (unsigned int l = 1; l < L; ++l)
      for (unsigned int c = 0; c < material[l].size(); ++c)
        if (!hierarchy->in_domain(l, c))
          material[l][c] = material[l - 1][parent(l, c)];
    return material;
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::classify_active_functions(const std::vector<bool> &leaf_has_material)
  {
    const std::vector<std::vector<bool>> material = material_per_level(leaf_has_material);
    const unsigned int                   n_active = hierarchy->n_active_functions();
    std::vector<bool>                    interior(n_active, false), boundary(n_active, false);
    for (unsigned int leaf = 0; leaf < hierarchy->n_leaf_cells(); ++leaf)
      {
        if (!leaf_has_material[leaf])
          continue;
        // A leaf is a boundary cell of its level when a neighbour of that level (face, edge or
        // corner) holds no material, as on the uniform grid (§3.5).
        const auto &[level, cell]  = hierarchy->leaf_cell(leaf);
        const BSplineSpace<dim> &s = hierarchy->level_space(level);
        const auto               c = s.cell_multi_index(cell);
        std::array<int, dim>     lo, hi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::max(0, static_cast<int>(c[d]) - 1);
            hi[d] = std::min(static_cast<int>(s.n_cells_per_direction()[d]) - 1,
                             static_cast<int>(c[d]) + 1);
          }
        bool next_to_outer = false;
        for_each_in_box<dim>(lo, hi, [&](const std::array<int, dim> &i) {
          next_to_outer |= !material[level][s.cell_index(to_unsigned<dim>(i))];
        });
        for (const unsigned int f : hierarchy->leaf_functions(leaf))
          (next_to_outer ? boundary : interior)[f] = true;
      }
    function_kinds.assign(n_active, ControlPointKind::outer);
    for (unsigned int f = 0; f < n_active; ++f)
      function_kinds[f] = interior[f]   ? ControlPointKind::interior
                          : boundary[f] ? ControlPointKind::boundary
                                        : ControlPointKind::outer;
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::number_hierarchical_dofs()
  {
    const unsigned int n_active = hierarchy->n_active_functions();
    function_dof.assign(n_active, dealii::numbers::invalid_unsigned_int);
    function_weights.assign(n_active, {});
    n_dofs_ = 0;
    for (unsigned int f = 0; f < n_active; ++f)
      if (function_kinds[f] == ControlPointKind::interior ||
          (function_kinds[f] == ControlPointKind::boundary && !use_extension))
        function_dof[f] = n_dofs_++;
    if (!use_extension)
      return;

    // Level by level: a boundary function is extrapolated from the nearest block of interior
    // functions of its own level. By the preservation of coefficients of THB-splines, the
    // coefficient of an active function in a polynomial is its B-spline coefficient of its
    // level, a polynomial of the index: the extrapolation is exact, as on the uniform grid.
    for (unsigned int level = 0; level < hierarchy->n_levels(); ++level)
      {
        const BSplineSpace<dim> &space = hierarchy->level_space(level);
        std::vector<bool>        interior(space.n_functions(), false);
        bool                     has_boundary = false;
        for (unsigned int i = 0; i < space.n_functions(); ++i)
          {
            const unsigned int f = hierarchy->active_function_number(level, i);
            if (f == dealii::numbers::invalid_unsigned_int)
              continue;
            interior[i] = function_kinds[f] == ControlPointKind::interior;
            has_boundary |= function_kinds[f] == ControlPointKind::boundary;
          }
        if (!has_boundary)
          continue;
        const std::vector<bool> block_ok = interior_blocks(space, interior);
        for (unsigned int i = 0; i < space.n_functions(); ++i)
          {
            const unsigned int f = hierarchy->active_function_number(level, i);
            if (f == dealii::numbers::invalid_unsigned_int ||
                function_kinds[f] != ControlPointKind::boundary)
              continue;
            for (const auto &[j, E] :
                 extrapolation_weights_from_nearest_block(space, block_ok, i, level))
              function_weights[f].emplace_back(hierarchy->active_function_number(level, j), E);
          }
      }
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::build_leaf_matrices()
  {
    leaves_of_cell.assign(space_.n_cells(), {});
    leaf_matrices_of_cell.assign(space_.n_cells(), {});
    leaf_dofs_of_cell.assign(space_.n_cells(), {});
    leaf_rows_in_cell.assign(space_.n_cells(), {});
    dofs_of_cell.assign(space_.n_cells(), {});
    piece_of_leaf.assign(hierarchy->n_leaf_cells(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int leaf = 0; leaf < hierarchy->n_leaf_cells(); ++leaf)
      {
        const auto &[level, cell] = hierarchy->leaf_cell(leaf);
        auto index                = hierarchy->level_space(level).cell_multi_index(cell);
        for (auto &i : index)
          i >>= level;
        const unsigned int base = space_.cell_index(index);
        piece_of_leaf[leaf]     = leaves_of_cell[base].size();
        leaves_of_cell[base].push_back(leaf);
      }

    for (unsigned int cell = 0; cell < space_.n_cells(); ++cell)
      {
        if (cell_kinds[cell] == CellKind::outer)
          continue;
        const auto &leaves = leaves_of_cell[cell];
        // dof -> per leaf, (local B-spline of the leaf's level, weight)
        std::map<unsigned int, std::vector<std::map<unsigned int, double>>> rows;
        const auto add = [&](const unsigned int dof,
                             const unsigned int piece,
                             const unsigned int a,
                             const double       E) {
          auto &row = rows[dof];
          row.resize(leaves.size());
          row[piece][a] += E;
        };
        for (unsigned int piece = 0; piece < leaves.size(); ++piece)
          {
            const auto &functions = hierarchy->leaf_functions(leaves[piece]);
            const auto &C         = hierarchy->leaf_coefficients(leaves[piece]);
            for (unsigned int r = 0; r < functions.size(); ++r)
              {
                const unsigned int f = functions[r];
                for (unsigned int a = 0; a < C.n(); ++a)
                  {
                    if (C(r, a) == 0.)
                      continue;
                    if (function_dof[f] != dealii::numbers::invalid_unsigned_int)
                      add(function_dof[f], piece, a, C(r, a));
                    else
                      for (const auto &[g, E] : function_weights[f])
                        add(function_dof[g], piece, a, E * C(r, a));
                  }
              }
          }
        // Per leaf, only the rows of the DoFs that are nonzero on it: the cell's DoFs are their
        // union.
        auto &dofs = dofs_of_cell[cell];
        for (const auto &row : rows)
          dofs.push_back(row.first);
        leaf_dofs_of_cell[cell].assign(leaves.size(), {});
        leaf_rows_in_cell[cell].assign(leaves.size(), {});
        leaf_matrices_of_cell[cell].assign(leaves.size(), CellMatrix());
        for (unsigned int piece = 0; piece < leaves.size(); ++piece)
          {
            auto &matrix = leaf_matrices_of_cell[cell][piece];
            matrix.row_start.push_back(0);
            unsigned int position = 0;
            for (const auto &[dof, per_leaf] : rows)
              {
                bool nonzero = false;
                if (piece >= per_leaf.size())
                  continue;
                for (const auto &[a, E] : per_leaf[piece])
                  if (E != 0.)
                    {
                      matrix.column.push_back(a);
                      matrix.weight.push_back(E);
                      nonzero = true;
                    }
                if (nonzero)
                  {
                    matrix.row_start.push_back(matrix.column.size());
                    leaf_dofs_of_cell[cell][piece].push_back(dof);
                    leaf_rows_in_cell[cell][piece].push_back(position);
                  }
                ++position;
              }
          }
      }
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::n_control_points() const
  {
    return hierarchy ? hierarchy->n_active_functions() : space_.n_functions();
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::classify_cells(const std::vector<bool> &cell_has_material)
  {
    const auto &n = space_.n_cells_per_direction();
    cell_kinds.assign(space_.n_cells(), CellKind::outer);
    for (unsigned int cell = 0; cell < space_.n_cells(); ++cell)
      {
        if (!cell_has_material[cell])
          continue;
        const auto           c = space_.cell_multi_index(cell);
        std::array<int, dim> lo, hi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::max(0, static_cast<int>(c[d]) - 1);
            hi[d] = std::min(static_cast<int>(n[d]) - 1, static_cast<int>(c[d]) + 1);
          }
        bool next_to_outer = false;
        for_each_in_box<dim>(lo, hi, [&](const std::array<int, dim> &i) {
          if (!cell_has_material[space_.cell_index(to_unsigned<dim>(i))])
            next_to_outer = true;
        });
        cell_kinds[cell] = next_to_outer ? CellKind::boundary : CellKind::interior;
      }
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::classify_control_points()
  {
    const auto &n = space_.n_cells_per_direction();
    const int   q = space_.degree();
    point_kinds.assign(space_.n_functions(), ControlPointKind::outer);
    dof_index.assign(space_.n_functions(), dealii::numbers::invalid_unsigned_int);
    n_dofs_ = 0;
    for (unsigned int i = 0; i < space_.n_functions(); ++i)
      {
        // The support of function f covers cells f-q ... f in each direction.
        const auto           f = space_.function_multi_index(i);
        std::array<int, dim> lo, hi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::max(0, static_cast<int>(f[d]) - q);
            hi[d] = std::min(static_cast<int>(n[d]) - 1, static_cast<int>(f[d]));
          }
        bool interior = false, boundary = false;
        for_each_in_box<dim>(lo, hi, [&](const std::array<int, dim> &c) {
          const CellKind kind = cell_kinds[space_.cell_index(to_unsigned<dim>(c))];
          interior |= (kind == CellKind::interior);
          boundary |= (kind == CellKind::boundary);
        });
        point_kinds[i]    = interior   ? ControlPointKind::interior
                            : boundary ? ControlPointKind::boundary
                                       : ControlPointKind::outer;
        const bool is_dof = interior || (boundary && !use_extension);
        if (is_dof)
          dof_index[i] = n_dofs_++;
      }
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::compute_extrapolation_weights()
  {
    std::vector<bool> interior(space_.n_functions());
    for (unsigned int i = 0; i < space_.n_functions(); ++i)
      interior[i] = point_kinds[i] == ControlPointKind::interior;
    const std::vector<bool> block_ok = interior_blocks(space_, interior);
    weights.assign(space_.n_functions(), {});
    for (unsigned int k = 0; k < space_.n_functions(); ++k)
      if (point_kinds[k] == ControlPointKind::boundary)
        weights[k] = extrapolation_weights_from_nearest_block(space_, block_ok, k, 0);
  }


  template <int dim>
  std::vector<bool>
  ExtendedBSplineSpace<dim>::interior_blocks(const BSplineSpace<dim> &space,
                                             const std::vector<bool> &interior) const
  {
    const int         q = space.degree();
    std::vector<bool> block_ok(space.n_functions(), false);
    for (unsigned int l = 0; l < space.n_functions(); ++l)
      {
        const auto           corner = space.function_multi_index(l);
        std::array<int, dim> lo, hi;
        bool                 fits = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = corner[d];
            hi[d] = corner[d] + q;
            fits &= (hi[d] < static_cast<int>(space.basis_1d(d).n_functions()));
          }
        if (!fits)
          continue;
        bool all_interior = true;
        for_each_in_box<dim>(lo, hi, [&](const std::array<int, dim> &i) {
          all_interior &= interior[space.function_index(to_unsigned<dim>(i))];
        });
        block_ok[l] = all_interior;
      }
    return block_ok;
  }


  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  ExtendedBSplineSpace<dim>::extrapolation_weights_from_nearest_block(
    const BSplineSpace<dim> &space,
    const std::vector<bool> &block_ok,
    const unsigned int       k,
    const unsigned int       level)
  {
    const int            q = space.degree();
    std::array<int, dim> n_functions;
    for (unsigned int d = 0; d < dim; ++d)
      n_functions[d] = space.basis_1d(d).n_functions();
    const int  max_radius = *std::max_element(n_functions.begin(), n_functions.end());
    const auto kk         = space.function_multi_index(k);

    // Scan windows of growing radius; once a block is found at Chebyshev radius r, a block at
    // smaller Euclidean distance lies within radius r*sqrt(dim).
    double               best_distance = std::numeric_limits<double>::max();
    double               best_centre   = std::numeric_limits<double>::max();
    std::array<int, dim> best;
    bool                 found = false;
    int                  limit = max_radius;
    for (int r = 1; r <= limit; ++r)
      {
        std::array<int, dim> lo, hi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::max(0, static_cast<int>(kk[d]) - q - r);
            hi[d] = std::min(n_functions[d] - q - 1, static_cast<int>(kk[d]) + r);
          }
        for_each_in_box<dim>(lo, hi, [&](const std::array<int, dim> &l) {
          if (!block_ok[space.function_index(to_unsigned<dim>(l))])
            return;
          double distance = 0., centre = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const int gap =
                std::max({0, l[d] - static_cast<int>(kk[d]), static_cast<int>(kk[d]) - (l[d] + q)});
              distance += gap * gap;
              const double offset = kk[d] - (l[d] + 0.5 * q);
              centre += offset * offset;
            }
          // Strictly better, or equal and lexicographically earlier (x fastest). Both
          // measures are sums of squared (half-)integers, so a tie is exact up to round-off.
          constexpr double tie    = 1e-12;
          bool             better = distance < best_distance - tie ||
                        (distance < best_distance + tie && centre < best_centre - tie);
          if (!better && found && std::abs(distance - best_distance) < tie &&
              std::abs(centre - best_centre) < tie)
            for (int d = dim - 1; d >= 0; --d)
              if (l[d] != best[d])
                {
                  better = l[d] < best[d];
                  break;
                }
          if (!found || better)
            {
              found         = true;
              best          = l;
              best_distance = distance;
              best_centre   = centre;
            }
        });
        if (found && limit == max_radius)
          limit = std::min(max_radius, static_cast<int>(std::ceil(r * std::sqrt(dim))) + 1);
      }
    if (!found && level == 0)
      {
        std::ostringstream where;
        where << "(";
        for (unsigned int d = 0; d < dim; ++d)
          where << (d > 0 ? ", " : "") << space.basis_1d(d).greville(kk[d]);
        where << ")";
        throw std::runtime_error(
          "extended B-splines: no block of (q+1)^dim interior control points for the boundary "
          "control point at " +
          where.str() +
          "; the body is thinner than q+1 interior cells there, or it ends within a cell at "
          "the grid's edge (a plane of symmetry that cuts cells: let the body end on a grid "
          "line there, or let the grid reach q+1 cells beyond it)");
      }
    if (!found)
      throw std::runtime_error(
        "extended B-splines: a boundary function of refinement level " + std::to_string(level) +
        " has no block of (q+1)^dim interior functions of its level; a refined region that "
        "meets the body's boundary must reach at least 2(q+1) cells of its finest level into "
        "the body (q = " +
        std::to_string(q) + ")");

    // Lagrange extrapolation in the index is exact for polynomials only where the B-spline
    // (Marsden) coefficients are polynomials of the index: away from the repeated end knots,
    // i.e. for indices q-1 ... n_cells in each direction that is extrapolated along.
    for (unsigned int d = 0; d < dim; ++d)
      {
        const int k_d = kk[d];
        if (k_d >= best[d] && k_d <= best[d] + q)
          continue;
        const bool exact =
          std::min(k_d, best[d]) >= q - 1 &&
          std::max(k_d, best[d] + q) <= static_cast<int>(space.n_cells_per_direction()[d]);
        if (exact)
          continue;
        if (!exact_extrapolation_required)
          {
            ++n_inexact;
            break;
          }
        throw std::runtime_error(
          "extended B-splines (degree " + std::to_string(q) + ", " +
          std::to_string(space.n_cells_per_direction()[d]) + " cells in direction " +
          std::to_string(d) +
          "): a boundary control point must be extrapolated across the first or last " +
          std::to_string(q) +
          " cells of the grid, where extrapolation is not exact; either the body's boundary "
          "cuts cells that close to the grid edge (enlarge the grid so that it reaches at "
          "least q cells beyond the body, or let the body end on the edge) or the body is "
          "only a few cells thick there (refine the grid)");
      }

    // Tensor-product Lagrange extrapolation weights, eq. (54).
    std::vector<std::pair<unsigned int, double>> block_weights;
    std::array<int, dim>                         hi;
    for (unsigned int d = 0; d < dim; ++d)
      hi[d] = best[d] + q;
    for_each_in_box<dim>(best, hi, [&](const std::array<int, dim> &i) {
      double E = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        for (int s = best[d]; s <= best[d] + q; ++s)
          if (s != i[d])
            E *= static_cast<double>(static_cast<int>(kk[d]) - s) / (i[d] - s);
      block_weights.emplace_back(space.function_index(to_unsigned<dim>(i)), E);
    });
    return block_weights;
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::n_inexact_extrapolations() const
  {
    return n_inexact;
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::build_cell_matrices()
  {
    dofs_of_cell.assign(space_.n_cells(), {});
    matrix_of_cell.assign(space_.n_cells(), CellMatrix());
    std::vector<unsigned int> local;
    for (unsigned int cell = 0; cell < space_.n_cells(); ++cell)
      {
        if (cell_kinds[cell] == CellKind::outer)
          continue;
        space_.cell_functions(cell, local);
        std::map<unsigned int, std::vector<std::pair<unsigned int, double>>>
          rows; // dof -> (local, weight)
        for (unsigned int a = 0; a < local.size(); ++a)
          {
            const unsigned int i = local[a];
            if (dof_index[i] != dealii::numbers::invalid_unsigned_int)
              rows[dof_index[i]].emplace_back(a, 1.);
            else if (point_kinds[i] == ControlPointKind::boundary)
              for (const auto &[interior, E] : weights[i])
                rows[dof_index[interior]].emplace_back(a, E);
          }
        auto &dofs   = dofs_of_cell[cell];
        auto &matrix = matrix_of_cell[cell];
        matrix.row_start.push_back(0);
        // Each row's entries arrive in increasing local index a.
        for (const auto &[dof, entries] : rows)
          {
            dofs.push_back(dof);
            for (const auto &[a, E] : entries)
              if (E != 0.)
                {
                  matrix.column.push_back(a);
                  matrix.weight.push_back(E);
                }
            matrix.row_start.push_back(matrix.column.size());
          }
      }
  }


  template <int dim>
  const BSplineSpace<dim> &
  ExtendedBSplineSpace<dim>::space() const
  {
    return space_;
  }


  template <int dim>
  CellKind
  ExtendedBSplineSpace<dim>::cell_kind(const unsigned int cell) const
  {
    return cell_kinds[cell];
  }


  template <int dim>
  ControlPointKind
  ExtendedBSplineSpace<dim>::control_point_kind(const unsigned int i) const
  {
    if (hierarchy)
      return function_kinds[i];
    return point_kinds[i];
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::n_dofs() const
  {
    return n_dofs_;
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::dof_of_control_point(const unsigned int i) const
  {
    if (hierarchy)
      return function_dof[i];
    return dof_index[i];
  }


  template <int dim>
  const std::vector<unsigned int> &
  ExtendedBSplineSpace<dim>::cell_dofs(const unsigned int cell) const
  {
    return dofs_of_cell[cell];
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::apply(const CellMatrix                          &E,
                                   const std::vector<double>                 &scratch_values,
                                   const std::vector<dealii::Tensor<1, dim>> &scratch_gradients,
                                   std::vector<double>                       &values,
                                   std::vector<dealii::Tensor<1, dim>>       &gradients)
  {
    for (unsigned int r = 0; r + 1 < E.row_start.size(); ++r)
      {
        double                 v = 0.;
        dealii::Tensor<1, dim> g;
        for (unsigned int k = E.row_start[r]; k < E.row_start[r + 1]; ++k)
          {
            v += E.weight[k] * scratch_values[E.column[k]];
            g += E.weight[k] * scratch_gradients[E.column[k]];
          }
        values[r]    = v;
        gradients[r] = g;
      }
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::evaluate(const dealii::Point<dim>            &p,
                                      const unsigned int                   cell,
                                      std::vector<double>                 &values,
                                      std::vector<dealii::Tensor<1, dim>> &gradients,
                                      std::vector<double>                 &scratch_values,
                                      std::vector<dealii::Tensor<1, dim>> &scratch_gradients) const
  {
    if (!hierarchy)
      {
        space_.evaluate(p, cell, scratch_values, scratch_gradients);
        apply(matrix_of_cell[cell], scratch_values, scratch_gradients, values, gradients);
        return;
      }
    // The piece's values, spread over the cell's DoFs (zero for those not on the piece).
    const unsigned int                               piece = piece_containing(p, cell);
    const auto                                      &rows  = leaf_rows_in_cell[cell][piece];
    thread_local std::vector<double>                 piece_values;
    thread_local std::vector<dealii::Tensor<1, dim>> piece_gradients;
    piece_values.resize(rows.size());
    piece_gradients.resize(rows.size());
    evaluate(p, cell, piece, piece_values, piece_gradients, scratch_values, scratch_gradients);
    std::fill(values.begin(), values.end(), 0.);
    std::fill(gradients.begin(), gradients.end(), dealii::Tensor<1, dim>());
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        values[rows[r]]    = piece_values[r];
        gradients[rows[r]] = piece_gradients[r];
      }
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::n_pieces(const unsigned int cell) const
  {
    return hierarchy ? leaves_of_cell[cell].size() : 1;
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::piece_containing(const dealii::Point<dim> &p,
                                              const unsigned int        cell) const
  {
    if (!hierarchy || leaves_of_cell[cell].size() == 1)
      return 0;
    // The leaf of the cell nearest to p: p clamped into the cell, a little inside.
    const auto         index = space_.cell_multi_index(cell);
    dealii::Point<dim> inside;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double h     = space_.cell_size(d);
        const double lower = space_.basis_1d(d).x_min() + index[d] * h;
        inside[d]          = std::clamp(p[d], lower + 1e-9 * h, lower + h - 1e-9 * h);
      }
    return piece_of_leaf[hierarchy->leaf_cell_containing(inside)];
  }


  template <int dim>
  bool
  ExtendedBSplineSpace<dim>::refined() const
  {
    return hierarchy != nullptr;
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::finest_level(const unsigned int cell) const
  {
    unsigned int level = 0;
    if (hierarchy)
      for (const unsigned int leaf : leaves_of_cell[cell])
        level = std::max(level, hierarchy->leaf_cell(leaf).level);
    return level;
  }


  template <int dim>
  unsigned int
  ExtendedBSplineSpace<dim>::leaf_of_piece(const unsigned int cell, const unsigned int piece) const
  {
    return leaves_of_cell[cell][piece];
  }


  template <int dim>
  const std::vector<unsigned int> &
  ExtendedBSplineSpace<dim>::cell_dofs(const unsigned int cell, const unsigned int piece) const
  {
    return hierarchy ? leaf_dofs_of_cell[cell][piece] : dofs_of_cell[cell];
  }


  template <int dim>
  void
  ExtendedBSplineSpace<dim>::evaluate(const dealii::Point<dim>            &p,
                                      const unsigned int                   cell,
                                      const unsigned int                   piece,
                                      std::vector<double>                 &values,
                                      std::vector<dealii::Tensor<1, dim>> &gradients,
                                      std::vector<double>                 &scratch_values,
                                      std::vector<dealii::Tensor<1, dim>> &scratch_gradients) const
  {
    if (!hierarchy)
      {
        evaluate(p, cell, values, gradients, scratch_values, scratch_gradients);
        return;
      }
    const auto &[level, leaf_cell] = hierarchy->leaf_cell(leaves_of_cell[cell][piece]);
    hierarchy->level_space(level).evaluate(p, leaf_cell, scratch_values, scratch_gradients);
    apply(leaf_matrices_of_cell[cell][piece], scratch_values, scratch_gradients, values, gradients);
  }


  template <int dim>
  const std::vector<std::pair<unsigned int, double>> &
  ExtendedBSplineSpace<dim>::extrapolation_weights(const unsigned int k) const
  {
    static const std::vector<std::pair<unsigned int, double>> none;
    if (hierarchy)
      return function_weights[k];
    return use_extension ? weights[k] : none;
  }


  template class ExtendedBSplineSpace<1>;
  template class ExtendedBSplineSpace<2>;
  template class ExtendedBSplineSpace<3>;
} // namespace GelMPM

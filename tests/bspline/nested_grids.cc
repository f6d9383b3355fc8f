// The prolongations of the nested B-spline grids (NestedBSplineGrids, the geometric multigrid on
// the displacement block) against the B-splines of the coarse grids themselves, q = 2, on a disk
// (2D, 32 x 48 cells) and a ball (3D, 16^3 cells) that cut the grid, away from its edges:
// - a random field of every coarse level (2h, 4h, ...), its coefficients prolonged level by level
//   to the DoFs of the extended space, evaluates to the coarse field at random points of the
//   interior cells, where every nonzero B-spline is a DoF, to 1e-12 relative;
// - a linear field, from its Greville coefficients on every coarse level, is reproduced on all
//   cells with material (boundary cells included: the extrapolation is exact for polynomials of
//   degree q) to 1e-12;
// - the levels: as many as the cell counts allow (each direction even, at least q + 1 cells),
//   each with fewer functions than the one above, and columns that are never empty.

#include <gelmpm/bspline/nested_grids.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "check_report.h"

using namespace dealii;
using namespace GelMPM;

namespace
{
  using check_report::all_ok;
  using check_report::report;

  /** y = P x for a prolongation. */
  std::vector<double>
  prolong(const NestedBSplineLevel &level, const std::vector<double> &x)
  {
    std::vector<double> y(level.n_rows, 0.);
    const auto         &P = level.prolongation;
    for (std::size_t k = 0; k < P.size(); ++k)
      y[P.rows[k]] += P.values[k] * x[P.columns[k]];
    return y;
  }

  /** The DoF coefficients of the extended space from those of the functions of level @p k. */
  std::vector<double>
  to_fine(const std::vector<NestedBSplineLevel> &levels,
          const unsigned int                     k,
          const std::vector<double>             &coefficients)
  {
    std::vector<double> x(levels[k - 1].control_points.size());
    for (unsigned int j = 0; j < x.size(); ++j)
      x[j] = coefficients[levels[k - 1].control_points[j]];
    for (unsigned int l = k; l-- > 0;)
      x = prolong(levels[l], x);
    return x;
  }

  template <int dim>
  double
  fine_value(const ExtendedBSplineSpace<dim> &u,
             const std::vector<double>       &dofs,
             const Point<dim>                &p,
             const unsigned int               cell)
  {
    const auto                 &cell_dofs = u.cell_dofs(cell);
    const unsigned int          n_local   = u.space().functions_per_cell();
    std::vector<double>         v(cell_dofs.size()), sv(n_local);
    std::vector<Tensor<1, dim>> g(cell_dofs.size()), sg(n_local);
    u.evaluate(p, cell, v, g, sv, sg);
    double value = 0.;
    for (unsigned int a = 0; a < cell_dofs.size(); ++a)
      value += v[a] * dofs[cell_dofs[a]];
    return value;
  }

  template <int dim>
  double
  coarse_value(const BSplineSpace<dim>   &space,
               const std::vector<double> &coefficients,
               const Point<dim>          &p)
  {
    const unsigned int          cell = space.cell_containing(p);
    std::vector<unsigned int>   functions;
    std::vector<double>         v(space.functions_per_cell());
    std::vector<Tensor<1, dim>> g(space.functions_per_cell());
    space.cell_functions(cell, functions);
    space.evaluate(p, cell, v, g);
    double value = 0.;
    for (unsigned int a = 0; a < functions.size(); ++a)
      value += v[a] * coefficients[functions[a]];
    return value;
  }

  /** A random point of @p cell. */
  template <int dim>
  Point<dim>
  point_in(const BSplineSpace<dim> &space, const unsigned int cell, std::mt19937 &rng)
  {
    std::uniform_real_distribution<> u(0., 1.);
    const auto                       index = space.cell_multi_index(cell);
    Point<dim>                       p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = space.basis_1d(d).x_min() + (index[d] + u(rng)) * space.cell_size(d);
    return p;
  }

  template <int dim>
  void
  check(const std::array<unsigned int, dim> &n_cells, const double radius)
  {
    std::cout << dim << "D, a ball of radius " << radius << " in [0, 1]^" << dim << ":"
              << std::endl;
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1.;
    const BSplineSpace<dim> space(2, Point<dim>(), upper, n_cells);
    Point<dim>              centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5 + 0.013 * (d + 1);
    // A cell holds material when its centre lies in the ball.
    std::vector<bool> material(space.n_cells());
    for (unsigned int c = 0; c < space.n_cells(); ++c)
      {
        const auto index = space.cell_multi_index(c);
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = (index[d] + 0.5) * space.cell_size(d);
        material[c] = x.distance(centre) < radius;
      }
    const ExtendedBSplineSpace<dim> u(space, material);
    const NestedBSplineGrids<dim>   grids(space);
    const auto                      levels = grids.levels(u);
    std::cout << "  " << u.n_dofs() << " DoFs; coarse levels of";
    for (const auto &level : levels)
      std::cout << " " << level.control_points.size();
    std::cout << " functions (grids: " << grids.n_levels() << ")" << std::endl;

    bool        fewer = true, columns_used = true;
    std::size_t above = u.n_dofs();
    for (const auto &level : levels)
      {
        fewer = fewer && level.control_points.size() < above && level.n_rows == above;
        std::vector<bool> used(level.control_points.size(), false);
        for (const auto column : level.prolongation.columns)
          used[column] = true;
        columns_used = columns_used && std::all_of(used.begin(), used.end(), [](bool b) {
                         return b;
                       });
        above        = level.control_points.size();
      }
    report("levels with more functions than the level above", fewer ? 0. : 1., 0.5);
    report("empty columns", columns_used ? 0. : 1., 0.5);

    std::mt19937                     rng(7);
    std::uniform_real_distribution<> coefficient(-1., 1.);
    for (unsigned int k = 1; k <= levels.size(); ++k)
      {
        const BSplineSpace<dim> &coarse = grids.space(k);
        std::vector<double>      random(coarse.n_functions()), linear(coarse.n_functions());
        for (unsigned int I = 0; I < coarse.n_functions(); ++I)
          {
            random[I]        = coefficient(rng);
            const auto index = coarse.function_multi_index(I);
            linear[I]        = 0.3;
            for (unsigned int d = 0; d < dim; ++d)
              linear[I] += (d + 1.) * coarse.basis_1d(d).greville(index[d]);
          }
        const auto fine_random  = to_fine(levels, k, random);
        const auto fine_linear  = to_fine(levels, k, linear);
        double     random_error = 0., random_scale = 0., linear_error = 0.;
        for (unsigned int c = 0; c < space.n_cells(); ++c)
          {
            if (!material[c])
              continue;
            for (unsigned int t = 0; t < 3; ++t)
              {
                const Point<dim> p     = point_in(space, c, rng);
                double           exact = 0.3;
                for (unsigned int d = 0; d < dim; ++d)
                  exact += (d + 1.) * p[d];
                linear_error =
                  std::max(linear_error, std::abs(fine_value(u, fine_linear, p, c) - exact));
                if (u.cell_kind(c) != CellKind::interior)
                  continue;
                const double reference = coarse_value(coarse, random, p);
                random_scale           = std::max(random_scale, std::abs(reference));
                random_error =
                  std::max(random_error, std::abs(fine_value(u, fine_random, p, c) - reference));
              }
          }
        std::cout << " level " << k << " (cell size " << (1u << k) << "h):" << std::endl;
        report("random field on interior cells, relative error",
               random_error / random_scale,
               1e-12);
        report("linear field on all cells with material, error", linear_error, 1e-12);
      }
  }
} // namespace


int
main()
{
  check<2>({{32, 48}}, 0.3);
  check<3>({{16, 16, 16}}, 0.3);
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

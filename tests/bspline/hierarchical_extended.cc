// Extended B-splines on a locally refined grid (ExtendedBSplineSpace over a
// HierarchicalBSplineSpace), 2D, q = 1, 2, 3: a grid-aligned box body [0, 0.5]^2 in a [0, 0.8]^2
// grid of 16 x 16 cells, refined once or twice in two bands: one across the body's top (level-0
// rows 8-11, columns 0-12, into the cells above the body; level-1 rows 18-19, columns 0-15),
// with the extension off (plain B-splines at every level), and one inside the body (level-0 rows
// 1-3, columns 0-3; level-1 rows 4-5, columns 0-5), with the extension on. A leaf cell holds
// material when its centre lies in the body.
// - At 3000 random points of the body, evaluated in their level-0 cell (the space finds the leaf),
//   the extended functions sum to 1 within 1e-12 and their gradients to 0 within 1e-10 / h_min.
// - Across the faces between leaf cells of different levels and between level-0 cells, a field
//   with random coefficients is continuous: |f(p - e n) - f(p + e n)| < 1e-5 for e = 1e-9.
// - Without refinement, the hierarchical path gives the uniform extended space exactly: the same
//   DoFs per cell and the same values (difference 0).
// - The top band with the extension on is refused (std::runtime_error): the extension is built
//   on level 0 only.
// - Control: a leaf function dropped from the cell lists (the sum without the last DoF of each
//   refined cell) is off by more than 1e-3 somewhere.
// Run with --figures to print the measured maxima.
#include <gelmpm/bspline/extended_bspline_space.h>
#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/base/numbers.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

using namespace dealii;
using namespace GelMPM;

namespace
{
  bool all_ok  = true;
  bool figures = false;

  const Point<2>                    lower(0., 0.), upper(0.8, 0.8), body_upper(0.5, 0.5);
  const std::array<unsigned int, 2> n_cells{{16, 16}};

  bool
  in_body(const Point<2> &p)
  {
    return p[0] < body_upper[0] && p[1] < body_upper[1];
  }

  Point<2>
  centre(const BSplineSpace<2> &space, const unsigned int cell)
  {
    const auto index = space.cell_multi_index(cell);
    Point<2>   c;
    for (unsigned int d = 0; d < 2; ++d)
      c[d] = space.basis_1d(d).x_min() + (index[d] + 0.5) * space.cell_size(d);
    return c;
  }

  std::vector<std::vector<unsigned int>>
  band(const unsigned int levels, const bool top)
  {
    // {first row, last row, last column} per level; the first column is 0.
    const unsigned int rows[2][2][3] = {{{1, 3, 3}, {4, 5, 5}}, {{8, 11, 12}, {18, 19, 15}}};
    std::vector<std::vector<unsigned int>> refined(levels);
    for (unsigned int l = 0; l < levels; ++l)
      for (unsigned int j = rows[top][l][0]; j <= rows[top][l][1]; ++j)
        for (unsigned int i = 0; i <= rows[top][l][2]; ++i)
          refined[l].push_back(j * (n_cells[0] << l) + i);
    return refined;
  }

  struct Field
  {
    const ExtendedBSplineSpace<2>    &space;
    std::vector<double>               coefficients;
    mutable std::vector<double>       v, sv;
    mutable std::vector<Tensor<1, 2>> g, sg;

    double
    operator()(const Point<2>    &p,
               const unsigned int cell,
               double            *sum          = nullptr,
               Tensor<1, 2>      *gradient_sum = nullptr,
               const bool         drop_last    = false) const
    {
      const auto &dofs = space.cell_dofs(cell);
      v.resize(dofs.size());
      g.resize(dofs.size());
      sv.resize(space.space().functions_per_cell());
      sg.resize(space.space().functions_per_cell());
      space.evaluate(p, cell, v, g, sv, sg);
      double f = 0.;
      if (sum)
        *sum = 0.;
      if (gradient_sum)
        *gradient_sum = Tensor<1, 2>();
      const unsigned int n = drop_last ? dofs.size() - 1 : dofs.size();
      for (unsigned int a = 0; a < n; ++a)
        {
          f += coefficients[dofs[a]] * v[a];
          if (sum)
            *sum += v[a];
          if (gradient_sum)
            *gradient_sum += g[a];
        }
      return f;
    }
  };

  void
  check(const unsigned int q, const unsigned int levels, const bool top)
  {
    const HierarchicalBSplineSpace<2> hierarchy(q, lower, upper, n_cells, band(levels, top));
    const BSplineSpace<2>            &base = hierarchy.level_space(0);
    std::vector<bool>                 cells(base.n_cells()), leaves(hierarchy.n_leaf_cells());
    for (unsigned int c = 0; c < base.n_cells(); ++c)
      cells[c] = in_body(centre(base, c));
    for (unsigned int l = 0; l < leaves.size(); ++l)
      {
        const auto &leaf = hierarchy.leaf_cell(l);
        leaves[l]        = in_body(centre(hierarchy.level_space(leaf.level), leaf.cell));
      }
    if (top)
      {
        bool refused = false;
        try
          {
            const ExtendedBSplineSpace<2> extended(hierarchy, cells, leaves, true, true);
          }
        catch (const std::runtime_error &)
          {
            refused = true;
          }
        all_ok &= refused;
        std::cout << "q=" << q << ", " << levels
                  << " level(s) across the top, extension on: refused: " << (refused ? "yes" : "NO")
                  << std::endl;
      }
    const ExtendedBSplineSpace<2> space(hierarchy, cells, leaves, !top, true);

    std::mt19937                           random(17 + q + 10 * levels);
    std::uniform_real_distribution<double> unit(0., 1.), coefficient(-1., 1.);
    Field field{space, std::vector<double>(space.n_dofs()), {}, {}, {}, {}};
    for (auto &c : field.coefficients)
      c = coefficient(random);

    const double h_min     = base.cell_size(0) / (1u << levels);
    double       worst_sum = 0., worst_gradient = 0., worst_dropped = 0.;
    for (unsigned int k = 0; k < 3000; ++k)
      {
        const Point<2>     p(body_upper[0] * unit(random), body_upper[1] * unit(random));
        const unsigned int cell = base.cell_containing(p);
        double             sum;
        Tensor<1, 2>       gradient;
        field(p, cell, &sum, &gradient);
        worst_sum      = std::max(worst_sum, std::abs(sum - 1.));
        worst_gradient = std::max(worst_gradient, gradient.norm() * h_min);
        if (levels > 0 && hierarchy.is_refined(0, cell))
          {
            field(p, cell, &sum, nullptr, true);
            worst_dropped = std::max(worst_dropped, std::abs(sum - 1.));
          }
      }

    // Faces y = const and x = const through the body, inside and at the band's edges.
    double       worst_jump = 0.;
    const double e          = 1e-9;
    for (unsigned int k = 0; k < 2000; ++k)
      {
        const unsigned int direction = k % 2;
        const double       h         = base.cell_size(direction) / (1u << levels);
        Point<2>           p(body_upper[0] * unit(random), body_upper[1] * unit(random));
        p[direction] = h * std::round(p[direction] / h);
        if (p[direction] <= 0. || p[direction] >= body_upper[direction])
          continue;
        Point<2> below = p, above = p;
        below[direction] -= e;
        above[direction] += e;
        worst_jump = std::max(worst_jump,
                              std::abs(field(below, base.cell_containing(below)) -
                                       field(above, base.cell_containing(above))));
      }

    const bool ok = worst_sum < 1e-12 && worst_gradient < 1e-10 && worst_jump < 1e-5 &&
                    (levels == 0 || worst_dropped > 1e-3);
    all_ok &= ok;
    std::cout << "q=" << q << ", " << levels << " level(s) "
              << (top ? "across the top, extension off: " : "inside, extension on: ")
              << space.n_dofs()
              << " DoFs; |sum - 1| < 1e-12, |sum of gradients| h_min < 1e-10, jumps < 1e-5"
              << (levels > 0 ? ", dropped DoF > 1e-3" : "") << ": " << (ok ? "yes" : "NO")
              << std::endl;
    if (figures)
      std::cout << "  measured: sum " << worst_sum << ", gradients " << worst_gradient << ", jump "
                << worst_jump << ", dropped " << worst_dropped << std::endl;
  }

  void
  check_uniform_equivalence(const unsigned int q)
  {
    const HierarchicalBSplineSpace<2> hierarchy(q, lower, upper, n_cells, {});
    const BSplineSpace<2>            &base = hierarchy.level_space(0);
    std::vector<bool>                 cells(base.n_cells());
    for (unsigned int c = 0; c < base.n_cells(); ++c)
      cells[c] = in_body(centre(base, c));
    const ExtendedBSplineSpace<2>          refined(hierarchy, cells, cells, true, true);
    const ExtendedBSplineSpace<2>          uniform(base, cells, true, true);
    bool                                   same       = refined.n_dofs() == uniform.n_dofs();
    double                                 difference = 0.;
    std::mt19937                           random(5 + q);
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<double>       v1, v2, s1(base.functions_per_cell()), s2(base.functions_per_cell());
    std::vector<Tensor<1, 2>> g1, g2, t1(base.functions_per_cell()), t2(base.functions_per_cell());
    for (unsigned int k = 0; k < 1000 && same; ++k)
      {
        const Point<2>     p(body_upper[0] * unit(random), body_upper[1] * unit(random));
        const unsigned int cell = base.cell_containing(p);
        same &= refined.cell_dofs(cell) == uniform.cell_dofs(cell);
        if (!same)
          break;
        v1.resize(refined.cell_dofs(cell).size());
        v2.resize(v1.size());
        g1.resize(v1.size());
        g2.resize(v1.size());
        refined.evaluate(p, cell, v1, g1, s1, t1);
        uniform.evaluate(p, cell, v2, g2, s2, t2);
        for (unsigned int a = 0; a < v1.size(); ++a)
          difference = std::max({difference, std::abs(v1[a] - v2[a]), (g1[a] - g2[a]).norm()});
      }
    (void)t1;
    const bool ok = same && difference == 0.;
    all_ok &= ok;
    std::cout << "q=" << q << ", no refinement: the uniform extended space's DoFs and values: "
              << (ok ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  figures = argc > 1 && std::string(argv[1]) == "--figures";
  for (unsigned int q = 1; q <= 3; ++q)
    {
      check_uniform_equivalence(q);
      for (unsigned int levels = 1; levels <= 2; ++levels)
        for (const bool top : {false, true})
          check(q, levels, top);
    }
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

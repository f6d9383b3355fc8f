// Truncated hierarchical B-splines of degree q (HierarchicalBSplineSpace) are C^(q-1) across
// the boundaries between levels: for a field with random coefficients in [-1, 1] on the active
// functions, at 3 random points of every face between a leaf cell and a leaf cell of a coarser
// level (1D, 2D and 3D, q = 1, 2, 3, two and three levels refined in a corner and in the
// middle), the derivatives of order r = 0 ... q - 1 in the direction normal to the face agree
// from both sides within 1e-9 (relative to the field's scale, |f| <= 1, derivatives scaled by
// w^r, w the finer cell's width). Each side's derivative is a one-sided finite difference of
// q + 1 points at distances (k + 1/2) w / (q + 1), k = 0 ... q, evaluated in that side's leaf
// cell: it is exact for the polynomial of degree q that the field is on a cell, so a continuous
// derivative gives round-off (about 1e-14) and a discontinuous one its jump, whatever w. The
// control: the derivative of order q jumps (scaled jump above 1e-3 on some face), so the
// differences see a jump where there is one.
// Run with --figures to print the measured jumps.

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>

#include "hierarchical_setup.h"

using namespace dealii;
using namespace GelMPM;
using namespace hierarchical_setup;

namespace
{
  bool all_ok = true;

  /** The field sum_i c_i T_i at @p p, evaluated in leaf cell @p leaf. */
  template <int dim>
  double
  field(const HierarchicalBSplineSpace<dim> &space,
        const std::vector<double>           &c,
        const Point<dim>                    &p,
        const unsigned int                   leaf)
  {
    std::vector<double>         values;
    std::vector<Tensor<1, dim>> gradients;
    space.evaluate(p, leaf, values, gradients);
    double f = 0.;
    for (unsigned int a = 0; a < values.size(); ++a)
      f += c[space.leaf_functions(leaf)[a]] * values[a];
    return f;
  }

  /**
   * The derivatives at s = 0 of the polynomial of degree n - 1 through the n points (s_k, f_k):
   * r! a_r for its coefficients a_r (s is the distance in units of the cell width w, so these
   * are the field's derivatives scaled by w^r).
   */
  std::vector<double>
  scaled_derivatives(const std::vector<double> &s, const std::vector<double> &f)
  {
    const unsigned int n = s.size();
    FullMatrix<double> V(n, n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int j = 0; j < n; ++j)
        V(k, j) = std::pow(s[k], j);
    V.gauss_jordan();
    Vector<double> a(n), b(n);
    for (unsigned int k = 0; k < n; ++k)
      b(k) = f[k];
    V.vmult(a, b);
    std::vector<double> derivatives(n);
    double              factorial = 1.;
    for (unsigned int r = 0; r < n; ++r)
      {
        derivatives[r] = factorial * a(r);
        factorial *= r + 1;
      }
    return derivatives;
  }

  template <int dim>
  void
  check(const unsigned int           q,
        const unsigned int           n_cells,
        const std::string           &where,
        const std::vector<Box<dim>> &boxes)
  {
    const HierarchicalBSplineSpace<dim> space = make_space<dim>(q, n_cells, boxes);
    std::mt19937                        rng(3 + q);
    std::uniform_real_distribution<>    uniform(0., 1.);
    std::vector<double>                 c(space.n_active_functions());
    for (auto &ci : c)
      ci = 2. * uniform(rng) - 1.;

    // Distances from the face in units of w.
    std::vector<double> s(q + 1), inner_s(q + 1), outer_s(q + 1), f_inner(q + 1), f_outer(q + 1);
    for (unsigned int k = 0; k <= q; ++k)
      s[k] = (k + 0.5) / (q + 1);
    double       continuous_jump = 0., order_q_jump = 0.;
    unsigned int n_faces = 0;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        const auto              &Q     = space.leaf_cell(leaf);
        const BSplineSpace<dim> &level = space.level_space(Q.level);
        const auto               index = level.cell_multi_index(Q.cell);
        const double             w     = level.cell_size(0);
        for (unsigned int d = 0; d < dim; ++d)
          for (const int side : {-1, 1})
            {
              // The face's centre, and the leaf just beyond it.
              Point<dim> centre;
              for (unsigned int e = 0; e < dim; ++e)
                centre[e] = (index[e] + 0.5) * w;
              centre[d] += 0.5 * side * w;
              Point<dim> beyond = centre;
              beyond[d] += 0.25 * side * w;
              if (beyond[d] < 0. || beyond[d] > 1.)
                continue;
              const unsigned int neighbour = space.leaf_cell_containing(beyond);
              if (space.leaf_cell(neighbour).level >= Q.level)
                continue;
              ++n_faces;
              for (unsigned int k = 0; k <= q; ++k)
                {
                  inner_s[k] = -side * s[k];
                  outer_s[k] = side * s[k];
                }
              for (unsigned int t = 0; t < 3; ++t)
                {
                  Point<dim> x = centre;
                  for (unsigned int e = 0; e < dim; ++e)
                    if (e != d)
                      x[e] += (uniform(rng) - 0.5) * w;
                  for (unsigned int k = 0; k <= q; ++k)
                    {
                      Point<dim> inner = x, outer = x;
                      inner[d] += inner_s[k] * w;
                      outer[d] += outer_s[k] * w;
                      f_inner[k] = field(space, c, inner, leaf);
                      f_outer[k] = field(space, c, outer, neighbour);
                    }
                  const auto inner_derivatives = scaled_derivatives(inner_s, f_inner);
                  const auto outer_derivatives = scaled_derivatives(outer_s, f_outer);
                  for (unsigned int r = 0; r < q; ++r)
                    continuous_jump =
                      std::max(continuous_jump,
                               std::abs(inner_derivatives[r] - outer_derivatives[r]));
                  order_q_jump =
                    std::max(order_q_jump, std::abs(inner_derivatives[q] - outer_derivatives[q]));
                }
            }
      }
    const bool ok = n_faces > 0 && continuous_jump < 1e-9 && order_q_jump > 1e-3;
    all_ok &= ok;
    std::cout << dim << "D q=" << q << " " << boxes.size() + 1 << " levels, " << where << ": "
              << n_faces << " faces between levels; jumps of derivatives 0..q-1 < 1e-9, "
              << "of derivative q > 1e-3: " << (ok ? "yes" : "no  FAIL") << std::endl;
    figure("largest scaled jump of derivatives 0..q-1", continuous_jump);
    figure("largest scaled jump of derivative q", order_q_jump);
  }

  template <int dim>
  void
  check_all(const unsigned int n_cells, const unsigned int max_levels)
  {
    for (unsigned int q = 1; q <= 3; ++q)
      for_each_refinement<dim>(max_levels,
                               [&](const std::string &where, const std::vector<Box<dim>> &boxes) {
                                 check<dim>(q, n_cells, where, boxes);
                               });
  }
} // namespace


int
main(int argc, char **argv)
{
  read_arguments(argc, argv);
  check_all<1>(8, 3);
  check_all<2>(8, 3);
  check_all<3>(4, 2);
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

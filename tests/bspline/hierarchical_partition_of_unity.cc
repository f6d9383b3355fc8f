// Truncated hierarchical B-splines (HierarchicalBSplineSpace) form a nonnegative partition of
// unity, in 1D, 2D and 3D, degrees q = 1, 2, 3, with two and three levels refined in a corner
// and in the middle of [0, 1]^dim (base grids of 8, 8 and 4 cells per direction):
// - at random points (half of them in the first refined box), the values of the truncated
//   functions nonzero there sum to 1 within 1e-12 and their gradients to 0 within 1e-12 / h_min
//   (h_min the finest cell size);
// - no value at these points is below -1e-14, and no coefficient of a truncated function on a
//   leaf cell below -1e-14 (they are products of the two-scale relation's entries, all >= 0);
// - the control: the same active B-splines without truncation (Kraft's hierarchical basis) do
//   not sum to one (deviation above 0.1 somewhere), which is what the first check would see if
//   the truncation were missing.
// Run with --figures to print the measured maxima.

#include <gelmpm/bspline/hierarchical_bspline_space.h>

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

  /** Sum at @p p of the active B-splines of every level, untruncated. */
  template <int dim>
  double
  untruncated_sum(const HierarchicalBSplineSpace<dim> &space, const Point<dim> &p)
  {
    double sum = 0.;
    for (unsigned int l = 0; l < space.n_levels(); ++l)
      {
        const BSplineSpace<dim>    &level = space.level_space(l);
        const unsigned int          cell  = level.cell_containing(p);
        std::vector<unsigned int>   functions;
        std::vector<double>         v(level.functions_per_cell());
        std::vector<Tensor<1, dim>> g(level.functions_per_cell());
        level.cell_functions(cell, functions);
        level.evaluate(p, cell, v, g);
        for (unsigned int a = 0; a < functions.size(); ++a)
          if (space.active_function_number(l, functions[a]) != numbers::invalid_unsigned_int)
            sum += v[a];
      }
    return sum;
  }

  template <int dim>
  void
  check(const unsigned int           q,
        const unsigned int           n_cells,
        const std::string           &where,
        const std::vector<Box<dim>> &boxes)
  {
    const HierarchicalBSplineSpace<dim> space = make_space<dim>(q, n_cells, boxes);
    const double                        h_min = 1. / (n_cells << boxes.size());

    double most_negative_coefficient = 0.;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        const auto &M = space.leaf_coefficients(leaf);
        for (unsigned int a = 0; a < M.m(); ++a)
          for (unsigned int b = 0; b < M.n(); ++b)
            most_negative_coefficient = std::min(most_negative_coefficient, M(a, b));
      }

    std::mt19937                rng(11 + q);
    double                      sum_error = 0., gradient_error = 0., most_negative_value = 0.;
    double                      untruncated_error = 0.;
    std::vector<double>         values;
    std::vector<Tensor<1, dim>> gradients;
    for (unsigned int k = 0; k < 400; ++k)
      {
        const Point<dim>   p    = k % 2 ? random_point<dim>(rng) : random_point<dim>(rng, boxes[0]);
        const unsigned int leaf = space.leaf_cell_containing(p);
        space.evaluate(p, leaf, values, gradients);
        double         sum = 0.;
        Tensor<1, dim> gradient;
        for (unsigned int a = 0; a < values.size(); ++a)
          {
            sum += values[a];
            gradient += gradients[a];
            most_negative_value = std::min(most_negative_value, values[a]);
          }
        sum_error         = std::max(sum_error, std::abs(sum - 1.));
        gradient_error    = std::max(gradient_error, gradient.norm() * h_min);
        untruncated_error = std::max(untruncated_error, std::abs(untruncated_sum(space, p) - 1.));
      }

    const bool ok = sum_error < 1e-12 && gradient_error < 1e-12 && most_negative_value > -1e-14 &&
                    most_negative_coefficient > -1e-14 && untruncated_error > 0.1;
    all_ok &= ok;
    std::cout << dim << "D q=" << q << " " << boxes.size() + 1 << " levels, " << where << ": "
              << space.n_active_functions() << " functions, " << space.n_leaf_cells()
              << " leaf cells; |sum - 1| < 1e-12, |sum of gradients| h_min < 1e-12, values and "
                 "coefficients > -1e-14, untruncated |sum - 1| > 0.1: "
              << (ok ? "yes" : "no  FAIL") << std::endl;
    figure("max |sum - 1|", sum_error);
    figure("max |sum of gradients| h_min", gradient_error);
    figure("min value", most_negative_value);
    figure("min coefficient", most_negative_coefficient);
    figure("untruncated max |sum - 1|", untruncated_error);
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

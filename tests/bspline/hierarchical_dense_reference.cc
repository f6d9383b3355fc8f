// Truncated hierarchical B-splines (HierarchicalBSplineSpace) against references computed by
// hand and by dense linear algebra on small cases:
// - by hand, 1D on [0, 1]: the active functions (level, index) and the truncated functions'
//   coefficients in the finest level's B-splines, exact to 1e-14:
//   q = 1, 4 cells, the right half refined: level 0 {0, 1, 2}, level 1 {5, 6, 7, 8};
//     Trunc N^0_2 = 1/2 N^1_3 + N^1_4 (N^1_5 is dropped: its support lies in the refined half);
//   q = 2, 8 cells, the right half refined: level 0 {0 ... 5}, level 1 {10 ... 17};
//     Trunc N^0_5 = 1/4 N^1_8 + 3/4 N^1_9 (of its mask 1/4, 3/4, 3/4, 1/4), N^0_4 whole;
//   q = 1, 4 cells, three levels ([1/2, 1] and [3/4, 1] refined): level 1 {5, 6}, level 2
//     {13 ... 16}; Trunc N^0_2 = 1/4 N^2_5 + 1/2 N^2_6 + 3/4 N^2_7 + N^2_8 + 1/2 N^2_9 and
//     Trunc N^1_6 = 1/2 N^2_11 + N^2_12;
// - the truncation level by level as dense matrices (1D q = 3 and 2D q = 2, three levels): the
//   coefficient vector e_i of level l multiplied by the transposed tensor-product two-scale
//   matrix and masked (the B-splines whose support lies in the next domain set to zero), level
//   after level, gives finest_level_coefficients() within 1e-14, and its values in the finest
//   level's B-splines equal evaluate() at 200 random points within 1e-13;
// - linear independence: the Gram matrix of the active functions (Gauss quadrature of q + 1
//   points per direction on the leaf cells, exact) has full rank, its smallest singular value
//   above 1e-6 of the largest (LAPACKFullMatrix::compute_svd), on a two-level 1D (q = 2) and 2D
//   (q = 2) case; the control: with one more function, the level-0 B-spline whose support lies
//   in the refined domain (a combination of level-1 functions), the ratio falls below 1e-10.
// - input: a refined cell of level 1 whose parent is not refined, or a cell index beyond the
//   level's cells, is rejected (std::invalid_argument).
// Run with --figures to print the measured figures.

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "hierarchical_setup.h"

using namespace dealii;
using namespace GelMPM;
using namespace hierarchical_setup;

namespace
{
  bool all_ok = true;

  void
  report(const std::string &what, const bool ok)
  {
    all_ok &= ok;
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
  }

  using Coefficients = std::vector<std::pair<unsigned int, double>>;

  /** max |a - b| over the union of their indices. */
  double
  difference(const Coefficients &a, const Coefficients &b)
  {
    std::map<unsigned int, double> d;
    for (const auto &[i, c] : a)
      d[i] += c;
    for (const auto &[i, c] : b)
      d[i] -= c;
    double largest = 0.;
    for (const auto &[i, c] : d)
      largest = std::max(largest, std::abs(c));
    return largest;
  }

  /** The active functions of @p space as (level, index). */
  std::vector<std::pair<unsigned int, unsigned int>>
  active_set(const HierarchicalBSplineSpace<1> &space)
  {
    std::vector<std::pair<unsigned int, unsigned int>> result;
    for (unsigned int i = 0; i < space.n_active_functions(); ++i)
      result.emplace_back(space.active_function(i).level, space.active_function(i).index);
    return result;
  }

  /** Trunc of B-spline @p index of @p level in the finest level's B-splines. */
  Coefficients
  truncated(const HierarchicalBSplineSpace<1> &space,
            const unsigned int                 level,
            const unsigned int                 index)
  {
    return space.finest_level_coefficients(space.active_function_number(level, index));
  }

  void
  check_by_hand()
  {
    std::cout << "1D by hand:" << std::endl;
    {
      const HierarchicalBSplineSpace<1> space(1, Point<1>(0.), Point<1>(1.), {{4}}, {{2, 3}});
      report("q=1, 2 levels: active functions 0:{0,1,2} 1:{5,6,7,8}",
             active_set(space) == std::vector<std::pair<unsigned int, unsigned int>>{{0, 0},
                                                                                     {0, 1},
                                                                                     {0, 2},
                                                                                     {1, 5},
                                                                                     {1, 6},
                                                                                     {1, 7},
                                                                                     {1, 8}});
      report("q=1, 2 levels: Trunc N^0_2 = 1/2 N^1_3 + N^1_4, N^0_1 = 1/2 N^1_1 + N^1_2 + 1/2 "
             "N^1_3, N^1_5 = N^1_5, to 1e-14",
             difference(truncated(space, 0, 2), {{3, 0.5}, {4, 1.}}) < 1e-14 &&
               difference(truncated(space, 0, 1), {{1, 0.5}, {2, 1.}, {3, 0.5}}) < 1e-14 &&
               difference(truncated(space, 1, 5), {{5, 1.}}) < 1e-14);
    }
    {
      const HierarchicalBSplineSpace<1> space(2, Point<1>(0.), Point<1>(1.), {{8}}, {{4, 5, 6, 7}});
      std::vector<std::pair<unsigned int, unsigned int>> expected;
      for (unsigned int i = 0; i <= 5; ++i)
        expected.emplace_back(0, i);
      for (unsigned int j = 10; j <= 17; ++j)
        expected.emplace_back(1, j);
      report("q=2, 2 levels: active functions 0:{0...5} 1:{10...17}",
             active_set(space) == expected);
      report("q=2, 2 levels: Trunc N^0_5 = 1/4 N^1_8 + 3/4 N^1_9, Trunc N^0_4 = 1/4 N^1_6 + 3/4 "
             "N^1_7 + 3/4 N^1_8 + 1/4 N^1_9, to 1e-14",
             difference(truncated(space, 0, 5), {{8, 0.25}, {9, 0.75}}) < 1e-14 &&
               difference(truncated(space, 0, 4), {{6, 0.25}, {7, 0.75}, {8, 0.75}, {9, 0.25}}) <
                 1e-14);
    }
    {
      const HierarchicalBSplineSpace<1> space(1,
                                              Point<1>(0.),
                                              Point<1>(1.),
                                              {{4}},
                                              {{2, 3}, {6, 7}});
      report("q=1, 3 levels: active functions 0:{0,1,2} 1:{5,6} 2:{13,14,15,16}",
             active_set(space) == std::vector<std::pair<unsigned int, unsigned int>>{{0, 0},
                                                                                     {0, 1},
                                                                                     {0, 2},
                                                                                     {1, 5},
                                                                                     {1, 6},
                                                                                     {2, 13},
                                                                                     {2, 14},
                                                                                     {2, 15},
                                                                                     {2, 16}});
      report("q=1, 3 levels: Trunc N^0_2 = 1/4 N^2_5 + 1/2 N^2_6 + 3/4 N^2_7 + N^2_8 + 1/2 N^2_9, "
             "Trunc N^1_6 = 1/2 N^2_11 + N^2_12, to 1e-14",
             difference(truncated(space, 0, 2),
                        {{5, 0.25}, {6, 0.5}, {7, 0.75}, {8, 1.}, {9, 0.5}}) < 1e-14 &&
               difference(truncated(space, 1, 6), {{11, 0.5}, {12, 1.}}) < 1e-14);
    }
  }

  /** The tensor-product two-scale matrix from level @p l to level l + 1 (dense). */
  template <int dim>
  FullMatrix<double>
  two_scale_matrix(const HierarchicalBSplineSpace<dim> &space, const unsigned int l)
  {
    const BSplineSpace<dim>        &coarse = space.level_space(l), &fine = space.level_space(l + 1);
    std::vector<FullMatrix<double>> S;
    for (unsigned int d = 0; d < dim; ++d)
      S.push_back(refinement_operator_1d(coarse.basis_1d(d), fine.basis_1d(d)));
    FullMatrix<double> result(coarse.n_functions(), fine.n_functions());
    for (unsigned int I = 0; I < coarse.n_functions(); ++I)
      for (unsigned int J = 0; J < fine.n_functions(); ++J)
        {
          const auto i = coarse.function_multi_index(I), j = fine.function_multi_index(J);
          double     s = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            s *= S[d](i[d], j[d]);
          result(I, J) = s;
        }
    return result;
  }

  /** Whether the support of B-spline @p J of level @p l lies in Omega^l. */
  template <int dim>
  bool
  support_in_domain(const HierarchicalBSplineSpace<dim> &space,
                    const unsigned int                   l,
                    const unsigned int                   J)
  {
    const BSplineSpace<dim>  &level = space.level_space(l);
    std::vector<unsigned int> functions;
    for (unsigned int c = 0; c < level.n_cells(); ++c)
      {
        level.cell_functions(c, functions);
        if (std::find(functions.begin(), functions.end(), J) != functions.end() &&
            !space.in_domain(l, c))
          return false;
      }
    return true;
  }

  template <int dim>
  void
  check_dense_truncation(const unsigned int q, const std::vector<Box<dim>> &boxes)
  {
    const HierarchicalBSplineSpace<dim> space = make_space<dim>(q, 4, boxes);
    const unsigned int                  L     = space.n_levels();
    std::vector<FullMatrix<double>>     S;
    std::vector<std::vector<bool>>      dropped(L);
    for (unsigned int l = 0; l + 1 < L; ++l)
      S.push_back(two_scale_matrix(space, l));
    for (unsigned int l = 1; l < L; ++l)
      for (unsigned int J = 0; J < space.level_space(l).n_functions(); ++J)
        dropped[l].push_back(support_in_domain(space, l, J));

    const BSplineSpace<dim> &finest = space.level_space(L - 1);
    std::mt19937             rng(17);
    std::vector<Point<dim>>  points;
    for (unsigned int k = 0; k < 200; ++k)
      points.push_back(random_point<dim>(rng));
    double                      coefficient_error = 0., value_error = 0.;
    std::vector<double>         values, fine_values(finest.functions_per_cell());
    std::vector<Tensor<1, dim>> gradients, fine_gradients(finest.functions_per_cell());
    std::vector<unsigned int>   fine_functions;
    for (unsigned int i = 0; i < space.n_active_functions(); ++i)
      {
        const auto     f = space.active_function(i);
        Vector<double> c(space.level_space(f.level).n_functions());
        c(f.index) = 1.;
        for (unsigned int l = f.level; l + 1 < L; ++l)
          {
            Vector<double> next(S[l].n());
            S[l].Tvmult(next, c);
            for (unsigned int J = 0; J < next.size(); ++J)
              if (dropped[l + 1][J])
                next(J) = 0.;
            c = next;
          }
        Coefficients reference;
        for (unsigned int J = 0; J < c.size(); ++J)
          if (c(J) != 0.)
            reference.emplace_back(J, c(J));
        coefficient_error =
          std::max(coefficient_error, difference(reference, space.finest_level_coefficients(i)));
        for (const auto &p : points)
          {
            const unsigned int leaf = space.leaf_cell_containing(p);
            space.evaluate(p, leaf, values, gradients);
            const auto        &on_leaf = space.leaf_functions(leaf);
            const auto         a       = std::find(on_leaf.begin(), on_leaf.end(), i);
            const double       value   = a == on_leaf.end() ? 0. : values[a - on_leaf.begin()];
            const unsigned int cell    = finest.cell_containing(p);
            finest.cell_functions(cell, fine_functions);
            finest.evaluate(p, cell, fine_values, fine_gradients);
            double fine_value = 0.;
            for (unsigned int b = 0; b < fine_functions.size(); ++b)
              fine_value += c(fine_functions[b]) * fine_values[b];
            value_error = std::max(value_error, std::abs(value - fine_value));
          }
      }
    std::cout << dim << "D q=" << q << " " << L << " levels, dense truncation:" << std::endl;
    report(std::to_string(space.n_active_functions()) +
             " functions: coefficients in the finest level within 1e-14, values within 1e-13",
           coefficient_error < 1e-14 && value_error < 1e-13);
    figure("coefficient error", coefficient_error);
    figure("value error", value_error);
  }

  /**
   * sigma_min / sigma_max of the Gram matrix of the active functions, and of the active
   * functions with B-spline @p extra of level 0.
   */
  template <int dim>
  std::pair<double, double>
  gram_ratios(const HierarchicalBSplineSpace<dim> &space, const unsigned int extra)
  {
    const unsigned int          n = space.n_active_functions();
    LAPACKFullMatrix<double>    G(n + 1, n + 1);
    const QGauss<dim>           gauss(space.degree() + 1);
    std::vector<double>         values, level_values(space.level_space(0).functions_per_cell());
    std::vector<Tensor<1, dim>> gradients, level_gradients(level_values.size());
    std::vector<unsigned int>   level_functions;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        const auto              &cell  = space.leaf_cell(leaf);
        const BSplineSpace<dim> &level = space.level_space(cell.level);
        const auto               index = level.cell_multi_index(cell.cell);
        for (unsigned int k = 0; k < gauss.size(); ++k)
          {
            Point<dim> p;
            double     weight = gauss.weight(k);
            for (unsigned int d = 0; d < dim; ++d)
              {
                p[d] = (index[d] + gauss.point(k)[d]) * level.cell_size(d);
                weight *= level.cell_size(d);
              }
            space.evaluate(p, leaf, values, gradients);
            // All n + 1 functions at p, the extra one last.
            std::vector<std::pair<unsigned int, double>> at_p;
            for (unsigned int a = 0; a < values.size(); ++a)
              at_p.emplace_back(space.leaf_functions(leaf)[a], values[a]);
            const BSplineSpace<dim> &base = space.level_space(0);
            const unsigned int       c0   = base.cell_containing(p);
            base.cell_functions(c0, level_functions);
            base.evaluate(p, c0, level_values, level_gradients);
            for (unsigned int a = 0; a < level_functions.size(); ++a)
              if (level_functions[a] == extra)
                at_p.emplace_back(n, level_values[a]);
            for (const auto &[i, vi] : at_p)
              for (const auto &[j, vj] : at_p)
                G(i, j) += weight * vi * vj;
          }
      }
    LAPACKFullMatrix<double> G_active(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        G_active(i, j) = G(i, j);
    G_active.compute_svd();
    G.compute_svd();
    return {G_active.singular_value(n - 1) / G_active.singular_value(0),
            G.singular_value(n) / G.singular_value(0)};
  }

  template <int dim>
  void
  check_independence(const unsigned int q, const std::vector<Box<dim>> &boxes)
  {
    const HierarchicalBSplineSpace<dim> space = make_space<dim>(q, 4, boxes);
    // The extra function: a level-0 B-spline whose support lies in Omega^1.
    unsigned int              extra = numbers::invalid_unsigned_int;
    const BSplineSpace<dim>  &base  = space.level_space(0);
    std::vector<unsigned int> functions;
    for (unsigned int J = 0; J < base.n_functions() && extra == numbers::invalid_unsigned_int; ++J)
      {
        bool inside = true;
        for (unsigned int c = 0; c < base.n_cells(); ++c)
          {
            base.cell_functions(c, functions);
            if (std::find(functions.begin(), functions.end(), J) != functions.end() &&
                !space.is_refined(0, c))
              inside = false;
          }
        if (inside)
          extra = J;
      }
    const auto [active, with_extra] = gram_ratios(space, extra);
    std::cout << dim << "D q=" << q << " 2 levels, Gram matrix of " << space.n_active_functions()
              << " functions:" << std::endl;
    report("sigma_min / sigma_max > 1e-6", active > 1e-6);
    report("with level-0 B-spline " + std::to_string(extra) +
             " added: sigma_min / sigma_max < 1e-10",
           extra != numbers::invalid_unsigned_int && with_extra < 1e-10);
    figure("sigma_min / sigma_max", active);
    figure("with the extra function", with_extra);
  }


  /** Whether building a 1D space of q = 1 on 4 cells with @p refined throws invalid_argument. */
  bool
  rejected(const std::vector<std::vector<unsigned int>> &refined)
  {
    try
      {
        const HierarchicalBSplineSpace<1> space(1, Point<1>(0.), Point<1>(1.), {{4}}, refined);
      }
    catch (const std::invalid_argument &)
      {
        return true;
      }
    return false;
  }

  void
  check_input()
  {
    std::cout << "Input:" << std::endl;
    report("a refined cell of level 1 outside Omega^1 (parent not refined) is rejected",
           rejected({{2, 3}, {2}}) && !rejected({{2, 3}, {4}}));
    report("a refined cell index beyond the level's cells is rejected", rejected({{4}}));
  }
} // namespace


int
main(int argc, char **argv)
{
  read_arguments(argc, argv);
  check_input();
  check_by_hand();
  check_dense_truncation<1>(3, {box<1>(0.25, 0.75), box<1>(0.375, 0.625)});
  check_dense_truncation<2>(2, {box<2>(0., 0.5), box<2>(0., 0.25)});
  check_independence<1>(2, {box<1>(0., 0.75)});
  check_independence<2>(2, {box<2>(0., 0.75)});
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

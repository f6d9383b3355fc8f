// Truncated hierarchical B-splines of degree q (HierarchicalBSplineSpace) reproduce the
// polynomials of degree q in each variable, in 1D and 2D, q = 1, 2, 3, two and three levels
// refined in a corner and in the middle of [0, 1]^dim (base grid of 8 cells per direction):
// the least-squares fit (LAPACK's SVD-based dgelsd) of the product over the directions of
// 0.3 - 0.7 x + 1.1 x^2 + 0.5 x^3 (up to x^q) at (q + 2)^dim random points per leaf cell
// equals the polynomial within 1e-10 at 500 other random points. The control: x_0^(q+1) is not
// in the space, and its fit misses it by more than 1e-8 somewhere.
// Run with --figures to print the measured errors.

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

#include "hierarchical_setup.h"

using namespace dealii;
using namespace GelMPM;
using namespace hierarchical_setup;

namespace
{
  bool all_ok = true;

  /** The polynomial of degree q in each variable. */
  template <int dim>
  double
  polynomial(const unsigned int q, const Point<dim> &p)
  {
    const double a[4] = {0.3, -0.7, 1.1, 0.5};
    double       f    = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        double factor = 0., power = 1.;
        for (unsigned int k = 0; k <= q; ++k, power *= p[d])
          factor += a[k] * power;
        f *= factor;
      }
    return f;
  }

  /**
   * The least-squares solution of A x = b, A of m rows and n columns stored by columns, by
   * LAPACK's dgelsd (SVD without the m x m factor, which LAPACKFullMatrix::compute_svd() forms).
   */
  Vector<double>
  least_squares(std::vector<double> &A,
                const unsigned int   m,
                const unsigned int   n,
                std::vector<double>  b)
  {
    const types::blas_int        M = m, N = n, one = 1;
    types::blas_int              rank = 0, info = 0, query = -1;
    const double                 rcond = -1.; // machine precision
    std::vector<double>          s(n);
    std::vector<types::blas_int> iwork(3 * n * 32 + 11 * n);
    double                       size = 0.;
    gelsd(&M,
          &N,
          &one,
          A.data(),
          &M,
          b.data(),
          &M,
          s.data(),
          &rcond,
          &rank,
          &size,
          &query,
          iwork.data(),
          &info);
    std::vector<double>   work(static_cast<std::size_t>(size) + 1);
    const types::blas_int lwork = work.size();
    gelsd(&M,
          &N,
          &one,
          A.data(),
          &M,
          b.data(),
          &M,
          s.data(),
          &rcond,
          &rank,
          work.data(),
          &lwork,
          iwork.data(),
          &info);
    if (info != 0)
      throw std::runtime_error("dgelsd failed");
    Vector<double> x(n);
    for (unsigned int j = 0; j < n; ++j)
      x(j) = b[j];
    return x;
  }

  /** The coefficients of the least-squares fit of @p f at (q + 2)^dim points per leaf cell. */
  template <int dim>
  Vector<double>
  fit(const HierarchicalBSplineSpace<dim>             &space,
      const std::function<double(const Point<dim> &)> &f,
      std::mt19937                                    &rng)
  {
    unsigned int per_cell = 1;
    for (unsigned int d = 0; d < dim; ++d)
      per_cell *= space.degree() + 2;
    const unsigned int          m = per_cell * space.n_leaf_cells(), n = space.n_active_functions();
    std::vector<double>         A(static_cast<std::size_t>(m) * n, 0.), b(m);
    std::vector<double>         values;
    std::vector<Tensor<1, dim>> gradients;
    unsigned int                row = 0;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        const auto              &cell  = space.leaf_cell(leaf);
        const BSplineSpace<dim> &level = space.level_space(cell.level);
        const auto               index = level.cell_multi_index(cell.cell);
        Box<dim>                 Q;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Q.lower[d] = index[d] * level.cell_size(d);
            Q.upper[d] = (index[d] + 1) * level.cell_size(d);
          }
        for (unsigned int k = 0; k < per_cell; ++k, ++row)
          {
            const Point<dim> p = random_point<dim>(rng, Q);
            space.evaluate(p, leaf, values, gradients);
            for (unsigned int a = 0; a < values.size(); ++a)
              A[static_cast<std::size_t>(space.leaf_functions(leaf)[a]) * m + row] = values[a];
            b[row] = f(p);
          }
      }
    return least_squares(A, m, n, b);
  }

  /** max |fit - f| at 500 random points. */
  template <int dim>
  double
  fit_error(const HierarchicalBSplineSpace<dim>             &space,
            const std::function<double(const Point<dim> &)> &f)
  {
    std::mt19937                rng(5);
    const Vector<double>        x = fit(space, f, rng);
    std::vector<double>         values;
    std::vector<Tensor<1, dim>> gradients;
    double                      error = 0.;
    for (unsigned int k = 0; k < 500; ++k)
      {
        const Point<dim>   p    = random_point<dim>(rng);
        const unsigned int leaf = space.leaf_cell_containing(p);
        space.evaluate(p, leaf, values, gradients);
        double value = 0.;
        for (unsigned int a = 0; a < values.size(); ++a)
          value += values[a] * x(space.leaf_functions(leaf)[a]);
        error = std::max(error, std::abs(value - f(p)));
      }
    return error;
  }

  template <int dim>
  void
  check(const unsigned int q, const std::string &where, const std::vector<Box<dim>> &boxes)
  {
    const HierarchicalBSplineSpace<dim> space   = make_space<dim>(q, 8, boxes);
    const double                        error   = fit_error<dim>(space, [q](const Point<dim> &p) {
      return polynomial<dim>(q, p);
    });
    const double                        control = fit_error<dim>(space, [q](const Point<dim> &p) {
      return std::pow(p[0], q + 1);
    });
    const bool                          ok      = error < 1e-10 && control > 1e-8;
    all_ok &= ok;
    std::cout << dim << "D q=" << q << " " << boxes.size() + 1 << " levels, " << where << ": "
              << space.n_active_functions() << " functions; degree q error < 1e-10, "
              << "x^(q+1) error > 1e-8: " << (ok ? "yes" : "no  FAIL") << std::endl;
    figure("degree q error", error);
    figure("x^(q+1) error", control);
  }

  template <int dim>
  void
  check_all()
  {
    for (unsigned int q = 1; q <= 3; ++q)
      {
        check<dim>(q, "corner", {box<dim>(0., 0.5)});
        check<dim>(q, "middle", {box<dim>(0.25, 0.75)});
        check<dim>(q, "corner", {box<dim>(0., 0.5), box<dim>(0., 0.25)});
        check<dim>(q, "middle", {box<dim>(0.25, 0.75), box<dim>(0.375, 0.625)});
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  read_arguments(argc, argv);
  check_all<1>();
  check_all<2>();
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

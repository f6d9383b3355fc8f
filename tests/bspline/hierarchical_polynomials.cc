// Truncated hierarchical B-splines of degree q (HierarchicalBSplineSpace) reproduce the
// polynomials of degree q in each variable, in 1D and 2D, q = 1, 2, 3, two and three levels
// refined in a corner and in the middle of [0, 1]^dim (base grid of 8 cells per direction):
// the least-squares fit (LAPACK's SVD-based dgelsd) of the product over the directions of
// 0.3 - 0.7 x + 1.1 x^2 + 0.5 x^3 (up to x^q) at (q + 2)^dim random points per leaf cell
// equals the polynomial within 1e-10 at 500 other random points. The control: x_0^(q+1) is not
// in the space, and its fit misses it by more than 1e-8 somewhere.
// Run with --figures to print the measured errors.

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <functional>
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
      for_each_refinement<dim>(3,
                               [&](const std::string &where, const std::vector<Box<dim>> &boxes) {
                                 check<dim>(q, where, boxes);
                               });
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

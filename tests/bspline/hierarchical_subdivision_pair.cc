// The subdivision pair on refined grids: the chemical-potential space mu (truncated hierarchical
// B-splines, base grid of 4 cells per direction over [0, 1]^dim) and the displacement space u
// built from it by subdivision_refinement() (base grid of 8 cells, the same domains), q = 2,
// 1D, 2D and 3D, two and three levels refined in a corner and in the middle:
// - mu stays one level coarser than u everywhere: at 500 random points, the leaf cell of u that
//   holds the point has the level of mu's and is one of its 2^dim halves (no exception);
// - mu's space lies in u's (1D and 2D): a mu field with random coefficients in [-1, 1] is fitted
//   by u (least squares at 4^dim random points per leaf cell) within 1e-10 at 500 other random
//   points. The control: a u field is not in mu's space (fit error above 1e-3).
// Run with --figures to print the measured errors.

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

  /** Random coefficients in [-1, 1] for the active functions of @p space. */
  template <int dim>
  Vector<double>
  random_field(const HierarchicalBSplineSpace<dim> &space, std::mt19937 &rng)
  {
    std::uniform_real_distribution<> u(-1., 1.);
    Vector<double>                   x(space.n_active_functions());
    for (auto &xi : x)
      xi = u(rng);
    return x;
  }

  /** max |fit by @p to of the field x of @p from - the field| at 500 random points. */
  template <int dim>
  double
  fit_error(const HierarchicalBSplineSpace<dim> &from,
            const HierarchicalBSplineSpace<dim> &to,
            std::mt19937                        &rng)
  {
    const Vector<double> x = random_field(from, rng);
    const auto           f = [&](const Point<dim> &p) {
      return field_value(from, x, p);
    };
    const Vector<double> y     = fit<dim>(to, f, rng);
    double               error = 0.;
    for (unsigned int k = 0; k < 500; ++k)
      {
        const Point<dim> p = random_point<dim>(rng);
        error              = std::max(error, std::abs(field_value(to, y, p) - f(p)));
      }
    return error;
  }

  template <int dim>
  void
  check(const std::string &where, const std::vector<Box<dim>> &boxes)
  {
    // The dense least-squares fits cost too much memory in 3D.
    const bool                          with_fit = dim < 3;
    const unsigned int                  q        = 2;
    const HierarchicalBSplineSpace<dim> mu       = make_space<dim>(q, 4, boxes);
    const HierarchicalBSplineSpace<dim> u(q,
                                          Point<dim>(),
                                          box<dim>(1., 1.).upper,
                                          cells_per_direction<dim>(8),
                                          subdivision_refinement(mu));
    std::mt19937                        rng(23);
    unsigned int                        not_coarser = 0;
    for (unsigned int k = 0; k < 500; ++k)
      {
        const Point<dim> p       = random_point<dim>(rng);
        const auto      &u_leaf  = u.leaf_cell(u.leaf_cell_containing(p));
        const auto      &mu_leaf = mu.leaf_cell(mu.leaf_cell_containing(p));
        auto             index   = u.level_space(u_leaf.level).cell_multi_index(u_leaf.cell);
        for (auto &i : index)
          i /= 2;
        if (u_leaf.level != mu_leaf.level ||
            index != mu.level_space(mu_leaf.level).cell_multi_index(mu_leaf.cell))
          ++not_coarser;
      }
    const double mu_in_u = with_fit ? fit_error(mu, u, rng) : 0.;
    const double u_in_mu = with_fit ? fit_error(u, mu, rng) : 1.;
    const bool   ok      = not_coarser == 0 && mu_in_u < 1e-10 && u_in_mu > 1e-3;
    all_ok &= ok;
    std::cout << dim << "D " << boxes.size() + 1 << " levels, " << where << ": "
              << mu.n_active_functions() << " mu and " << u.n_active_functions()
              << " u functions; mu one level coarser at every point"
              << (with_fit ? ", mu field fitted by u within 1e-10, u field not by mu (> 1e-3)" : "")
              << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    figure("points where mu is not one level coarser", not_coarser);
    if (with_fit)
      {
        figure("mu field fitted by u, error", mu_in_u);
        figure("u field fitted by mu, error", u_in_mu);
      }
  }

  template <int dim>
  void
  check_all(const unsigned int max_levels)
  {
    for_each_refinement<dim>(max_levels,
                             [](const std::string &where, const std::vector<Box<dim>> &boxes) {
                               check<dim>(where, boxes);
                             });
  }
} // namespace


int
main(int argc, char **argv)
{
  read_arguments(argc, argv);
  check_all<1>(3);
  check_all<2>(3);
  check_all<3>(2);
  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

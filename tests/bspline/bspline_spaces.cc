// B-spline bases and tensor-product spaces against independent references:
// - q = 1..4: partition of unity and nonnegativity (1e-14), first and second derivatives
//   against central differences of the values (1e-6 relative), the closed-form quadratic
//   open-uniform B-splines on the first cell (1e-14);
// - cell numbering equal to deal.II's subdivided_hyper_rectangle active_cell_index (1D, 2D, 3D);
// - subdivision (§3.4): every coarse function equals the refinement mask of eq. (46)/(49)
//   applied to the fine functions at random points, to 1e-13, q = 1, 2, 3, in 1D, 2D and 3D
//   (for functions away from the open ends, where the uniform mask holds), and the collocated
//   operator of eq. (48) reproduces all coarse functions everywhere.
#include <gelmpm/bspline/bspline_space.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

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

  void
  check_basis_1d()
  {
    std::cout << "1D bases:" << std::endl;
    std::mt19937                     rng(1);
    std::uniform_real_distribution<> u(0., 1.);
    for (unsigned int q = 1; q <= 4; ++q)
      {
        const BSplineBasis1D basis(q, -1., 2., 7);
        double               pu = 0., negative = 0., d1 = 0., d2 = 0.;
        std::vector<double>  v(3 * (q + 1)), vp(3 * (q + 1)), vm(3 * (q + 1));
        for (unsigned int t = 0; t < 200; ++t)
          {
            const double       x    = -1. + 3. * u(rng);
            const unsigned int cell = basis.cell_of(x);
            basis.evaluate(x, cell, 2, v.data());
            double sum = 0.;
            for (unsigned int a = 0; a <= q; ++a)
              {
                sum += v[a];
                negative = std::max(negative, -v[a]);
              }
            pu             = std::max(pu, std::abs(sum - 1.));
            const double h = 1e-6;
            // Stay inside the cell for the differences (the functions are C^{q-1} across cells).
            const double lo = basis.x_min() + cell * basis.cell_size();
            if (x - h < lo || x + h > lo + basis.cell_size())
              continue;
            basis.evaluate(x + h, cell, 2, vp.data());
            basis.evaluate(x - h, cell, 2, vm.data());
            for (unsigned int a = 0; a <= q; ++a)
              {
                d1 = std::max(d1,
                              std::abs((vp[a] - vm[a]) / (2. * h) - v[q + 1 + a]) /
                                (1. + std::abs(v[q + 1 + a])));
                d2 = std::max(d2,
                              std::abs((vp[q + 1 + a] - vm[q + 1 + a]) / (2. * h) -
                                       v[2 * (q + 1) + a]) /
                                (1. + std::abs(v[2 * (q + 1) + a])));
              }
          }
        std::cout << " q = " << q << std::endl;
        report("partition of unity", pu, 1e-14);
        report("negative values", negative, 1e-14);
        report("first derivatives vs FD", d1, 1e-6);
        report("second derivatives vs FD", d2, 1e-6);
      }
    // Quadratic open-uniform B-splines on [0, 3] with 3 cells: on the first cell (t = x),
    // N0 = (1-t)^2, N1 = 2t - 1.5t^2, N2 = t^2/2.
    const BSplineBasis1D basis(2, 0., 3., 3);
    double               closed = 0.;
    std::vector<double>  v(3);
    for (const double t : {0., 0.25, 0.5, 0.9})
      {
        basis.evaluate(t, 0, 0, v.data());
        closed = std::max({closed,
                           std::abs(v[0] - (1. - t) * (1. - t)),
                           std::abs(v[1] - (2. * t - 1.5 * t * t)),
                           std::abs(v[2] - 0.5 * t * t)});
      }
    report("quadratic closed form on the first cell", closed, 1e-14);
  }

  template <int dim>
  void
  check_cell_numbering()
  {
    std::array<unsigned int, dim> n;
    std::vector<unsigned int>     reps;
    Point<dim>                    lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[d] = 3 + 2 * d;
        reps.push_back(n[d]);
        lower[d] = -0.5 * d;
        upper[d] = 1. + d;
      }
    Triangulation<dim> tria;
    GridGenerator::subdivided_hyper_rectangle(tria, reps, lower, upper);
    const BSplineSpace<dim> space(2, lower, upper, n);
    unsigned int            mismatches = 0;
    for (const auto &cell : tria.active_cell_iterators())
      mismatches += (space.cell_containing(cell->center()) != cell->active_cell_index());
    report(std::to_string(dim) + "D cell numbering mismatches with deal.II", mismatches, 0.5);
  }

  template <int dim>
  void
  check_subdivision()
  {
    std::cout << dim << "D two-scale relation:" << std::endl;
    std::mt19937                     rng(2);
    std::uniform_real_distribution<> u(0., 1.);
    for (unsigned int q = 1; q <= 3; ++q)
      {
        Point<dim>                    lower, upper;
        std::array<unsigned int, dim> n_coarse, n_fine;
        for (unsigned int d = 0; d < dim; ++d)
          {
            upper[d]    = 1. + 0.5 * d;
            n_coarse[d] = 5;
            n_fine[d]   = 10;
          }
        const BSplineSpace<dim> coarse(q, lower, upper, n_coarse), fine(q, lower, upper, n_fine);
        const auto              mask = refinement_mask(q);
        std::vector<FullMatrix<double>> S;
        for (unsigned int d = 0; d < dim; ++d)
          S.push_back(refinement_operator_1d(coarse.basis_1d(d), fine.basis_1d(d)));

        // Uniform mask away from the ends: coarse function i = sum_k a_k fine function 2i+k-q
        // (eq. (46) with 1-based indices shifted to our 0-based open-knot numbering).
        double mask_error = 0., operator_error = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int i = q; i + 2 * q < coarse.basis_1d(d).n_functions(); ++i)
            for (unsigned int k = 0; k <= q + 1; ++k)
              mask_error = std::max(mask_error, std::abs(S[d](i, 2 * i + k - q) - mask[k]));

        std::vector<double>         vc(coarse.functions_per_cell()), vf(fine.functions_per_cell());
        std::vector<Tensor<1, dim>> gc(vc.size()), gf(vf.size());
        std::vector<unsigned int>   ic, iff;
        for (unsigned int t = 0; t < 100; ++t)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = upper[d] * u(rng);
            const unsigned int cc = coarse.cell_containing(p), cf = fine.cell_containing(p);
            coarse.evaluate(p, cc, vc, gc);
            fine.evaluate(p, cf, vf, gf);
            coarse.cell_functions(cc, ic);
            fine.cell_functions(cf, iff);
            for (unsigned int a = 0; a < ic.size(); ++a)
              {
                const auto ci    = coarse.function_multi_index(ic[a]);
                double     value = 0.;
                for (unsigned int b = 0; b < iff.size(); ++b)
                  {
                    const auto fi     = fine.function_multi_index(iff[b]);
                    double     weight = 1.;
                    for (unsigned int d = 0; d < dim; ++d)
                      weight *= S[d](ci[d], fi[d]);
                    value += weight * vf[b];
                  }
                operator_error = std::max(operator_error, std::abs(value - vc[a]));
              }
          }
        std::cout << " q = " << q << std::endl;
        report("mask of eq. (46) vs the refinement operator", mask_error, 1e-13);
        report("coarse = S fine at random points", operator_error, 1e-13);
      }
  }
} // namespace


int
main()
{
  check_basis_1d();
  std::cout << "Cell numbering:" << std::endl;
  check_cell_numbering<1>();
  check_cell_numbering<2>();
  check_cell_numbering<3>();
  check_subdivision<1>();
  check_subdivision<2>();
  check_subdivision<3>();
  std::cout << "Masks of eq. (49):";
  for (unsigned int q = 1; q <= 3; ++q)
    {
      std::cout << " [";
      for (const double a : refinement_mask(q))
        std::cout << " " << a * std::pow(2., q);
      std::cout << " ]/" << std::pow(2, q);
    }
  std::cout << std::endl;
  std::cout << (all_ok ? "all B-spline checks passed" : "SOME B-SPLINE CHECKS FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

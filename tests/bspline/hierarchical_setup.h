// Set-ups shared by the tests of HierarchicalBSplineSpace: refined domains given by nested boxes,
// random points, least-squares fits, and the figures printed on request.
#ifndef gelmpm_tests_bspline_hierarchical_setup_h
#define gelmpm_tests_bspline_hierarchical_setup_h

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cstring>
#include <functional>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace hierarchical_setup
{
  using namespace dealii;
  using namespace GelMPM;

  /** An axis-parallel box. */
  template <int dim>
  struct Box
  {
    Point<dim> lower, upper;

    bool
    contains(const Point<dim> &x) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] < lower[d] || x[d] > upper[d])
          return false;
      return true;
    }
  };

  template <int dim>
  Box<dim>
  box(const double lower, const double upper)
  {
    Box<dim> b;
    for (unsigned int d = 0; d < dim; ++d)
      {
        b.lower[d] = lower;
        b.upper[d] = upper;
      }
    return b;
  }

  template <int dim>
  std::array<unsigned int, dim>
  cells_per_direction(const unsigned int n)
  {
    std::array<unsigned int, dim> cells;
    cells.fill(n);
    return cells;
  }

  /**
   * refined[l]: the cells of level l of the grid with n_cells << l cells per direction over
   * [0, 1]^dim whose centre lies in boxes[l] and whose parent is refined (so that the domains
   * are nested whatever the boxes).
   */
  template <int dim>
  std::vector<std::vector<unsigned int>>
  refine_boxes(const unsigned int n_cells, const std::vector<Box<dim>> &boxes)
  {
    std::vector<std::vector<unsigned int>> refined(boxes.size());
    std::vector<bool>                      parent_refined;
    for (unsigned int l = 0; l < boxes.size(); ++l)
      {
        const Point<dim>        one = box<dim>(1., 1.).upper;
        const BSplineSpace<dim> space(1, Point<dim>(), one, cells_per_direction<dim>(n_cells << l));
        const BSplineSpace<dim> coarse(1,
                                       Point<dim>(),
                                       one,
                                       cells_per_direction<dim>(n_cells << (l > 0 ? l - 1 : 0)));
        std::vector<bool>       is_refined(space.n_cells(), false);
        for (unsigned int c = 0; c < space.n_cells(); ++c)
          {
            const auto                    index = space.cell_multi_index(c);
            Point<dim>                    centre;
            std::array<unsigned int, dim> parent;
            for (unsigned int d = 0; d < dim; ++d)
              {
                centre[d] = (index[d] + 0.5) * space.cell_size(d);
                parent[d] = index[d] / 2;
              }
            if (l > 0 && !parent_refined[coarse.cell_index(parent)])
              continue;
            if (boxes[l].contains(centre))
              {
                is_refined[c] = true;
                refined[l].push_back(c);
              }
          }
        parent_refined = is_refined;
      }
    return refined;
  }

  /** The space of degree @p q over [0, 1]^dim on a base grid of @p n_cells^dim cells. */
  template <int dim>
  HierarchicalBSplineSpace<dim>
  make_space(const unsigned int q, const unsigned int n_cells, const std::vector<Box<dim>> &boxes)
  {
    return HierarchicalBSplineSpace<dim>(q,
                                         Point<dim>(),
                                         box<dim>(1., 1.).upper,
                                         cells_per_direction<dim>(n_cells),
                                         refine_boxes<dim>(n_cells, boxes));
  }

  template <int dim>
  Point<dim>
  random_point(std::mt19937 &rng, const Box<dim> &b = box<dim>(0., 1.))
  {
    std::uniform_real_distribution<> u(0., 1.);
    Point<dim>                       p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = b.lower[d] + u(rng) * (b.upper[d] - b.lower[d]);
    return p;
  }

  /**
   * The least-squares solution of A x = b, A of m rows and n columns stored by columns, by
   * LAPACK's dgelsd (SVD without the m x m factor, which LAPACKFullMatrix::compute_svd() forms).
   */
  inline Vector<double>
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

  /** The field with coefficients @p x on the active functions of @p space, at @p p. */
  template <int dim>
  double
  field_value(const HierarchicalBSplineSpace<dim> &space,
              const Vector<double>                &x,
              const Point<dim>                    &p)
  {
    std::vector<double>         values;
    std::vector<Tensor<1, dim>> gradients;
    const unsigned int          leaf = space.leaf_cell_containing(p);
    space.evaluate(p, leaf, values, gradients);
    double value = 0.;
    for (unsigned int a = 0; a < values.size(); ++a)
      value += values[a] * x(space.leaf_functions(leaf)[a]);
    return value;
  }

  /**
   * Calls @p check(where, boxes) for the refinements the hierarchical tests run: one box in a
   * corner and one in the middle of the unit box (two levels) and, with @p max_levels 3, each
   * with a second, nested box (three levels).
   */
  template <int dim, class Check>
  void
  for_each_refinement(const unsigned int max_levels, const Check &check)
  {
    check("corner", std::vector<Box<dim>>{box<dim>(0., 0.5)});
    check("middle", std::vector<Box<dim>>{box<dim>(0.25, 0.75)});
    if (max_levels < 3)
      return;
    check("corner", std::vector<Box<dim>>{box<dim>(0., 0.5), box<dim>(0., 0.25)});
    check("middle", std::vector<Box<dim>>{box<dim>(0.25, 0.75), box<dim>(0.375, 0.625)});
  }

  /** Whether the case was started with --figures: then it also prints the measured figures. */
  inline bool print_figures = false;

  inline void
  read_arguments(int argc, char **argv)
  {
    for (int i = 1; i < argc; ++i)
      if (std::strcmp(argv[i], "--figures") == 0)
        print_figures = true;
  }

  /** Prints "    (<what> = <value>)" when figures are asked for. */
  inline void
  figure(const std::string &what, const double value)
  {
    if (print_figures)
      std::cout << "    (" << what << " = " << value << ")" << std::endl;
  }
} // namespace hierarchical_setup

#endif

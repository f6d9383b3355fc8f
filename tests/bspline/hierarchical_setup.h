// Set-ups shared by the tests of HierarchicalBSplineSpace: refined domains given by nested boxes,
// random points, and the figures printed on request.
#ifndef gelmpm_tests_bspline_hierarchical_setup_h
#define gelmpm_tests_bspline_hierarchical_setup_h

#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <array>
#include <cstring>
#include <iostream>
#include <random>
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

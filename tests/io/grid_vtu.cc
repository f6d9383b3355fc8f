// GridOutput writes what ParaView reads: a block of 8 x 8 displacement cells of a 24 x 12 grid,
// aligned with the grid and touching its left edge, is classified (Q2 for u, Q2 on the 2h grid
// for mu), linear fields are given by their Greville coefficients, and the written .vtu is read
// back with VTK's XML reader (through Python, tests/vtu_reader.h). Checked: the cell count; the
// number of interior, boundary and outer cells of both spaces against their closed forms; the
// volume points per cell as given; du and mu at every vertex of a cell with material equal to the
// linear fields (extended B-splines reproduce them), NaN on cells without material; the .pvd series
// lists the output time.
#include <gelmpm/bspline/bspline_space.h>
#include <gelmpm/bspline/extended_bspline_space.h>
#include <gelmpm/io/grid_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "../vtu_reader.h"

using namespace dealii;
using namespace GelMPM;

namespace
{
  constexpr unsigned int nx = 24, ny = 12;        // displacement cells on [0, 2] x [0, 1]
  constexpr unsigned int first_i = 0, end_i = 8;  // material: cells first_i <= i < end_i
  constexpr unsigned int first_j = 2, end_j = 10; //           and first_j <= j < end_j
  const Point<2>         lower(0., 0.), upper(2., 1.);

  /** Greville abscissa of quadratic B-spline i on the open uniform knot vector of [a, b]. */
  double
  greville(const unsigned int i, const double a, const double b, const unsigned int n_cells)
  {
    const auto clamp = [&](const int k) {
      return std::min(std::max(k, 0), int(n_cells));
    };
    return a + (b - a) / n_cells * (clamp(int(i) - 1) + clamp(int(i))) / 2.;
  }

  Tensor<1, 2>
  du_exact(const Point<2> &p)
  {
    return Tensor<1, 2>({0.1 + 0.5 * p[0], 0.05 * p[0] - 0.2 * p[1]});
  }

  double
  mu_exact(const Point<2> &p)
  {
    return -0.146 + 0.01 * p[0] + 0.02 * p[1];
  }

  /**
   * Interior and boundary cells of a block of m x n cells with material; a flag is true for a
   * side of the block that has outer cells beyond it (not the edge of the grid). The boundary
   * cells are the block's cells next to those sides.
   */
  std::array<unsigned int, 2>
  expected_kinds(const unsigned int m,
                 const unsigned int n,
                 const bool         outer_left,
                 const bool         outer_right,
                 const bool         outer_bottom,
                 const bool         outer_top)
  {
    const unsigned int interior = (m - outer_left - outer_right) * (n - outer_bottom - outer_top);
    return {{interior, m * n - interior}};
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<2>                 tria;
  GridGenerator::subdivided_hyper_rectangle(tria, {nx, ny}, lower, upper);
  const BSplineSpace<2> u_space(2, lower, upper, {{nx, ny}});
  const BSplineSpace<2> mu_space(2, lower, upper, {{nx / 2, ny / 2}});

  std::vector<bool>         u_material(u_space.n_cells(), false), mu_material(mu_space.n_cells());
  std::vector<unsigned int> points(u_space.n_cells(), 0);
  for (unsigned int j = first_j; j < end_j; ++j)
    for (unsigned int i = first_i; i < end_i; ++i)
      {
        const unsigned int c                               = u_space.cell_index({{i, j}});
        u_material[c]                                      = true;
        points[c]                                          = 1 + c % 5;
        mu_material[mu_space.cell_index({{i / 2, j / 2}})] = true;
      }
  const ExtendedBSplineSpace<2> u(u_space, u_material), mu(mu_space, mu_material);

  Vector<double> solution(2 * u.n_dofs() + mu.n_dofs());
  for (unsigned int k = 0; k < u_space.n_functions(); ++k)
    if (u.dof_of_control_point(k) != numbers::invalid_unsigned_int)
      {
        const auto     index = u_space.function_multi_index(k);
        const Point<2> g(greville(index[0], 0., 2., nx), greville(index[1], 0., 1., ny));
        for (unsigned int c = 0; c < 2; ++c)
          solution(2 * u.dof_of_control_point(k) + c) = du_exact(g)[c];
      }
  for (unsigned int k = 0; k < mu_space.n_functions(); ++k)
    if (mu.dof_of_control_point(k) != numbers::invalid_unsigned_int)
      {
        const auto     index = mu_space.function_multi_index(k);
        const Point<2> g(greville(index[0], 0., 2., nx / 2), greville(index[1], 0., 1., ny / 2));
        solution(2 * u.n_dofs() + mu.dof_of_control_point(k)) = mu_exact(g);
      }

  std::filesystem::create_directories("vtu");
  GridOutput<2> output("vtu", tria);
  output.record(u, mu, points, solution);
  output.write(0.5);

  const auto file = GelMPMTests::read_vtu("vtu/grid-00000.vtu");
  bool       ok   = file.cells.size() == nx * ny;
  std::cout << "cells read back: " << file.cells.size() << " (expected " << nx * ny << ")"
            << std::endl;

  for (const char *name :
       {"u_cell_kind", "mu_cell_kind", "n_volume_points", "displacement_increment", "mu_over_kT"})
    {
      const bool present = file.array(name) != nullptr;
      ok &= present;
      std::cout << "field " << name << " present: " << (present ? "yes" : "no  FAIL") << std::endl;
    }
  if (!ok)
    return 1;

  // DataOut writes every field as point data on each cell's own points; cell fields are constant
  // there. Cells are identified by the centre of their points.
  std::array<unsigned int, 3> u_kinds = {{0, 0, 0}}, mu_kinds = {{0, 0, 0}};
  bool                        counts_ok = true, nan_ok = true;
  double                      error = 0.;
  for (const auto &cell : file.cells)
    {
      Point<2> centre;
      for (const std::size_t id : cell)
        centre += Point<2>(file.points[id][0], file.points[id][1]) / double(cell.size());
      const unsigned int c     = u_space.cell_containing(centre);
      const std::size_t  first = cell[0];
      ++u_kinds[std::lround(file.field("u_cell_kind")(first))];
      ++mu_kinds[std::lround(file.field("mu_cell_kind")(first))];
      counts_ok &= file.field("n_volume_points")(first) == points[c];
      for (const std::size_t id : cell)
        {
          const Point<2> p(file.points[id][0], file.points[id][1]);
          const double   mu_value = file.field("mu_over_kT")(id);
          const double   du_x     = file.field("displacement_increment")(id, 0);
          const double   du_y     = file.field("displacement_increment")(id, 1);
          if (u_material[c])
            error = std::max({error,
                              std::abs(mu_value - mu_exact(p)),
                              std::abs(du_x - du_exact(p)[0]),
                              std::abs(du_y - du_exact(p)[1])});
          else
            nan_ok &= std::isnan(mu_value) && std::isnan(du_x) && std::isnan(du_y);
        }
    }

  const auto u_expected = expected_kinds(end_i - first_i, end_j - first_j, false, true, true, true);
  const auto mu_expected =
    expected_kinds((end_i - first_i) / 2, (end_j - first_j) / 2, false, true, true, true);
  const unsigned int n_material = (end_i - first_i) * (end_j - first_j);
  const bool         u_ok       = u_kinds[0] == u_expected[0] && u_kinds[1] == u_expected[1] &&
                    u_kinds[2] == nx * ny - n_material;
  // Each mu cell covers 2 x 2 displacement cells, and each of those shows the mu cell's kind.
  const bool mu_ok = mu_kinds[0] == 4 * mu_expected[0] && mu_kinds[1] == 4 * mu_expected[1] &&
                     mu_kinds[2] == nx * ny - n_material;
  std::cout << "u cells interior/boundary/outer: " << u_kinds[0] << "/" << u_kinds[1] << "/"
            << u_kinds[2] << (u_ok ? " (as in closed form)" : "  FAIL") << std::endl;
  std::cout << "mu kind on u cells interior/boundary/outer: " << mu_kinds[0] << "/" << mu_kinds[1]
            << "/" << mu_kinds[2] << (mu_ok ? " (as in closed form)" : "  FAIL") << std::endl;
  std::cout << "volume points per cell as given: " << (counts_ok ? "yes" : "no  FAIL") << std::endl;
  const bool values_ok = error < 1e-6; // single precision in the .vtu
  std::cout << "du and mu at the vertices of cells with material equal the linear fields: "
            << (values_ok ? "yes" : "no  FAIL") << std::endl;
  std::cout << "NaN at the vertices of cells without material: " << (nan_ok ? "yes" : "no  FAIL")
            << std::endl;

  std::ifstream      pvd("vtu/grid.pvd");
  std::ostringstream text;
  text << pvd.rdbuf();
  const bool series = text.str().find("timestep=\"0.5\"") != std::string::npos &&
                      text.str().find("grid-00000.vtu") != std::string::npos;
  std::cout << "pvd lists time 0.5 with its file: " << (series ? "yes" : "no  FAIL") << std::endl;
  ok &= u_ok && mu_ok && counts_ok && values_ok && nan_ok && series;
  return ok ? 0 : 1;
}

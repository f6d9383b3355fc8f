#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/symmetry_planes.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    /** How far a point's initial coordinate may lie off its piece's plane, in cells. */
    constexpr double flatness_in_cells = 1e-6;

    /** How far a normal may lie from its axis: the selectors' usual 'nx < -0.99'. */
    constexpr double axis_tolerance = 0.01;

    char
    axis_name(const unsigned int d)
    {
      return "xyz"[d];
    }

    /** "x = 0 (on the grid's side)", "y = 0.05 (0.8 cells from the grid's side)". */
    template <int dim>
    std::string
    where(const RollerPlane &plane, const BackgroundGrid<dim> &grid)
    {
      std::ostringstream text;
      const double       k = cells_beyond(plane, grid);
      text << axis_name(plane.direction) << " = " << plane.position() << " (";
      if (std::abs(k) < flatness_in_cells)
        text << "on the grid's side";
      else
        text << std::setprecision(3) << k << (std::abs(k - 1.) < 1e-9 ? " cell" : " cells")
             << " from the grid's side";
      text << ")";
      return text.str();
    }

    template <int dim>
    std::string
    corner_list(const dealii::Point<dim> &p)
    {
      std::ostringstream text;
      text << std::setprecision(12);
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << p[d];
      return text.str();
    }
  } // namespace


  bool
  RollerPlane::flat(const double tolerance) const
  {
    return highest - lowest <= tolerance;
  }


  double
  RollerPlane::position() const
  {
    return 0.5 * (lowest + highest);
  }


  template <int dim>
  std::vector<RollerPlane>
  roller_planes(const dealii::Particles::ParticleHandler<dim> &particles,
                const BoundaryConditions<dim>                 &boundary_conditions,
                const MPI_Comm                                 communicator)
  {
    using Layout           = PropertyLayout<dim>;
    const unsigned int n   = boundary_conditions.n_pieces();
    const double       inf = std::numeric_limits<double>::infinity();
    // Per piece and signed axis (2 dim slots): how many of its points have their normal along
    // it, and the range of their coordinate along it; and the piece's count of points.
    std::vector<double> along(n * 2 * dim, 0.), total(n, 0.);
    std::vector<double> lowest(n * 2 * dim, inf), highest(n * 2 * dim, -inf);
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        const int  piece = piece_of(props);
        if (piece < 0 || kind_of(props) == PointKind::volume ||
            boundary_conditions.piece(piece).displacement_condition !=
              BoundaryPiece<dim>::DisplacementCondition::normal)
          continue;
        total[piece] += 1.;
        dealii::Tensor<1, dim> normal;
        for (unsigned int d = 0; d < dim; ++d)
          normal[d] = props[Layout::normal_area_0 + d];
        normal /= normal.norm();
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(std::abs(normal[d]) - 1.) < axis_tolerance)
            {
              const unsigned int slot = (piece * dim + d) * 2 + (normal[d] > 0. ? 1 : 0);
              const double       x    = props[Layout::position_0 + d];
              along[slot] += 1.;
              lowest[slot]  = std::min(lowest[slot], x);
              highest[slot] = std::max(highest[slot], x);
            }
      }
    dealii::Utilities::MPI::sum(along, communicator, along);
    dealii::Utilities::MPI::sum(total, communicator, total);
    dealii::Utilities::MPI::min(lowest, communicator, lowest);
    dealii::Utilities::MPI::max(highest, communicator, highest);

    std::vector<RollerPlane> planes;
    for (unsigned int piece = 0; piece < n; ++piece)
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int s = 0; s < 2; ++s)
          {
            const unsigned int slot = (piece * dim + d) * 2 + s;
            if (total[piece] == 0. || along[slot] != total[piece])
              continue;
            RollerPlane plane;
            plane.piece     = boundary_conditions.piece(piece).name;
            plane.direction = d;
            plane.side      = s == 1 ? 1 : -1;
            plane.lowest    = lowest[slot];
            plane.highest   = highest[slot];
            planes.push_back(plane);
          }
    return planes;
  }


  template <int dim>
  double
  cells_beyond(const RollerPlane &plane, const BackgroundGrid<dim> &grid)
  {
    const unsigned int d = plane.direction;
    const double       c = plane.position();
    return (plane.side < 0 ? c - grid.lower[d] : grid.upper[d] - c) / grid.cell_size(d);
  }


  template <int dim>
  std::string
  grid_entries_for_planes(const std::vector<RollerPlane> &planes,
                          const BackgroundGrid<dim>      &grid,
                          const unsigned int              wanted_cells,
                          const bool                      even_cells)
  {
    dealii::Point<dim>            lower = grid.lower, upper = grid.upper;
    std::array<unsigned int, dim> cells = grid.n_cells;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double h = grid.cell_size(d);
        for (const auto &plane : planes)
          if (plane.direction == d)
            {
              if (plane.side < 0)
                lower[d] = plane.position() - wanted_cells * h;
              else
                upper[d] = plane.position() + wanted_cells * h;
            }
        // The cell size kept: the side without a plane moves out to the next grid line.
        unsigned int n = static_cast<unsigned int>(std::ceil((upper[d] - lower[d]) / h - 1e-6));
        if (even_cells && n % 2 == 1)
          ++n;
        const bool lower_fixed = std::any_of(planes.begin(), planes.end(), [&](const auto &p) {
          return p.direction == d && p.side < 0;
        });
        if (lower_fixed)
          upper[d] = lower[d] + n * h;
        else
          lower[d] = upper[d] - n * h;
        cells[d] = n;
      }
    std::ostringstream text;
    text << "'Lower corner = " << corner_list(lower) << "', 'Upper corner = " << corner_list(upper)
         << "', 'Cells = ";
    for (unsigned int d = 0; d < dim; ++d)
      text << (d > 0 ? ", " : "") << cells[d];
    text << "'";
    return text.str();
  }


  template <int dim>
  std::string
  symmetry_plane_notes(const std::vector<RollerPlane> &planes,
                       const BackgroundGrid<dim>      &grid,
                       const unsigned int              degree,
                       const bool                      even_cells)
  {
    const double             tolerance = flatness_in_cells * grid.smallest_cell_size();
    std::ostringstream       notes;
    std::vector<RollerPlane> within_cells;
    for (const auto &plane : planes)
      {
        if (!plane.flat(tolerance))
          {
            const char x = axis_name(plane.direction);
            notes << "  note: piece '" << plane.piece << "' holds the normal displacement and "
                  << "its normals all point along " << (plane.side < 0 ? "-" : "+") << "e_" << x
                  << ", but its points lie between " << x << " = " << plane.lowest << " and "
                  << plane.highest
                  << ", not on one plane: a curved wall whose normal points that way (a ring's "
                     "inner wall) is held with it. If the piece is a plane of symmetry, select it "
                     "by its position as well, e.g. '"
                  << x << (plane.side < 0 ? " < " : " > ")
                  << (plane.side < 0 ? plane.lowest + 1e-3 * grid.smallest_cell_size()
                                     : plane.highest - 1e-3 * grid.smallest_cell_size())
                  << " && n" << x << (plane.side < 0 ? " < -0.99" : " > 0.99") << "'\n";
            continue;
          }
        const double k = cells_beyond(plane, grid);
        if (std::abs(k - std::round(k)) > flatness_in_cells)
          within_cells.push_back(plane);
      }
    if (!within_cells.empty())
      {
        notes << "  note: the plane(s) held by 'Displacement = normal' (planes of symmetry, "
                 "rollers) "
              << plane_list(within_cells, grid)
              << " fall within cells of the background grid: their points lie in cut cells, "
                 "where the condition holds only weakly, and the body's material beyond them "
                 "shares those cells' functions (doc/own_scenes.md, \"Planes of symmetry\"). "
                 "A grid of the same cell size with each plane on a grid line and "
              << degree + 1 << " cells beyond it: "
              << grid_entries_for_planes(within_cells, grid, degree + 1, even_cells) << '\n';
      }
    return notes.str();
  }


  template <int dim>
  std::vector<RollerPlane>
  planes_near_grid_side(const std::vector<RollerPlane> &planes,
                        const BackgroundGrid<dim>      &grid,
                        const unsigned int              degree)
  {
    const double             tolerance = flatness_in_cells * grid.smallest_cell_size();
    std::vector<RollerPlane> near;
    for (const auto &plane : planes)
      if (plane.flat(tolerance) && cells_beyond(plane, grid) < degree + 1 - flatness_in_cells)
        near.push_back(plane);
    return near;
  }


  template <int dim>
  std::string
  plane_list(const std::vector<RollerPlane> &planes, const BackgroundGrid<dim> &grid)
  {
    std::string text;
    for (unsigned int i = 0; i < planes.size(); ++i)
      text += (i > 0 ? ", '" : "'") + planes[i].piece + "' at " + where(planes[i], grid);
    return text;
  }


  template std::vector<RollerPlane>
  roller_planes<2>(const dealii::Particles::ParticleHandler<2> &,
                   const BoundaryConditions<2> &,
                   const MPI_Comm);
  template std::vector<RollerPlane>
  roller_planes<3>(const dealii::Particles::ParticleHandler<3> &,
                   const BoundaryConditions<3> &,
                   const MPI_Comm);
  template double
  cells_beyond<2>(const RollerPlane &, const BackgroundGrid<2> &);
  template double
  cells_beyond<3>(const RollerPlane &, const BackgroundGrid<3> &);
  template std::string
  grid_entries_for_planes<2>(const std::vector<RollerPlane> &,
                             const BackgroundGrid<2> &,
                             const unsigned int,
                             const bool);
  template std::string
  grid_entries_for_planes<3>(const std::vector<RollerPlane> &,
                             const BackgroundGrid<3> &,
                             const unsigned int,
                             const bool);
  template std::string
  symmetry_plane_notes<2>(const std::vector<RollerPlane> &,
                          const BackgroundGrid<2> &,
                          const unsigned int,
                          const bool);
  template std::string
  symmetry_plane_notes<3>(const std::vector<RollerPlane> &,
                          const BackgroundGrid<3> &,
                          const unsigned int,
                          const bool);
  template std::vector<RollerPlane>
  planes_near_grid_side<2>(const std::vector<RollerPlane> &,
                           const BackgroundGrid<2> &,
                           const unsigned int);
  template std::vector<RollerPlane>
  planes_near_grid_side<3>(const std::vector<RollerPlane> &,
                           const BackgroundGrid<3> &,
                           const unsigned int);
  template std::string
  plane_list<2>(const std::vector<RollerPlane> &, const BackgroundGrid<2> &);
  template std::string
  plane_list<3>(const std::vector<RollerPlane> &, const BackgroundGrid<3> &);
} // namespace GelMPM

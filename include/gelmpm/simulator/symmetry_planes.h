#ifndef gelmpm_simulator_symmetry_planes_h
#define gelmpm_simulator_symmetry_planes_h

#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/boundary_conditions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/particles/particle_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A boundary piece that holds the normal displacement ('Displacement = normal') and
   * whose initial normals all point one way along one axis: a plane of symmetry, or a wall taken
   * for one by a selector on the normal alone.
   *
   * Where such a plane lies in the background grid decides whether the extended B-splines can
   * carry the body next to it (doc/own_scenes.md, "Planes of symmetry"): a plane on a grid line
   * with q + 1 cells of grid beyond it never cuts a cell, and the cut cells where a curved
   * surface meets it are extrapolated from control points away from the grid's edge. A plane
   * within a cell puts its points in cut cells, where its condition holds only weakly; a plane
   * fewer than q cells from the grid's edge asks for extrapolations there that are not exact,
   * which the first step refuses.
   */
  struct RollerPlane
  {
    /** The piece's name. */
    std::string piece;
    /** The axis of the normals (0, 1, 2 for x, y, z). */
    unsigned int direction = 0;
    /** -1 where the outward normals are -e_d (the body lies above the plane), +1 for +e_d. */
    int side = -1;
    /** The smallest and the largest initial coordinate x_d of the piece's points. */
    double lowest  = 0.;
    double highest = 0.;

    /** Whether the points lie on one plane, within @p tolerance in x_d. */
    bool
    flat(const double tolerance) const;

    /** The plane's coordinate (the middle of the points' range). */
    double
    position() const;
  };


  /**
   * The pieces with 'Displacement = normal' of @p boundary_conditions whose surface points in
   * @p particles all have initial normals within 0.01 of one of -e_d, +e_d, with the range of
   * their initial coordinate along d. Collective over @p communicator; the same on every rank.
   */
  template <int dim>
  std::vector<RollerPlane>
  roller_planes(const dealii::Particles::ParticleHandler<dim> &particles,
                const BoundaryConditions<dim>                 &boundary_conditions,
                const MPI_Comm                                 communicator);


  /**
   * How many cells of @p grid lie beyond @p plane (between it and the grid's side behind the
   * body), fractional where the plane falls within a cell.
   */
  template <int dim>
  double
  cells_beyond(const RollerPlane &plane, const BackgroundGrid<dim> &grid);


  /**
   * 'Background grid' entries that keep the cell size of @p grid and put each of @p planes on a
   * grid line with @p wanted_cells cells beyond it, the other directions unchanged, with
   * @p even_cells an even count of cells in every direction: "Lower corner = ..., Upper corner =
   * ..., Cells = ...", ready to copy into the scene.
   */
  template <int dim>
  std::string
  grid_entries_for_planes(const std::vector<RollerPlane> &planes,
                          const BackgroundGrid<dim>      &grid,
                          const unsigned int              wanted_cells,
                          const bool                      even_cells);


  /**
   * Notes for the log before a run (and under `--check`): a plane of symmetry of @p planes that
   * falls within a cell of @p grid (with the entries that put it on a grid line with
   * @p degree + 1 cells beyond), and a piece whose normals point along one axis but whose points
   * do not lie on one plane (a curved wall selected with the plane). Empty when none applies.
   */
  template <int dim>
  std::string
  symmetry_plane_notes(const std::vector<RollerPlane> &planes,
                       const BackgroundGrid<dim>      &grid,
                       const unsigned int              degree,
                       const bool                      even_cells);


  /**
   * The flat ones of @p planes with fewer than @p degree + 1 cells of @p grid beyond them: where
   * the extended B-splines may not carry a curved body that meets its planes of symmetry.
   */
  template <int dim>
  std::vector<RollerPlane>
  planes_near_grid_side(const std::vector<RollerPlane> &planes,
                        const BackgroundGrid<dim>      &grid,
                        const unsigned int              degree);


  /** "'xplane' at x = 0 (on the grid's side), 'yplane' at y = 0.05 (0.8 cells from ...)". */
  template <int dim>
  std::string
  plane_list(const std::vector<RollerPlane> &planes, const BackgroundGrid<dim> &grid);
} // namespace GelMPM

#endif

#ifndef gelmpm_particles_point_location_h
#define gelmpm_particles_point_location_h

#include <gelmpm/scene/background_grid.h>

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The cell of the structured background grid that holds a point, by index arithmetic.
   *
   * A point on a face between two cells goes to one of them (round-off decides); a point outside
   * the grid goes to the nearest cell. The reference coordinates are clamped to the unit cell, so
   * that a point on a face is inside its cell also when round-off says otherwise.
   */
  template <int dim>
  class GridCellLocator
  {
  public:
    /** @p triangulation: the grid's triangulation (BackgroundGrid::create_triangulation()). */
    GridCellLocator(const BackgroundGrid<dim>        &grid,
                    const dealii::Triangulation<dim> &triangulation);

    /** The cell holding @p p and the reference coordinates of @p p in it. */
    std::pair<typename dealii::Triangulation<dim>::active_cell_iterator, dealii::Point<dim>>
    locate(const dealii::Point<dim> &p) const;

  private:
    const BackgroundGrid<dim>                                             &grid;
    std::vector<typename dealii::Triangulation<dim>::active_cell_iterator> cells;
  };


  /**
   * Sort the material points into the cells of the background grid after they moved, keeping
   * every point that lies in the grid. Returns the number of points that had to be re-inserted.
   *
   * deal.II's ParticleHandler::sort_particles_into_subdomains_and_cells() decides whether a point
   * lies in a cell from its reference coordinates, without tolerance. A point on a face between
   * two cells, e.g. a surface point of a body whose side runs along a grid line (§4.3: the
   * column's sides at x = H and 2H with h = 0.05H), can come out just outside both cells by
   * round-off and is then deleted as lost. Such points are put back here, with their id and
   * properties, into the cell given by GridCellLocator. Points outside the grid stay lost (the
   * caller reports them).
   *
   * @p triangulation is the grid's triangulation, on which @p particles live.
   */
  template <int dim>
  unsigned int
  sort_into_cells(dealii::Particles::ParticleHandler<dim> &particles,
                  const BackgroundGrid<dim>               &grid,
                  const dealii::Triangulation<dim>        &triangulation);
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_background_grid_h
#define gelmpm_scene_background_grid_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <array>

namespace GelMPM
{
  /**
   * @brief The "Background grid" section: the fixed Cartesian grid [lower, upper] with n_cells[d]
   * cells per direction that carries the displacement field (cell size h_u). The
   * chemical-potential grid is the same or twice as coarse (see DiscretisationSettings).
   */
  template <int dim>
  struct BackgroundGrid
  {
    dealii::Point<dim>            lower;
    dealii::Point<dim>            upper;
    std::array<unsigned int, dim> n_cells;
    /**
     * 'Coordinate system = axisymmetric' (2D only): x is the radius R >= 0, y the axis z, and the
     * scene is the meridian plane of a body of revolution (doc/axisymmetric.md). The grid's lower
     * x edge is then the axis R = 0.
     */
    bool axisymmetric = false;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section; throws InputError unless upper > lower and cells >= 1 in each direction.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    cell_size(const unsigned int d) const;

    /** Throw InputError if @p cells (per direction) cannot fit in the machine's memory. */
    void
    check_memory(const std::vector<double> &cells) const;

    /** True if @p p lies in the closed box of the grid (with a round-off tolerance). */
    bool
    contains(const dealii::Point<dim> &p) const;

    /** The grid as a deal.II triangulation (GridGenerator::subdivided_hyper_rectangle). */
    void
    create_triangulation(dealii::Triangulation<dim> &triangulation) const;
  };
} // namespace GelMPM

#endif

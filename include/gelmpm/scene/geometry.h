#ifndef gelmpm_scene_geometry_h
#define gelmpm_scene_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Geometry" section: the body in its initial (pre-swollen) configuration Omega_0,
   * as a union of boxes minus balls. Enough for the paper's scenes: a block (§4.1), a square
   * (§4.2), a column (§4.3), a square cell with quarter-circle holes at its corners (§4.4).
   */
  template <int dim>
  class Geometry
  {
  public:
    /** A piece of the boundary: centre, outward normal times measure (N_0 A_0), and measure. */
    struct SurfaceElement
    {
      dealii::Point<dim>     centre;
      dealii::Tensor<1, dim> normal_area;
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section; throws InputError on malformed or degenerate boxes and holes. */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Add a box [lower, upper] (for programmatic scenes and tests). */
    void
    add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper);

    /** Remove a ball (for programmatic scenes and tests). */
    void
    add_hole(const dealii::Point<dim> &centre, const double radius);

    /** Closed union of the boxes minus the open balls. */
    bool
    inside(const dealii::Point<dim> &p) const;

    /** Whether @p p lies in one of the boxes, holes disregarded. */
    bool
    inside_boxes(const dealii::Point<dim> &p) const;

    /**
     * The boundary of the body cut into elements of length at most @p spacing (2D): the parts of
     * box edges that are not inside another box or a hole, and the arcs of hole boundaries that
     * lie inside the boxes. Edges are split at their intersections with hole circles and arcs at
     * their intersections with box edges, so that each element lies entirely on the boundary.
     * For an arc element, normal_area is the exact integral of the outward normal over the arc,
     * so the sum over a closed boundary vanishes to round-off. Throws std::logic_error in 3D.
     */
    std::vector<SurfaceElement>
    surface_elements(const double spacing) const;

  private:
    /** Whether the point just outside (inside) @p p along @p normal is (not) in the body. */
    bool
    on_boundary(const dealii::Point<dim> &p, const dealii::Tensor<1, dim> &normal) const;

    std::vector<std::pair<dealii::Point<dim>, dealii::Point<dim>>> boxes;
    std::vector<std::pair<dealii::Point<dim>, double>>             holes;
  };
} // namespace GelMPM

#endif

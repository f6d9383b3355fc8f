#ifndef gelmpm_scene_box_body_h
#define gelmpm_scene_box_body_h

#include <gelmpm/scene/body.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A body given by "Geometry/Boxes" and "Geometry/Holes": a union of boxes minus balls
   * (disks in 2D) and, in 3D, cylinders. Enough for the paper's scenes: a block (§4.1), a square
   * (§4.2), a column (§4.3), a square cell with quarter-circle holes at its corners (§4.4).
   *
   * Its boundary is cut so that every element lies wholly on it (doc/architecture.md, "A body's
   * boundary"): in 2D, box edges split where hole circles cross them and hole arcs where box
   * edges cross them, with the exact integral of the normal over each arc; in 3D, box faces cut
   * along the other boxes' edges, and the holes parametrised (a cube projected onto a sphere,
   * angle and axis on a cylinder) and integrated per patch, with 8 x 8 sub-patches where another
   * part of the boundary cuts a patch. Where faces of two boxes coincide, the first box's face
   * alone is boundary.
   */
  template <int dim>
  class BoxBody : public Body<dim>
  {
  public:
    using typename Body<dim>::SurfaceElement;

    /**
     * A cylindrical hole (3D): the points closer than @p radius to the line through @p centre
     * along the unit vector @p axis.
     */
    struct Cylinder
    {
      dealii::Point<dim>     centre;
      double                 radius;
      dealii::Tensor<1, dim> axis;

      double
      distance_to_axis(const dealii::Point<dim> &p) const
      {
        const dealii::Tensor<1, dim> r = p - centre;
        return (r - (r * axis) * axis).norm();
      }

      /** Two unit vectors orthogonal to the axis and to each other (3D). */
      std::pair<dealii::Tensor<1, dim>, dealii::Tensor<1, dim>>
      frame() const;
    };

    /** Add the box [lower, upper]. */
    void
    add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper);

    /** Remove a ball. */
    void
    add_hole(const dealii::Point<dim> &centre, const double radius);

    /** Remove a cylinder, 3D; @p axis need not be unit. */
    void
    add_cylinder(const dealii::Point<dim>     &centre,
                 const double                  radius,
                 const dealii::Tensor<1, dim> &axis);

    /** Whether there is a box. */
    bool
    empty() const;

    BodySource
    source() const override;

    std::string
    entry() const override;

    /** The closed union of the boxes minus the open balls and cylinders. */
    bool
    inside(const dealii::Point<dim> &p) const override;

    /** Whether @p p lies in one of the boxes, holes disregarded. */
    bool
    inside_boxes(const dealii::Point<dim> &p) const override;

    /** Blames the holes if there were points in the boxes, else the boxes. */
    void
    check_volume_points(const unsigned long n_points,
                        const bool          any_in_boxes,
                        const unsigned long n_samples) const override;

    /**
     * 2D: the parts of box edges that are not inside another box or a hole, and the arcs of hole
     * boundaries that lie inside the boxes, each cut into elements no longer than @p spacing.
     * For an arc element, normal_area is the exact integral of the outward normal over the arc,
     * so the sum over a closed boundary vanishes to round-off. 3D: surface_elements_3d().
     * (@p lower and @p upper are not used: the boxes bound the body.)
     */
    std::vector<SurfaceElement>
    surface_elements(const double              spacing,
                     const dealii::Point<dim> &lower,
                     const dealii::Point<dim> &upper) const override;

  private:
    /**
     * A patch of a surface parametrised over a rectangle of (s, t): the point at (s, t) and the
     * body's outward normal times the area element per unit parameter area.
     */
    using PatchMap = std::function<
      void(const double, const double, dealii::Point<dim> &, dealii::Tensor<1, dim> &)>;

    /** 2D: box edges split at the hole circles, each part that is boundary cut to @p spacing. */
    void
    add_box_edges(const double spacing, std::vector<SurfaceElement> &elements) const;

    /** 2D: hole arcs split at the box edges, each part that is boundary cut to @p spacing. */
    void
    add_hole_arcs(const double spacing, std::vector<SurfaceElement> &elements) const;

    /**
     * 3D boxes minus holes: box faces cut along the other boxes' edges into rectangles of side at
     * most @p spacing; ball holes as six patches of a cube projected onto the sphere, cylinder
     * holes in angle and along the axis, both divided to about @p spacing.
     */
    std::vector<SurfaceElement>
    surface_elements_3d(const double spacing) const;

    /**
     * Whether a part of the boundary other than the hole @p own_hole (balls first, then
     * cylinders; -1: none) comes within @p radius of @p p: a hole surface, and, with
     * @p boxes_too, a box face.
     */
    bool
    near_cut(const dealii::Point<dim> &p,
             const double              radius,
             const int                 own_hole,
             const bool                boxes_too) const;

    /**
     * Add the element of the patch @p map over @p range = {s0, s1, t0, t1}: the integral of the
     * normal over the part of it on the boundary (two-point Gauss rule in each direction, on 8 x 8
     * sub-patches kept by their centres if another part of the boundary crosses it, near_cut()),
     * at the point of the patch at the mean parameter of that part. Nothing if no part is on the
     * boundary.
     */
    void
    add_patch(std::vector<SurfaceElement> &elements,
              const PatchMap              &map,
              const std::array<double, 4> &range,
              const int                    own_hole,
              const bool                   boxes_cut) const;

    /**
     * Whether @p p lies on the face with outward @p normal (a coordinate direction) of one of the
     * boxes before @p box: where faces of two boxes coincide, the first box's face alone is
     * boundary.
     */
    bool
    on_earlier_box_face(const unsigned int            box,
                        const dealii::Point<dim>     &p,
                        const dealii::Tensor<1, dim> &normal) const;

    /** Whether the point just outside (inside) @p p along @p normal is (not) in the body. */
    bool
    on_boundary(const dealii::Point<dim> &p, const dealii::Tensor<1, dim> &normal) const;

    /** The length below which two points of the boxes' faces count as one: 1e-9 of a box. */
    double
    face_tolerance() const;

    std::vector<std::pair<dealii::Point<dim>, dealii::Point<dim>>> boxes;
    std::vector<std::pair<dealii::Point<dim>, double>>             holes;
    std::vector<Cylinder>                                          cylinders;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_body_h
#define gelmpm_scene_body_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /** How a body is given: the entry of the "Geometry" section that describes it. */
  enum class BodySource
  {
    boxes,
    level_set,
    mesh
  };


  /**
   * @brief A body in its initial (pre-swollen) configuration Omega_0, as the point generator
   * sees it: what is inside, where the volume points go, the boundary cut into surface elements,
   * and the checks of the points it gives. One class per way of giving it (BoxBody, LevelSetBody,
   * MeshBody), chosen once when the "Geometry" section is read (Geometry).
   *
   * Volume points are either the sub-cell centres of the background grid that inside() accepts
   * (boxes, level sets), or the body's own (has_own_volume_points(): the quadrature points of a
   * mesh's cells, volume_elements()).
   */
  template <int dim>
  class Body
  {
  public:
    /**
     * A piece of the boundary: centre, outward normal times measure (N_0 A_0), and, for a body
     * from a mesh, the boundary id of the face it lies on and the name of that physical group
     * (empty if the file names none).
     */
    struct SurfaceElement
    {
      dealii::Point<dim>         centre;
      dealii::Tensor<1, dim>     normal_area;
      dealii::types::boundary_id boundary_id = dealii::numbers::invalid_boundary_id;
      std::string                group_name;
      /** Mesh bodies: the physical group (dimension dim) of the cell the face belongs to. */
      std::string volume_group;
    };

    /** A piece of the body: a point and the volume (area in 2D) it stands for. */
    struct VolumeElement
    {
      dealii::Point<dim> centre;
      double             volume;
      /** Mesh bodies: the physical group (dimension dim) of the element's cell, or empty. */
      std::string group_name = "";
    };

    virtual ~Body() = default;

    /** How the body is given. */
    virtual BodySource
    source() const = 0;

    /** The entry that gives the body ("Geometry/Boxes", ".../Level set", ".../Mesh file"). */
    virtual std::string
    entry() const = 0;

    /** Whether @p p lies in the body. */
    virtual bool
    inside(const dealii::Point<dim> &p) const = 0;

    /** Whether @p p lies in the body before anything is cut from it (boxes: holes disregarded). */
    virtual bool
    inside_boxes(const dealii::Point<dim> &p) const;

    /** Whether the volume points are the body's own (volume_elements()) and not sub-cell centres.
     */
    virtual bool
    has_own_volume_points() const;

    /**
     * The body's own volume points (has_own_volume_points()), about as dense as
     * @p points_per_direction per direction of a background cell, @p spacing the sub-cell size.
     */
    virtual std::vector<VolumeElement>
    volume_elements(const unsigned int points_per_direction, const double spacing) const;

    /**
     * Throw InputError naming the entry to blame if the sub-cell centres gave no volume point:
     * @p n_points points were found among @p n_samples centres, @p any_in_boxes whether one
     * lay in the body before anything was cut from it (inside_boxes()).
     */
    virtual void
    check_volume_points(const unsigned long n_points,
                        const bool          any_in_boxes,
                        const unsigned long n_samples) const;

    /**
     * The boundary of the body cut into elements of size at most @p spacing; a body that is not
     * bounded by its own description (a level set) is taken inside the box [@p lower, @p upper],
     * the background grid.
     */
    virtual std::vector<SurfaceElement>
    surface_elements(const double              spacing,
                     const dealii::Point<dim> &lower,
                     const dealii::Point<dim> &upper) const = 0;

  protected:
    /** A surface element without boundary id or groups. */
    static SurfaceElement
    element(const dealii::Point<dim> &centre, const dealii::Tensor<1, dim> &normal_area)
    {
      return {centre, normal_area, dealii::numbers::invalid_boundary_id, {}, {}};
    }
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_geometry_h
#define gelmpm_scene_geometry_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Geometry" section: the body in its initial (pre-swollen) configuration Omega_0,
   * given in one of three ways:
   *
   * - **boxes**: a union of boxes minus balls, and in 3D cylinders ("Boxes", "Holes"). Enough for
   * the paper's scenes: a block (§4.1), a square (§4.2), a column (§4.3), a square cell with
   * quarter-circle holes at its corners (§4.4).
   * - **level set**: the set where an expression phi(x, y[, z]) is negative ("Level set",
   *   "Level set constants"), inside the background grid.
   * - **mesh**: the cells of a Gmsh mesh ("Mesh file"; all quadrilaterals or all triangles in 2D,
   *   all hexahedra or all tetrahedra in 3D), whose boundary faces carry the boundary ids of its
   *   physical groups.
   *
   * A level set and a mesh file exclude each other and the boxes: with either of them, "Boxes"
   * must keep its default and "Holes" be empty (an InputError names the entry otherwise). Holes
   * in a level-set body are written into the expression (max(phi, r - |x - c|)).
   *
   * The class describes the body and cuts its boundary into surface elements; where the volume
   * points go is decided by MaterialPointGenerator (sub-cell centres for boxes and level sets,
   * quadrature points of the mesh cells for a mesh: mesh_volume_elements()).
   */
  template <int dim>
  class Geometry
  {
  public:
    /** How the body is given. */
    enum class Source
    {
      boxes,
      level_set,
      mesh
    };

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
      frame() const
      {
        // The coordinate axis least aligned with the cylinder's, made orthogonal to it.
        unsigned int least = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(axis[d]) < std::abs(axis[least]))
            least = d;
        dealii::Tensor<1, dim> e1, e2;
        e1[least] = 1.;
        e1 -= (e1 * axis) * axis;
        e1 /= e1.norm();
        if constexpr (dim == 3)
          e2 = dealii::cross_product_3d(axis, e1);
        return {e1, e2};
      }
    };

    /** A piece of the body: a point and the volume (area in 2D) it stands for. */
    struct VolumeElement
    {
      dealii::Point<dim> centre;
      double             volume;
      /** Mesh bodies: the physical group (dimension dim) of the element's cell, or empty. */
      std::string group_name = "";
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Read the section; throws InputError on malformed or degenerate boxes and holes, a level set
     * that cannot be parsed, a mesh file that cannot be read or has another dimension, and an
     * inconsistent combination of the entries. A relative "Mesh file" is taken from
     * @p scene_directory (the directory of the scene file; empty: the current directory).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &scene_directory = "");

    /** Add a box [lower, upper] (for programmatic scenes and tests). */
    void
    add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper);

    /** Remove a ball (for programmatic scenes and tests). */
    void
    add_hole(const dealii::Point<dim> &centre, const double radius);

    /** Remove a cylinder, 3D (for programmatic scenes and tests); @p axis need not be unit. */
    void
    add_cylinder(const dealii::Point<dim>     &centre,
                 const double                  radius,
                 const dealii::Tensor<1, dim> &axis);

    /**
     * Make the body the set where @p expression (in x, y[, z] and @p constants) is negative
     * (for programmatic scenes and tests). Throws InputError naming "Geometry/Level set" if the
     * expression cannot be parsed.
     */
    void
    set_level_set(const std::string &expression, const std::string &constants = "");

    /**
     * Make the body the mesh in the Gmsh file @p file_name (for programmatic scenes and tests).
     * Throws InputError naming "Geometry/Mesh file" if it cannot be read or is not a mesh of
     * dimension dim.
     */
    void
    read_mesh(const std::string &file_name);

    Source
    source() const;

    /** The entry that gives the body ("Geometry/Boxes", ".../Level set", ".../Mesh file"). */
    std::string
    entry() const;

    /**
     * Whether @p p lies in the body: the closed union of the boxes minus the open balls, the
     * open set {phi < 0}, or the closure of a mesh cell (a search over the cells: for tests).
     */
    bool
    inside(const dealii::Point<dim> &p) const;

    /** Whether @p p lies in one of the boxes, holes disregarded (boxes only; else inside()). */
    bool
    inside_boxes(const dealii::Point<dim> &p) const;

    /** The level set phi at @p p (level-set bodies only). */
    double
    level_set(const dealii::Point<dim> &p) const;

    /**
     * The boundary of the body cut into elements of length at most @p spacing.
     *
     * Boxes: the parts of box edges that are not inside another box or a hole, and the arcs of
     * hole boundaries that lie inside the boxes. Edges are split at their intersections with
     * hole circles and arcs at their intersections with box edges, so that each element lies
     * entirely on the boundary. For an arc element, normal_area is the exact integral of the
     * outward normal over the arc, so the sum over a closed boundary vanishes to round-off.
     *
     * Level set: the zero contour inside the box [@p lower, @p upper] (the background grid),
     * traced by marching squares on a sampling grid of spacing at most @p spacing / 2, each
     * closed contour divided into elements of equal length along it; the end points and centres
     * of the elements are projected onto the zero set by Newton steps along the gradient, and
     * normal_area is the rotated chord between the end points, which is the exact integral of the
     * normal over the piece of the zero set between them: the sum over a closed contour vanishes
     * to round-off. Throws InputError if phi < 0 on the edge of the box (the body reaches
     * outside the grid).
     *
     * Mesh: the Gauss points of the boundary faces (see mesh_surface_elements()).
     *
     * In 3D: box faces and holes by box_surface_elements_3d(), a level set by
     * level_set_surface_elements_3d(), elements of size at most @p spacing.
     */
    std::vector<SurfaceElement>
    surface_elements(const double              spacing,
                     const dealii::Point<dim> &lower = dealii::Point<dim>(),
                     const dealii::Point<dim> &upper = dealii::Point<dim>()) const;

    /**
     * Mesh bodies: the Gauss points of every cell with V_0 = JxW. A quadrilateral/hexahedron gets
     * q^dim points, with q = max(@p points_per_direction, ceil(longest edge / @p spacing)): with
     * @p spacing the sub-cell size h/n, the points are about as dense as those of a box body. A
     * triangle/tetrahedron gets the centroids of k^dim equal sub-simplices, k the smallest power of
     * two for which they are no larger than a sub-cell and at least (points_per_direction)^dim/dim!
     * many.
     */
    std::vector<VolumeElement>
    mesh_volume_elements(const unsigned int points_per_direction, const double spacing) const;

    /**
     * Mesh bodies: the Gauss points of every boundary face with N_0 A_0 = the outward unit normal
     * times JxW, the face's boundary id and group name. A face gets q^(dim-1) points with q the
     * smallest number for which no Gauss point of its longest edge stands for more than
     * @p spacing of it: in 2D no element is longer than @p spacing, as on boxes (a triangular
     * face in 3D: the centroids of k^2 equal sub-triangles, k the power of two at least q). Works
     * in 2D and 3D.
     */
    std::vector<SurfaceElement>
    mesh_surface_elements(const double spacing) const;

    /** Mesh bodies: the boundary ids on the mesh's boundary faces. */
    std::set<dealii::types::boundary_id>
    mesh_boundary_ids() const;

    /** Mesh bodies: the names of the physical groups of dimension dim - 1 by boundary id. */
    const std::map<dealii::types::boundary_id, std::string> &
    mesh_group_names() const;

    /** Mesh bodies: the names of the physical groups of dimension dim by material id. */
    const std::map<dealii::types::boundary_id, std::string> &
    mesh_volume_group_names() const;

    /** Mesh bodies: the mesh. */
    const dealii::Triangulation<dim> &
    mesh() const;

  private:
    /**
     * A patch of a surface parametrised over a rectangle of (s, t): the point at (s, t) and the
     * body's outward normal times the area element per unit parameter area.
     */
    using PatchMap = std::function<
      void(const double, const double, dealii::Point<dim> &, dealii::Tensor<1, dim> &)>;

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
     * 3D boxes minus holes: box faces cut along the other boxes' edges into rectangles of side at
     * most @p spacing; ball holes as six patches of a cube projected onto the sphere, cylinder
     * holes in angle and along the axis, both divided to about @p spacing.
     */
    std::vector<SurfaceElement>
    box_surface_elements_3d(const double spacing) const;

    /**
     * 3D level sets: one element in each sampling cube (edge at most @p spacing) the zero
     * surface crosses, with the integral of the normal over the surface in it from the
     * divergence theorem (exact closure), at the mean of its edge crossings projected onto the
     * zero set.
     */
    std::vector<SurfaceElement>
    level_set_surface_elements_3d(const double              spacing,
                                  const dealii::Point<dim> &lower,
                                  const dealii::Point<dim> &upper) const;

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

    std::vector<SurfaceElement>
    box_surface_elements(const double spacing) const;

    std::vector<SurfaceElement>
    level_set_surface_elements(const double              spacing,
                               const dealii::Point<dim> &lower,
                               const dealii::Point<dim> &upper) const;

    /** Gradient of phi by central differences with step @p delta. */
    dealii::Tensor<1, dim>
    level_set_gradient(const dealii::Point<dim> &p, const double delta) const;

    /**
     * 3D level sets: when the @p crossings of the zero set with a sampling cube's edges fall
     * into two or three groups of distinct normals (an edge or a corner of the body runs through
     * the cube), add one element per group with that group's normal, the cube's integral of the
     * normal @p normal_area split among them, and return true; false (nothing added) for a
     * smooth piece of surface or a split that would not carry the integral.
     */
    bool
    split_at_edge(const std::vector<dealii::Point<dim>> &crossings,
                  const dealii::Tensor<1, dim>          &normal_area,
                  const double                           max_shift,
                  std::vector<SurfaceElement>           &elements) const;

    /**
     * @p p moved onto the zero set of phi by Newton steps along the gradient, at most
     * @p max_shift from where it started (else @p p itself: a degenerate gradient).
     */
    dealii::Point<dim>
    project_onto_zero_set(const dealii::Point<dim> &p, const double max_shift) const;

    Source source_ = Source::boxes;

    std::vector<std::pair<dealii::Point<dim>, dealii::Point<dim>>> boxes;
    std::vector<std::pair<dealii::Point<dim>, double>>             holes;
    std::vector<Cylinder>                                          cylinders;

    // Shared, not unique: a Geometry stays copyable, and neither is changed after parsing.
    std::shared_ptr<dealii::FunctionParser<dim>> phi;
    std::string                                  level_set_text;

    std::shared_ptr<dealii::Triangulation<dim>>       mesh_;
    std::string                                       mesh_file;
    std::map<dealii::types::boundary_id, std::string> group_names;
    std::map<dealii::types::boundary_id, std::string> volume_group_names;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_mesh_body_h
#define gelmpm_scene_mesh_body_h

#include <gelmpm/scene/body.h>

#include <deal.II/grid/tria.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A body given by "Geometry/Mesh file": the cells of a Gmsh mesh (all quadrilaterals
   * or all triangles in 2D, all hexahedra or all tetrahedra in 3D), whose boundary faces carry
   * the boundary ids of its physical groups and whose cells the material ids of its volume
   * groups.
   *
   * The mesh brings its own points: volume points at quadrature points of its cells
   * (V_0 = JxW), surface points at those of its boundary faces (N_0 A_0 = normal x JxW), as
   * densely as the sub-cells of a box body.
   */
  template <int dim>
  class MeshBody : public Body<dim>
  {
  public:
    using typename Body<dim>::SurfaceElement;
    using typename Body<dim>::VolumeElement;

    /**
     * Read the mesh in the Gmsh file @p file_name. Throws InputError naming "Geometry/Mesh file"
     * if it cannot be read, is not a mesh of dimension dim, mixes kinds of cells or has a flat,
     * inverted or crossed cell.
     */
    explicit MeshBody(const std::string &file_name);

    BodySource
    source() const override;

    std::string
    entry() const override;

    /** Whether @p p lies in the closure of a cell (a search over the cells: for tests). */
    bool
    inside(const dealii::Point<dim> &p) const override;

    bool
    has_own_volume_points() const override;

    /**
     * The Gauss points of every cell with V_0 = JxW. A quadrilateral/hexahedron gets
     * q^dim points, with q = max(@p points_per_direction, ceil(longest edge / @p spacing)): with
     * @p spacing the sub-cell size h/n, the points are about as dense as those of a box body. A
     * triangle/tetrahedron gets the centroids of k^dim equal sub-simplices, k the smallest power
     * of two for which they are no larger than a sub-cell and at least
     * (points_per_direction)^dim/dim! many.
     */
    std::vector<VolumeElement>
    volume_elements(const unsigned int points_per_direction, const double spacing) const override;

    /**
     * The Gauss points of every boundary face with N_0 A_0 = the outward unit normal times JxW,
     * the face's boundary id and group name. A face gets q^(dim-1) points with q the smallest
     * number for which no Gauss point of its longest edge stands for more than @p spacing of it:
     * in 2D no element is longer than @p spacing, as on boxes (a triangular face in 3D: the
     * centroids of k^2 equal sub-triangles, k the power of two at least q). (@p lower and
     * @p upper are not used.)
     */
    std::vector<SurfaceElement>
    surface_elements(const double              spacing,
                     const dealii::Point<dim> &lower,
                     const dealii::Point<dim> &upper) const override;

    /** The boundary ids on the mesh's boundary faces. */
    std::set<dealii::types::boundary_id>
    boundary_ids() const;

    /** The names of the physical groups of dimension dim - 1 by boundary id. */
    const std::map<dealii::types::boundary_id, std::string> &
    group_names() const;

    /** The names of the physical groups of dimension dim by material id. */
    const std::map<dealii::types::boundary_id, std::string> &
    volume_group_names() const;

    const dealii::Triangulation<dim> &
    mesh() const;

  private:
    // Shared, not unique: a body stays copyable, and the mesh is not changed after reading.
    std::shared_ptr<dealii::Triangulation<dim>>       mesh_;
    std::map<dealii::types::boundary_id, std::string> group_names_;
    std::map<dealii::types::boundary_id, std::string> volume_group_names_;
  };
} // namespace GelMPM

#endif

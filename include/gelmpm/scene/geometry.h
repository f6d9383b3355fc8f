#ifndef gelmpm_scene_geometry_h
#define gelmpm_scene_geometry_h

#include <gelmpm/scene/body.h>
#include <gelmpm/scene/mesh_body.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

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
   * The section is read once into one Body, chosen by the entries given: a BoxBody, a
   * LevelSetBody or a MeshBody, which the Geometry owns (body()). What depends on how the body is
   * given is the body's: what is inside, where the volume points go (sub-cell centres for boxes
   * and level sets, quadrature points of the mesh cells for a mesh), the boundary cut into
   * surface elements and the checks of the points. The functions below pass on to it; those of
   * one kind of body (level_set(), mesh_...()) require that kind.
   */
  template <int dim>
  class Geometry
  {
  public:
    /** How the body is given. */
    using Source = BodySource;

    /** A piece of the boundary (Body::SurfaceElement). */
    using SurfaceElement = typename Body<dim>::SurfaceElement;

    /** A piece of the body (Body::VolumeElement). */
    using VolumeElement = typename Body<dim>::VolumeElement;

    /** Until a section is read or a body is given: a body of no boxes. */
    Geometry();

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

    /**
     * Make the body the mesh in the Gmsh file @p file_name (for programmatic scenes and tests).
     * Throws InputError naming "Geometry/Mesh file" if it cannot be read or is not a mesh of
     * dimension dim.
     */
    void
    read_mesh(const std::string &file_name);

    /** The body. */
    const Body<dim> &
    body() const;

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

    /** The level set phi at @p p (level-set bodies only). */
    double
    level_set(const dealii::Point<dim> &p) const;

    /** Mesh bodies: the Gauss points of every cell (MeshBody::volume_elements()). */
    std::vector<VolumeElement>
    mesh_volume_elements(const unsigned int points_per_direction, const double spacing) const;

    /** Mesh bodies: the Gauss points of every boundary face (MeshBody::surface_elements()). */
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
    /** The body as a MeshBody (an internal error for another body). */
    const MeshBody<dim> &
    mesh_body() const;

    // Shared, not unique: a Geometry stays copyable, and a body is not changed once made.
    std::shared_ptr<const Body<dim>> body_;
  };
} // namespace GelMPM

#endif

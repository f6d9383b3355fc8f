#ifndef gelmpm_particles_material_point_generator_h
#define gelmpm_particles_material_point_generator_h

#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/geometry.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

namespace GelMPM
{
  /**
   * @brief The "Material points" section and the generation of the initial material points
   * (paper §3.2) into a deal.II ParticleHandler with the PropertyLayout.
   *
   * Volume points: n^dim per background cell at the centres of the n^dim sub-cells that lie inside
   * the body (boxes, level set), each with V_0 = the sub-cell volume (area per unit thickness in
   * 2D); for a body from a mesh, the Gauss points of its cells with V_0 = JxW, at least n per
   * direction and cell and no farther apart than about h/n (MeshBody::volume_elements()).
   * Surface points: one per boundary element of length at most h/n_s
   * (Geometry::surface_elements()), with N_0 A_0, the boundary piece that selects it, and the
   * kind that follows from that piece's conditions.
   * All points start in the stress-free initial state: F = lambda_0 I, mu = mu_0.
   */
  template <int dim>
  class MaterialPointGenerator
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Fill @p particles (initialised on @p tria, the grid's triangulation, with
     * PropertyLayout<dim>::n_properties properties). Throws InputError when the body reaches
     * outside the grid (naming Geometry::entry()), when a boundary piece selects no surface
     * point, selects by the physical groups of a body that is not a mesh or names a group the
     * mesh does not have ("Boundary conditions/<name>/Selector"), or when no volume point lies in
     * the body. Each point gets the region of @p regions it lies in, that region's initial
     * stretch and the common initial chemical potential; a surface point that of the volume just
     * inside it (for a mesh: of its face's cell). Throws InputError for overlapping regions, a
     * region without volume points or a region's mesh group that is not a volume group.
     */
    void
    generate(const Geometry<dim>                     &geometry,
             const BackgroundGrid<dim>               &grid,
             const dealii::Triangulation<dim>        &tria,
             const BoundaryConditions<dim>           &boundary_conditions,
             const MaterialRegions<dim>              &regions,
             dealii::Particles::ParticleHandler<dim> &particles) const;

    /**
     * As above for a body of one gel, every point at the initial stretch @p lambda_0 and the
     * chemical potential @p mu_0 (for tests of the generation alone).
     */
    void
    generate(const Geometry<dim>                     &geometry,
             const BackgroundGrid<dim>               &grid,
             const dealii::Triangulation<dim>        &tria,
             const BoundaryConditions<dim>           &boundary_conditions,
             const double                             lambda_0,
             const double                             mu_0,
             dealii::Particles::ParticleHandler<dim> &particles) const;

  private:
    /** generate() with the points' initial chemical potential @p mu_0. */
    void
    generate_at(const Geometry<dim>                     &geometry,
                const BackgroundGrid<dim>               &grid,
                const dealii::Triangulation<dim>        &tria,
                const BoundaryConditions<dim>           &boundary_conditions,
                const MaterialRegions<dim>              &regions,
                const double                             mu_0,
                dealii::Particles::ParticleHandler<dim> &particles) const;

  public:
    /**
     * Throw InputError if a body given by boxes or a level set needs more memory than the
     * machine has available, estimated from the cells whose centre lies in the body: its volume
     * points ('Material points/Points per cell'), or the whole run, grid, points, tangent and
     * factorisation ('Background grid/Cells', above 80 % of the available memory). Needs no
     * triangulation: Scene calls it before the grid is built (also under --check).
     */
    void
    check_point_memory(const Geometry<dim> &geometry, const BackgroundGrid<dim> &grid) const;

    unsigned int points_per_cell         = 3;
    unsigned int surface_points_per_edge = 2;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_particles_point_refinement_h
#define gelmpm_particles_point_refinement_h

#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <array>
#include <vector>

namespace GelMPM
{
  /**
   * The offsets of the children of a volume point that stands for a box of sides @p sides,
   * split into @p parts per direction: the centres of the box's parts, relative to its centre.
   */
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  volume_point_offsets(const std::array<double, dim> &sides, const unsigned int parts);

  /**
   * The offsets of the children of the surface element with N A = @p normal_area (of the plane
   * or meridian plane, not revolved), split into @p parts per direction of the boundary:
   * - 2D: parts along the tangent, on the element's chord of length |N A|;
   * - 3D: parts x parts over the square of the element's area (side sqrt|N A|) in its tangent
   *   plane, with sides along the coordinate axis most nearly in the facet and the normal's
   *   cross product with it (a box face's element splits into the fine grid's elements).
   */
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  surface_element_offsets(const dealii::Tensor<1, dim> &normal_area, const unsigned int parts);

  /**
   * Split every material point whose leaf cell of @p grid is finer than its spacing
   * (PropertyLayout::spacing_level) into 2^(l - s) children per direction of its volume (of its
   * boundary for a surface point), so that a cell of every level holds the scene's points per
   * cell. A body's mesh elements (spacing -1) are never split. Returns the number of points
   * added over all ranks.
   *
   * The children are placed in the initial configuration as the generator places the points of
   * a refined cell (volume_point_offsets(), surface_element_offsets()), and in the current one
   * by the parent's deformation from it, x_c = x + F_n (X_c - X), F_n = F / lambda_0. Each takes
   * the parent's state (F, mu, the last increments, the region) and 1 / 2^(dim (l - s)) of its
   * measures (1 / 2^((dim-1)(l - s)) of a surface point's N A), scaled by R_c / R (r_c / r in the
   * current measures) in an axisymmetric scene, where every measure is revolved: the children's
   * V_0, V_n, N_0 A_0 and N_n A_n sum to the parent's to round-off, so that the body's volume and
   * solvent content stay. The parent becomes the first child; the others get ids from the
   * handler's next free index, the same on every rank.
   */
  template <int dim>
  unsigned long
  split_points_to_leaves(dealii::Particles::ParticleHandler<dim> &particles,
                         const BackgroundGrid<dim>               &grid,
                         const MaterialRegions<dim>              &regions,
                         const unsigned int                       points_per_cell,
                         const dealii::Triangulation<dim>        &triangulation);

  /**
   * Merge the volume points whose leaf cell of @p grid is coarser than their spacing back into
   * their parents, one level at a time: the 2^dim points of spacing s whose X_0 lie in one
   * sub-cell of spacing s - 1 of the generator's lattice (the children of one split), when all
   * of them are on this rank and lie in leaves of level below s. The merged point has the sum of
   * their V_0 and V_n (so the body's volume and solvent content stay to round-off), the mean of
   * their X_0, x, mu and increments weighted by their shares of the parent's sub-cell (V_0, or
   * V_0 / R_0 in an axisymmetric scene), and their weighted mean F scaled
   * so that its J is V_n / V_0 (the children of one split, deformed alike, give back the
   * parent). Surface points are not merged. Returns the number of points removed over all ranks.
   */
  template <int dim>
  unsigned long
  merge_points_to_leaves(dealii::Particles::ParticleHandler<dim> &particles,
                         const BackgroundGrid<dim>               &grid,
                         const MaterialRegions<dim>              &regions,
                         const unsigned int                       points_per_cell,
                         const dealii::Triangulation<dim>        &triangulation);
} // namespace GelMPM

#endif

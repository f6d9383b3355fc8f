#ifndef gelmpm_particles_property_layout_h
#define gelmpm_particles_property_layout_h

#include <deal.II/base/point.h>

#include <cmath>

namespace GelMPM
{
  /**
   * @brief The five kinds of material points (paper §3.2). A surface point's kind says which of
   * its two fields carries an essential (Dirichlet) condition: the first letter is the
   * displacement, the second the chemical potential.
   */
  enum class PointKind : unsigned int
  {
    volume              = 0, ///< bulk point, carries a volume V
    dirichlet_dirichlet = 1, ///< prescribed displacement (some component) and chemical potential
    dirichlet_neumann   = 2, ///< prescribed displacement (some component), solvent flux
    neumann_dirichlet   = 3, ///< traction, prescribed chemical potential
    neumann_neumann     = 4  ///< traction and solvent flux
  };

  /** Kind of a surface point from whether u and mu are prescribed on its piece. */
  inline PointKind
  surface_point_kind(const bool displacement_prescribed, const bool chemical_potential_prescribed)
  {
    if (displacement_prescribed)
      return chemical_potential_prescribed ? PointKind::dirichlet_dirichlet
                                           : PointKind::dirichlet_neumann;
    return chemical_potential_prescribed ? PointKind::neumann_dirichlet
                                         : PointKind::neumann_neumann;
  }

  /**
   * @brief Where each quantity sits in a material point's property array
   * (dealii::Particles::Particle::get_properties()).
   *
   * Every point, volume or surface, carries the same layout so that one ParticleHandler holds
   * them all; entries that a kind does not use are zero. Tensors are stored row-major
   * (F[i][j] at F + i*dim + j). Positions are the particle's own location (x_n).
   *
   * - kind: PointKind as a double.
   * - piece: index of the boundary piece (into "Boundary conditions/Pieces") of a surface point;
   *   -1 for volume points and for surface points that belong to no piece.
   * - mu: chemical potential mu/(k_B T) at the point, last converged step.
   * - measure_0: V_0 (volume points) or A_0 (surface points) in the initial configuration
   *   Omega_0 (per unit thickness in 2D).
   * - measure_n: V_n or A_n in the last converged configuration Omega_n, eq. (34).
   * - position_0: X_0, the point's position in the initial configuration.
   * - F: F_n F_0, the in-plane deformation gradient from the dry state to Omega_n (in 2D the
   *   out-of-plane stretch is lambda_0 and is not stored).
   * - normal_area_0: N_0 A_0 (surface points; zero for volume points).
   * - normal_area_n: N_n A_n = J_n F_n^{-T} N_0 A_0, eq. (34).
   * - increment: the point's displacement in the last accepted step, x_n - x_{n-1} (zero before
   *   the first step): the predictor of the next step's displacement ('Time stepping/Displacement
   *   tolerance', 'Newton/Initial displacement').
   * - mu_increment: the change of mu at the point in the last accepted step, mu_n - mu_{n-1}:
   *   the predictor of the next step's change ('Time stepping/Tolerance').
   * - edge_offset: x_n minus the particle's location, nonzero only for a point that has crossed
   *   an edge of the background grid by the violation of a weakly imposed condition there (a
   *   roller or a contact plane on the edge). The location stays on the edge, inside the
   *   grid, where the point's cell is found and the basis evaluated; the offset keeps the
   *   violation in the point's displacement, so that the next step's Nitsche or contact term
   *   sees it and removes it. Dropping it would reset the violation at every step and let the
   *   body creep through the edge by one violation per step (doc/method.md).
   * - region: the material region of the point (MaterialRegions; 0: the body's own material),
   *   fixed at its creation.
   * - out_of_plane (2D only): the out-of-plane stretch F_33 from the dry state, lambda_0 in plane
   *   strain, the hoop stretch lambda_0 r_n / R_0 in an axisymmetric scene (doc/axisymmetric.md).
   * - spacing_level: the refinement level l whose spacing the point has (a volume point stands
   *   for a sub-cell of side h / (points per cell 2^l), a surface point for an element of its
   *   spacing); -1 for a point of a body's own mesh element, which is never split
   *   (split_points_to_leaves()).
   */
  template <int dim>
  struct PropertyLayout
  {
    static constexpr unsigned int kind          = 0;
    static constexpr unsigned int piece         = 1;
    static constexpr unsigned int mu            = 2;
    static constexpr unsigned int measure_0     = 3;
    static constexpr unsigned int measure_n     = 4;
    static constexpr unsigned int position_0    = 5;
    static constexpr unsigned int F             = position_0 + dim;
    static constexpr unsigned int normal_area_0 = F + dim * dim;
    static constexpr unsigned int normal_area_n = normal_area_0 + dim;
    static constexpr unsigned int increment     = normal_area_n + dim;
    static constexpr unsigned int mu_increment  = increment + dim;
    static constexpr unsigned int edge_offset   = mu_increment + 1;
    static constexpr unsigned int region        = edge_offset + dim;
    static constexpr unsigned int out_of_plane  = region + 1;
    static constexpr unsigned int spacing_level = out_of_plane + (dim == 2 ? 1 : 0);
    static constexpr unsigned int n_properties  = spacing_level + 1;
  };


  /**
   * The position x_n of a point whose particle sits at @p location with the property array
   * @p properties: the location plus its edge offset (PropertyLayout::edge_offset).
   */
  template <int dim, typename Properties>
  inline dealii::Point<dim>
  position_of(const dealii::Point<dim> &location, const Properties &properties)
  {
    dealii::Point<dim> x = location;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += properties[PropertyLayout<dim>::edge_offset + d];
    return x;
  }


  /**
   * The kind of the point whose property array is @p properties. The array holds doubles only,
   * so the kind is stored as one; rounding makes the conversion exact whatever arithmetic touched
   * the value. The first two entries do not depend on the dimension.
   */
  template <typename Properties>
  inline PointKind
  kind_of(const Properties &properties)
  {
    return static_cast<PointKind>(std::lround(properties[PropertyLayout<1>::kind]));
  }


  /**
   * The out-of-plane stretch F_33 of the point whose property array is @p properties in 2D
   * (PropertyLayout::out_of_plane); 1 in 3D, where F holds every stretch.
   */
  template <int dim, typename Properties>
  inline double
  out_of_plane_stretch_of(const Properties &properties)
  {
    if constexpr (dim == 2)
      return properties[PropertyLayout<dim>::out_of_plane];
    else
      return 1.;
  }


  /** The material region of the point whose property array is @p properties. */
  template <int dim, typename Properties>
  inline unsigned int
  region_of_point(const Properties &properties)
  {
    return static_cast<unsigned int>(std::lround(properties[PropertyLayout<dim>::region]));
  }


  /** The boundary piece of the point whose property array is @p properties (-1: none). */
  template <typename Properties>
  inline int
  piece_of(const Properties &properties)
  {
    return static_cast<int>(std::lround(properties[PropertyLayout<1>::piece]));
  }
} // namespace GelMPM

#endif

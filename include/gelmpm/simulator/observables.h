#ifndef gelmpm_simulator_observables_h
#define gelmpm_simulator_observables_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/geometry/surface_geometry.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <array>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Observables" section: scene-specific quantities added as columns of
   * statistics.csv. Each is off unless the scene names it, and costs nothing then.
   *
   * - Thickness (column delta_h_over_h0): with "Thickness pieces = top, bottom" and direction d,
   *   h(t) is the mean coordinate x_d of the surface points of the first piece minus that of the
   *   second, h_0 the same in the initial configuration, and the column is h/h_0 - 1 (paper §4.1:
   *   Delta h / h_0).
   * - Radius (column radius_over_R0): with "Radius piece" and "Radius centre" c, the mean
   *   distance |x - c| of the piece's surface points over its initial value: the radius of a
   *   swelling sphere, disk or cylinder, r/R_0 (doc/axisymmetric.md).
   * - Centre offset (columns centre_offset_x, _y, (_z), centre_distance): with "Centre offset
   *   pieces = bottom, top", the vector between the mean positions of the two pieces' surface
   *   points minus its initial value, and its length (paper §4.3, Fig. 10a).
   * - Pore shapes (columns pore_ratio_1 ... pore_ratio_N, pore_curvature_1 ... _N,
   *   pore_turning_1 ... _N, pore_creases_1 ... _N, (pore_contact_1 ... _N), mu_boundary): with
   * "Pore piece" and "Pore centres", each pore's extent along x over its extent along y, from the
   * current positions of the piece's surface points nearest (initially) to its centre; the largest
   * curvature of the polyline of these points, ordered by their initial angle about the centre,
   * times the pore's initial radius (PoreGeometry, Fig. 12b), and its largest turning angle in
   * degrees (pore_turning_k, a crease beyond 'Crease angle'); with contact planes, the number of
   * its points on a plane; and the mean mu over the piece (paper §4.4: the holes turning into
   * alternating ellipses, closing and creasing).
   * - Surface shapes (columns <piece>_relief, and in 2D <piece>_curvature, <piece>_turning,
   *   <piece>_folds, per piece of "Surface pieces"): the extent of the piece's current surface
   *   points along its mean current normal (SurfaceGeometry::relief()); in 2D, of the polyline of
   *   the points ordered along the surface in the initial configuration
   *   (SurfaceGeometry::order_along_surface(), no centre needed), the largest Menger curvature
   *   times h_u, the largest turning angle in degrees, and the number of folds
   *   (SurfaceGeometry::count_folds(): self-approach within 'Fold approach distance' of points
   *   more than 'Fold arc length' apart along the surface, or self-intersection). A new fold is
   *   the event 'crease_<piece>'; at every output time the polyline is written to
   *   surface_<piece>-NNNNN.csv (write_surfaces()). Made for a film's surface crease: once
   *   resolved it turns by less than 'Crease angle' at every point, and folds.
   * - Volume ratio range (columns J_min, J_mean, J_max): the extremes and the V_0-weighted mean of
   *   J (dry state to current) over the volume points; the spread measures how far a state is
   *   from homogeneous (patch tests).
   * - Chemical potential oscillation (column mu_oscillation): the mean over rows of volume points
   *   (equal initial y) of the summed |second differences| of mu along the row, over the range of
   *   mu: of order one for the spurious modes of inf-sup unstable pairs (paper §4.2).
   * - Boundary condition error (columns u_bc_error, mu_bc_error): the largest violation of the
   *   weakly imposed conditions over the surface points (MixedSystem::dirichlet_errors()).
   */
  template <int dim>
  class Observables
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section; @p pieces are the scene's boundary piece names (for validation). */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    /** The statistics columns these observables fill. */
    std::vector<std::string>
    columns() const;

    /**
     * Evaluate every observable on the current material points into @p statistics;
     * @p dirichlet_errors gives the boundary-condition errors of the converged step (empty in the
     * initial state) and is called only when they are asked for.
     */
    void
    evaluate(const dealii::Particles::ParticleHandler<dim>    &particles,
             const MaterialRegions<dim>                       &material,
             const std::function<std::pair<double, double>()> &dirichlet_errors,
             StatisticsFile                                   &statistics) const;

    /**
     * With 'Pore piece': the mean mu/k_BT over that piece's surface points (the column
     * mu_boundary); empty otherwise.
     */
    std::optional<double>
    boundary_chemical_potential(const dealii::Particles::ParticleHandler<dim> &particles) const;

    /**
     * The contact planes of the scene (ContactSettings) and the distance @p tolerance within
     * which a surface point counts as touching one; adds the pore_contact_k columns.
     */
    void
    set_contact_planes(const std::vector<ContactSettings::Plane> &planes, const double tolerance);

    /**
     * The cell size h_u (@p spacing) of the displacement grid, the unit of the surface measures
     * ('Fold approach distance', 'Fold arc length', <piece>_curvature); needed in 2D with 'Surface
     * pieces' before evaluate().
     */
    void
    set_grid_spacing(const double spacing);

    /**
     * The events that happened since the last call, as (name, pore number from 1, or 0 for an
     * event of a surface piece). With 'Pore piece': 'self_contact' when a pore first touches a
     * contact plane, 'crease' when its surface polyline turns by more than 'Crease angle' at one
     * more place than ever before (or first crosses itself). With 'Surface pieces' (2D):
     * 'crease_<piece>' when the piece has one more fold than ever before.
     */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /** Whether new_events() can report anything (then the simulator writes events.csv). */
    bool
    writes_events() const;

    /**
     * With 'Surface pieces' in 2D: write each piece's polyline, in its order along the surface,
     * to `<directory>/surface_<piece>-NNNNN.csv` (columns s_0, x, y, mu: the arc length in the
     * initial configuration, the current position and mu/k_BT), NNNNN counting the calls from 0
     * (the number of the particles-NNNNN.vtu written at the same time). Collective; rank 0
     * writes, under a temporary name renamed when complete. Nothing otherwise.
     */
    void
    write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                   const std::string                             &directory);

    /** The events seen and the surface files written so far, for a checkpoint (boost
     * serialization). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &contact_seen &creases_seen &folds_seen &surface_outputs;
    }

    /**
     * The ranks whose material points make the body (default: this process alone); every
     * observable is reduced or gathered over them, and is the same on all.
     */
    void
    set_communicator(const MPI_Comm communicator);

  private:
    /** What pore_shapes() measures of one pore. */
    struct PoreShape
    {
      double       ratio          = 0.;
      double       curvature      = 0.;
      double       turning        = 0.; // radians
      unsigned int creases        = 0;  // sharp corners of its surface polyline
      unsigned int contact_points = 0;
    };

    /** What surface_shapes() measures of one surface piece. */
    struct SurfaceShape
    {
      double       relief    = 0.;
      double       curvature = 0.; // times h_u
      double       turning   = 0.; // radians
      unsigned int folds     = 0;
    };

    /**
     * Per piece of 'Surface pieces', its shape; in 2D its polyline into @p polylines if given.
     * Gathers the pieces' points over the communicator.
     */
    std::vector<SurfaceShape>
    surface_shapes(const dealii::Particles::ParticleHandler<dim> &particles,
                   std::vector<SurfaceGeometry::Polyline>        *polylines = nullptr) const;

    /** The indices of the two pieces named in @p names (entry @p entry); {-1, -1} if empty. */
    static std::array<int, 2>
    piece_pair(const std::vector<std::string> &names,
               const std::vector<std::string> &pieces,
               const std::string              &entry,
               const std::string              &example);
    /** Mean current positions of the surface points of the two pieces, then their initial ones. */
    std::array<dealii::Point<dim>, 4>
    piece_means(const dealii::Particles::ParticleHandler<dim> &particles,
                const std::array<int, 2>                      &pair) const;
    /** Per pore, its shape (ratio 0 for a pore without points); the mean mu over the pore
     * piece's points into @p mu_mean. */
    std::vector<PoreShape>
    pore_shapes(const dealii::Particles::ParticleHandler<dim> &particles, double &mu_mean) const;
    /** (min, V_0-weighted mean, max) of J over the volume points. */
    std::array<double, 3>
    volume_ratio_statistics(const dealii::Particles::ParticleHandler<dim> &particles,
                            const MaterialRegions<dim>                    &material) const;
    /** The oscillation measure of mu over the volume points (one MPI rank). */
    double
    chemical_potential_oscillation(const dealii::Particles::ParticleHandler<dim> &particles) const;

    std::array<int, 2>                  thickness_pieces = {{-1, -1}};
    std::array<int, 2>                  offset_pieces    = {{-1, -1}};
    int                                 radius_piece     = -1;
    dealii::Point<dim>                  radius_centre;
    int                                 pore_piece   = -1;
    MPI_Comm                            communicator = MPI_COMM_SELF;
    std::vector<dealii::Point<dim>>     pore_centres;
    std::vector<ContactSettings::Plane> contact_planes;
    double                              contact_tolerance = 0.;
    std::vector<bool>                   contact_seen;
    std::vector<unsigned int>           creases_seen;
    double                              crease_angle = M_PI / 3.;
    std::vector<unsigned int>           surface_pieces;
    std::vector<std::string>            surface_names;
    double                              fold_approach_distance = 0.5; // times h_u
    double                              fold_arc_length        = 3.;  // times h_u
    double                              h_u                    = 0.;
    std::vector<unsigned int>           folds_seen;
    unsigned int                        surface_outputs     = 0;
    unsigned int                        thickness_direction = 1;
    bool                                volume_ratio_range  = false;
    bool                                mu_oscillation      = false;
    bool                                boundary_error      = false;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_simulator_observables_h
#define gelmpm_simulator_observables_h

#include <gelmpm/assembly/contact_settings.h>
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
     * With 'Pore piece': the events of the pores that happened since the last call, as (name,
     * pore number from 1): 'self_contact' when a pore first touches a contact plane, 'crease' when
     * its surface polyline turns by more than 'Crease angle' at one more place than ever before (or
     * first crosses itself).
     */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /** The events seen so far, for a checkpoint (boost serialization). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &contact_seen &creases_seen;
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
    int                                 pore_piece       = -1;
    MPI_Comm                            communicator     = MPI_COMM_SELF;
    std::vector<dealii::Point<dim>>     pore_centres;
    std::vector<ContactSettings::Plane> contact_planes;
    double                              contact_tolerance = 0.;
    std::vector<bool>                   contact_seen;
    std::vector<unsigned int>           creases_seen;
    double                              crease_angle        = M_PI / 3.;
    unsigned int                        thickness_direction = 1;
    bool                                volume_ratio_range  = false;
    bool                                mu_oscillation      = false;
    bool                                boundary_error      = false;
  };
} // namespace GelMPM

#endif

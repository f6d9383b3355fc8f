#ifndef gelmpm_simulator_observable_pore_shapes_h
#define gelmpm_simulator_observable_pore_shapes_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <boost/serialization/vector.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The shapes of the pores of a porous gel and their events (columns pore_ratio_1 ...
   * pore_ratio_N, pore_curvature_1 ... _N, pore_turning_1 ... _N, pore_creases_1 ... _N,
   * (pore_contact_1 ... _N), mu_boundary): with "Pore piece" and "Pore centres", each pore's
   * extent along x over its extent along y, from the current positions of the piece's surface
   * points nearest (initially) to its centre; the largest curvature of the polyline of these
   * points, ordered by their initial angle about the centre, times the pore's initial radius
   * (PoreGeometry, Fig. 12b), and its largest turning angle in degrees (pore_turning_k, a crease
   * beyond 'Crease angle'); with contact planes, the number of its points on a plane; and the
   * mean mu over the piece (paper §4.4: the holes turning into alternating ellipses, closing and
   * creasing). 2D only.
   *
   * Its events: 'self_contact' when a pore first touches a contact plane, 'crease' when its
   * polyline turns by more than 'Crease angle' at one more place than ever before (or first
   * crosses itself).
   */
  template <int dim>
  class PoreShapes : public Observable<dim>
  {
  public:
    /** Its entries, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered), @p pieces being the scene's piece names; none if off. */
    static std::unique_ptr<PoreShapes>
    parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

    /** The mean mu/k_BT over the pore piece's surface points (the column mu_boundary). */
    double
    boundary_chemical_potential(const dealii::Particles::ParticleHandler<dim> &particles) const;

    /**
     * The contact planes of the scene and the distance @p tolerance within which a surface
     * point counts as touching one; adds the pore_contact_k columns.
     */
    void
    set_contact_planes(const std::vector<ContactSettings::Plane> &planes, const double tolerance);

    /** The events since the last call, as (name, pore number from 1). */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /** The pore (from 1) whose centre lies nearest to the initial position @p X0, as a pore
     * takes its points; 0 without pores. */
    unsigned int
    pore_of(const dealii::Point<dim> &X0) const;

    /** The events seen so far, for a checkpoint (the archive's fields, no class record). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &contact_seen &creases_seen;
    }

  private:
    /** What shapes() measures of one pore. */
    struct Shape
    {
      double       ratio          = 0.;
      double       curvature      = 0.;
      double       turning        = 0.; // radians
      unsigned int creases        = 0;  // sharp corners of its surface polyline
      unsigned int contact_points = 0;
    };

    /** Per pore, its shape (ratio 0 for a pore without points); the mean mu over the pore
     * piece's points into @p mu_mean. Gathers the piece's points over the communicator. */
    std::vector<Shape>
    shapes(const dealii::Particles::ParticleHandler<dim> &particles, double &mu_mean) const;

    int                                 pore_piece = -1;
    std::vector<dealii::Point<dim>>     pore_centres;
    double                              crease_angle = M_PI / 3.;
    std::vector<ContactSettings::Plane> contact_planes;
    double                              contact_tolerance = 0.;
    std::vector<bool>                   contact_seen;
    std::vector<unsigned int>           creases_seen;
  };
} // namespace GelMPM

#endif

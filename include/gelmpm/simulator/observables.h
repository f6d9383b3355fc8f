#ifndef gelmpm_simulator_observables_h
#define gelmpm_simulator_observables_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/scene/material_regions.h>
#include <gelmpm/simulator/observable.h>
#include <gelmpm/simulator/observable_pore_shapes.h>
#include <gelmpm/simulator/observable_shape_fits.h>
#include <gelmpm/simulator/observable_surface_shapes.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Observables" section: scene-specific quantities added as columns of
   * statistics.csv, each kind of observable a class of its own (Observable) that declares and
   * checks its own entries. A kind is made only when the scene names it, so a scene does no
   * work for what it does not observe. The kinds, in the order of their columns:
   * SwellingExtent (delta_h_over_h0, radius_over_R0), CentreOffset (centre_offset_x, ...,
   * centre_distance), PoreShapes (pore_*_k, mu_boundary; events 'self_contact', 'crease'),
   * SurfaceShapes (<piece>_relief, _curvature, _turning, _folds; events 'crease_<piece>',
   * surface_<piece>-NNNNN.csv), ShapeFits (<piece>_fit_curvature, _fit_residual, _amplitude,
   * _skewness, _wavelength, _relative_amplitude, _dip_crest_ratio; events
   * 'instability_crease_<piece>', 'instability_wrinkle_<piece>'), VolumeRatioRange (J_min,
   * J_mean, J_max),
   * ChemicalPotentialOscillation (mu_oscillation) and BoundaryConditionError (u_bc_error,
   * mu_bc_error). The section's 'Forces and fluxes' belongs to BoundaryBalance.
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
     * ('Fold approach distance', 'Fold arc length', <piece>_curvature) and of the polylines of
     * 'Shape pieces'; needed in 2D with 'Surface pieces' or 'Shape pieces' before evaluate().
     */
    void
    set_grid_spacing(const double spacing);

    /**
     * The events that happened since the last call, as (name, pore number from 1, or 0 for an
     * event of a surface piece): SurfaceShapes::new_events(), ShapeFits::new_events(), then
     * PoreShapes::new_events().
     */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /** With 'Pore piece': PoreShapes::pore_of(); 0 otherwise. */
    unsigned int
    pore_of(const dealii::Point<dim> &X0) const
    {
      return pores ? pores->pore_of(X0) : 0;
    }

    /** Whether new_events() can report anything (then the simulator writes events.csv). */
    bool
    writes_events() const;

    /** With 'Surface pieces': SurfaceShapes::write_surfaces(); nothing otherwise. */
    void
    write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                   const std::string                             &directory);

    /**
     * The events seen and the surface files written so far, for a checkpoint (boost
     * serialization): the pores' and the surfaces' fields, in the order the archive has always
     * had them, then the shape fits'; a kind the scene does not ask for writes, and reads, its
     * empty state.
     */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int version)
    {
      PoreShapes<dim>    no_pores;
      SurfaceShapes<dim> no_surfaces;
      ShapeFits<dim>     no_fits;
      (pores ? *pores : no_pores).serialize(ar, version);
      (surfaces ? *surfaces : no_surfaces).serialize(ar, version);
      (fits ? *fits : no_fits).serialize(ar, version);
    }

    /**
     * The ranks whose material points make the body (default: this process alone); every
     * observable is reduced or gathered over them, and is the same on all.
     */
    void
    set_communicator(const MPI_Comm communicator);

  private:
    /** Appends @p kind (if the scene asks for it) to the kinds; returns it. */
    template <class Kind>
    Kind *
    add(std::unique_ptr<Kind> kind);

    /** The kinds the scene asks for, in the order of their columns. */
    std::vector<std::unique_ptr<Observable<dim>>> kinds;
    /** The kinds with events, files and a state in checkpoints, if asked for (in kinds). */
    PoreShapes<dim>    *pores        = nullptr;
    SurfaceShapes<dim> *surfaces     = nullptr;
    ShapeFits<dim>     *fits         = nullptr;
    MPI_Comm            communicator = MPI_COMM_SELF;
  };
} // namespace GelMPM

#endif

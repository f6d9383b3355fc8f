#include <gelmpm/simulator/observable_boundary_condition_error.h>
#include <gelmpm/simulator/observable_centre_offset.h>
#include <gelmpm/simulator/observable_chemical_potential_oscillation.h>
#include <gelmpm/simulator/observable_swelling_extent.h>
#include <gelmpm/simulator/observable_volume_ratio_range.h>
#include <gelmpm/simulator/observables.h>

namespace GelMPM
{
  template <int dim>
  void
  Observables<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Observables");
    SwellingExtent<dim>::declare_parameters(prm);
    CentreOffset<dim>::declare_parameters(prm);
    PoreShapes<dim>::declare_parameters(prm);
    SurfaceShapes<dim>::declare_parameters(prm);
    ShapeFits<dim>::declare_parameters(prm);
    VolumeRatioRange<dim>::declare_parameters(prm);
    BoundaryConditionError<dim>::declare_parameters(prm);
    ChemicalPotentialOscillation<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }


  template <int dim>
  void
  Observables<dim>::parse_parameters(dealii::ParameterHandler       &prm,
                                     const std::vector<std::string> &pieces)
  {
    kinds.clear();
    pores    = nullptr;
    surfaces = nullptr;
    fits     = nullptr;
    prm.enter_subsection("Observables");
    add(SwellingExtent<dim>::parse(prm, pieces));
    add(CentreOffset<dim>::parse(prm, pieces));
    pores    = add(PoreShapes<dim>::parse(prm, pieces));
    surfaces = add(SurfaceShapes<dim>::parse(prm, pieces));
    fits     = add(ShapeFits<dim>::parse(prm, pieces));
    add(VolumeRatioRange<dim>::parse(prm));
    add(ChemicalPotentialOscillation<dim>::parse(prm));
    add(BoundaryConditionError<dim>::parse(prm));
    prm.leave_subsection();
  }


  template <int dim>
  template <class Kind>
  Kind *
  Observables<dim>::add(std::unique_ptr<Kind> kind)
  {
    Kind *added = kind.get();
    if (added)
      {
        added->set_communicator(communicator);
        kinds.push_back(std::move(kind));
      }
    return added;
  }


  template <int dim>
  std::vector<std::string>
  Observables<dim>::columns() const
  {
    std::vector<std::string> all;
    for (const auto &kind : kinds)
      for (const auto &column : kind->columns())
        all.push_back(column);
    return all;
  }


  template <int dim>
  void
  Observables<dim>::evaluate(const dealii::Particles::ParticleHandler<dim>    &particles,
                             const MaterialRegions<dim>                       &material,
                             const std::function<std::pair<double, double>()> &dirichlet_errors,
                             StatisticsFile                                   &statistics) const
  {
    const ObservedState<dim> state{particles, material, dirichlet_errors};
    for (const auto &kind : kinds)
      kind->evaluate(state, statistics);
  }


  template <int dim>
  std::optional<double>
  Observables<dim>::boundary_chemical_potential(
    const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    if (!pores)
      return std::nullopt;
    return pores->boundary_chemical_potential(particles);
  }


  template <int dim>
  void
  Observables<dim>::set_contact_planes(const std::vector<ContactSettings::Plane> &planes,
                                       const double                               tolerance)
  {
    if (pores)
      pores->set_contact_planes(planes, tolerance);
  }


  template <int dim>
  void
  Observables<dim>::set_grid_spacing(const double spacing)
  {
    if (surfaces)
      surfaces->set_grid_spacing(spacing);
    if (fits)
      fits->set_grid_spacing(spacing);
  }


  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  Observables<dim>::new_events(const dealii::Particles::ParticleHandler<dim> &particles)
  {
    std::vector<std::pair<std::string, unsigned int>> events;
    if (surfaces)
      events = surfaces->new_events(particles);
    if (fits)
      for (auto &event : fits->new_events(particles))
        events.push_back(std::move(event));
    if (pores)
      for (auto &event : pores->new_events(particles))
        events.push_back(std::move(event));
    return events;
  }


  template <int dim>
  bool
  Observables<dim>::writes_events() const
  {
    // A surface's folds are counted on its polyline, which 2D alone has.
    return pores != nullptr || (dim == 2 && surfaces != nullptr) ||
           (fits != nullptr && fits->writes_events());
  }


  template <int dim>
  void
  Observables<dim>::write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                                   const std::string                             &directory)
  {
    if (surfaces)
      surfaces->write_surfaces(particles, directory);
  }


  template <int dim>
  void
  Observables<dim>::set_communicator(const MPI_Comm comm)
  {
    communicator = comm;
    for (const auto &kind : kinds)
      kind->set_communicator(comm);
  }


  template class Observables<2>;
  template class Observables<3>;
} // namespace GelMPM

#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/scene.h>

namespace GelMPM
{
  template <int dim>
  void
  Scene<dim>::declare_parameters(dealii::ParameterHandler       &prm,
                                 const std::vector<std::string> &boundary_pieces)
  {
    FloryRehnerGel<dim>::declare_parameters(prm);
    BackgroundGrid<dim>::declare_parameters(prm);
    Geometry<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm, boundary_pieces);
    MaterialPointGenerator<dim>::declare_parameters(prm);
    DiscretisationSettings::declare_parameters(prm);
    NitscheSettings::declare_parameters(prm);
    ContactSettings::declare_parameters(prm);
  }


  template <int dim>
  Scene<dim>::Scene(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &boundary_pieces,
                    const std::string              &scene_directory)
  {
    material.parse_parameters(prm);
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm, scene_directory);
    boundary_conditions.parse_parameters(prm, boundary_pieces);
    generator.parse_parameters(prm);
    discretisation.parse_parameters(prm);
    nitsche.parse_parameters(prm);
    contact.parse_parameters(prm, dim);
  }


  template <int dim>
  void
  Scene<dim>::create_material_points()
  {
    // The spaces first: an odd cell count with subdivision is reported before point generation,
    // which may take long on a large grid.
    spaces = std::make_unique<DiscreteSpaces<dim>>(grid, discretisation);
    grid.create_triangulation(triangulation);
    particles.initialize(triangulation, mapping, PropertyLayout<dim>::n_properties);
    generator.generate(geometry,
                       grid,
                       triangulation,
                       boundary_conditions,
                       material.lambda_0(),
                       material.mu_0(),
                       particles);
  }


  template <int dim>
  void
  Scene<dim>::create_system()
  {
    system = std::make_unique<MixedSystem<dim>>(material, boundary_conditions, nitsche, *spaces);
    if (contact.enabled())
      system->set_contact(contact);
  }


  template class Scene<2>;
  template class Scene<3>;
} // namespace GelMPM

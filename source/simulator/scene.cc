#include <gelmpm/core/collective.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/distributed/tria.h>

namespace GelMPM
{
  template <int dim>
  void
  Scene<dim>::declare_parameters(dealii::ParameterHandler       &prm,
                                 const std::vector<std::string> &boundary_pieces,
                                 const std::vector<std::string> &material_regions,
                                 const std::vector<std::string> &obstacle_names)
  {
    FloryRehnerGel<dim>::declare_parameters(prm);
    MaterialRegions<dim>::declare_parameters(prm, material_regions);
    BackgroundGrid<dim>::declare_parameters(prm);
    Geometry<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm, boundary_pieces);
    MaterialPointGenerator<dim>::declare_parameters(prm);
    DiscretisationSettings::declare_parameters(prm);
    NitscheSettings::declare_parameters(prm);
    ContactSettings::declare_parameters(prm);
    declare_obstacles<dim>(prm, obstacle_names);
  }


  template <int dim>
  Scene<dim>::Scene(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &boundary_pieces,
                    const std::string              &scene_directory,
                    const MPI_Comm                  communicator,
                    const std::vector<std::string> &material_regions,
                    const std::vector<std::string> &obstacle_names)
    : communicator(communicator)
  {
    material.parse_parameters(prm);
    regions.parse_parameters(prm, material_regions, material);
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm, scene_directory);
    boundary_conditions.parse_parameters(prm, boundary_pieces);
    generator.parse_parameters(prm);
    discretisation.parse_parameters(prm);
    nitsche.parse_parameters(prm);
    contact.parse_parameters(prm, dim, obstacle_names);
    obstacles = parse_obstacles<dim>(prm, obstacle_names);
    for (auto &obstacle : obstacles)
      obstacle.check_inside_grid(grid.lower, grid.upper);
  }


  template <int dim>
  void
  Scene<dim>::create_material_points()
  {
    // The spaces first: an odd cell count with subdivision is reported before point generation,
    // which may take long on a large grid.
    spaces = std::make_unique<DiscreteSpaces<dim>>(grid, discretisation);
    // The run's memory from the grid and the body's cells, before any cell or point is made
    // (also under --check): a body of boxes or a level set, whose cells are known from the
    // grid alone.
    if (geometry.source() != Geometry<dim>::Source::mesh)
      generator.check_point_memory(geometry, grid);
    if (Collective::is_parallel(communicator))
      {
        auto distributed =
          std::make_unique<dealii::parallel::distributed::Triangulation<dim>>(communicator);
        distributed->signals.weight.connect(
          [this](const typename dealii::Triangulation<dim>::cell_iterator &cell,
                 const typename dealii::Triangulation<dim>::CellStatus) -> unsigned int {
            return added_weight(particles.n_particles_in_cell(cell));
          });
        triangulation = std::move(distributed);
      }
    else
      triangulation = std::make_unique<dealii::Triangulation<dim>>();
    grid.create_triangulation(*triangulation);
    particles.initialize(*triangulation, mapping, PropertyLayout<dim>::n_properties);
    generator.generate(geometry, grid, *triangulation, boundary_conditions, regions, particles);
    balance_partition();
  }


  template <int dim>
  void
  Scene<dim>::balance_partition()
  {
    auto *distributed =
      dynamic_cast<dealii::parallel::distributed::Triangulation<dim> *>(triangulation.get());
    if (distributed == nullptr)
      return;
    particles.prepare_for_coarsening_and_refinement();
    distributed->repartition();
    particles.unpack_after_coarsening_and_refinement();
  }


  template <int dim>
  double
  Scene<dim>::imbalance() const
  {
    if (!Collective::is_parallel(communicator))
      return 1.;
    double local = 0.;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        local += base_weight + added_weight(particles.n_particles_in_cell(cell));
    const double mean = dealii::Utilities::MPI::sum(local, communicator) /
                        dealii::Utilities::MPI::n_mpi_processes(communicator);
    return mean > 0. ? dealii::Utilities::MPI::max(local, communicator) / mean : 1.;
  }


  template <int dim>
  void
  Scene<dim>::create_system()
  {
    system = std::make_unique<MixedSystem<dim>>(regions,
                                                boundary_conditions,
                                                nitsche,
                                                *spaces,
                                                triangulation->get_communicator());
    if (contact.enabled())
      system->set_contact(contact, obstacles);
  }


  template class Scene<2>;
  template class Scene<3>;
} // namespace GelMPM

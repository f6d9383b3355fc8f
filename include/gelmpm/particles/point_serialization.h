#ifndef gelmpm_particles_point_serialization_h
#define gelmpm_particles_point_serialization_h

#include <deal.II/base/array_view.h>
#include <deal.II/grid/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <boost/serialization/array_wrapper.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * Write the material points of @p particles into the boost archive @p ar, for a checkpoint:
   * per point, in the order the handler holds them, its cell (active cell index), position,
   * reference position, id and property array (doubles in binary, so exactly).
   *
   * deal.II serialises the points of a ParticleHandler only together with a distributed
   * triangulation; the background grid here is regenerated from the scene, so the points go
   * on their own. The order matters: sums over the points (assembly, observables) are taken
   * in it, and load_material_points() restores it.
   */
  template <class Archive, int dim>
  void
  save_material_points(Archive &ar, const dealii::Particles::ParticleHandler<dim> &particles)
  {
    const std::uint64_t n_points     = particles.n_locally_owned_particles();
    const std::uint32_t n_properties = particles.n_properties_per_particle();
    ar << n_points << n_properties;
    for (const auto &p : particles)
      {
        const std::uint64_t      cell      = p.get_surrounding_cell()->active_cell_index();
        const std::uint64_t      id        = p.get_id();
        const dealii::Point<dim> location  = p.get_location();
        const dealii::Point<dim> reference = p.get_reference_location();
        ar << cell << id << location << reference;
        const auto properties = p.get_properties();
        ar << boost::serialization::make_array(properties.data(), properties.size());
      }
  }


  /**
   * Add to @p particles, on @p triangulation (the grid they were saved on, regenerated), the
   * points save_material_points() wrote into @p ar that lie in cells this rank owns, in the
   * same cells and the same order. On several ranks each rank saved its own points and each
   * reads all of them (a resumed run may partition the grid otherwise). The caller clears the
   * handler before and updates its cached numbers after. Throws std::runtime_error if the
   * points do not fit the handler or the grid.
   */
  template <class Archive, int dim>
  void
  load_material_points(Archive                                 &ar,
                       dealii::Particles::ParticleHandler<dim> &particles,
                       const dealii::Triangulation<dim>        &triangulation)
  {
    std::uint64_t n_points     = 0;
    std::uint32_t n_properties = 0;
    ar >> n_points >> n_properties;
    if (n_properties != particles.n_properties_per_particle())
      throw std::runtime_error("the checkpoint's material points have " +
                               std::to_string(n_properties) + " properties, this scene's " +
                               std::to_string(particles.n_properties_per_particle()));
    std::vector<typename dealii::Triangulation<dim>::active_cell_iterator> cells;
    for (const auto &cell : triangulation.active_cell_iterators())
      cells.push_back(cell);

    std::vector<double> properties(n_properties);
    for (std::uint64_t i = 0; i < n_points; ++i)
      {
        std::uint64_t      cell = 0, id = 0;
        dealii::Point<dim> location, reference;
        ar >> cell >> id >> location >> reference;
        ar >> boost::serialization::make_array(properties.data(), properties.size());
        if (cell >= cells.size())
          throw std::runtime_error("a material point of the checkpoint lies in cell " +
                                   std::to_string(cell) + " of a grid of " +
                                   std::to_string(cells.size()) + " cells");
        if (cells[cell]->is_locally_owned())
          particles.insert_particle(location,
                                    reference,
                                    id,
                                    cells[cell],
                                    dealii::ArrayView<const double>(properties));
      }
  }
} // namespace GelMPM

#endif

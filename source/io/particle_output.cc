#include <gelmpm/io/particle_output.h>
#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  ParticleOutput<dim>::ParticleOutput(const std::string          &directory,
                                      const MaterialRegions<dim> &materials,
                                      const MPI_Comm              communicator)
    : materials(materials)
    , series(directory, "particles", communicator)
  {}


  template <int dim>
  void
  ParticleOutput<dim>::write(const dealii::Particles::ParticleHandler<dim> &particles,
                             const double                                   time)
  {
    using Layout = PropertyLayout<dim>;
    using namespace dealii;

    std::vector<std::string> names = {"kind", "piece", "mu_over_kT", "J", "phi", "measure"};
    // The region only where there are several: one gel writes nothing it does not need.
    const bool regions = materials.size() > 1;
    if (regions)
      names.push_back("region");
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("stretch_" + std::to_string(d + 1));
    const unsigned int stress_first = names.size();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        names.push_back("cauchy_stress");
    const unsigned int displacement_first = names.size();
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("displacement");
    const unsigned int normal_first = names.size();
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("normal_area");

    std::vector<std::tuple<unsigned int,
                           unsigned int,
                           std::string,
                           DataComponentInterpretation::DataComponentInterpretation>>
      ranges = {{stress_first,
                 stress_first + dim * dim - 1,
                 "cauchy_stress",
                 DataComponentInterpretation::component_is_part_of_tensor},
                {displacement_first,
                 displacement_first + dim - 1,
                 "displacement",
                 DataComponentInterpretation::component_is_part_of_vector},
                {normal_first,
                 normal_first + dim - 1,
                 "normal_area",
                 DataComponentInterpretation::component_is_part_of_vector}};

    std::vector<DataOutBase::Patch<0, dim>> patches;
    patches.reserve(particles.n_locally_owned_particles());
    for (const auto &particle : particles)
      {
        const auto           props    = particle.get_properties();
        const Tensor<2, dim> F        = deformation_gradient_of<dim>(props);
        const double         mu       = props[Layout::mu];
        const auto           material = material_state_of(materials, props);
        const double         stretch  = out_of_plane_stretch_of<dim>(props);
        const double         J        = material.gel->J(F, stretch);

        DataOutBase::Patch<0, dim> patch;
        const Point<dim>           x = position_of(particle.get_location(), props);
        patch.vertices[0]            = x;
        patch.patch_index            = patches.size();
        patch.data.reinit(names.size(), 1);
        patch.data(0, 0)                 = props[Layout::kind];
        patch.data(1, 0)                 = props[Layout::piece];
        patch.data(2, 0)                 = mu;
        patch.data(3, 0)                 = J;
        patch.data(4, 0)                 = 1. - 1. / J;
        patch.data(5, 0)                 = props[Layout::measure_n];
        const unsigned int first_stretch = regions ? 7 : 6;
        if (regions)
          patch.data(6, 0) = material.region;
        // Principal stretches from F F^T by Jacobi rotations: the closed-form eigenvalues of a
        // nearly isotropic tensor take the root of a discriminant that round-off can make
        // slightly negative, a NaN in ParaView (sorted in descending order either way).
        const auto principal =
          eigenvectors(symmetrize(F * transpose(F)), SymmetricTensorEigenvectorMethod::jacobi);
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(first_stretch + d, 0) = std::sqrt(std::max(principal[dim - 1 - d].first, 0.));
        if (J > 1.)
          {
            const Tensor<2, dim> sigma = material.gel->stress(F, mu, stretch) * transpose(F) / J;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                patch.data(stress_first + i * dim + j, 0) = sigma[i][j];
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            patch.data(displacement_first + d, 0) = x[d] - props[Layout::position_0 + d];
            patch.data(normal_first + d, 0)       = props[Layout::normal_area_n + d];
          }
        patches.push_back(std::move(patch));
      }

    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    series.write(
      time,
      [&](std::ostream &out) {
        DataOutBase::write_vtu(patches, names, ranges, flags, out);
      },
      [&](std::ostream &out, const std::vector<std::string> &pieces) {
        DataOutBase::write_pvtu_record(out, pieces, names, ranges, flags);
      });
  }


  template <int dim>
  const std::vector<std::pair<double, std::string>> &
  ParticleOutput<dim>::times_and_names() const
  {
    return series.times_and_names();
  }


  template class ParticleOutput<2>;
  template class ParticleOutput<3>;
} // namespace GelMPM

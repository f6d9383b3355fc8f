#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable_volume_ratio_range.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>

namespace GelMPM
{
  template <int dim>
  void
  VolumeRatioRange<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Volume ratio range",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the columns J_min, J_mean and J_max: the smallest, mean (weighted "
                      "by the initial volumes V_0) and largest volume ratio J (dry state to "
                      "current) over the volume points. A homogeneous state has J_min = J_max.");
  }


  template <int dim>
  std::unique_ptr<VolumeRatioRange<dim>>
  VolumeRatioRange<dim>::parse(dealii::ParameterHandler &prm)
  {
    if (!prm.get_bool("Volume ratio range"))
      return nullptr;
    return std::make_unique<VolumeRatioRange>();
  }


  template <int dim>
  std::vector<std::string>
  VolumeRatioRange<dim>::columns() const
  {
    return {"J_min", "J_mean", "J_max"};
  }


  template <int dim>
  void
  VolumeRatioRange<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    const auto J = range(state.particles, state.material);
    statistics.set("J_min", J[0]);
    statistics.set("J_mean", J[1]);
    statistics.set("J_max", J[2]);
  }


  template <int dim>
  std::array<double, 3>
  VolumeRatioRange<dim>::range(const dealii::Particles::ParticleHandler<dim> &particles,
                               const MaterialRegions<dim>                    &material) const
  {
    using Layout = PropertyLayout<dim>;
    double J_min = std::numeric_limits<double>::max(), J_max = -J_min;
    double sum_JV = 0., sum_V = 0.;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (kind_of(props) != PointKind::volume)
          continue;
        const double J = volume_ratio_of(material, props);
        J_min          = std::min(J_min, J);
        J_max          = std::max(J_max, J);
        sum_JV += J * props[Layout::measure_0];
        sum_V += props[Layout::measure_0];
      }
    return {{dealii::Utilities::MPI::min(J_min, this->communicator),
             dealii::Utilities::MPI::sum(sum_JV, this->communicator) /
               dealii::Utilities::MPI::sum(sum_V, this->communicator),
             dealii::Utilities::MPI::max(J_max, this->communicator)}};
  }


  template class VolumeRatioRange<2>;
  template class VolumeRatioRange<3>;
} // namespace GelMPM

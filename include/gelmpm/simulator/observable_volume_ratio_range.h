#ifndef gelmpm_simulator_observable_volume_ratio_range_h
#define gelmpm_simulator_observable_volume_ratio_range_h

#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <memory>

namespace GelMPM
{
  /**
   * @brief The range of the volume ratio (columns J_min, J_mean, J_max): the extremes and the
   * V_0-weighted mean of J (dry state to current) over the volume points, each point's J from
   * the gel of its material state; the spread measures how far a state is from homogeneous
   * (patch tests).
   */
  template <int dim>
  class VolumeRatioRange : public Observable<dim>
  {
  public:
    /** Its entry, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered); none if off. */
    static std::unique_ptr<VolumeRatioRange>
    parse(dealii::ParameterHandler &prm);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

  private:
    /** (min, V_0-weighted mean, max) of J over the volume points. */
    std::array<double, 3>
    range(const dealii::Particles::ParticleHandler<dim> &particles,
          const MaterialRegions<dim>                    &material) const;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_simulator_observable_chemical_potential_oscillation_h
#define gelmpm_simulator_observable_chemical_potential_oscillation_h

#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>

namespace GelMPM
{
  /**
   * @brief The oscillation of the chemical potential (column mu_oscillation): the mean over
   * rows of volume points (equal initial y) of the summed |second differences| of mu along the
   * row, over the range of mu: of order one for the spurious modes of inf-sup unstable pairs
   * (paper §4.2). 2D only.
   */
  template <int dim>
  class ChemicalPotentialOscillation : public Observable<dim>
  {
  public:
    /** Its entry, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered); none if off. */
    static std::unique_ptr<ChemicalPotentialOscillation>
    parse(dealii::ParameterHandler &prm);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

  private:
    /** The measure over the volume points of every rank. */
    double
    oscillation(const dealii::Particles::ParticleHandler<dim> &particles) const;
  };
} // namespace GelMPM

#endif

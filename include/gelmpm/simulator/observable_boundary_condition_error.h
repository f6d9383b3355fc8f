#ifndef gelmpm_simulator_observable_boundary_condition_error_h
#define gelmpm_simulator_observable_boundary_condition_error_h

#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>

namespace GelMPM
{
  /**
   * @brief The error of the weakly imposed boundary conditions (columns u_bc_error,
   * mu_bc_error): their largest violation over the surface points in the converged step
   * (MixedSystem::dirichlet_errors(), ObservedState::dirichlet_errors); empty in the initial
   * row.
   */
  template <int dim>
  class BoundaryConditionError : public Observable<dim>
  {
  public:
    /** Its entry, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered); none if off. */
    static std::unique_ptr<BoundaryConditionError>
    parse(dealii::ParameterHandler &prm);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;
  };
} // namespace GelMPM

#endif

#include <gelmpm/simulator/observable_boundary_condition_error.h>

namespace GelMPM
{
  template <int dim>
  void
  BoundaryConditionError<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Boundary condition error",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the columns u_bc_error and mu_bc_error: after every converged step, "
                      "the largest violation of the weakly imposed (Nitsche) conditions over the "
                      "surface points, |Pi (u - ubar)| for prescribed displacements (in the "
                      "scene's length unit) and |mu - mubar|/k_BT for prescribed chemical "
                      "potentials. Empty in the initial row.");
  }


  template <int dim>
  std::unique_ptr<BoundaryConditionError<dim>>
  BoundaryConditionError<dim>::parse(dealii::ParameterHandler &prm)
  {
    if (!prm.get_bool("Boundary condition error"))
      return nullptr;
    return std::make_unique<BoundaryConditionError>();
  }


  template <int dim>
  std::vector<std::string>
  BoundaryConditionError<dim>::columns() const
  {
    return {"u_bc_error", "mu_bc_error"};
  }


  template <int dim>
  void
  BoundaryConditionError<dim>::evaluate(const ObservedState<dim> &state,
                                        StatisticsFile           &statistics) const
  {
    if (!state.dirichlet_errors)
      return;
    const auto [u_error, mu_error] = state.dirichlet_errors();
    statistics.set("u_bc_error", u_error);
    statistics.set("mu_bc_error", mu_error);
  }


  template class BoundaryConditionError<2>;
  template class BoundaryConditionError<3>;
} // namespace GelMPM

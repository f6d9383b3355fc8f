#include <gelmpm/solvers/linear_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <stdexcept>

namespace GelMPM
{
  void
  LinearSolver::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
      "Solver",
      "KLU",
      dealii::Patterns::Selection("KLU|MUMPS"),
      "Sparse direct solver for the Newton system (Trilinos Amesos): KLU or MUMPS.");
    prm.leave_subsection();
  }


  void
  LinearSolver::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    solver_type = (prm.get("Solver") == "MUMPS") ? "Amesos_Mumps" : "Amesos_Klu";
    prm.leave_subsection();
  }


  void
  LinearSolver::solve(const dealii::TrilinosWrappers::SparseMatrix &K,
                      dealii::Vector<double>                       &x,
                      const dealii::Vector<double>                 &b) const
  {
    dealii::SolverControl                                  control(1, 0.);
    dealii::TrilinosWrappers::SolverDirect::AdditionalData data(false, solver_type);
    dealii::TrilinosWrappers::SolverDirect                 solver(control, data);
    try
      {
        solver.solve(K, x, b);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error("the direct solver (" + solver_type +
                                 ") failed on the Newton system: " + e.what());
      }
    for (const double v : x)
      if (!std::isfinite(v))
        throw std::runtime_error("the direct solver (" + solver_type +
                                 ") returned a non-finite solution (singular tangent)");
  }


  const std::string &
  LinearSolver::name() const
  {
    return solver_type;
  }
} // namespace GelMPM

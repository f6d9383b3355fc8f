#ifndef gelmpm_solvers_linear_solver_h
#define gelmpm_solvers_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>

namespace GelMPM
{
  /**
   * @brief The "Linear solver" section and the direct solve of the Newton system.
   *
   * A sparse direct solver from Trilinos' Amesos (KLU by default, MUMPS on request). A fresh
   * solver object is made for every factorisation: Amesos_Mumps behind
   * TrilinosWrappers::SolverDirect fails when re-initialised with a new matrix.
   */
  class LinearSolver
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Solve K x = b. Throws std::runtime_error when the factorisation fails. */
    void
    solve(const dealii::TrilinosWrappers::SparseMatrix &K,
          dealii::Vector<double>                       &x,
          const dealii::Vector<double>                 &b) const;

    /** The Amesos solver name, e.g. "Amesos_Klu". */
    const std::string &
    name() const;

  private:
    std::string solver_type = "Amesos_Klu";
  };
} // namespace GelMPM

#endif

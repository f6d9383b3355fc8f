#ifndef gelmpm_solvers_linear_solver_h
#define gelmpm_solvers_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <memory>
#include <string>

namespace GelMPM
{
  /**
   * @brief The "Linear solver" section and the direct solve of the Newton system.
   *
   * A sparse direct solver from Trilinos' Amesos (MUMPS by default, KLU on request), used
   * directly rather than through TrilinosWrappers::SolverDirect so that the symbolic
   * factorisation (ordering and structure analysis) is kept while the sparsity pattern does not
   * change: the Newton iterations and the retried attempts of a time step share one pattern, and
   * only refactorise numerically. The caller says when the pattern changes (new_pattern(), once
   * per time step after the grid reset); a different matrix object also starts afresh.
   */
  class LinearSolver
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * The sparsity pattern of the next matrix differs: forget the symbolic factorisation. Call it
     * before the matrix last solved with is destroyed or re-initialised (MUMPS refers to it when
     * its factorisation is released), and before the solver's owner destroys that matrix.
     */
    void
    new_pattern() const;

    /**
     * Solve K x = b, reusing the symbolic factorisation of the previous call unless new_pattern()
     * was called or @p K is another matrix object. Throws std::runtime_error when the
     * factorisation fails.
     */
    void
    solve(const dealii::TrilinosWrappers::SparseMatrix &K,
          dealii::Vector<double>                       &x,
          const dealii::Vector<double>                 &b) const;

    /** How many symbolic factorisations solve() has made (for tests and performance notes). */
    unsigned int
    n_symbolic_factorisations() const;

    /** The Amesos solver name, e.g. "Amesos_Klu". */
    const std::string &
    name() const;

  private:
    std::string solver_type = "Amesos_Mumps";
    // The kept factorisation: a cache, so solve() stays const for its callers.
    mutable std::unique_ptr<Epetra_LinearProblem> problem;
    mutable std::unique_ptr<Amesos_BaseSolver>    factorisation;
    mutable unsigned int                          symbolic_count = 0;
  };
} // namespace GelMPM

#endif

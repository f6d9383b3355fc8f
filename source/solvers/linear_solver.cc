#include <gelmpm/solvers/linear_solver.h>

#include <Amesos.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Vector.h>
#include <cmath>
#include <stdexcept>

namespace GelMPM
{
  void
  LinearSolver::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Solver",
                      "MUMPS",
                      dealii::Patterns::Selection("KLU|MUMPS"),
                      "Sparse direct solver for the Newton system (Trilinos Amesos): MUMPS "
                      "(multifrontal, fast with an optimised BLAS such as OpenBLAS; the "
                      "default) or KLU (no BLAS; slower on the wide stencils of B-splines, "
                      "doc/performance.md).");
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
  LinearSolver::new_pattern() const
  {
    factorisation.reset();
    problem.reset();
  }


  void
  LinearSolver::solve(const dealii::TrilinosWrappers::SparseMatrix &K,
                      dealii::Vector<double>                       &x,
                      const dealii::Vector<double>                 &b) const
  {
    const Epetra_CrsMatrix &matrix = K.trilinos_matrix();
    Epetra_Vector           x_view(View, matrix.DomainMap(), x.begin());
    Epetra_Vector           b_view(View, matrix.RangeMap(), const_cast<double *>(b.begin()));
    int                     error = 0;
    if (!factorisation || problem->GetMatrix() != &matrix)
      {
        // A new sparsity pattern (or a new matrix object): analyse it once; the Newton
        // iterations of a step then only refactorise numerically.
        problem = std::make_unique<Epetra_LinearProblem>(const_cast<Epetra_CrsMatrix *>(&matrix),
                                                         &x_view,
                                                         &b_view);
        Amesos factory;
        factorisation.reset(factory.Create(solver_type, *problem));
        if (!factorisation)
          throw std::runtime_error("the direct solver " + solver_type + " is not available");
        error = factorisation->SymbolicFactorization();
        ++symbolic_count;
      }
    else
      {
        problem->SetLHS(&x_view);
        problem->SetRHS(&b_view);
      }
    if (error == 0)
      error = factorisation->NumericFactorization();
    if (error == 0)
      error = factorisation->Solve();
    // The views die with this call: no dangling vectors in the kept problem.
    problem->SetLHS(nullptr);
    problem->SetRHS(nullptr);
    if (error != 0)
      {
        new_pattern();
        throw std::runtime_error("the direct solver (" + solver_type +
                                 ") failed on the Newton system (Amesos error " +
                                 std::to_string(error) + ")");
      }
    for (const double v : x)
      if (!std::isfinite(v))
        throw std::runtime_error("the direct solver (" + solver_type +
                                 ") returned a non-finite solution (singular tangent)");
  }


  unsigned int
  LinearSolver::n_symbolic_factorisations() const
  {
    return symbolic_count;
  }


  const std::string &
  LinearSolver::name() const
  {
    return solver_type;
  }
} // namespace GelMPM

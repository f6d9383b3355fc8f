// The LDL^T path of LinearSolver (MUMPS, symmetric matrices) against its LU path on a small
// symmetric indefinite saddle-point matrix with wide stencils, like the u-mu tangent: a
// positive definite block of 30 unknowns (7 nonzeros per row) coupled to a negative definite
// block of 10.
// - both give the same solution to 1e-12; the LDL^T factorisation's inertia is (30, 10, 0);
// - a second matrix on the same pattern is factorised with the kept analysis (one symbolic
//   factorisation for both) and again agrees with LU;
// - solve() after factorize() solves with the factorisation of the matrix given then, however
//   often it is called (the modified Newton iteration);
// - KLU and unsymmetric matrices keep LU.
#include <gelmpm/solvers/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <iostream>

namespace
{
  constexpr unsigned int n_u = 30, n_mu = 10, n = n_u + n_mu;

  /** The saddle-point matrix, scaled off-diagonal coupling @p s. */
  void
  fill(dealii::TrilinosWrappers::SparseMatrix &K, const double s)
  {
    K = 0.;
    for (unsigned int i = 0; i < n_u; ++i)
      for (unsigned int j = 0; j < n_u; ++j)
        if (i == j)
          K.set(i, j, 8. + 0.1 * i);
        else if (i + 3 >= j && j + 3 >= i)
          K.set(i, j, -s / (1. + std::abs(double(i) - double(j))));
    for (unsigned int b = 0; b < n_mu; ++b)
      {
        K.set(n_u + b, n_u + b, -1. - 0.05 * b);
        for (unsigned int a = 3 * b; a < 3 * b + 3; ++a)
          {
            K.set(a, n_u + b, 0.5 * s);
            K.set(n_u + b, a, 0.5 * s);
          }
      }
    K.compress(dealii::VectorOperation::insert);
  }

  double
  difference(const dealii::Vector<double> &x, const dealii::Vector<double> &y)
  {
    dealii::Vector<double> d = x;
    d -= y;
    return d.l2_norm() / y.l2_norm();
  }

  const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "no  FAIL";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  dealii::DynamicSparsityPattern pattern(n, n);
  for (unsigned int i = 0; i < n_u; ++i)
    for (unsigned int j = 0; j < n_u; ++j)
      if (i + 3 >= j && j + 3 >= i)
        pattern.add(i, j);
  for (unsigned int b = 0; b < n_mu; ++b)
    {
      pattern.add(n_u + b, n_u + b);
      for (unsigned int a = 3 * b; a < 3 * b + 3; ++a)
        {
          pattern.add(a, n_u + b);
          pattern.add(n_u + b, a);
        }
    }
  dealii::TrilinosWrappers::SparseMatrix K;
  K.reinit(pattern);
  fill(K, 1.);
  dealii::Vector<double> b(n), x_lu(n), x_ldlt(n), x_again(n);
  for (unsigned int i = 0; i < n; ++i)
    b(i) = std::sin(1. + i);

  dealii::ParameterHandler prm;
  GelMPM::LinearSolver::declare_parameters(prm);
  // MUMPS by name: 'automatic' would choose it too, but says so in name().
  prm.enter_subsection("Linear solver");
  prm.set("Solver", "MUMPS");
  prm.leave_subsection();
  GelMPM::LinearSolver lu, ldlt;
  lu.parse_parameters(prm);
  ldlt.parse_parameters(prm);
  ldlt.set_symmetric(true);
  bool ok = true;

  std::cout << "solvers: " << lu.name() << ", " << ldlt.name() << std::endl;
  ok &= lu.name() == "Amesos_Mumps" && ldlt.name() == "MUMPS LDL^T";
  lu.solve(K, x_lu, b);
  ldlt.solve(K, x_ldlt, b);
  const bool same = difference(x_ldlt, x_lu) < 1e-12;
  std::cout << "LDL^T and LU give the same solution to 1e-12: " << verdict(same) << std::endl;
  ok &= same;
  const auto *factorization = ldlt.symmetric_factorization();
  const bool  inertia       = factorization && factorization->inertia().n_positive == n_u &&
                       factorization->inertia().n_negative == n_mu &&
                       factorization->inertia().n_zero == 0;
  std::cout << "inertia of the LDL^T factorisation (30, 10, 0): " << verdict(inertia) << std::endl;
  ok &= inertia && lu.symmetric_factorization() == nullptr;

  // A new tangent on the same pattern; the old factorisation is kept until factorize().
  fill(K, 1.7);
  ldlt.solve(x_again, b);
  const bool kept = difference(x_again, x_ldlt) < 1e-14;
  std::cout << "solve() uses the factorisation until the next factorize(): " << verdict(kept)
            << std::endl;
  ok &= kept;
  lu.solve(K, x_lu, b);
  ldlt.solve(K, x_ldlt, b);
  const bool same_again = difference(x_ldlt, x_lu) < 1e-12;
  std::cout << "on the second matrix too: " << verdict(same_again) << std::endl;
  const bool one_analysis =
    ldlt.n_symbolic_factorisations() == 1 && ldlt.n_numeric_factorisations() == 2;
  std::cout << "one analysis, two numeric factorisations: " << verdict(one_analysis) << std::endl;
  ok &= same_again && one_analysis;

  // KLU, and MUMPS for matrices not declared symmetric, factorise LU.
  prm.enter_subsection("Linear solver");
  prm.set("Solver", "KLU");
  prm.leave_subsection();
  GelMPM::LinearSolver klu;
  klu.parse_parameters(prm);
  klu.set_symmetric(true);
  klu.solve(K, x_again, b);
  const bool klu_lu = klu.name() == "Amesos_Klu" && klu.symmetric_factorization() == nullptr &&
                      difference(x_again, x_lu) < 1e-12;
  std::cout << "KLU stays LU and agrees: " << verdict(klu_lu) << std::endl;
  ok &= klu_lu;

  lu.new_pattern();
  ldlt.new_pattern();
  klu.new_pattern();
  return ok ? 0 : 1;
}

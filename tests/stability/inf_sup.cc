// The discrete inf-sup constant (dense generalised eigenproblem B A^{-1} B^T q = beta^2 M q)
// against two independent references on K = [A B^T; B C] (C does not enter):
// 1. closed form: A = I, B = diag(b), M = diag(m) gives beta = min_i |b_i| / sqrt(m_i);
// 2. random banded SPD A (60 x 60), random sparse B (25 x 60), diagonal M: beta^2 is the smallest
//    eigenvalue of M^{-1/2} B A^{-1} B^T M^{-1/2}, with A^{-1} by Gauss-Jordan elimination and the
//    eigenvalues by LAPACK's symmetric solver;
// and a rank-deficient B (a zero row: a pressure mode that no displacement sees) gives beta = 0.
// Agreement asserted to 1e-10 relative.
#include <gelmpm/stability/inf_sup.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace dealii;

namespace
{
  /** K = [A B^T; B -I] as a Trilinos matrix (the mu-mu block only fills the pattern). */
  TrilinosWrappers::SparseMatrix
  saddle_point_matrix(const FullMatrix<double> &A, const FullMatrix<double> &B)
  {
    const unsigned int     n = A.m(), m = B.m();
    DynamicSparsityPattern pattern(n + m, n + m);
    for (unsigned int i = 0; i < n + m; ++i)
      for (unsigned int j = 0; j < n + m; ++j)
        pattern.add(i, j);
    TrilinosWrappers::SparseMatrix K;
    K.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (A(i, j) != 0.)
          K.set(i, j, A(i, j));
    for (unsigned int i = 0; i < m; ++i)
      {
        K.set(n + i, n + i, -1.);
        for (unsigned int j = 0; j < n; ++j)
          if (B(i, j) != 0.)
            {
              K.set(n + i, j, B(i, j));
              K.set(j, n + i, B(i, j));
            }
      }
    K.compress(VectorOperation::insert);
    return K;
  }

  /** sqrt(lambda_min(M^{-1/2} B A^{-1} B^T M^{-1/2})) for diagonal M, by another route. */
  double
  reference_beta(const FullMatrix<double> &A,
                 const FullMatrix<double> &B,
                 const FullMatrix<double> &M)
  {
    FullMatrix<double> A_inverse(A);
    A_inverse.gauss_jordan();
    const unsigned int m = B.m();
    FullMatrix<double> BA(m, A.n()), S(m, m);
    B.mmult(BA, A_inverse);
    BA.mTmult(S, B);
    LAPACKFullMatrix<double> scaled(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        scaled(i, j) = S(i, j) / std::sqrt(M(i, i) * M(j, j));
    Vector<double>           eigenvalues;
    FullMatrix<double>       eigenvectors;
    LAPACKFullMatrix<double> copy(scaled);
    copy.compute_eigenvalues_symmetric(-1e300, 1e300, 0., eigenvalues, eigenvectors);
    double smallest = eigenvalues(0);
    for (unsigned int i = 1; i < eigenvalues.size(); ++i)
      smallest = std::min(smallest, eigenvalues(i));
    return std::sqrt(std::max(smallest, 0.));
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  {
    const unsigned int n = 6;
    FullMatrix<double> A(n, n), B(n, n), M(n, n);
    double             expected = 1e300;
    for (unsigned int i = 0; i < n; ++i)
      {
        A(i, i)  = 1.;
        B(i, i)  = 0.5 + 0.3 * i;
        M(i, i)  = 1. + 0.1 * i * i;
        expected = std::min(expected, B(i, i) / std::sqrt(M(i, i)));
      }
    const double beta = GelMPM::discrete_inf_sup_constant(saddle_point_matrix(A, B), n, M);
    std::cout << "diagonal blocks: beta equals min |b_i|/sqrt(m_i) to 1e-10: "
              << (std::abs(beta / expected - 1.) < 1e-10) << std::endl;
  }

  std::mt19937                     rng(11);
  std::uniform_real_distribution<> uniform(-1., 1.);
  const unsigned int               n = 60, m = 25;
  FullMatrix<double>               A(n, n), B(m, n), M(m, m);
  for (unsigned int i = 0; i < n; ++i)
    {
      A(i, i) = 3. + 0.1 * i;
      for (unsigned int j = i + 1; j < std::min(n, i + 4); ++j)
        A(i, j) = A(j, i) = 0.4 * uniform(rng);
    }
  for (unsigned int i = 0; i < m; ++i)
    {
      M(i, i) = 0.5 + 0.05 * i;
      for (unsigned int j = 0; j < n; ++j)
        if ((i * 5 + j * 3) % 7 == 0)
          B(i, j) = uniform(rng);
    }
  const double beta     = GelMPM::discrete_inf_sup_constant(saddle_point_matrix(A, B), n, M);
  const double expected = reference_beta(A, B, M);
  std::cout << "random blocks: beta agrees with the reference to 1e-10: "
            << (std::abs(beta / expected - 1.) < 1e-10) << std::endl;
  if (std::abs(beta / expected - 1.) >= 1e-10)
    std::cout << "  (" << beta << " against " << expected << ")" << std::endl;

  for (unsigned int j = 0; j < n; ++j)
    B(3, j) = 0.;
  const double singular = GelMPM::discrete_inf_sup_constant(saddle_point_matrix(A, B), n, M);
  std::cout << "a pressure mode that no displacement sees gives beta below 1e-6 of the above: "
            << (singular < 1e-6 * beta) << std::endl;
  return 0;
}

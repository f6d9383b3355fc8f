#include <gelmpm/stability/inf_sup.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  namespace
  {
    /** The blocks K_uu (n_u x n_u) and B = K_mu,u (n_mu x n_u) of K, dense. */
    void
    extract_blocks(const dealii::TrilinosWrappers::SparseMatrix &K,
                   const unsigned int                            n_u,
                   dealii::LAPACKFullMatrix<double>             &A,
                   dealii::LAPACKFullMatrix<double>             &B)
    {
      const unsigned int n_mu = K.m() - n_u;
      A.reinit(n_u, n_u);
      B.reinit(n_mu, n_u);
      for_each_entry(K,
                     K.m(),
                     [&](const unsigned int row, const unsigned int column, const double value) {
                       if (column < n_u)
                         {
                           if (row < n_u)
                             A(row, column) = value;
                           else
                             B(row - n_u, column) = value;
                         }
                     });
    }
  } // namespace


  double
  discrete_inf_sup_constant(const dealii::TrilinosWrappers::SparseMatrix &K,
                            const unsigned int                            n_u,
                            const dealii::FullMatrix<double>             &mass_mu)
  {
    const unsigned int n_mu = K.m() - n_u;
    if (n_u > 8000)
      throw std::runtime_error("'Stability/Inf-sup constant' uses dense matrices; " +
                               std::to_string(n_u) +
                               " displacement unknowns are too many (at most 8000): use a "
                               "coarser grid for this analysis or set it to false");
    if (mass_mu.m() != n_mu || mass_mu.n() != n_mu)
      throw std::logic_error("mass matrix does not match the chemical-potential block");

    dealii::LAPACKFullMatrix<double> A, B;
    extract_blocks(K, n_u, A, B);
    // X = A^{-1} B^T by Cholesky (A is symmetric positive definite in a stable state).
    dealii::LAPACKFullMatrix<double> X(n_u, n_mu);
    for (unsigned int i = 0; i < n_mu; ++i)
      for (unsigned int j = 0; j < n_u; ++j)
        X(j, i) = B(i, j);
    try
      {
        A.compute_cholesky_factorization();
      }
    catch (const std::exception &)
      {
        throw std::runtime_error("the displacement block of the tangent is not positive "
                                 "definite: the inf-sup constant is defined for stable states");
      }
    A.solve(X);

    dealii::LAPACKFullMatrix<double> S(n_mu, n_mu);
    B.mmult(S, X);
    // Symmetrise against round-off: S = B A^{-1} B^T is symmetric in exact arithmetic.
    for (unsigned int i = 0; i < n_mu; ++i)
      for (unsigned int j = 0; j < i; ++j)
        S(i, j) = S(j, i) = 0.5 * (S(i, j) + S(j, i));

    dealii::LAPACKFullMatrix<double> M(n_mu, n_mu);
    M = mass_mu;
    std::vector<dealii::Vector<double>> eigenvectors(n_mu, dealii::Vector<double>(n_mu));
    S.compute_generalized_eigenvalues_symmetric(M, eigenvectors);
    double smallest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n_mu; ++i)
      smallest = std::min(smallest, S.eigenvalue(i).real());
    return std::sqrt(std::max(smallest, 0.));
  }
} // namespace GelMPM

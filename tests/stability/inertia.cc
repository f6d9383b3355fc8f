// The inertia from MUMPS's LDL^T (SymmetricFactorization) against the signs of the eigenvalues from
// dense LAPACK, on symmetric matrices with known structure: definite, indefinite, saddle-point
// (quasi-definite like a stable u-mu tangent), saddle-point made unstable, and singular. Also the
// accuracy of solves with the factorisation (relative residual < 1e-10).
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <iostream>
#include <random>

using namespace dealii;
using GelMPM::Inertia;

namespace
{
  std::mt19937 rng(20261122);

  FullMatrix<double>
  random_orthogonal(const unsigned int n)
  {
    std::normal_distribution<double> normal;
    LAPACKFullMatrix<double>         A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        A(i, j) = normal(rng);
    // Orthonormalise the columns (modified Gram-Schmidt).
    FullMatrix<double> Q(n, n);
    for (unsigned int j = 0; j < n; ++j)
      {
        Vector<double> v(n);
        for (unsigned int i = 0; i < n; ++i)
          v(i) = A(i, j);
        for (unsigned int k = 0; k < j; ++k)
          {
            double dot = 0.;
            for (unsigned int i = 0; i < n; ++i)
              dot += Q(i, k) * v(i);
            for (unsigned int i = 0; i < n; ++i)
              v(i) -= dot * Q(i, k);
          }
        v /= v.l2_norm();
        for (unsigned int i = 0; i < n; ++i)
          Q(i, j) = v(i);
      }
    return Q;
  }

  /** Q diag(lambda) Q^T. */
  FullMatrix<double>
  with_spectrum(const std::vector<double> &lambda)
  {
    const unsigned int n = lambda.size();
    const auto         Q = random_orthogonal(n);
    FullMatrix<double> K(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          K(i, j) += Q(i, k) * lambda[k] * Q(j, k);
    return K;
  }

  Inertia
  eigenvalue_inertia(const FullMatrix<double> &K, const double zero_tolerance)
  {
    LAPACKFullMatrix<double> A(K.m(), K.n());
    A = K;
    A.compute_eigenvalues();
    Inertia result;
    for (unsigned int i = 0; i < K.m(); ++i)
      {
        const double lambda = A.eigenvalue(i).real();
        if (std::abs(lambda) <= zero_tolerance)
          ++result.n_zero;
        else if (lambda > 0.)
          ++result.n_positive;
        else
          ++result.n_negative;
      }
    return result;
  }

  TrilinosWrappers::SparseMatrix
  to_sparse(const FullMatrix<double> &K)
  {
    DynamicSparsityPattern dsp(K.m(), K.n());
    for (unsigned int i = 0; i < K.m(); ++i)
      for (unsigned int j = 0; j < K.n(); ++j)
        if (K(i, j) != 0.)
          dsp.add(i, j);
    TrilinosWrappers::SparseMatrix S;
    S.reinit(dsp);
    for (unsigned int i = 0; i < K.m(); ++i)
      for (unsigned int j = 0; j < K.n(); ++j)
        if (K(i, j) != 0.)
          S.set(i, j, K(i, j));
    S.compress(VectorOperation::insert);
    return S;
  }

  bool
  check(const std::string &name, const FullMatrix<double> &K, const Inertia &expected)
  {
    const Inertia                  reference = eigenvalue_inertia(K, 1e-10 * K.frobenius_norm());
    GelMPM::SymmetricFactorization factorization;
    factorization.factorize(to_sparse(K));
    const Inertia computed = factorization.inertia();

    // Solve accuracy (nonsingular cases only).
    double relative_residual = 0.;
    if (computed.n_zero == 0)
      {
        Vector<double> b(K.m()), x(K.m()), r(K.m());
        for (unsigned int i = 0; i < K.m(); ++i)
          b(i) = std::sin(1. + i);
        x = b;
        factorization.solve(x);
        K.vmult(r, x);
        r -= b;
        relative_residual = r.l2_norm() / b.l2_norm();
      }

    const bool ok = (computed == reference) && (computed == expected) && relative_residual < 1e-10;
    std::cout << name << ": MUMPS (" << computed.n_positive << ", " << computed.n_negative << ", "
              << computed.n_zero << "), LAPACK (" << reference.n_positive << ", "
              << reference.n_negative << ", " << reference.n_zero
              << "), solve residual < 1e-10: " << (relative_residual < 1e-10 ? "yes" : "no")
              << (ok ? "" : "  FAIL") << std::endl;
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  // Definite and indefinite matrices with prescribed spectra.
  {
    std::vector<double> lambda;
    for (unsigned int i = 0; i < 20; ++i)
      lambda.push_back(0.5 + i);
    ok &= check("positive definite n=20", with_spectrum(lambda), {20, 0, 0});
    for (unsigned int i = 0; i < 7; ++i)
      lambda[3 * i] = -lambda[3 * i];
    ok &= check("indefinite n=20", with_spectrum(lambda), {13, 7, 0});
  }

  // Saddle point [A B^T; B -C] with A > 0, C >= 0: quasi-definite, inertia (n, m, 0), like a
  // stable u-mu tangent. Then A made indefinite by one eigenvalue: one more negative.
  {
    const unsigned int               n = 16, m = 8;
    std::uniform_real_distribution<> uniform(-1., 1.);
    std::vector<double>              a(n), c(m);
    for (unsigned int i = 0; i < n; ++i)
      a[i] = 1. + i;
    for (unsigned int i = 0; i < m; ++i)
      c[i] = 10. * (1. + i);
    for (const bool unstable : {false, true})
      {
        if (unstable)
          a[0] = -5.;
        const auto         A = with_spectrum(a);
        const auto         C = with_spectrum(c);
        FullMatrix<double> K(n + m, n + m);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            K(i, j) = A(i, j);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < n; ++j)
            K(n + i, j) = K(j, n + i) = uniform(rng);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            K(n + i, n + j) = -C(i, j);
        // inertia(K) = inertia(-C) + inertia(S), S = A + B^T C^-1 B the Schur complement (eq.
        // (63)); with |B^T C^-1 B| <= 0.8 here, a[0] = -5 leaves S with one negative eigenvalue.
        ok &= check(unstable ? "saddle point, one unstable mode" : "saddle point, stable",
                    K,
                    unstable ? Inertia{n - 1, m + 1, 0} : Inertia{n, m, 0});
      }
  }

  // Singular: a zero eigenvalue that MUMPS must report as a null pivot.
  {
    FullMatrix<double> K(6, 6);
    for (unsigned int i = 0; i < 5; ++i)
      K(i, i) = (i % 2 ? -1. : 1.) * (1. + i);
    ok &= check("singular diagonal", K, {3, 2, 1});
  }

  std::cout << (ok ? "all inertia checks passed" : "SOME INERTIA CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

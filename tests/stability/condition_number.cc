// condition_number_estimate() against the exact 1-norm condition number |A|_1 |A^{-1}|_1 from a
// dense inverse, on matrices with known structure: definite with a spread spectrum, a saddle point
// (like the u-mu tangent), a 3D seven-point Laplacian with a block of rows scaled by 1e3 (like a
// Nitsche penalty), and a singular one (infinity). The estimate is a lower bound, and within a
// factor of 3 of the exact value. (LAPACK's dgecon of OpenBLAS 0.3.21 gave 1.8e111 for the
// tangent of the 26^3 free-swelling cube, whose singular values lie between 0.0019 and 1171.)
#include <gelmpm/stability/condition_number.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>

using namespace dealii;

namespace
{
  std::mt19937 rng(20261126);

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

  double
  exact_condition(const FullMatrix<double> &K)
  {
    LAPACKFullMatrix<double> A(K.m(), K.n());
    A                 = K;
    const double norm = A.l1_norm();
    A.invert();
    return norm * A.l1_norm();
  }

  /** Q diag(lambda) Q^T with a random orthogonal Q (Householder reflections). */
  FullMatrix<double>
  with_spectrum(const std::vector<double> &lambda)
  {
    const unsigned int n = lambda.size();
    FullMatrix<double> K(n, n);
    for (unsigned int i = 0; i < n; ++i)
      K(i, i) = lambda[i];
    std::normal_distribution<double> normal;
    for (unsigned int r = 0; r < 3; ++r)
      {
        Vector<double> v(n);
        for (unsigned int i = 0; i < n; ++i)
          v(i) = normal(rng);
        v /= v.l2_norm();
        FullMatrix<double> H(n, n), T(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            H(i, j) = (i == j ? 1. : 0.) - 2. * v(i) * v(j);
        H.mmult(T, K);
        T.mmult(K, H);
      }
    return K;
  }

  bool
  check(const std::string &name, const FullMatrix<double> &K)
  {
    const double estimate = GelMPM::condition_number_estimate(to_sparse(K));
    const double exact    = exact_condition(K);
    const double ratio    = estimate / exact;
    const bool   ok       = std::isfinite(estimate) && ratio >= 1. / 3. && ratio <= 1. + 1e-8;
    std::cout << name << " n=" << K.m()
              << ": estimate / exact within [1/3, 1]: " << (ok ? "yes" : "NO") << std::endl;
    if (!ok)
      std::cout << "  estimate " << estimate << ", exact " << exact << std::endl;
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  {
    std::vector<double> lambda(60);
    for (unsigned int i = 0; i < lambda.size(); ++i)
      lambda[i] = std::pow(10., 6. * i / (lambda.size() - 1.));
    ok &= check("definite, spectrum 1 to 1e6", with_spectrum(lambda));
  }
  {
    // [[K, B^T], [B, -C]]: K definite, C small and definite.
    const unsigned int               n_u = 40, n_mu = 10;
    std::vector<double>              lambda(n_u);
    std::uniform_real_distribution<> uniform(0.5, 2.);
    for (auto &l : lambda)
      l = uniform(rng);
    const auto         K = with_spectrum(lambda);
    FullMatrix<double> S(n_u + n_mu, n_u + n_mu);
    for (unsigned int i = 0; i < n_u; ++i)
      for (unsigned int j = 0; j < n_u; ++j)
        S(i, j) = K(i, j);
    for (unsigned int i = 0; i < n_mu; ++i)
      {
        for (unsigned int j = 0; j < n_u; ++j)
          S(n_u + i, j) = S(j, n_u + i) = uniform(rng) - 1.25;
        S(n_u + i, n_u + i) = -1e-3;
      }
    ok &= check("saddle point", S);
  }
  {
    // A seven-point Laplacian on 7^3 interior nodes; the rows of the lowest plane scaled by 1e3.
    const unsigned int m = 7, n = m * m * m;
    FullMatrix<double> L(n, n);
    const auto         index = [m](int i, int j, int k) {
      return static_cast<unsigned int>((k * m + j) * m + i);
    };
    for (int k = 0; k < int(m); ++k)
      for (int j = 0; j < int(m); ++j)
        for (int i = 0; i < int(m); ++i)
          {
            const unsigned int row   = index(i, j, k);
            const double       scale = k == 0 ? 1e3 : 1.;
            L(row, row)              = 6. * scale;
            for (const auto &[di, dj, dk] : {std::array<int, 3>{{1, 0, 0}},
                                             std::array<int, 3>{{-1, 0, 0}},
                                             std::array<int, 3>{{0, 1, 0}},
                                             std::array<int, 3>{{0, -1, 0}},
                                             std::array<int, 3>{{0, 0, 1}},
                                             std::array<int, 3>{{0, 0, -1}}})
              {
                const int a = i + di, b = j + dj, c = k + dk;
                if (a >= 0 && a < int(m) && b >= 0 && b < int(m) && c >= 0 && c < int(m))
                  L(row, index(a, b, c)) = -scale;
              }
          }
    ok &= check("3D Laplacian, a plane of rows scaled by 1e3", L);
  }
  {
    FullMatrix<double> Z(4, 4);
    Z(0, 0) = Z(1, 1) = Z(2, 2) = 1.;
    Z(0, 3)                     = 1.; // the last row is zero
    const double estimate       = GelMPM::condition_number_estimate(to_sparse(Z));
    const bool   singular_ok    = std::isinf(estimate);
    std::cout << "singular: estimate infinite: " << (singular_ok ? "yes" : "NO") << std::endl;
    ok &= singular_ok;
  }
  std::cout << (ok ? "all condition number checks passed" : "SOME CONDITION NUMBER CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}

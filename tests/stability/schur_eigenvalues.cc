// The smallest Schur-complement eigenvalues from ARPACK (shift-invert through the LDL^T of the
// full matrix, S never formed) against the eigenvalues of the dense Schur complement
// S = A + B^T C^{-1} B of K = [A B^T; B -C] from LAPACK: agreement to 1e-8 relative, for a stable
// (S > 0) and an unstable (one negative eigenvalue) saddle-point matrix of size 60 + 25.
// And analyse_stability()'s drained mode (the eigenvector of K_uu = A for its negative eigenvalue,
// perturbation at a drained onset) on a matrix whose A has one small negative eigenvalue: the
// drained inertia counts it, and the mode satisfies A v = lambda_min v with LAPACK's lambda_min.
#include <gelmpm/stability/schur_eigenvalues.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <random>

using namespace dealii;

namespace
{
  std::mt19937 rng(7);

  /** A banded symmetric matrix with diagonal d and random off-diagonals (a small FE-like pattern).
   */
  FullMatrix<double>
  banded(const unsigned int n, const double diagonal, const double off)
  {
    std::uniform_real_distribution<> uniform(-1., 1.);
    FullMatrix<double>               A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        A(i, i) = diagonal + 0.5 * i;
        for (unsigned int j = i + 1; j < std::min(n, i + 4); ++j)
          A(i, j) = A(j, i) = off * uniform(rng);
      }
    return A;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n = 60, m = 25, k = 5;
  bool                             ok = true;
  std::uniform_real_distribution<> uniform(-1., 1.);

  for (const int variant : {0, 1, 2})
    {
      const bool         unstable = variant > 0, drained = variant == 2;
      FullMatrix<double> A = banded(n, 2., 0.3), C = banded(m, 4., 0.2), B(m, n);
      if (unstable)
        A(n / 2, n / 2) = drained ? -0.4 : -3.;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < n; ++j)
          if ((i * 7 + j * 3) % 11 == 0)
            B(i, j) = uniform(rng);

      // Full K = [A B^T; B -C] as a sparse matrix.
      DynamicSparsityPattern dsp(n + m, n + m);
      FullMatrix<double>     K(n + m, n + m);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          K(i, j) = A(i, j);
      for (unsigned int i = 0; i < m; ++i)
        {
          for (unsigned int j = 0; j < n; ++j)
            K(n + i, j) = K(j, n + i) = B(i, j);
          for (unsigned int j = 0; j < m; ++j)
            K(n + i, n + j) = -C(i, j);
        }
      for (unsigned int i = 0; i < n + m; ++i)
        for (unsigned int j = 0; j < n + m; ++j)
          if (K(i, j) != 0.)
            dsp.add(i, j);
      TrilinosWrappers::SparseMatrix sparse;
      sparse.reinit(dsp);
      for (unsigned int i = 0; i < n + m; ++i)
        for (unsigned int j = 0; j < n + m; ++j)
          if (K(i, j) != 0.)
            sparse.set(i, j, K(i, j));
      sparse.compress(VectorOperation::insert);

      if (drained)
        {
          GelMPM::StabilitySettings settings;
          settings.inertia                = true;
          settings.n_eigenvalues          = 1;
          settings.drained_onset          = true;
          settings.perturbation_amplitude = 1e-2;
          const auto               report = GelMPM::analyse_stability(sparse, n, settings, []() {
            return FullMatrix<double>();
          });
          LAPACKFullMatrix<double> A_lapack(n, n);
          A_lapack = A;
          A_lapack.compute_eigenvalues();
          double lowest = 0.;
          for (unsigned int i = 0; i < n; ++i)
            lowest = std::min(lowest, A_lapack.eigenvalue(i).real());
          const auto    &v = report.drained_mode;
          Vector<double> Av(n);
          if (v.size() == n)
            {
              A.vmult(Av, v);
              Av.add(-lowest, v);
            }
          const bool this_ok = report.drained_inertia.n_negative == 1 && v.size() == n &&
                               Av.l2_norm() < 1e-8 * v.l2_norm();
          std::cout << "drained onset: K_uu has " << report.drained_inertia.n_negative
                    << " negative eigenvalue (LAPACK: " << std::setprecision(6) << lowest
                    << "), the drained mode is its eigenvector: " << (this_ok ? "yes" : "no")
                    << std::endl;
          ok &= this_ok;
          continue;
        }

      GelMPM::SymmetricFactorization factorization;
      factorization.factorize(sparse);
      const auto arpack = GelMPM::smallest_schur_eigenvalues(factorization, n, k, true);

      // Dense reference: S = A + B^T C^{-1} B.
      LAPACKFullMatrix<double> C_inverse(m, m);
      C_inverse = C;
      C_inverse.invert();
      FullMatrix<double> C_inv(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          C_inv(i, j) = C_inverse(i, j);
      FullMatrix<double> S(A), CinvB(m, n), BtCinvB(n, n);
      C_inv.mmult(CinvB, B);
      B.Tmmult(BtCinvB, CinvB);
      S.add(1., BtCinvB);
      LAPACKFullMatrix<double> S_lapack(n, n);
      S_lapack = S;
      S_lapack.compute_eigenvalues();
      std::vector<double> dense;
      for (unsigned int i = 0; i < n; ++i)
        dense.push_back(S_lapack.eigenvalue(i).real());
      std::sort(dense.begin(), dense.end(), [](const double a, const double b) {
        return std::abs(a) < std::abs(b);
      });
      dense.resize(k);
      std::sort(dense.begin(), dense.end());

      std::cout << (unstable ? "unstable" : "stable") << " saddle point, " << k
                << " smallest Schur eigenvalues (ARPACK | LAPACK):" << std::endl;
      double worst = 0.;
      for (unsigned int i = 0; i < k; ++i)
        {
          const double error = std::abs(arpack.values[i] - dense[i]) / std::abs(dense[i]);
          worst              = std::max(worst, error);
          std::cout << "  " << std::setprecision(8) << arpack.values[i] << " | " << dense[i]
                    << std::endl;
        }
      // The eigenvector satisfies S v = lambda v (residual checked with the dense S).
      Vector<double> Sv(n);
      S.vmult(Sv, arpack.vectors[0]);
      Sv.add(-arpack.values[0], arpack.vectors[0]);
      const double vector_residual = Sv.l2_norm() / arpack.vectors[0].l2_norm();
      const bool   this_ok         = worst < 1e-8 &&
                           vector_residual < 1e-8 * std::abs(arpack.values[0]) + 1e-10 &&
                           (unstable ? arpack.values[0] < 0. : arpack.values[0] > 0.);
      std::cout << "  relative error < 1e-8: " << (worst < 1e-8 ? "yes" : "no")
                << ", eigenvector residual small: " << (vector_residual < 1e-8 ? "yes" : "no")
                << (this_ok ? "" : "  FAIL") << std::endl;
      ok &= this_ok;
    }
  return ok ? 0 : 1;
}

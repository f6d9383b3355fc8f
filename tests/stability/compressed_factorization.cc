// The block low-rank LDL^T (SymmetricFactorization::set_compression) against the full-rank one
// and against closed forms, on the 7-point Laplacian L of an n^3 grid (Dirichlet, unit spacing),
// whose eigenvalues are sums of 2 (1 - cos(k pi / (n + 1))), k = 1..n, per direction:
// - on L + I (condition number below 13): the compressed factorisation keeps fewer entries than
//   the full-rank one (it compresses at all: about 0.81 of them here), and its solve is within
//   1e-4 of the full-rank solve (about 1e-5 here) at a dropping threshold of 1e-4;
// - on L - sigma I, sigma in a gap of the spectrum wider than 1e-3: the inertia of the compressed
//   factorisation is the closed form's count of eigenvalues below sigma, as the full-rank one's.
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace dealii;

namespace
{
  constexpr unsigned int n = 28; // grid points per direction

  unsigned int
  index(const unsigned int i, const unsigned int j, const unsigned int k)
  {
    return (k * n + j) * n + i;
  }

  /** The 7-point Laplacian of the n^3 grid plus @p shift times the identity. */
  TrilinosWrappers::SparseMatrix
  shifted_laplacian(const double shift)
  {
    const unsigned int     size = n * n * n;
    DynamicSparsityPattern dsp(size, size);
    const auto             for_each_coupling = [](const auto &f) {
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int row = index(i, j, k);
              f(row, row, 6.);
              if (i > 0)
                f(row, index(i - 1, j, k), -1.);
              if (i + 1 < n)
                f(row, index(i + 1, j, k), -1.);
              if (j > 0)
                f(row, index(i, j - 1, k), -1.);
              if (j + 1 < n)
                f(row, index(i, j + 1, k), -1.);
              if (k > 0)
                f(row, index(i, j, k - 1), -1.);
              if (k + 1 < n)
                f(row, index(i, j, k + 1), -1.);
            }
    };
    for_each_coupling([&](unsigned int r, unsigned int c, double) {
      dsp.add(r, c);
    });
    TrilinosWrappers::SparseMatrix K;
    K.reinit(dsp);
    for_each_coupling([&](unsigned int r, unsigned int c, double v) {
      K.set(r, c, r == c ? v + shift : v);
    });
    K.compress(VectorOperation::insert);
    return K;
  }

  /** The eigenvalues of the unshifted Laplacian, sorted. */
  std::vector<double>
  laplacian_eigenvalues()
  {
    std::vector<double> one_d(n), all;
    for (unsigned int k = 0; k < n; ++k)
      one_d[k] = 2. * (1. - std::cos((k + 1) * M_PI / (n + 1)));
    for (const double a : one_d)
      for (const double b : one_d)
        for (const double c : one_d)
          all.push_back(a + b + c);
    std::sort(all.begin(), all.end());
    return all;
  }

  Vector<double>
  solve(const GelMPM::SymmetricFactorization &factorization)
  {
    Vector<double> x(n * n * n);
    for (unsigned int i = 0; i < x.size(); ++i)
      x(i) = std::sin(1. + i);
    factorization.solve(x);
    return x;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  // Definite: compression and solve accuracy.
  {
    const auto                     K = shifted_laplacian(1.);
    GelMPM::SymmetricFactorization full, compressed;
    full.factorize(K);
    compressed.set_compression(1e-4);
    compressed.factorize(K);
    const auto     full_statistics       = full.statistics();
    const auto     compressed_statistics = compressed.statistics();
    Vector<double> difference            = solve(compressed);
    const auto     reference             = solve(full);
    difference -= reference;
    const bool fewer_entries = compressed_statistics.entries < 0.9 * full_statistics.entries &&
                               full_statistics.entries == full_statistics.full_rank_entries;
    const bool accurate = difference.l2_norm() < 1e-4 * reference.l2_norm();
    std::cout << "L + I, threshold 1e-4: factors below 0.9 of the full-rank entries: "
              << (fewer_entries ? "yes" : "no") << std::endl
              << "L + I, threshold 1e-4: solve within 1e-4 of the full-rank solve: "
              << (accurate ? "yes" : "no") << std::endl;
    ok &= fewer_entries && accurate;
  }

  // Indefinite: the inertia in a gap of the spectrum.
  {
    const auto eigenvalues = laplacian_eigenvalues();
    // The widest gap between distinct eigenvalues in [0.8, 1.2].
    double sigma = 0., gap = 0.;
    for (unsigned int i = 0; i + 1 < eigenvalues.size(); ++i)
      if (eigenvalues[i] > 0.8 && eigenvalues[i + 1] < 1.2 &&
          eigenvalues[i + 1] - eigenvalues[i] > gap)
        {
          gap   = eigenvalues[i + 1] - eigenvalues[i];
          sigma = 0.5 * (eigenvalues[i] + eigenvalues[i + 1]);
        }
    const unsigned int below =
      std::lower_bound(eigenvalues.begin(), eigenvalues.end(), sigma) - eigenvalues.begin();
    const GelMPM::Inertia expected{static_cast<unsigned int>(eigenvalues.size()) - below, below, 0};
    const auto            K         = shifted_laplacian(-sigma);
    bool                  all_equal = gap > 1e-3;
    for (const double threshold : {0., 1e-8, 1e-6})
      {
        GelMPM::SymmetricFactorization factorization;
        factorization.set_compression(threshold);
        factorization.factorize(K);
        const bool equal = factorization.inertia() == expected;
        std::cout << "L - sigma I, sigma in a gap wider than 1e-3, threshold " << threshold
                  << ": inertia the closed form's (" << expected.n_negative
                  << " negative): " << (equal ? "yes" : "no") << std::endl;
        all_equal &= equal;
      }
    ok &= all_equal;
  }

  std::cout << (ok ? "all compressed factorisation checks passed"
                   : "SOME COMPRESSED FACTORISATION CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}

#include <gelmpm/stability/schur_eigenvalues.h>

#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/identity_matrix.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    /** x -> S^{-1} x as the u block of K^{-1} [x; 0]. */
    class InverseSchurComplement
    {
    public:
      InverseSchurComplement(const SymmetricFactorization &K, const unsigned int n_u)
        : K(K)
        , n_u(n_u)
        , work(K.size())
      {}

      void
      vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
      {
        work = 0.;
        for (unsigned int i = 0; i < n_u; ++i)
          work(i) = src(i);
        K.solve(work);
        for (unsigned int i = 0; i < n_u; ++i)
          dst(i) = work(i);
      }

    private:
      const SymmetricFactorization  &K;
      const unsigned int             n_u;
      mutable dealii::Vector<double> work;
    };
  } // namespace


  SchurEigenvalues
  smallest_schur_eigenvalues(const SymmetricFactorization &K,
                             const unsigned int            n_u,
                             const unsigned int            n_eigenvalues,
                             const bool                    want_vectors)
  {
    if (n_eigenvalues + 2 >= n_u)
      throw std::runtime_error("the displacement block (" + std::to_string(n_u) +
                               " unknowns) is too small for " + std::to_string(n_eigenvalues) +
                               " Schur-complement eigenvalues");
    const unsigned int n_arnoldi = std::min(n_u - 1, std::max(2 * n_eigenvalues + 2, 20u));

    dealii::SolverControl                control(10 * n_u + 1000, 1e-12, false, false);
    dealii::ArpackSolver::AdditionalData data(n_arnoldi,
                                              dealii::ArpackSolver::largest_magnitude,
                                              true);
    dealii::ArpackSolver                 solver(control, data);
    std::vector<std::complex<double>>    lambda(n_eigenvalues);
    std::vector<dealii::Vector<double>>  vectors(n_eigenvalues, dealii::Vector<double>(n_u));
    const InverseSchurComplement         inverse(K, n_u);
    const dealii::IdentityMatrix         identity(n_u);
    // A deterministic start vector keeps results reproducible.
    dealii::Vector<double> start(n_u);
    for (unsigned int i = 0; i < n_u; ++i)
      start(i) = 1. + 0.1 * std::sin(1. + i);
    solver.set_initial_vector(start);
    try
      {
        solver.solve(identity, identity, inverse, lambda, vectors, n_eigenvalues);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error(std::string("ARPACK failed: ") + e.what());
      }

    std::vector<unsigned int> order(n_eigenvalues);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return lambda[a].real() < lambda[b].real();
    });
    SchurEigenvalues result;
    for (const unsigned int i : order)
      {
        result.values.push_back(lambda[i].real());
        if (want_vectors)
          result.vectors.push_back(vectors[i]);
      }
    return result;
  }
} // namespace GelMPM

#ifndef gelmpm_stability_schur_eigenvalues_h
#define gelmpm_stability_schur_eigenvalues_h

#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace GelMPM
{
  /**
   * @brief The eigenvalues of smallest magnitude of the Schur complement
   * S = K_uu - K_umu K_mumu^{-1} K_muu of eq. (63), by ARPACK (deal.II's ArpackSolver) in
   * shift-invert mode about zero, without forming S.
   *
   * S^{-1} x is the displacement block of K^{-1} [x; 0] (block elimination), so each application
   * costs one solve with the LDL^T factorisation of K that the inertia computation already made.
   * The displacement unknowns must come first in K (as in MixedSystem).
   */
  struct SchurEigenvalues
  {
    /** The eigenvalues, sorted ascending. */
    std::vector<double> values;
    /** The corresponding eigenvectors (displacement unknowns), if requested. */
    std::vector<dealii::Vector<double>> vectors;
  };


  /**
   * Compute the @p n_eigenvalues eigenvalues of S of smallest magnitude from the factorisation
   * @p K of the full tangent, whose first @p n_u unknowns are the displacement block. With
   * @p want_vectors, also the eigenvectors. Throws std::runtime_error if ARPACK fails.
   */
  SchurEigenvalues
  smallest_schur_eigenvalues(const SymmetricFactorization &K,
                             const unsigned int            n_u,
                             const unsigned int            n_eigenvalues,
                             const bool                    want_vectors = false);
} // namespace GelMPM

#endif

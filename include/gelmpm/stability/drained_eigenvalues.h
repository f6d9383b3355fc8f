#ifndef gelmpm_stability_drained_eigenvalues_h
#define gelmpm_stability_drained_eigenvalues_h

#include <gelmpm/stability/displacement_block_amg.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace GelMPM
{
  /**
   * @brief The smallest (algebraic) eigenvalues of the symmetric displacement block K_uu and their
   * eigenvectors, found iteratively, without factorising anything: the drained stability
   * criterion (K_uu has a negative eigenvalue exactly when lambda_min < 0) and its mode.
   *
   * LOBPCG (Trilinos Anasazi, LOBPCGSolMgr, full orthogonalisation, locking) on A = K_uu with the
   * smoothed aggregation AMG of A (DisplacementBlockAMG) as the preconditioner. An eigenpair has
   * converged when ||A v - lambda v|| <= tolerance ||A||_inf for a unit v: the test is absolute
   * in the scale of A, not relative to lambda, since at an onset lambda_min passes through zero.
   * The eigenvalue is then accurate to about (tolerance ||A||)^2 / gap.
   *
   * Every row of A takes part, also the diagonal-only rows (the radial unknowns held on the axis
   * of an axisymmetric scene): such a row i is an eigenvector e_i with the eigenvalue A_ii, as it
   * is a 1 x 1 block of the LDL^T whose inertia the factorisation path counts, so both paths see
   * the same spectrum.
   */
  struct DrainedEigenvalues
  {
    /** The eigenvalues, ascending. */
    std::vector<double> values;
    /** The corresponding eigenvectors (unit 2-norm), if requested. */
    std::vector<dealii::Vector<double>> vectors;
    /** ||A v - lambda v|| / (||A||_inf ||v||) of each pair, as checked after the solve. */
    std::vector<double> residuals;
    /** LOBPCG iterations (each one application of A and of the AMG per block vector). */
    unsigned int iterations = 0;
  };


  /**
   * The @p n_eigenvalues smallest eigenvalues of the block A of @p block (set up beforehand),
   * with the eigenvectors if @p want_vectors. @p start, if not empty, gives start vectors (e.g.
   * the previous state's eigenvectors); the rest of the block is filled deterministically.
   * Throws std::runtime_error if LOBPCG does not reach @p tolerance in @p max_iterations.
   */
  DrainedEigenvalues
  smallest_drained_eigenvalues(const DisplacementBlockAMG                &block,
                               const unsigned int                         n_eigenvalues,
                               const bool                                 want_vectors,
                               const double                               tolerance      = 1e-8,
                               const unsigned int                         max_iterations = 1000,
                               const std::vector<dealii::Vector<double>> &start          = {});
} // namespace GelMPM

#endif

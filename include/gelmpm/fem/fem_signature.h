#ifndef gelmpm_fem_fem_signature_h
#define gelmpm_fem_fem_signature_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/stability/symmetric_factorization.h>

namespace GelMPM
{
  /** The inertia of a FemMixedSystem's tangent and the inertia a stable state gives it. */
  struct FemSignature
  {
    /** The inertia of matrix() (MUMPS LDL^T). */
    Inertia measured;
    /** (n_u, n_mu, 0), corrected for the constrained rows (FemTangentSignature). */
    Inertia expected;
    /** Constrained rows of the displacement and mu blocks. */
    unsigned int constrained_u = 0, constrained_mu = 0;
    /** With the drained criterion: the inertia of the displacement block K_uu, and what a
     * positive definite K_uu gives (corrected for the constrained rows as above). */
    Inertia drained_measured, drained_expected;

    bool
    stable() const
    {
      return measured == expected;
    }

    /** K_uu positive definite on the unconstrained DoFs: no mode grows (doc/method.md). */
    bool
    drained_stable() const
    {
      return drained_measured == drained_expected;
    }
  };


  /**
   * @brief The stability test of paper §3.6 on the tangent K of a FemMixedSystem: a state is
   * stable when K has n_u positive, n_mu negative and no zero eigenvalues (K_uu positive and
   * K_mumu negative definite on the unconstrained DoFs, i.e. a positive definite Schur
   * complement S = K_uu - K_umu K_mumu^{-1} K_muu, eq. (63)). The inertia is that of the LDL^T
   * factorisation (SymmetricFactorization, Sylvester's law).
   *
   * Why the expectation is corrected: the Dirichlet conditions are strong (AffineConstraints),
   * so a constrained row i of matrix() holds only its diagonal entry K_ii, and column i is zero
   * elsewhere too. K is therefore, up to a symmetric permutation, block diagonal: the
   * unconstrained tangent K_f, and one 1 x 1 block K_ii per constrained row. By Sylvester's law
   * the inertia of K is that of K_f plus the signs of the K_ii. K_ii is an artificial entry:
   * deal.II puts the sum over cells of |K_ii| of the cell matrices there (or their mean |K_jj|),
   * positive whatever block the row belongs to, so a constrained mu row (mu prescribed on a
   * boundary) adds a positive eigenvalue where its block would have a negative one. A stable
   * state thus has
   *
   *   n_+ = (n_u - c_u) + c_+,   n_- = (n_mu - c_mu) + c_-,   n_0 = c_0,
   *
   * with c_u, c_mu the constrained rows of each block and c_+, c_-, c_0 the constrained rows with
   * a positive, negative and zero diagonal entry, read from matrix() itself rather than assumed
   * (tests/fem/fem_column checks this against a dense eigenvalue count).
   */
  template <int dim>
  class FemTangentSignature
  {
  public:
    /** Keeps @p system by reference; with @p drained evaluate() also factorises K_uu. */
    explicit FemTangentSignature(const FemMixedSystem<dim> &system, const bool drained = false);

    /**
     * Factorise the system's matrix() (the tangent at the last assembly: after a converged
     * Newton solve, at the converged state) and compare its inertia with the expected one.
     * Throws std::runtime_error if MUMPS fails.
     */
    const FemSignature &
    evaluate();

    /** The result of the last evaluate(). */
    const FemSignature &
    last() const;

    /** The inertia a stable state gives the system's current matrix() (see the class text). */
    static FemSignature
    expected(const FemMixedSystem<dim> &system);

  private:
    const FemMixedSystem<dim> &system;
    bool                       drained;
    SymmetricFactorization     factorization;
    FemSignature               last_;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_stability_inf_sup_h
#define gelmpm_stability_inf_sup_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace GelMPM
{
  /**
   * @brief The discrete inf-sup constant of the undrained (dt -> 0) saddle-point problem of a
   * tangent K = [K_uu B^T; B K_mumu] (displacement unknowns first, @p n_u of them):
   *
   *   beta_h = inf_q sup_v (q^T B v) / (|v|_A |q|_M),   A = K_uu,  M = @p mass_mu,
   *
   * i.e. beta_h^2 is the smallest eigenvalue of B A^{-1} B^T q = beta^2 M q. K_mumu does not enter:
   * it carries only the diffusion and the Nitsche terms of mu, which vanish with dt.
   *
   * With A the energy norm of the drained elastic operator and M the L2 mass of the mu basis,
   * beta_h stays bounded away from zero under refinement for an inf-sup stable pair and decays for
   * an unstable one (spurious pressure modes). Dense LAPACK: for small discretisations only
   * (throws std::runtime_error above 8000 displacement unknowns, or if K_uu is not positive
   * definite).
   */
  double
  discrete_inf_sup_constant(const dealii::TrilinosWrappers::SparseMatrix &K,
                            const unsigned int                            n_u,
                            const dealii::FullMatrix<double>             &mass_mu);
} // namespace GelMPM

#endif

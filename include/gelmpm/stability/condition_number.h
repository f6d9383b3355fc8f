#ifndef gelmpm_stability_condition_number_h
#define gelmpm_stability_condition_number_h

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace GelMPM
{
  /**
   * An estimate of the 1-norm condition number |K|_1 |K^{-1}|_1 of @p K from a dense LU
   * factorisation (inverse_one_norm_estimate()): for studies of small discretisations (the Nitsche
   * penalty range of doc/extremes.md). Throws std::runtime_error above 10000 unknowns; returns
   * infinity for a singular matrix.
   */
  double
  condition_number_estimate(const dealii::TrilinosWrappers::SparseMatrix &K);

  /**
   * An estimate (a lower bound, usually within a factor of 3) of |A^{-1}|_1 from the LU
   * factorisation @p lu of A: Hager's and Higham's method, as LAPACK's dlacon, with the solves of
   * the factorisation.
   */
  double
  inverse_one_norm_estimate(const dealii::LAPACKFullMatrix<double> &lu);
} // namespace GelMPM

#endif

#ifndef gelmpm_stability_condition_number_h
#define gelmpm_stability_condition_number_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace GelMPM
{
  /**
   * LAPACK's estimate of the 1-norm condition number |K|_1 |K^{-1}|_1 of @p K from a dense LU
   * factorisation: for studies of small discretisations (the Nitsche penalty range of
   * doc/extremes.md). Throws std::runtime_error above 10000 unknowns; returns infinity for a
   * singular matrix.
   */
  double
  condition_number_estimate(const dealii::TrilinosWrappers::SparseMatrix &K);
} // namespace GelMPM

#endif

#include <gelmpm/stability/condition_number.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  double
  condition_number_estimate(const dealii::TrilinosWrappers::SparseMatrix &K)
  {
    if (K.m() > 10000)
      throw std::runtime_error("'Stability/Condition number' uses a dense matrix; " +
                               std::to_string(K.m()) +
                               " unknowns are too many (at most 10000): use a coarser grid or "
                               "set it to false");
    dealii::LAPACKFullMatrix<double> dense(K.m(), K.n());
    for_each_entry(K,
                   K.m(),
                   [&dense](const unsigned int row, const unsigned int column, const double value) {
                     dense(row, column) = value;
                   });
    const double norm = dense.l1_norm();
    try
      {
        dense.compute_lu_factorization();
      }
    catch (const std::exception &)
      {
        return std::numeric_limits<double>::infinity();
      }
    const double reciprocal = dense.reciprocal_condition_number(norm);
    return reciprocal > 0. ? 1. / reciprocal : std::numeric_limits<double>::infinity();
  }
} // namespace GelMPM

#include <gelmpm/stability/condition_number.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  double
  inverse_one_norm_estimate(const dealii::LAPACKFullMatrix<double> &lu)
  {
    // Hager's method with Higham's refinements (the algorithm of LAPACK's dlacon), each product
    // with A^{-1} or A^{-T} a solve with the LU factors. LAPACK's own dgecon (OpenBLAS 0.3.21)
    // gave a reciprocal condition number of 1.8e-111 on the tangent of a 3D cube whose LU
    // pivots lie between 0.068 and 454 and whose singular values between 0.0019 and 1171.
    const unsigned int     n = lu.m();
    dealii::Vector<double> x(n), y(n), z(n);
    x                           = 1. / n;
    double       estimate       = 0.;
    unsigned int last_direction = n;
    for (unsigned int iteration = 0; iteration < 5; ++iteration)
      {
        y = x;
        lu.solve(y, false);
        const double norm_y = y.l1_norm();
        if (!std::isfinite(norm_y))
          return std::numeric_limits<double>::infinity();
        if (iteration > 0 && norm_y <= estimate)
          break;
        estimate = norm_y;
        for (unsigned int i = 0; i < n; ++i)
          z(i) = y(i) >= 0. ? 1. : -1.;
        lu.solve(z, true);
        unsigned int direction = 0;
        for (unsigned int i = 1; i < n; ++i)
          if (std::abs(z(i)) > std::abs(z(direction)))
            direction = i;
        if (iteration > 0 && (std::abs(z(direction)) <= z * x || direction == last_direction))
          break;
        x              = 0.;
        x(direction)   = 1.;
        last_direction = direction;
      }
    // Higham's alternative vector guards against the cases where the iteration stops early.
    for (unsigned int i = 0; i < n; ++i)
      x(i) = (i % 2 == 0 ? 1. : -1.) * (1. + (n > 1 ? double(i) / (n - 1) : 0.));
    lu.solve(x, false);
    return std::max(estimate, 2. * x.l1_norm() / (3. * n));
  }


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
    const double inverse_norm = inverse_one_norm_estimate(dense);
    return std::isfinite(inverse_norm) ? norm * inverse_norm
                                       : std::numeric_limits<double>::infinity();
  }
} // namespace GelMPM

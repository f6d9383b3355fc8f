// The entries of a tangent assembled on one rank, read once through Epetra's row views: deal.II's
// iterators over a Trilinos matrix copy a row at every step, and el(i, j) looks a row up and copies
// it per call, which made the comparisons of the assembly tests cost more than the assemblies
// (assembly/nitsche_tangent: 16 s of CPU, 85 % of it in those copies).
#ifndef gelmpm_tests_matrix_entries_h
#define gelmpm_tests_matrix_entries_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

/** The entries of the sparsity pattern, row by row, the columns of each row in increasing order. */
struct MatrixEntries
{
  std::vector<std::size_t>   row_start; // row i: [row_start[i], row_start[i + 1])
  std::vector<long long int> column;
  std::vector<double>        value;

  explicit MatrixEntries(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix                       &A = matrix.trilinos_matrix();
    const int                                     n = A.NumMyRows();
    std::vector<std::pair<long long int, double>> row;
    row_start.assign(n + 1, 0);
    for (int i = 0; i < n; ++i)
      {
        AssertThrow(A.GRID64(i) == i, dealii::ExcMessage("the matrix must be on one rank"));
        int     length  = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        A.ExtractMyRowView(i, length, values, indices);
        row.clear();
        for (int k = 0; k < length; ++k)
          row.emplace_back(A.GCID64(indices[k]), values[k]);
        std::sort(row.begin(), row.end());
        for (const auto &[j, v] : row)
          {
            column.push_back(j);
            value.push_back(v);
          }
        row_start[i + 1] = column.size();
      }
  }

  /** The entry (i, j), 0 outside the pattern (as el()). */
  double
  at(const std::size_t i, const long long int j) const
  {
    const auto first = column.begin() + row_start[i], last = column.begin() + row_start[i + 1];
    const auto found = std::lower_bound(first, last, j);
    return (found != last && *found == j) ? value[found - column.begin()] : 0.;
  }

  /** max |K_ij - K_ji| over the pattern. */
  double
  asymmetry() const
  {
    double largest = 0.;
    for (std::size_t i = 0; i + 1 < row_start.size(); ++i)
      for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
        largest = std::max(largest, std::abs(value[e] - at(column[e], i)));
    return largest;
  }
};

#endif

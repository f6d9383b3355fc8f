#ifndef gelmpm_core_sparse_entries_h
#define gelmpm_core_sparse_entries_h

#include <boost/serialization/vector.hpp>
#include <cstddef>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Entries of a sparse matrix as (global row, global column, value) triplets: a matrix
   * that outlives its object (a checkpoint keeps the tangent a factorisation was made of) and
   * that any partition of the rows over MPI ranks can take back.
   */
  struct SparseEntries
  {
    std::vector<unsigned int> rows, columns;
    std::vector<double>       values;

    std::size_t
    size() const
    {
      return values.size();
    }

    bool
    empty() const
    {
      return values.empty();
    }

    void
    clear()
    {
      rows.clear();
      columns.clear();
      values.clear();
    }

    /** Append the entries of @p other (e.g. another rank's rows). */
    void
    append(const SparseEntries &other)
    {
      rows.insert(rows.end(), other.rows.begin(), other.rows.end());
      columns.insert(columns.end(), other.columns.begin(), other.columns.end());
      values.insert(values.end(), other.values.begin(), other.values.end());
    }

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &rows &columns &values;
    }
  };
} // namespace GelMPM

#endif

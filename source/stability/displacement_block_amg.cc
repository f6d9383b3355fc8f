#include <gelmpm/stability/displacement_block_amg.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <Teuchos_ParameterList.hpp>
#include <array>
#include <ml_MultiLevelPreconditioner.h>
#include <stdexcept>

namespace GelMPM
{
  void
  copy_block(const dealii::TrilinosWrappers::SparseMatrix &K,
             const unsigned int                            row_begin,
             const unsigned int                            row_end,
             const unsigned int                            column_begin,
             const unsigned int                            column_end,
             dealii::TrilinosWrappers::SparseMatrix       &M)
  {
    const auto part_in =
      [](const dealii::IndexSet &owned, const unsigned int begin, const unsigned int end) {
        dealii::IndexSet part(end - begin);
        for (const auto i : owned)
          if (i >= begin && i < end)
            part.add_index(i - begin);
        part.compress();
        return part;
      };
    const dealii::IndexSet rows = part_in(K.locally_owned_range_indices(), row_begin, row_end);
    const dealii::IndexSet columns =
      part_in(K.locally_owned_domain_indices(), column_begin, column_end);
    const auto in_block = [&](const unsigned int i, const unsigned int j) {
      return i >= row_begin && j >= column_begin && j < column_end;
    };
    dealii::DynamicSparsityPattern pattern(row_end - row_begin, column_end - column_begin, rows);
    for_each_entry(K, row_end, [&](const unsigned int i, const unsigned int j, const double) {
      if (in_block(i, j))
        pattern.add(i - row_begin, j - column_begin);
    });
    M.reinit(rows, columns, pattern, K.get_mpi_communicator());
    pattern.reinit(0, 0);
    for_each_entry(K, row_end, [&](const unsigned int i, const unsigned int j, const double v) {
      if (in_block(i, j))
        M.set(i - row_begin, j - column_begin, v);
    });
    M.compress(dealii::VectorOperation::insert);
  }


  void
  copy_leading_block(const dealii::TrilinosWrappers::SparseMatrix &K,
                     const unsigned int                            n_u,
                     dealii::TrilinosWrappers::SparseMatrix       &A)
  {
    copy_block(K, 0, n_u, 0, n_u, A);
  }


  void
  DisplacementBlockAMG::setup(const dealii::TrilinosWrappers::SparseMatrix &K,
                              const unsigned int                            n_u,
                              const unsigned int                            dim,
                              const std::vector<double>                    &points)
  {
    // The old hierarchy refers to the old A and null space: it goes before they change.
    amg.clear();
    if (n_u == 0 || n_u > K.m() || points.size() != n_u || (dim != 2 && dim != 3))
      throw std::logic_error("DisplacementBlockAMG: n_u unknowns with one point coordinate each, "
                             "dim 2 or 3");

    copy_leading_block(K, n_u, A);

    // Rigid-body modes about the points' centroid: dim translations and dim(dim-1)/2 rotations,
    // on the rows this rank owns (ML's null space is distributed like A).
    const unsigned int  n_nodes = n_u / dim, n_modes = dim == 2 ? 3 : 6;
    std::vector<double> centre(dim, 0.);
    for (unsigned int k = 0; k < n_nodes; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] += points[k * dim + d] / n_nodes;
    const dealii::IndexSet owned   = A.locally_owned_range_indices();
    const unsigned int     n_local = owned.n_elements();
    modes.assign(n_modes * n_local, 0.);
    const auto mode = [&](const unsigned int m, const unsigned int local_row) -> double & {
      return modes[m * n_local + local_row];
    };
    unsigned int local_row = 0;
    for (const auto row : owned)
      {
        const unsigned int    k = row / dim, component = row % dim;
        std::array<double, 3> x = {{0., 0., 0.}};
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = points[k * dim + d] - centre[d];
        mode(component, local_row) = 1.;
        // Rotation about axis a: u = e_a x x.
        const unsigned int n_rotations = dim == 2 ? 1 : 3;
        for (unsigned int r = 0; r < n_rotations; ++r)
          {
            const unsigned int a = dim == 2 ? 2 : r, b = (a + 1) % 3, c = (a + 2) % 3;
            if (component == b)
              mode(dim + r, local_row) = -x[c];
            if (component == c)
              mode(dim + r, local_row) = x[b];
          }
        ++local_row;
      }
    Teuchos::ParameterList parameters;
    ML_Epetra::SetDefaults("SA", parameters);
    parameters.set("ML output", 0);
    parameters.set("PDE equations", static_cast<int>(dim));
    // On the wide stencils of B-splines, symmetric Gauss-Seidel smooths better than Chebyshev
    // at the same cost (§4.1 at 40 x 320 cells: 95 against 144 iterations per solve; cube at
    // 26^3: 114 against 290).
    parameters.set("smoother: type", "symmetric Gauss-Seidel");
    parameters.set("smoother: sweeps", 2);
    parameters.set("aggregation: threshold", 0.02);
    parameters.set("coarse: type", "Amesos-KLU");
    parameters.set("coarse: max size", 2000);
    parameters.set("null space: type", "pre-computed");
    parameters.set("null space: dimension", static_cast<int>(n_modes));
    parameters.set("null space: vectors", modes.data());
    amg.initialize(A, parameters);
  }


  void
  DisplacementBlockAMG::clear()
  {
    amg.clear();
    A.clear();
    modes.clear();
  }


  const dealii::TrilinosWrappers::SparseMatrix &
  DisplacementBlockAMG::matrix() const
  {
    return A;
  }


  const dealii::TrilinosWrappers::PreconditionAMG &
  DisplacementBlockAMG::preconditioner() const
  {
    return amg;
  }
} // namespace GelMPM

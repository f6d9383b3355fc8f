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
  copy_leading_block(const dealii::TrilinosWrappers::SparseMatrix &K,
                     const unsigned int                            n_u,
                     dealii::TrilinosWrappers::SparseMatrix       &A)
  {
    dealii::DynamicSparsityPattern a_pattern(n_u, n_u);
    for_each_entry(K, n_u, [&](const unsigned int i, const unsigned int j, const double) {
      if (j < n_u)
        a_pattern.add(i, j);
    });
    A.reinit(a_pattern);
    a_pattern.reinit(0, 0);
    for_each_entry(K, n_u, [&](const unsigned int i, const unsigned int j, const double v) {
      if (j < n_u)
        A.set(i, j, v);
    });
    A.compress(dealii::VectorOperation::insert);
  }


  void
  DisplacementBlockAMG::setup(const dealii::TrilinosWrappers::SparseMatrix &K,
                              const unsigned int                            n_u,
                              const unsigned int                            dim,
                              const std::vector<double>                    &points)
  {
    // The old hierarchy refers to the old A and null space: it goes before they change.
    amg.clear();
    if (n_u == 0 || n_u > K.m() || points.size() != n_u || (dim != 2 && dim != 3) ||
        K.trilinos_matrix().Comm().NumProc() != 1)
      throw std::logic_error("DisplacementBlockAMG: n_u unknowns with one point coordinate each, "
                             "dim 2 or 3, one process only");

    copy_leading_block(K, n_u, A);

    // Rigid-body modes about the points' centroid: dim translations and dim(dim-1)/2 rotations.
    const unsigned int  n_nodes = n_u / dim, n_modes = dim == 2 ? 3 : 6;
    std::vector<double> centre(dim, 0.);
    for (unsigned int k = 0; k < n_nodes; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] += points[k * dim + d] / n_nodes;
    modes.assign(n_modes * n_u, 0.);
    const auto mode = [&](const unsigned int m, const unsigned int row) -> double & {
      return modes[m * n_u + row];
    };
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        std::array<double, 3> x = {{0., 0., 0.}};
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = points[k * dim + d] - centre[d];
        for (unsigned int d = 0; d < dim; ++d)
          mode(d, k * dim + d) = 1.;
        // Rotation about axis a: u = e_a x x.
        const unsigned int n_rotations = dim == 2 ? 1 : 3;
        for (unsigned int r = 0; r < n_rotations; ++r)
          {
            const unsigned int a = dim == 2 ? 2 : r, b = (a + 1) % 3, c = (a + 2) % 3;
            if (b < dim)
              mode(dim + r, k * dim + b) = -x[c];
            if (c < dim)
              mode(dim + r, k * dim + c) = x[b];
          }
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

#include <gelmpm/solvers/block_krylov.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <Teuchos_ParameterList.hpp>
#include <array>
#include <cmath>
#include <map>
#include <ml_MultiLevelPreconditioner.h>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  bool
  BlockKrylov::set_structure(const unsigned int         n_u_dofs,
                             const unsigned int         dimension,
                             const std::vector<double> &u_dof_points)
  {
    if (u_dof_points.size() != n_u_dofs)
      throw std::logic_error("BlockKrylov: one point coordinate per displacement unknown");
    if (n_u_dofs == n_u && dimension == dim && u_dof_points == points)
      return false;
    n_u    = n_u_dofs;
    dim    = dimension;
    points = u_dof_points;
    built  = false;
    return true;
  }


  bool
  BlockKrylov::ready() const
  {
    return built;
  }


  void
  BlockKrylov::setup(const dealii::TrilinosWrappers::SparseMatrix &K, const Settings &new_settings)
  {
    built = false;
    // The old hierarchy refers to the old A and null space: it goes before they change.
    amg.clear();
    settings                = new_settings;
    matrix                  = &K;
    const unsigned int n    = K.m();
    const unsigned int n_mu = n - n_u;
    if (n_u == 0 || n_u > n || K.trilinos_matrix().Comm().NumProc() != 1)
      throw std::logic_error("BlockKrylov: set_structure() first; one process only");

    // The blocks, from the rows of K (each stored entry is visited once). A is copied in two
    // passes, pattern then values, so that no second copy of its entries is held on the way.
    dealii::DynamicSparsityPattern a_pattern(n_u, n_u), b_pattern(n_mu, n_u);
    std::vector<std::vector<std::pair<unsigned int, double>>> b_rows(n_mu), bt_rows(n_u);
    std::vector<std::map<unsigned int, double>>               c_rows(n_mu);
    std::vector<double>                                       inverse_diagonal(n_u, 0.);
    for_each_entry(K, n, [&](const unsigned int i, const unsigned int j, const double v) {
      if (i < n_u && j < n_u)
        {
          a_pattern.add(i, j);
          if (i == j)
            inverse_diagonal[i] = v;
        }
      else if (i < n_u)
        bt_rows[i].emplace_back(j - n_u, v);
      else if (j < n_u)
        b_rows[i - n_u].emplace_back(j, v);
      else
        c_rows[i - n_u][j - n_u] += v;
    });
    // K_uu is not an M-matrix: a diagonal entry can be negative (measured on the cube at 34^3
    // cells after the cut cells changed), where the Nitsche terms or the geometric stiffness
    // outweigh the rest. The Schur approximation only needs a scale per row: its magnitude.
    for (unsigned int i = 0; i < n_u; ++i)
      {
        if (!(std::abs(inverse_diagonal[i]) > 0.) || !std::isfinite(inverse_diagonal[i]))
          throw std::runtime_error("the iterative solver's preconditioner needs a nonzero "
                                   "diagonal in the displacement block (row " +
                                   std::to_string(i) + ")");
        inverse_diagonal[i] = 1. / std::abs(inverse_diagonal[i]);
      }
    A.reinit(a_pattern);
    a_pattern.reinit(0, 0);
    for_each_entry(K, n_u, [&](const unsigned int i, const unsigned int j, const double v) {
      if (j < n_u)
        A.set(i, j, v);
    });
    A.compress(dealii::VectorOperation::insert);

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
    // On the wide stencils of B-splines in 3D, symmetric Gauss-Seidel smooths better than
    // Chebyshev at the same cost (cube at 26^3: 114 against 290 iterations per solve).
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


    // The coupling B = K_mu,u and the approximate Schur complement
    // S = C - B diag(A)^{-1} K_u,mu.
    for (unsigned int i = 0; i < n_mu; ++i)
      for (const auto &[j, v] : b_rows[i])
        b_pattern.add(i, j);
    coupling_pattern.copy_from(b_pattern);
    B.reinit(coupling_pattern);
    for (unsigned int i = 0; i < n_mu; ++i)
      {
        for (const auto &[j, v] : b_rows[i])
          {
            B.set(i, j, v);
            for (const auto &[l, w] : bt_rows[j])
              c_rows[i][l] -= v * inverse_diagonal[j] * w;
          }
      }
    dealii::DynamicSparsityPattern s_pattern(n_mu, n_mu);
    for (unsigned int i = 0; i < n_mu; ++i)
      for (const auto &[j, v] : c_rows[i])
        s_pattern.add(i, j);
    schur_pattern.copy_from(s_pattern);
    S.reinit(schur_pattern);
    for (unsigned int i = 0; i < n_mu; ++i)
      for (const auto &[j, v] : c_rows[i])
        S.set(i, j, v);
    try
      {
        schur.initialize(S);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error(std::string("the approximate Schur complement of the iterative "
                                             "solver's preconditioner is singular: ") +
                                 e.what());
      }
    r_u.reinit(n_u);
    y_u.reinit(n_u);
    r_mu.reinit(n_mu);
    y_mu.reinit(n_mu);
    built = true;
  }


  void
  BlockKrylov::vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
  {
    for (unsigned int i = 0; i < n_u; ++i)
      r_u[i] = src[i];
    amg.vmult(y_u, r_u);
    B.vmult(r_mu, y_u);
    for (unsigned int i = 0; i < r_mu.size(); ++i)
      r_mu[i] = src[n_u + i] - r_mu[i];
    schur.vmult(y_mu, r_mu);
    for (unsigned int i = 0; i < n_u; ++i)
      dst[i] = y_u[i];
    for (unsigned int i = 0; i < y_mu.size(); ++i)
      dst[n_u + i] = y_mu[i];
  }


  unsigned int
  BlockKrylov::solve(dealii::Vector<double> &x, const dealii::Vector<double> &b) const
  {
    if (!built)
      throw std::logic_error("BlockKrylov::solve() without setup()");
    x.reinit(b.size());
    dealii::SolverControl                       control(settings.max_iterations,
                                  settings.relative_tolerance * b.l2_norm(),
                                  false,
                                  false);
    dealii::SolverGMRES<dealii::Vector<double>> gmres(
      control,
      dealii::SolverGMRES<dealii::Vector<double>>::AdditionalData(settings.restart + 2, true));
    try
      {
        gmres.solve(*matrix, x, b, *this);
      }
    catch (const dealii::SolverControl::NoConvergence &e)
      {
        std::ostringstream why;
        why << "the iterative solver (GMRES) did not reduce the residual by "
            << settings.relative_tolerance << " in " << e.last_step << " iterations (reached "
            << e.last_residual / std::max(b.l2_norm(), 1e-300) << ")";
        throw std::runtime_error(why.str());
      }
    for (const double v : x)
      if (!std::isfinite(v))
        throw std::runtime_error("the iterative solver's solution is not finite");
    return control.last_step();
  }
} // namespace GelMPM

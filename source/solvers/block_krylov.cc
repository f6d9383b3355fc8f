#include <gelmpm/core/collective.h>
#include <gelmpm/solvers/block_krylov.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <Amesos.h>
#include <EpetraExt_MatrixMatrix.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    /**
     * Right-preconditioned GMRES on K x = b to the settings' relative tolerance of
     * @p b_norm (|b|); the number of iterations. Throws std::runtime_error when it does not
     * converge.
     */
    template <typename VectorType, typename Preconditioner>
    unsigned int
    gmres(const dealii::TrilinosWrappers::SparseMatrix &K,
          VectorType                                   &x,
          const VectorType                             &b,
          const Preconditioner                         &preconditioner,
          const BlockKrylov::Settings                  &settings,
          const double                                  b_norm)
    {
      x = 0.;
      dealii::SolverControl           control(settings.max_iterations,
                                    settings.relative_tolerance * b_norm,
                                    false,
                                    false);
      dealii::SolverGMRES<VectorType> solver(
        control,
        typename dealii::SolverGMRES<VectorType>::AdditionalData(settings.restart + 2, true));
      try
        {
          solver.solve(K, x, b, preconditioner);
        }
      catch (const dealii::SolverControl::NoConvergence &e)
        {
          std::ostringstream why;
          why << "the iterative solver (GMRES) did not reduce the residual by "
              << settings.relative_tolerance << " in " << e.last_step << " iterations (reached "
              << e.last_residual / std::max(b_norm, 1e-300) << ")";
          throw std::runtime_error(why.str());
        }
      return control.last_step();
    }
  } // namespace


  void
  DistributedBlockPreconditioner::clear()
  {
    schur.reset();
    schur_problem.reset();
    S.reset();
    B.clear();
    displacement.clear();
  }


  void
  DistributedBlockPreconditioner::setup(const dealii::TrilinosWrappers::SparseMatrix &K,
                                        const unsigned int                            n_u,
                                        const unsigned int                            dim,
                                        const std::vector<double>                    &u_dof_points)
  {
    clear();
    const unsigned int n    = K.m();
    const MPI_Comm     comm = K.get_mpi_communicator();
    if (!(K.locally_owned_domain_indices() == K.locally_owned_range_indices()))
      throw std::logic_error("DistributedBlockPreconditioner: the tangent's rows and columns "
                             "must be distributed alike");
    displacement.setup(K, n_u, dim, u_dof_points);
    const dealii::TrilinosWrappers::SparseMatrix &A = displacement.matrix();

    // As on one rank (BlockKrylov::setup()), the magnitude of A's diagonal scales the coupling.
    const dealii::IndexSet                owned_u = A.locally_owned_range_indices();
    dealii::TrilinosWrappers::MPI::Vector inverse_diagonal(owned_u, comm);
    for (const auto i : owned_u)
      {
        const double d = A.diag_element(i);
        if (!(std::abs(d) > 0.) || !std::isfinite(d))
          throw std::runtime_error("the iterative solver's preconditioner needs a nonzero "
                                   "diagonal in the displacement block (row " +
                                   std::to_string(i) + ")");
        inverse_diagonal[i] = 1. / std::abs(d);
      }
    inverse_diagonal.compress(dealii::VectorOperation::insert);

    dealii::TrilinosWrappers::SparseMatrix Bt, C, coupling;
    copy_block(K, n_u, n, 0, n_u, B);
    copy_block(K, 0, n_u, n_u, n, Bt);
    copy_block(K, n_u, n, n_u, n, C);
    B.mmult(coupling, Bt, inverse_diagonal);
    Bt.clear();
    // S = C - coupling; the sum's pattern is the union of both (EpetraExt allocates it).
    Epetra_CrsMatrix *sum   = nullptr;
    const int         error = EpetraExt::MatrixMatrix::Add(C.trilinos_matrix(),
                                                   false,
                                                   1.,
                                                   coupling.trilinos_matrix(),
                                                   false,
                                                   -1.,
                                                   sum);
    S.reset(sum);
    if (error != 0 || !S)
      throw std::runtime_error("the approximate Schur complement of the iterative solver's "
                               "preconditioner could not be formed (EpetraExt error " +
                               std::to_string(error) + ")");
    S->FillComplete(C.trilinos_matrix().DomainMap(), C.trilinos_matrix().RangeMap());

    schur_problem = std::make_unique<Epetra_LinearProblem>();
    schur_problem->SetOperator(S.get());
    Amesos factory;
    schur.reset(factory.Create("Amesos_Mumps", *schur_problem));
    int status = schur ? schur->SymbolicFactorization() : -1;
    if (status == 0)
      status = schur->NumericFactorization();
    if (status != 0)
      throw std::runtime_error("the approximate Schur complement of the iterative solver's "
                               "preconditioner could not be factorised (Amesos error " +
                               std::to_string(status) + ")");

    r_u.reinit(owned_u, comm);
    y_u.reinit(owned_u, comm);
    r_mu.reinit(C.locally_owned_range_indices(), comm);
    y_mu.reinit(r_mu);
  }


  void
  DistributedBlockPreconditioner::vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
                                        const dealii::TrilinosWrappers::MPI::Vector &src) const
  {
    const std::size_t n_u_local = r_u.locally_owned_size();
    std::copy(src.begin(), src.begin() + n_u_local, r_u.begin());
    displacement.preconditioner().vmult(y_u, r_u);
    B.vmult(r_mu, y_u);
    const double *src_mu = src.begin() + n_u_local;
    for (auto [k, r] = std::make_pair(std::size_t(0), r_mu.begin()); r != r_mu.end(); ++k, ++r)
      *r = src_mu[k] - *r;
    schur_problem->SetLHS(&y_mu.trilinos_vector());
    schur_problem->SetRHS(&r_mu.trilinos_vector());
    const int status = schur->Solve();
    schur_problem->SetLHS(nullptr);
    schur_problem->SetRHS(nullptr);
    if (status != 0)
      throw std::runtime_error("the approximate Schur complement's solve failed (Amesos error " +
                               std::to_string(status) + ")");
    std::copy(y_u.begin(), y_u.end(), dst.begin());
    std::copy(y_mu.begin(), y_mu.end(), dst.begin() + n_u_local);
  }


  bool
  BlockKrylov::set_structure(const unsigned int                     n_u_dofs,
                             const unsigned int                     dimension,
                             const std::vector<double>             &u_dof_points,
                             const std::vector<NestedBSplineLevel> &coarse_levels)
  {
    if (u_dof_points.size() != n_u_dofs)
      throw std::logic_error("BlockKrylov: one point coordinate per displacement unknown");
    // The levels are a function of the DoFs, and so of their points.
    if (n_u_dofs == n_u && dimension == dim && u_dof_points == points &&
        coarse_levels.size() == levels.size())
      return false;
    n_u    = n_u_dofs;
    dim    = dimension;
    points = u_dof_points;
    levels = coarse_levels;
    built  = false;
    return true;
  }


  bool
  BlockKrylov::ready() const
  {
    return built;
  }


  bool
  BlockKrylov::geometric() const
  {
    return use_geometric;
  }


  const BSplineMultigrid &
  BlockKrylov::multigrid() const
  {
    return geometric_multigrid;
  }


  std::string
  BlockKrylov::displacement_preconditioner() const
  {
    if (!use_geometric)
      return distributed ? "algebraic multigrid (several MPI ranks)" : "algebraic multigrid";
    std::string levels_text;
    for (const unsigned int size : geometric_multigrid.level_sizes())
      levels_text += (levels_text.empty() ? "" : ", ") + std::to_string(size);
    return "geometric multigrid, levels of " + levels_text + " unknowns" +
           (geometric_multigrid.direct_coarse_solve() ? "" : ", the coarsest by AMG");
  }


  void
  BlockKrylov::setup(const dealii::TrilinosWrappers::SparseMatrix &K, const Settings &new_settings)
  {
    built = false;
    // The old hierarchy refers to the old A: it goes before the block changes.
    displacement.clear();
    geometric_multigrid.clear();
    distributed_preconditioner.clear();
    settings                = new_settings;
    matrix                  = &K;
    const unsigned int n    = K.m();
    const unsigned int n_mu = n - n_u;
    if (n_u == 0 || n_u > n)
      throw std::logic_error("BlockKrylov: set_structure() first");
    distributed   = Collective::is_parallel(K.get_mpi_communicator());
    use_geometric = false;
    if (distributed)
      {
        distributed_preconditioner.setup(K, n_u, dim, points);
        built = true;
        return;
      }

    // The coupling blocks and A's diagonal, from the rows of K (each stored entry is visited
    // once); A itself and its multigrid are DisplacementBlockAMG's or BSplineMultigrid's.
    dealii::DynamicSparsityPattern                            b_pattern(n_mu, n_u);
    std::vector<std::vector<std::pair<unsigned int, double>>> b_rows(n_mu), bt_rows(n_u);
    std::vector<std::map<unsigned int, double>>               c_rows(n_mu);
    std::vector<double>                                       inverse_diagonal(n_u, 0.);
    for_each_entry(K, n, [&](const unsigned int i, const unsigned int j, const double v) {
      if (i < n_u && j < n_u)
        {
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
    use_geometric = new_settings.geometric && !levels.empty();
    if (use_geometric)
      geometric_multigrid.setup(K, n_u, dim, levels, settings.multigrid);
    else
      displacement.setup(K, n_u, dim, points);

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
    if (use_geometric)
      geometric_multigrid.vmult(y_u, r_u);
    else
      displacement.preconditioner().vmult(y_u, r_u);
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
    const unsigned int iterations =
      distributed ? solve_distributed(x, b) : gmres(*matrix, x, b, *this, settings, b.l2_norm());
    for (const double v : x)
      if (!std::isfinite(v))
        throw std::runtime_error("the iterative solver's solution is not finite");
    return iterations;
  }


  unsigned int
  BlockKrylov::solve_distributed(dealii::Vector<double> &x, const dealii::Vector<double> &b) const
  {
    const dealii::IndexSet                owned = matrix->locally_owned_range_indices();
    const MPI_Comm                        comm  = matrix->get_mpi_communicator();
    dealii::TrilinosWrappers::MPI::Vector b_owned(owned, comm), x_owned(owned, comm);
    {
      auto entry = b_owned.begin();
      for (const auto i : owned)
        *entry++ = b[i];
    }
    const unsigned int iterations =
      gmres(*matrix, x_owned, b_owned, distributed_preconditioner, settings, b.l2_norm());
    // The Newton vectors are whole on every rank: the ranks' parts are summed into place.
    x.reinit(b.size());
    {
      auto entry = x_owned.begin();
      for (const auto i : owned)
        x[i] = *entry++;
    }
    Collective::sum_in_place(comm, x.begin(), x.size());
    return iterations;
  }
} // namespace GelMPM

#include <gelmpm/core/collective.h>
#include <gelmpm/solvers/block_krylov.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <Amesos.h>
#include <EpetraExt_MatrixMatrix.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
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


    /**
     * Fill @p matrix (and its @p pattern) of @p n_columns columns from @p rows, each a list of
     * (column, value) pairs.
     */
    template <typename Rows>
    void
    copy_rows(const Rows                   &rows,
              const unsigned int            n_columns,
              dealii::SparsityPattern      &pattern,
              dealii::SparseMatrix<double> &matrix)
    {
      dealii::DynamicSparsityPattern dynamic(rows.size(), n_columns);
      for (unsigned int i = 0; i < rows.size(); ++i)
        for (const auto &[j, v] : rows[i])
          dynamic.add(i, j);
      pattern.copy_from(dynamic);
      matrix.reinit(pattern);
      for (unsigned int i = 0; i < rows.size(); ++i)
        for (const auto &[j, v] : rows[i])
          matrix.set(i, j, v);
    }


    /** The rows of the blocks B, B^T', C of the tangent, and 1 / |diag(A)|. */
    struct BlockRows
    {
      std::vector<std::vector<std::pair<unsigned int, double>>> b, bt;
      std::vector<std::map<unsigned int, double>>               c;
      dealii::Vector<double>                                    inverse_diagonal;
    };

    /**
     * Read the blocks of @p K (@p n_u displacement unknowns first) from its rows, each stored
     * entry once. Throws std::runtime_error if a diagonal entry of A is zero or not finite.
     */
    BlockRows
    read_blocks(const dealii::TrilinosWrappers::SparseMatrix &K, const unsigned int n_u)
    {
      const unsigned int n = K.m(), n_mu = n - n_u;
      BlockRows          blocks;
      blocks.b.resize(n_mu);
      blocks.bt.resize(n_u);
      blocks.c.resize(n_mu);
      blocks.inverse_diagonal.reinit(n_u);
      auto &d = blocks.inverse_diagonal;
      for_each_entry(K, n, [&](const unsigned int i, const unsigned int j, const double v) {
        if (i < n_u && j < n_u)
          {
            if (i == j)
              d[i] = v;
          }
        else if (i < n_u)
          blocks.bt[i].emplace_back(j - n_u, v);
        else if (j < n_u)
          blocks.b[i - n_u].emplace_back(j, v);
        else
          blocks.c[i - n_u][j - n_u] += v;
      });
      // K_uu is not an M-matrix: a diagonal entry can be negative (measured on the cube at 34^3
      // cells after the cut cells changed), where the Nitsche terms or the geometric stiffness
      // outweigh the rest. The Schur approximation only needs a scale per row: its magnitude.
      for (unsigned int i = 0; i < n_u; ++i)
        {
          if (!(std::abs(d[i]) > 0.) || !std::isfinite(d[i]))
            throw std::runtime_error("the iterative solver's preconditioner needs a nonzero "
                                     "diagonal in the displacement block (row " +
                                     std::to_string(i) + ")");
          d[i] = 1. / std::abs(d[i]);
        }
      return blocks;
    }


    /**
     * The groups of displacement unknowns that A couples strongly, |a_ij| > @p threshold
     * sqrt(|a_ii a_jj|) (@p inverse_diagonal = 1 / |a_ii|): the connected components of that
     * graph, as an AMG's strong connections. Each unknown's group and place in it, and each
     * group's members.
     */
    struct CoupledGroups
    {
      std::vector<unsigned int>              group, place;
      std::vector<std::vector<unsigned int>> members;
    };

    CoupledGroups
    strongly_coupled_groups(const dealii::TrilinosWrappers::SparseMatrix &K,
                            const unsigned int                            n_u,
                            const dealii::Vector<double>                 &inverse_diagonal,
                            const double                                  threshold)
    {
      std::vector<unsigned int> parent(n_u);
      std::iota(parent.begin(), parent.end(), 0u);
      const auto root = [&](unsigned int i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      if (threshold < 1.)
        for_each_entry(K, n_u, [&](const unsigned int i, const unsigned int j, const double v) {
          if (j < n_u && i != j &&
              v * v * inverse_diagonal[i] * inverse_diagonal[j] > threshold * threshold)
            {
              const unsigned int a = root(i), b = root(j);
              if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
            }
        });
      CoupledGroups                        groups;
      std::map<unsigned int, unsigned int> group_of_root;
      groups.group.resize(n_u);
      groups.place.resize(n_u);
      for (unsigned int i = 0; i < n_u; ++i)
        {
          const auto [it, added] = group_of_root.emplace(root(i), groups.members.size());
          if (added)
            groups.members.emplace_back();
          groups.group[i] = it->second;
          groups.place[i] = groups.members[it->second].size();
          groups.members[it->second].push_back(i);
        }
      return groups;
    }


    /** Whether the symmetric part of @p block is positive definite (LAPACK's Cholesky). */
    bool
    symmetric_part_is_definite(const dealii::FullMatrix<double> &block)
    {
      const unsigned int               m = block.m();
      dealii::LAPACKFullMatrix<double> symmetric(m, m);
      for (unsigned int a = 0; a < m; ++a)
        for (unsigned int b = 0; b < m; ++b)
          symmetric(a, b) = 0.5 * (block(a, b) + block(b, a));
      symmetric.set_property(dealii::LAPACKSupport::symmetric);
      try
        {
          symmetric.compute_cholesky_factorization();
        }
      catch (const std::exception &)
        {
          return false;
        }
      return true;
    }


    /**
     * The weight W of LSC: W^{-1} is the inverse of A's diagonal blocks over the groups of
     * strongly coupled displacement unknowns (strongly_coupled_groups()), |a_ii|^{-1} for the
     * others. With Nitsche's penalty (gamma / h times a boundary mass matrix) the u_n rows of the
     * functions nonzero on an immersed boundary are coupled almost as a rank-one block: its
     * diagonal overestimates A a hundredfold on the combinations whose trace vanishes, and the
     * commutator's error concentrates there. A group whose block's symmetric part is not
     * positive definite, or that has more than max_block unknowns, keeps |diag|^{-1}.
     * Returns the largest block inverted.
     */
    unsigned int
    build_weight(const dealii::TrilinosWrappers::SparseMatrix &K,
                 const unsigned int                            n_u,
                 const dealii::Vector<double>                 &inverse_diagonal,
                 const double                                  threshold,
                 dealii::SparsityPattern                      &pattern,
                 dealii::SparseMatrix<double>                 &weight)
    {
      weight.clear();
      constexpr unsigned int max_block = 64;
      const CoupledGroups    groups  = strongly_coupled_groups(K, n_u, inverse_diagonal, threshold);
      const auto            &members = groups.members;
      const auto            &group   = groups.group;
      std::vector<dealii::FullMatrix<double>> blocks(members.size());
      for (unsigned int g = 0; g < members.size(); ++g)
        if (members[g].size() > 1 && members[g].size() <= max_block)
          blocks[g].reinit(members[g].size(), members[g].size());
      if (threshold < 1.)
        for_each_entry(K, n_u, [&](const unsigned int i, const unsigned int j, const double v) {
          if (j < n_u && group[i] == group[j] && !blocks[group[i]].empty())
            blocks[group[i]](groups.place[i], groups.place[j]) = v;
        });
      unsigned int largest = 1;
      for (auto &block : blocks)
        if (!block.empty())
          {
            if (symmetric_part_is_definite(block))
              {
                block.gauss_jordan();
                largest = std::max<unsigned int>(largest, block.m());
              }
            else
              block.reinit(0, 0);
          }
      std::vector<std::vector<std::pair<unsigned int, double>>> rows(n_u);
      for (unsigned int i = 0; i < n_u; ++i)
        if (blocks[group[i]].empty())
          rows[i].emplace_back(i, inverse_diagonal[i]);
        else
          for (const unsigned int j : members[group[i]])
            rows[i].emplace_back(j, blocks[group[i]](groups.place[i], groups.place[j]));
      copy_rows(rows, n_u, pattern, weight);
      return largest;
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
      return distributed ? "algebraic multigrid (several MPI ranks; mu's Schur complement "
                           "approximated as 'diagonal')"
                         : "algebraic multigrid";
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

    // A itself and its multigrid are DisplacementBlockAMG's or BSplineMultigrid's.
    auto [b_rows, bt_rows, c_rows, diagonal] = read_blocks(K, n_u);
    inverse_diagonal                         = std::move(diagonal);
    use_geometric                            = new_settings.geometric && !levels.empty();
    if (use_geometric)
      geometric_multigrid.setup(K, n_u, dim, levels, settings.multigrid);
    else
      displacement.setup(K, n_u, dim, points);

    // The weight W^{-1}: |diag(A)|^{-1} for 'diagonal', blocks of A for LSC (build_weight()).
    const bool lsc = settings.schur == SchurApproximation::lsc;
    largest_block  = build_weight(K,
                                 n_u,
                                 inverse_diagonal,
                                 lsc ? settings.block_threshold : 1.,
                                 weight_pattern,
                                 weight);

    // The coupling B = K_mu,u and L_C = C - B W^{-1} K_u,mu: the approximate Schur complement of
    // 'diagonal', the outer factor of LSC's.
    copy_rows(b_rows, n_u, coupling_pattern, B);
    for (unsigned int i = 0; i < n_mu; ++i)
      for (const auto &[j, v] : b_rows[i])
        for (auto entry = weight.begin(j); entry != weight.end(j); ++entry)
          for (const auto &[l, w] : bt_rows[entry->column()])
            c_rows[i][l] -= v * entry->value() * w;
    // LSC also applies K_u,mu and A (through K).
    if (lsc)
      {
        copy_rows(bt_rows, n_mu, transposed_pattern, Bt);
        full_in.reinit(n);
        full_out.reinit(n);
        t_mu.reinit(n_mu);
        w_u.reinit(n_u);
        z_u.reinit(n_u);
      }
    else
      {
        Bt.clear();
        transposed_pattern.reinit(0, 0, 0);
        full_in.reinit(0);
        full_out.reinit(0);
        t_mu.reinit(0);
        w_u.reinit(0);
        z_u.reinit(0);
      }
    copy_rows(c_rows, n_mu, schur_pattern, S);
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
    if (settings.schur == SchurApproximation::lsc)
      {
        // y_mu = L_C^{-1} (L_C + L - H) L_C^{-1} r_mu with L_C = C - L, L = B W^{-1} B^T',
        // H = B W^{-1} A W^{-1} B^T': the first solve is above; here w = W^{-1} B^T' y_mu and
        // t = L_C y_mu + B (w - W^{-1} A w), A w being the u rows of K [w; 0].
        Bt.vmult(r_u, y_mu);
        weight.vmult(w_u, r_u);
        full_in = 0.;
        for (unsigned int i = 0; i < n_u; ++i)
          full_in[i] = w_u[i];
        matrix->vmult(full_out, full_in);
        for (unsigned int i = 0; i < n_u; ++i)
          r_u[i] = full_out[i];
        weight.vmult(z_u, r_u);
        w_u -= z_u;
        B.vmult(t_mu, w_u);
        S.vmult_add(t_mu, y_mu);
        schur.vmult(y_mu, t_mu);
      }
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

#ifndef gelmpm_solvers_block_krylov_h
#define gelmpm_solvers_block_krylov_h

#include <gelmpm/solvers/bspline_multigrid.h>
#include <gelmpm/stability/displacement_block_amg.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief BlockKrylov's preconditioner on several MPI ranks: the same block triangle
   * [A 0; B S], S = C - B |diag(A)|^{-1} B^T', on the distributed blocks of the tangent.
   *
   * Each rank copies the rows of the blocks it owns (copy_block()); A is approximated by ML's
   * smoothed aggregation (DisplacementBlockAMG, distributed), S is formed by Trilinos' sparse
   * products (EpetraExt) and factorised by MUMPS on all ranks. The geometric multigrid's
   * smoother visits cell blocks in order across the whole grid, so on several ranks A has the
   * algebraic multigrid only.
   *
   * A rank's part of a vector of the tangent's unknowns is its displacement unknowns followed by
   * its chemical potential unknowns: both are its owned indices in ascending order, and the
   * displacement unknowns come first in the global numbering.
   */
  class DistributedBlockPreconditioner
  {
  public:
    /** Build the blocks of @p K, the AMG of A and the factorised S (as BlockKrylov::setup()). */
    void
    setup(const dealii::TrilinosWrappers::SparseMatrix &K,
          const unsigned int                            n_u,
          const unsigned int                            dim,
          const std::vector<double>                    &u_dof_points);

    /** Release everything (the factorisation refers to S, the AMG to A). */
    void
    clear();

    /** Apply the preconditioner to a vector distributed like the tangent's rows. */
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

  private:
    DisplacementBlockAMG                          displacement;
    dealii::TrilinosWrappers::SparseMatrix        B;
    std::unique_ptr<Epetra_CrsMatrix>             S;
    std::unique_ptr<Epetra_LinearProblem>         schur_problem;
    std::unique_ptr<Amesos_BaseSolver>            schur;
    mutable dealii::TrilinosWrappers::MPI::Vector r_u, y_u, r_mu, y_mu;
  };


  /**
   * @brief GMRES on the u–mu Newton system with a block-triangular preconditioner: multigrid on
   * the displacement block, either algebraic (Trilinos ML, given the rigid-body modes;
   * DisplacementBlockAMG, shared with the iterative stability analysis) or geometric on the
   * nested B-spline grids (BSplineMultigrid), and a direct solve with an approximate Schur
   * complement of the chemical potential.
   *
   * With K = [A B^T'; B C] (A = K_uu, B = K_mu,u, B^T' = K_u,mu, C = K_mu,mu) the preconditioner
   * is the lower block triangle [A 0; B S], applied as y_u = MG(A)^{-1} r_u and
   * y_mu = S^{-1} (r_mu - B y_u). Right-preconditioned GMRES with the exact A and S would
   * converge in two iterations. The approximation of S must keep both limits: for large dt the mu
   * block C (dt times the mobility's Laplacian) dominates S, and in the undrained limit dt -> 0,
   * where C vanishes, S -> -B A^{-1} B^T', the pressure Schur complement of nearly
   * incompressible elasticity; the subdivision-stabilised pair (mu on the 2h grid) keeps it
   * bounded away from zero. With a weight W^{-1} ~ A^{-1} (below), L = B W^{-1} B^T' and
   * L_C = C - L (sparse; mu has few unknowns: factorised by UMFPACK):
   * - SchurApproximation::diagonal: W = D = |diag(A)| (the absolute value keeps the sign where a
   *   strongly compressed point makes a diagonal entry of A negative) and S ~ L_C. Right for
   *   large dt, but in the undrained limit L misestimates B A^{-1} B^T' by an h-dependent
   *   factor and the count grows with refinement (§4.1, A exact: 35, 54, 77 iterations per
   *   solve on 20 x 160, 40 x 320, 80 x 640 cells).
   * - SchurApproximation::lsc (the default): the least-squares commutator of Elman, Howle,
   *   Shadid, Shuttleworth and Tuminaro (SIAM J. Sci. Comput. 27, 2006) with A's own (block)
   *   diagonal as the weight, as in the scaled BFBt of May and Moresi (PEPI 171, 2008):
   *   (B A^{-1} B^T')^{-1} ~ L^{-1} H L^{-1}, H = B W^{-1} A W^{-1} B^T', the A_p that makes
   *   A W^{-1} B^T' ~ W^{-1} B^T' A_p best in the least-squares sense. Blended with C as
   *   S^{-1} ~ L_C^{-1} (C - H) L_C^{-1}: -L^{-1} H L^{-1} for C -> 0, C^{-1} where C dominates;
   *   a fixed linear operator, so plain GMRES stays valid. With W = D the commutator fails at the
   *   immersed boundaries, where the Nitsche penalty ties the normal components of the two or
   *   three functions nonzero on the boundary into an almost rank-one block whose diagonal
   *   overestimates A a hundredfold on the combinations with no trace (20, 26, 36 undrained on
   *   the grids above). So W is the block diagonal of A over the strongly coupled unknowns,
   *   |a_ij| > Settings::block_threshold sqrt(|a_ii a_jj|) (blocks of 2-3 unknowns there in
   *   2D, up to 6 on the cube; D elsewhere): 9.6, 10.7, 13.2. Cost per application: a second
   *   solve with L_C, a product with K, two with W and one each with B and B^T'.
   *
   * On one MPI rank the blocks are read from the rows of the matrix and GMRES runs on whole
   * vectors; on several ranks the blocks, the Krylov vectors and the preconditioner are
   * distributed like the tangent's rows (DistributedBlockPreconditioner), and only the solution
   * is made whole again for the caller.
   */
  class BlockKrylov
  {
  public:
    /**
     * The approximation of the mu Schur complement S = C - B A^{-1} B^T' (section "Linear
     * solver", entry "Schur complement"; the class's documentation has the notation):
     */
    enum class SchurApproximation
    {
      /** S ~ L_C with W = |diag(A)| (the approximation before LSC). */
      diagonal,
      /**
       * S^{-1} ~ L_C^{-1} (C - H) L_C^{-1} with H = B W^{-1} A W^{-1} B^T' and W the block
       * diagonal of A over its strongly coupled unknowns: the least-squares commutator; the
       * default.
       */
      lsc
    };

    /** Solver settings (section "Linear solver"). */
    struct Settings
    {
      /** The approximation of the mu Schur complement. */
      SchurApproximation schur = SchurApproximation::lsc;
      /**
       * LSC: displacement unknowns coupled by |a_ij| > block_threshold sqrt(|a_ii a_jj|) form
       * the blocks of A whose inverse weighs the commutator (1: the diagonal alone).
       */
      double block_threshold = 0.7;
      /** The relative residual reduction of each solve. */
      double relative_tolerance = 1e-8;
      /** At most this many iterations; more is a failure of the solve. */
      unsigned int max_iterations = 500;
      /** GMRES restart length. */
      unsigned int restart = 200;
      /**
       * Geometric multigrid on the displacement block where set_structure() gave coarse
       * levels; algebraic (ML) otherwise.
       */
      bool geometric = false;
      /** The geometric multigrid's settings. */
      BSplineMultigrid::Settings multigrid;
    };

    /**
     * The unknowns: @p n_u displacement unknowns (@p dim interleaved components per DoF) before
     * the chemical potential's, and the point at which each displacement DoF's linear-field
     * coefficient is taken (its Greville point), dim coordinates per DoF: the rigid-body modes.
     * @p levels: the coarse B-spline levels below the displacement DoFs (NestedBSplineGrids),
     * for the geometric multigrid; empty for the algebraic one. Returns whether the unknowns
     * changed (then setup() must come again before solve()).
     */
    bool
    set_structure(const unsigned int                     n_u,
                  const unsigned int                     dim,
                  const std::vector<double>             &u_dof_points,
                  const std::vector<NestedBSplineLevel> &levels = {});

    /**
     * Build the preconditioner of @p K: the blocks, the AMG hierarchy of A and the factorised
     * approximate Schur complement. Throws std::runtime_error if a diagonal entry of A is zero or
     * not finite, or S cannot be factorised.
     */
    void
    setup(const dealii::TrilinosWrappers::SparseMatrix &K, const Settings &settings);

    /**
     * Solve K x = b with the matrix of the last setup(); returns the number of iterations.
     * Throws std::runtime_error when GMRES does not reach the tolerance.
     */
    unsigned int
    solve(dealii::Vector<double> &x, const dealii::Vector<double> &b) const;

    /** Whether setup() has built a preconditioner. */
    bool
    ready() const;

    /** Whether the last setup() built the geometric multigrid (else ML's AMG). */
    bool
    geometric() const;

    /** The geometric multigrid of the last setup() (meaningful if geometric()). */
    const BSplineMultigrid &
    multigrid() const;

    /**
     * The displacement block's preconditioner of the last setup(), for the log: "algebraic
     * multigrid" or "geometric multigrid" with the unknowns of its levels.
     */
    std::string
    displacement_preconditioner() const;

    /** Apply the preconditioner (for deal.II's GMRES). */
    void
    vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const;

  private:
    /** solve() on several ranks: GMRES on vectors distributed like the rows of the tangent. */
    unsigned int
    solve_distributed(dealii::Vector<double> &x, const dealii::Vector<double> &b) const;

    unsigned int                    n_u = 0, dim = 2;
    std::vector<double>             points;
    std::vector<NestedBSplineLevel> levels;
    Settings                        settings;

    const dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
    // A = K_uu and its AMG hierarchy, or its geometric multigrid.
    DisplacementBlockAMG           displacement;
    BSplineMultigrid               geometric_multigrid;
    bool                           use_geometric = false;
    bool                           distributed   = false;
    DistributedBlockPreconditioner distributed_preconditioner;
    dealii::SparsityPattern        coupling_pattern, transposed_pattern, schur_pattern;
    // B = K_mu,u, B^T' = K_u,mu (LSC only), S = L_C (factorised in schur).
    dealii::SparseMatrix<double> B, Bt, S;
    // |diag(A)|^{-1}, and the weight W^{-1} (its blocks for LSC).
    dealii::Vector<double>         inverse_diagonal;
    dealii::SparsityPattern        weight_pattern;
    dealii::SparseMatrix<double>   weight;
    unsigned int                   largest_block = 1;
    mutable dealii::Vector<double> full_in, full_out, t_mu, w_u, z_u;
    dealii::SparseDirectUMFPACK    schur;
    mutable dealii::Vector<double> r_u, y_u, r_mu, y_mu;
    bool                           built = false;
  };
} // namespace GelMPM

#endif

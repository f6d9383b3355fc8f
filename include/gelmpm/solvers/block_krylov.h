#ifndef gelmpm_solvers_block_krylov_h
#define gelmpm_solvers_block_krylov_h

#include <gelmpm/solvers/bspline_multigrid.h>
#include <gelmpm/stability/displacement_block_amg.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief GMRES on the u–mu Newton system with a block-triangular preconditioner: multigrid on
   * the displacement block, either algebraic (Trilinos ML, given the rigid-body modes;
   * DisplacementBlockAMG, shared with the iterative stability analysis) or geometric on the
   * nested B-spline grids (BSplineMultigrid), and a direct solve with an approximate Schur
   * complement of the chemical potential.
   *
   * With K = [A B^T'; B C] (A = K_uu, B = K_mu,u, B^T' = K_u,mu, C = K_mu,mu) the preconditioner
   * is the lower block triangle [A 0; B S], applied as y_u = AMG(A)^{-1} r_u and
   * y_mu = S^{-1} (r_mu - B y_u), with S = C - B |diag(A)|^{-1} B^T'. Right-preconditioned GMRES
   * with the exact A and S would converge in two iterations. The approximation of S keeps both
   * limits: for large dt the mu block C (dt times the mobility's Laplacian) dominates S, and in
   * the undrained limit dt -> 0, where C vanishes, the coupling term B |diag(A)|^{-1} B^T' alone
   * keeps S definite, as it does for the pressure of nearly incompressible elasticity; the
   * subdivision-stabilised pair (mu on the 2h grid) keeps the pair inf–sup stable, so S stays
   * bounded away from zero. mu has few unknowns (the coarse grid's, one per node), so S is
   * factorised directly (UMFPACK). The absolute value keeps the sign of S where a strongly
   * compressed point makes a diagonal entry of A negative.
   *
   * Serial: the blocks are read from the rows of the matrix on one process.
   */
  class BlockKrylov
  {
  public:
    /** Solver settings (section "Linear solver"). */
    struct Settings
    {
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
    unsigned int                    n_u = 0, dim = 2;
    std::vector<double>             points;
    std::vector<NestedBSplineLevel> levels;
    Settings                        settings;

    const dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
    // A = K_uu and its AMG hierarchy, or its geometric multigrid.
    DisplacementBlockAMG           displacement;
    BSplineMultigrid               geometric_multigrid;
    bool                           use_geometric = false;
    dealii::SparsityPattern        coupling_pattern, schur_pattern;
    dealii::SparseMatrix<double>   B, S;
    dealii::SparseDirectUMFPACK    schur;
    mutable dealii::Vector<double> r_u, y_u, r_mu, y_mu;
    bool                           built = false;
  };
} // namespace GelMPM

#endif

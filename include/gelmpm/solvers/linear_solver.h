#ifndef gelmpm_solvers_linear_solver_h
#define gelmpm_solvers_linear_solver_h

#include <gelmpm/core/sparse_entries.h>
#include <gelmpm/solvers/block_krylov.h>
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Linear solver" section and the direct solve of the Newton system.
   *
   * A sparse direct solver: MUMPS by default, KLU on request. The symbolic factorisation
   * (ordering and structure analysis) is kept while the sparsity pattern does not change: the
   * Newton iterations and the retried attempts of a time step share one pattern, and only
   * refactorise numerically. The caller says when the pattern changes (new_pattern(), after a
   * grid reset that changed the cell classification); a different matrix object also starts
   * afresh. factorize() and solve() are separate so that a modified Newton iteration can solve
   * with the factorisation of an earlier tangent.
   *
   * A matrix known to be symmetric (set_symmetric(), the symmetric Nitsche variant) is
   * factorised by MUMPS as LDL^T (SymmetricFactorization, about half the work of LU, and its
   * inertia comes with it); otherwise, or with KLU, by Trilinos' Amesos (Amesos_Mumps,
   * Amesos_Klu), used directly rather than through TrilinosWrappers::SolverDirect to keep the
   * symbolic factorisation.
   *
   * "Krylov" instead solves iteratively (BlockKrylov: GMRES with geometric or algebraic
   * multigrid on the displacement block and an approximate Schur complement of mu):
   * factorize() builds the preconditioner, solve()
   * iterates. It needs the block structure (set_block_structure()) after every change of the
   * unknowns. On several MPI ranks it runs distributed (DistributedBlockPreconditioner), with the
   * algebraic multigrid on the displacement block.
   *
   * "automatic" (the default) decides at the first factorisation: MUMPS, unless MUMPS's own
   * estimate of its factorisation (SymmetricFactorization::estimated_memory(), doubled for LU)
   * exceeds 'Automatic memory share' of the memory available, then Krylov (on several ranks: all
   * ranks' estimate against the least memory available on any rank's machine). Until then
   * may_iterate() is true, so the caller keeps the block structure set.
   */
  class LinearSolver
  {
  public:
    LinearSolver();
    ~LinearSolver();

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Whether the matrices to come are symmetric: with MUMPS they are then factorised as LDL^T.
     * Only the lower triangle is read, so a matrix that is not symmetric gives wrong solutions.
     */
    void
    set_symmetric(const bool symmetric);

    /**
     * The sparsity pattern of the next matrix differs: forget the symbolic factorisation. Call it
     * before the matrix last solved with is destroyed or re-initialised (MUMPS refers to it when
     * its factorisation is released), and before the solver's owner destroys that matrix.
     */
    void
    new_pattern() const;

    /**
     * Factorise @p K numerically, reusing the symbolic factorisation of the previous call unless
     * new_pattern() was called or @p K is another matrix object. Throws std::runtime_error when
     * the factorisation fails.
     */
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &K) const;

    /**
     * Solve K x = b with the factorisation of the last factorize(). Throws std::runtime_error
     * when there is none or the solution is not finite. Single-precision factors are refined to
     * the relative residual @p refinement_target (SymmetricFactorization::solve()); the other
     * solvers ignore it.
     */
    void
    solve(dealii::Vector<double>       &x,
          const dealii::Vector<double> &b,
          const double refinement_target = SymmetricFactorization::refinement_tolerance) const;

    /** factorize(@p K), then solve(@p x, @p b). */
    void
    solve(const dealii::TrilinosWrappers::SparseMatrix &K,
          dealii::Vector<double>                       &x,
          const dealii::Vector<double>                 &b) const;

    /**
     * With @p keep, every factorize() keeps a copy of the entries it factorised (of the rows
     * this rank owns, with global indices): a checkpoint stores them, so that a resumed run
     * refactorises the matrix the run's next Newton iteration would have solved with (modified
     * Newton).
     */
    void
    keep_factorized_values(const bool keep);

    /** The entries of the current factorisation (empty: none, or not kept). */
    const SparseEntries &
    entries_of_factorization() const;

    /** Whether a factorisation of the current pattern is there to solve with. */
    bool
    has_factorization() const;

    /**
     * The time step of the tangent factorised last, as solve_newton() notes it after each
     * factorize() (0: not noted, e.g. the tangent a resumed run refactorised): the modified
     * Newton iteration's 'Reuse step ratio' compares it with the step's.
     */
    double
    factorized_step() const;

    /** Note the time step of the tangent just factorised (see factorized_step()). */
    void
    note_factorized_step(const double dt) const;

    /** The solves made with the current factorisation ('Newton/Maximum reuses'). */
    unsigned int
    solves_with_factorization() const;

    /**
     * Whether the last factorize() or solve() failed (threw). A Newton solve then takes at least
     * one iteration (solve_newton()): a state that meets the tolerance without a solve proves
     * nothing once the solver has failed.
     */
    bool
    last_call_failed() const;

    /**
     * The LDL^T factorisation of the last factorize() when the matrices are symmetric and
     * MUMPS factorises them in double precision, else nullptr: its inertia is the signature of
     * that matrix. (Without it the stability analysis factorises the tangent itself.)
     */
    const SymmetricFactorization *
    symmetric_factorization() const;

    /** How many symbolic factorisations factorize() has made (for tests and performance notes). */
    unsigned int
    n_symbolic_factorisations() const;

    /** How many numeric factorisations factorize() has made. */
    unsigned int
    n_numeric_factorisations() const;

    /** The solver's name: "Amesos_Klu", "Amesos_Mumps" or "MUMPS LDL^T". */
    std::string
    name() const;

    /** Whether factorize() makes an LDL^T factorisation (symmetric matrices and MUMPS). */
    bool
    uses_ldlt() const;

    /** Whether the Newton systems are solved iteratively ("Krylov"). */
    bool
    iterative() const;

    /** Whether the solve may still turn out iterative ('automatic' before its decision): the
     * block structure must then be set. */
    bool
    may_iterate() const;

    /** What 'automatic' chose and why (empty before the decision or without 'automatic'). */
    std::string
    automatic_choice() const;

    /**
     * For the iterative solver: the number of displacement unknowns (dim interleaved components
     * per DoF, before mu's), each one's Greville-point coordinate and, for the geometric
     * multigrid, the coarse B-spline levels below them (BlockKrylov::set_structure).
     */
    void
    set_block_structure(const unsigned int                     n_u,
                        const unsigned int                     dim,
                        const std::vector<double>             &u_dof_points,
                        const std::vector<NestedBSplineLevel> &levels = {});

    /**
     * Whether the iterative solver wants the coarse B-spline levels for a geometric multigrid
     * on the displacement block ('Displacement preconditioner = geometric').
     */
    bool
    geometric_multigrid() const;

    /** The iterative solver's displacement preconditioner at its last setup (for the log). */
    std::string
    krylov_preconditioner() const;

    /** Krylov iterations of all solves so far, and the number of solves. */
    std::pair<unsigned long, unsigned long>
    krylov_iterations() const;

    /**
     * The LDL^T factorisations' operations (summed over all so far, made and at full rank), and
     * the largest factors' entries and MUMPS memory of any (zero without LDL^T).
     */
    FactorStatistics
    factor_statistics() const;

    /**
     * With 'Compression': the share of the full-rank operations and of the full-rank factors'
     * entries the block low-rank factorisations took (empty at full rank).
     */
    std::string
    compression_report() const;

    /**
     * With 'Precision = single': the refinement steps so far, or why the run went back to
     * double precision (empty in double precision throughout).
     */
    std::string
    precision_report() const;

    /** The shortest 'Krylov restart' accepted (restart 2 stalled on the §4.1 test scene, 5 did
     * not). */
    static constexpr unsigned int smallest_krylov_restart = 10;

  private:
    /**
     * x = K^{-1} b by the LDL^T factors; where single-precision factors cannot be refined to
     * SymmetricFactorization::refinement_acceptance, the matrix is factorised again in double
     * precision, which the run keeps.
     */
    void
    solve_ldlt(dealii::Vector<double>       &x,
               const dealii::Vector<double> &b,
               const double                  refinement_target) const;

    /** Count the last LDL^T factorisation's operations, entries and memory. */
    void
    add_factor_statistics(const FactorStatistics &factor) const;

    /** 'automatic': choose MUMPS or Krylov at the first factorisation of @p K. */
    void
    decide(const dealii::TrilinosWrappers::SparseMatrix &K) const;

    mutable std::string solver_type  = "Amesos_Mumps";
    bool                automatic    = false;
    mutable bool        decided      = true;
    double              memory_share = 0.5;
    // The fill-reducing ordering of MUMPS's LDL^T analyses.
    SymmetricFactorization::Ordering ordering = SymmetricFactorization::Ordering::fewest_flops;
    mutable std::string              choice;
    // The dropping threshold of MUMPS's block low-rank LDL^T (0: full rank).
    double                   compression = 0.;
    mutable FactorStatistics factor_totals;
    // The arithmetic of the LDL^T factors; double after a failed refinement (and why).
    mutable SymmetricFactorization::Precision precision =
      SymmetricFactorization::Precision::double_precision;
    mutable std::string                                   precision_fallback;
    mutable unsigned long                                 refinement_steps  = 0;
    mutable const dealii::TrilinosWrappers::SparseMatrix *factorized_matrix = nullptr;
    bool                                                  symmetric         = false;
    // The kept factorisation: a cache, so solve() stays const for its callers.
    mutable std::unique_ptr<Epetra_LinearProblem>   problem;
    mutable std::unique_ptr<Amesos_BaseSolver>      factorisation;
    mutable std::unique_ptr<SymmetricFactorization> ldlt;
    // The matrix the factorisation was analysed for (LDL^T path).
    mutable const Epetra_CrsMatrix *analysed_matrix             = nullptr;
    mutable bool                    factorized                  = false;
    mutable double                  factorized_dt               = 0.;
    mutable unsigned int            n_solves_with_factorization = 0;
    mutable bool                    call_failed                 = false;
    bool                            keep_values                 = false;
    mutable SparseEntries           factorized_entries;
    mutable unsigned int            symbolic_count = 0;
    mutable unsigned int            numeric_count  = 0;
    mutable BlockKrylov             krylov;
    BlockKrylov::Settings           krylov_settings;
    mutable unsigned long           n_krylov_iterations = 0, n_krylov_solves = 0;
  };
} // namespace GelMPM

#endif

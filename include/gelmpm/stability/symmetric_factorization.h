#ifndef gelmpm_stability_symmetric_factorization_h
#define gelmpm_stability_symmetric_factorization_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  /**
   * @brief The inertia (signature) of a symmetric matrix: the numbers of positive, negative and
   * zero eigenvalues (paper §3.6). A stable state of the u–mu problem has (n_u, n_mu, 0).
   */
  struct Inertia
  {
    unsigned int n_positive = 0;
    unsigned int n_negative = 0;
    unsigned int n_zero     = 0;

    bool
    operator==(const Inertia &other) const
    {
      return n_positive == other.n_positive && n_negative == other.n_negative &&
             n_zero == other.n_zero;
    }
  };


  /**
   * @brief What a factorisation took: its floating-point operations and the entries of its
   * factors, as made and as they would have been at full rank, and MUMPS's memory.
   */
  struct FactorStatistics
  {
    /** Operations of the factorisation made (RINFOG(14)), and at full rank (RINFOG(3)). */
    double flops           = 0.;
    double full_rank_flops = 0.;
    /** Entries of the factors kept (INFOG(35) compressed, INFOG(29) at full rank). */
    double entries           = 0.;
    double full_rank_entries = 0.;
    /** Bytes MUMPS used in the factorisation, all ranks (INFOG(22)). */
    double memory = 0.;
  };


  /**
   * @brief A single-precision factorisation whose iterative refinement did not reach
   * SymmetricFactorization::refinement_acceptance: refactorise in double precision.
   */
  class RefinementFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };


  /**
   * @brief Symmetric indefinite LDL^T factorisation K = L D L^T by MUMPS (SYM = 2), through its
   * C interface, giving the inertia of K and solves with K.
   *
   * By Sylvester's law of inertia, K and D have the same signature; MUMPS counts the negative
   * pivots of D (INFOG(12)) and, with null-pivot detection (ICNTL(24) = 1), the null pivots
   * (INFOG(28)). The root node is factorised sequentially (ICNTL(13) = 1) so that the
   * negative-pivot count includes it. Trilinos' Amesos_Mumps cannot be used for this: it factorises
   * as unsymmetric.
   *
   * Only the lower triangle of K is passed; K must be symmetric. Every stored entry is passed,
   * zero or not, so that matrices with one sparsity pattern share one analysis (refactorize()).
   *
   * MUMPS runs on the communicator of the first matrix factorised. On several ranks each rank
   * passes the rows it owns (MUMPS's distributed input) and the calls are collective: every
   * rank factorises and solves together, with the right-hand side taken from rank 0 and the
   * solution given to all (the Newton vectors are whole on every rank, doc/architecture.md).
   * INFOG, and with it the inertia, is global and the same on every rank.
   *
   * The fill-reducing ordering: on one rank, by default, both a nested dissection of the matrix
   * graph by METIS (METIS_NodeND) and MUMPS's own choice are analysed and the one with fewer
   * estimated flops is kept, where the factorisation is costly enough to repay the second
   * analysis (default_comparison_threshold). Debian's MUMPS has no METIS of its own; its choice is
   * approximate minimum fill (AMF), which on a compact 3D body takes about twice the flops of the
   * nested dissection and on a slender one about half (doc/performance.md, "The ordering of the
   * direct solver"). On several ranks MUMPS orders by itself.
   */
  class SymmetricFactorization
  {
  public:
    /** The fill-reducing ordering of the analysis. */
    enum class Ordering
    {
      /**
       * Both below analysed, the one with fewer estimated flops kept (the default), where the
       * factorisation with MUMPS's ordering takes at least the comparison threshold's flops per
       * stored entry (set_comparison_threshold()); below it, MUMPS's.
       */
      fewest_flops,
      /** METIS's nested dissection of the matrix graph (one rank; several: MUMPS's choice). */
      nested_dissection,
      /** MUMPS's own choice (ICNTL(7) = 7: AMF with Debian's MUMPS). */
      automatic
    };

    /** The arithmetic of the factors. */
    enum class Precision
    {
      double_precision,
      /**
       * MUMPS's single-precision arithmetic (SMUMPS): half the memory of the factors and faster
       * dense kernels; solve() refines its solutions in double precision against the matrix
       * factorised, to refinement_tolerance, and throws RefinementFailure if that stalls above
       * refinement_acceptance (condition numbers near 1/6e-8).
       */
      single_precision
    };

    /** Relative residual at which the single-precision refinement stops. */
    static constexpr double refinement_tolerance = 1e-13;
    /**
     * Relative residual below which a stalled refinement is accepted (Newton's iteration
     * corrects the rest); above it solve() throws RefinementFailure.
     */
    static constexpr double refinement_acceptance = 1e-9;

    /** Parse the name of an Ordering ("fewest flops", "nested dissection" or "MUMPS"). */
    static Ordering
    parse_ordering(const std::string &name);

    SymmetricFactorization();
    ~SymmetricFactorization();
    SymmetricFactorization(const SymmetricFactorization &) = delete;
    SymmetricFactorization &
    operator=(const SymmetricFactorization &) = delete;

    /**
     * Analyse and factorise @p K, or only its leading @p leading x @p leading block (e.g. the
     * displacement block K_uu of the u–mu tangent). Throws std::runtime_error when MUMPS reports
     * an error.
     */
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &K,
              const unsigned int leading = std::numeric_limits<unsigned int>::max());

    /**
     * MUMPS's estimate, in bytes, of the memory an in-core LDL^T factorisation of @p K would take
     * (INFOG(17), summed over the ranks), from its analysis alone: nothing is factorised. The
     * object keeps no factorisation afterwards.
     */
    double
    estimated_memory(const dealii::TrilinosWrappers::SparseMatrix &K);

    /**
     * Factorise @p K (the same leading block as the last factorize()) numerically with the
     * analysis of the last factorize(): @p K must have the sparsity pattern of the matrix
     * analysed then. The Newton iterations of a step share one pattern.
     */
    void
    refactorize(const dealii::TrilinosWrappers::SparseMatrix &K);

    /** The inertia of the matrix factorised last. */
    Inertia
    inertia() const;

    /**
     * Solve K x = b with the factorisation: @p x holds b on entry (rank 0's is used) and x on
     * exit (on every rank). Single-precision factors refine the solution to the relative
     * residual @p refinement_target (at least refinement_tolerance): a modified Newton iteration
     * that solves with the factors of an older tangent needs no more than a fraction of its
     * own contraction (LinearSolver::solve()).
     */
    void
    solve(dealii::Vector<double> &x, const double refinement_target = refinement_tolerance) const;

    /** Use @p ordering in the analyses from now on (the default: fewest flops). */
    void
    set_ordering(const Ordering ordering);

    /**
     * Ordering::fewest_flops makes its second analysis (METIS's nested dissection) only where the
     * first, MUMPS's, estimates at least default_comparison_threshold flops per stored entry of
     * the matrix (lower triangle). Measured on the 2D column of paper §4.3 (7,200 unknowns, 800
     * flops per entry): METIS and the second analysis take 60 ms, twice the factorisation they
     * could shorten; on the 3D cube (4,800-13,000 flops per entry) they take 0.2 s against
     * factorisations of 0.2-1 s that the nested dissection shortens by 20-33 %.
     */
    static constexpr double default_comparison_threshold = 2000.;

    /** Compare the orderings from @p flops_per_entry on (0: always; the default above). */
    void
    set_comparison_threshold(const double flops_per_entry);

    /**
     * Floating-point operations of the last numeric factorisation (RINFOG(3)): the measure of the
     * ordering's quality.
     */
    double
    factorization_flops() const;

    /**
     * Factorise with block low-rank compression from now on (MUMPS's BLR, ICNTL(35)): blocks of
     * the fronts are replaced by low-rank products wherever that drops less than
     * @p dropping_threshold (CNTL(7), relative to the matrix's norm); 0 (the default) factorises
     * at full rank. The factors are then those of a matrix within about that threshold of K:
     * solves are approximate (Newton's iteration corrects them) and the inertia is that of the
     * perturbed matrix, which equals K's wherever no eigenvalue of K lies within about the
     * threshold times its norm of zero. Takes effect at the next analysis (factorize()).
     */
    void
    set_compression(const double dropping_threshold);

    /** The dropping threshold of the block low-rank compression (0: full rank). */
    double
    compression() const;

    /** Operations, entries and memory of the last factorisation. */
    FactorStatistics
    statistics() const;

    /** Floating-point operations the last analysis estimated for the factorisation (RINFOG(1)). */
    double
    estimated_flops() const;

    /** The ordering of the last analysis, by name (INFOG(7): "nested dissection" when ours). */
    std::string
    ordering_used() const;

    /** Factorise in @p precision (before the first factorize(); the default: double). */
    void
    set_precision(const Precision precision);

    Precision
    precision() const;

    /** The refinement steps of the last solve (single precision; 0 otherwise). */
    unsigned int
    refinement_steps() const;

    /** Size of the factorised matrix. */
    unsigned int
    size() const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };
} // namespace GelMPM

#endif

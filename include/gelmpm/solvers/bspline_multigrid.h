#ifndef gelmpm_solvers_bspline_multigrid_h
#define gelmpm_solvers_bspline_multigrid_h

#include <gelmpm/bspline/nested_grids.h>
#include <gelmpm/stability/displacement_block_amg.h>

#include <deal.II/base/mg_level_object.h>
#include <deal.II/lac/relaxation_block.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/multigrid.h>

#include <memory>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Geometric multigrid for the displacement block A = K_uu on the nested B-spline grids
   * (NestedBSplineGrids): one cycle of deal.II's Multigrid is an approximation of A^{-1}.
   *
   * Level matrices by Galerkin products, A_{l+1} = P_l^T A_l P_l, with P_l the B-spline
   * prolongation of NestedBSplineLevel times the identity on the dim interleaved components; so
   * the coarse operators are those of the coarse B-splines restricted to the material, with no
   * coarse assembly and no coarse extension.
   *
   * Smoothing: multiplicative overlapping Schwarz on cell blocks (deal.II's RelaxationBlockSSOR;
   * the unknowns of the functions nonzero on a cell, NestedBSplineLevel::row_blocks), the same
   * number of forward-backward sweeps before and after the coarse correction. The blocks of the
   * cells with even indices overlap by one function per direction: each unknown is in about
   * (3/2)^dim blocks, against (q+1)^dim with every cell, and a sweep costs that many products
   * with A's rows (on the cube at 20^3 both gave 26.3 iterations per solve, the even cells in
   * 40 % less time). Point Gauss-Seidel is the
   * alternative (Settings::cell_blocks = false), but it leaves the error that the Nitsche
   * penalty and the extrapolation of the boundary control points couple across a boundary cell:
   * on §4.1 at 40 x 320 cells the two-grid cycle contracted the error by 0.96 per cycle with two
   * symmetric Gauss-Seidel sweeps, with the slowest error in u_x next to the Nitsche boundary
   * x = 0.2, and by 0.03 with two sweeps of cell blocks (0.12 with one).
   *
   * The coarsest level is factorised (UMFPACK) when it has at most Settings::direct_coarse_size
   * unknowns, else approximated by ML's smoothed aggregation (DisplacementBlockAMG, with the
   * coarse functions' Greville points for the rigid-body modes). Coarsening stops at the first
   * level small enough for the direct solve.
   *
   * Serial: on several MPI ranks BlockKrylov uses the algebraic multigrid instead.
   */
  class BSplineMultigrid
  {
  public:
    /** The cycle's settings. */
    struct Settings
    {
      /** Smoother sweeps before and after each coarse correction. */
      unsigned int smoothing_steps = 1;
      /** The largest coarsest level solved by a direct factorisation. */
      unsigned int direct_coarse_size = 20000;
      /** W-cycle instead of V-cycle. */
      bool w_cycle = false;
      /**
       * Smoother: multiplicative overlapping Schwarz on cell blocks (per cell with material, the
       * unknowns of the functions nonzero on it: NestedBSplineLevel::row_blocks) if true, else
       * point symmetric Gauss-Seidel.
       */
      bool cell_blocks = true;
    };

    BSplineMultigrid();
    ~BSplineMultigrid();

    /**
     * Copy the leading @p n_u x @p n_u block of @p K (@p dim interleaved components per DoF) and
     * build the hierarchy on @p levels (finest first; the first one's prolongation has one row
     * per displacement DoF). Throws std::runtime_error when the coarsest level cannot be
     * factorised.
     */
    void
    setup(const dealii::TrilinosWrappers::SparseMatrix &K,
          const unsigned int                            n_u,
          const unsigned int                            dim,
          const std::vector<NestedBSplineLevel>        &levels,
          const Settings                               &settings);

    /** Release the hierarchy. */
    void
    clear();

    /** One cycle from a zero initial guess: dst ~ A^{-1} src. */
    void
    vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const;

    /** Unknowns per level, finest first (for the log and tests). */
    std::vector<unsigned int>
    level_sizes() const;

    /** Whether the coarsest level is factorised (else ML's AMG). */
    bool
    direct_coarse_solve() const;

  private:
    /** The transfer between consecutive levels by the prolongation matrices. */
    class Transfer;
    /** The coarsest level's solve. */
    class CoarseSolve;

    using Smoother = dealii::MGSmootherPrecondition<dealii::TrilinosWrappers::SparseMatrix,
                                                    dealii::TrilinosWrappers::PreconditionSSOR,
                                                    dealii::Vector<double>>;

    using BlockRelaxation =
      dealii::RelaxationBlockSSOR<dealii::SparseMatrix<double>, double, dealii::Vector<double>>;
    using BlockSmoother = dealii::mg::SmootherRelaxation<BlockRelaxation, dealii::Vector<double>>;

    /** The cell-block smoother on the levels above the coarsest. */
    std::unique_ptr<dealii::MGSmootherBase<dealii::Vector<double>>>
    block_smoother(const std::vector<NestedBSplineLevel> &levels,
                   const unsigned int                     dim,
                   const Settings                        &settings);

    // deal.II's numbering: level 0 the coarsest, the last one A.
    dealii::MGLevelObject<dealii::TrilinosWrappers::SparseMatrix> matrices;
    // prolongations[l]: from level l to level l + 1.
    std::vector<std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>> prolongations;
    // The cell-block smoother's copies of the level matrices and its blocks.
    dealii::MGLevelObject<dealii::SparsityPattern>         block_patterns;
    dealii::MGLevelObject<dealii::SparseMatrix<double>>    block_matrices;
    dealii::MGLevelObject<BlockRelaxation::AdditionalData> block_data;
    dealii::SparsityPattern                                coarse_pattern;
    dealii::SparseMatrix<double>                           coarse_matrix;
    dealii::SparseDirectUMFPACK                            coarse_direct;
    DisplacementBlockAMG                                   coarse_amg;
    bool                                                   direct = true;

    std::unique_ptr<dealii::mg::Matrix<dealii::Vector<double>>>        level_matrices;
    std::unique_ptr<Transfer>                                          transfer;
    std::unique_ptr<CoarseSolve>                                       coarse;
    std::unique_ptr<dealii::MGSmootherBase<dealii::Vector<double>>>    smoother;
    mutable std::unique_ptr<dealii::Multigrid<dealii::Vector<double>>> multigrid;
  };
} // namespace GelMPM

#endif

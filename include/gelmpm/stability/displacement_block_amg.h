#ifndef gelmpm_stability_displacement_block_amg_h
#define gelmpm_stability_displacement_block_amg_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace GelMPM
{
  /**
   * Copy the block of @p K with rows in [@p row_begin, @p row_end) and columns in
   * [@p column_begin, @p column_end) into @p M, its indices shifted to start at zero. @p M is
   * distributed like @p K: each rank copies the rows of the block it owns, and the block's
   * domain is the part of @p K's domain partition in the column range. Two passes (pattern,
   * then values), so that no second copy of the entries is held on the way.
   */
  void
  copy_block(const dealii::TrilinosWrappers::SparseMatrix &K,
             const unsigned int                            row_begin,
             const unsigned int                            row_end,
             const unsigned int                            column_begin,
             const unsigned int                            column_end,
             dealii::TrilinosWrappers::SparseMatrix       &M);


  /** copy_block() of the leading @p n_u x @p n_u block of @p K. */
  void
  copy_leading_block(const dealii::TrilinosWrappers::SparseMatrix &K,
                     const unsigned int                            n_u,
                     dealii::TrilinosWrappers::SparseMatrix       &A);


  /**
   * @brief The displacement block A = K_uu of the u–mu tangent, copied out of it, and smoothed
   * aggregation algebraic multigrid (Trilinos ML) on A, given the rigid-body modes.
   *
   * Shared by the iterative Newton solver (BlockKrylov: the (1,1) block of its preconditioner) and
   * the iterative stability analysis (smallest_drained_eigenvalues(): the preconditioner of
   * LOBPCG), so that both use one setup. ML's settings: symmetric Gauss-Seidel smoothing (2
   * sweeps), aggregation threshold 0.02, KLU on a coarse level of at most 2000 unknowns, and the
   * dim translations and dim(dim-1)/2 rotations about the points' centroid as the null space.
   *
   * Distributed like the tangent: each rank copies the rows of A it owns (all dim components of
   * a DoF are owned together, as ML's 'PDE equations' needs).
   */
  class DisplacementBlockAMG
  {
  public:
    /**
     * Copy the leading @p n_u x @p n_u block of @p K (displacement unknowns first, @p dim
     * interleaved components per DoF) and build the AMG hierarchy of it. @p u_dof_points: per
     * displacement unknown, the coordinate of its component's direction at its DoF's point (the
     * Greville point), dim per DoF: the linear field that gives the rigid-body modes.
     */
    void
    setup(const dealii::TrilinosWrappers::SparseMatrix &K,
          const unsigned int                            n_u,
          const unsigned int                            dim,
          const std::vector<double>                    &u_dof_points);

    /** Release the hierarchy and the block (they refer to one another). */
    void
    clear();

    /** The block A = K_uu of the last setup(). */
    const dealii::TrilinosWrappers::SparseMatrix &
    matrix() const;

    /** The AMG of A: its vmult() applies an approximation of A^{-1}. */
    const dealii::TrilinosWrappers::PreconditionAMG &
    preconditioner() const;

  private:
    dealii::TrilinosWrappers::SparseMatrix    A;
    dealii::TrilinosWrappers::PreconditionAMG amg;
    // The rigid-body modes, column by column; ML reads them while it builds the hierarchy.
    std::vector<double> modes;
  };
} // namespace GelMPM

#endif

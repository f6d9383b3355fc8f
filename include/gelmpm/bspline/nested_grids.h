#ifndef gelmpm_bspline_nested_grids_h
#define gelmpm_bspline_nested_grids_h

#include <gelmpm/bspline/bspline_space.h>
#include <gelmpm/bspline/extended_bspline_space.h>
#include <gelmpm/core/sparse_entries.h>

#include <deal.II/lac/full_matrix.h>

#include <memory>
#include <vector>

namespace GelMPM
{
  /**
   * @brief One coarse level of the nested B-spline grids below the displacement space: the
   * B-splines of cell size 2^l h that take part, and how they are written in the level above.
   */
  struct NestedBSplineLevel
  {
    /** Cells per direction of this level's grid. */
    std::vector<unsigned int> n_cells;
    /**
     * The functions of this level's BSplineSpace that take part (increasing index): those with a
     * nonzero coefficient on some function of the level above. Column k of the prolongation is
     * control_points[k].
     */
    std::vector<unsigned int> control_points;
    /** Per function, its Greville point (dim coordinates): the coefficients of a linear field. */
    std::vector<double> greville_points;
    /**
     * The prolongation, scalar (one component): rows the functions of the level above (for the
     * first coarse level the DoFs of the extended space), columns this level's functions.
     * Applied to the coefficients of a field of this level it gives the coefficients of the same
     * field in the level above, wherever the level above holds all the B-splines that are
     * nonzero there.
     */
    SparseEntries prolongation;
    /** Rows of the prolongation. */
    unsigned int n_rows = 0;
    /**
     * Blocks for a smoother on the level above (the rows), as row indices: per cell of that
     * level's grid that holds material whose indices are all even, the functions that are
     * nonzero on it (on the finest grid the DoFs among the cell's B-splines), then per other
     * cell whose functions are not all in a block yet, its functions: blocks that cover every
     * function and overlap by one function per direction.
     */
    std::vector<std::vector<unsigned int>> row_blocks;
  };


  /**
   * @brief The grids of cell size 2h, 4h, ... over the box of a BSplineSpace of cell size h, and
   * the prolongations between their B-spline spaces that a geometric multigrid on the DoFs of an
   * extended space needs.
   *
   * The two-scale relation N_coarse = S N_fine (refinement_operator_1d(), exact at the open ends
   * too) holds direction by direction, so the tensor-product functions of the 2h grid are the
   * tensor product of the 1D operators applied to those of the h grid. The first prolongation
   * keeps the rows of the DoFs of the extended space, P_iI = S_Ii for DoF i, and drops the coarse
   * functions whose column is then empty. On an interior cell, where every B-spline that is
   * nonzero is a DoF and its extended function is the B-spline itself, P reproduces each coarse
   * function exactly; on a boundary cell P differs from the coarse function by what the
   * extrapolation of the boundary control points misses (nothing for a polynomial of degree q).
   * Coarser levels restrict S to the functions kept on the level above, which gives the same
   * composition as restricting the product of the operators.
   *
   * The grids are fixed for a run, the DoFs change with the material: the 1D operators are
   * computed once (construction), the prolongations per set of DoFs (levels()).
   */
  template <int dim>
  class NestedBSplineGrids
  {
  public:
    /**
     * The grids below @p space while every direction has an even number of cells and the
     * coarser grid keeps at least q + 1 cells per direction, at most @p max_levels of them.
     */
    NestedBSplineGrids(const BSplineSpace<dim> &space, const unsigned int max_levels = 10);

    /** The space of cell size h the grids are made from. */
    const BSplineSpace<dim> &
    fine_space() const;

    /** Number of coarse grids. */
    unsigned int
    n_levels() const;

    /** The B-spline space of coarse grid @p level (1: cell size 2h, ...). */
    const BSplineSpace<dim> &
    space(const unsigned int level) const;

    /**
     * The coarse levels for the DoFs of @p u (an extended space of the space this was made
     * from), finest first. A level whose functions are no fewer than those of the level above
     * ends the list: the body is too small on it to coarsen further.
     */
    std::vector<NestedBSplineLevel>
    levels(const ExtendedBSplineSpace<dim> &u) const;

  private:
    /**
     * The coarse level below the functions @p fine_functions (control points of the space of
     * level @p level - 1, increasing) of that space.
     */
    NestedBSplineLevel
    coarsen(const unsigned int level, const std::vector<unsigned int> &fine_functions) const;

    /**
     * Per cell of the grid of @p level (0: the finest) in @p cells, the functions of
     * @p functions (control points of that level, increasing) that are nonzero on it, as
     * positions in @p functions.
     */
    std::vector<std::vector<unsigned int>>
    cell_blocks(const unsigned int               level,
                const std::vector<unsigned int> &cells,
                const std::vector<unsigned int> &functions) const;

    const BSplineSpace<dim>                        &finest;
    std::vector<std::unique_ptr<BSplineSpace<dim>>> spaces;
    /**
     * Per coarse level and direction, for each function of the finer 1D basis, the nonzero
     * entries (coarse function, S value) of its column of the refinement operator.
     */
    std::vector<std::vector<std::vector<std::vector<std::pair<unsigned int, double>>>>> parents;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_bspline_hierarchical_bspline_space_h
#define gelmpm_bspline_hierarchical_bspline_space_h

#include <gelmpm/bspline/bspline_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Truncated hierarchical B-splines (THB-splines, Giannelli, Jüttler & Speleers, CAGD 29,
   * 2012) of degree q, maximally smooth, on dyadically refined uniform grids of one box.
   *
   * **Levels.** Level l is the BSplineSpace of degree q over the box with 2^l n_cells[d] cells
   * in direction d (level 0 is the base grid). The domains Ω^0 ⊇ Ω^1 ⊇ ... ⊇ Ω^{L-1} are given
   * by the cells that are refined: refined_cells[l] lists cells of level l, and Ω^{l+1} is their
   * union; Ω^0 is the whole box. Each refined cell of level l >= 1 must lie in Ω^l (its parent
   * is refined), so the domains are nested and Ω^{l+1} is a union of cells of level l, which is
   * what the two-scale relation needs. The *leaf cells* (active cells) are the cells of level l
   * in Ω^l that are not refined; they tile the box.
   *
   * **Active functions (Kraft's selection).** A B-spline of level l is active when its support
   * lies in Ω^l and not in Ω^{l+1} (support = the closed cells of level l on which it is
   * nonzero). Every active function is identified by (level, index in that level's space).
   *
   * **Truncation.** An active function β of level l is replaced by Trunc β =
   * trunc^{L-1}(... trunc^{l+1}(β)): trunc^{k} writes a function of level k-1 in the B-splines of
   * level k by the two-scale relation N^{k-1} = S N^{k} (refinement_operator_1d(), direction by
   * direction, the same operator as the one of NestedBSplineGrids) and drops the coefficients
   * of the level-k B-splines whose support lies in Ω^k. Since the entries of S are nonnegative,
   * the truncated functions are nonnegative; with Ω^0 the whole box they sum to one; they span
   * the same space as the hierarchical (Kraft) basis, which contains the polynomials of degree q
   * and the B-splines of every level on their domains, and are linearly independent; each is a
   * combination of B-splines of the finest level and therefore C^{q-1}. Their supports are
   * those of HB or smaller: the truncation removes the part of a coarse function that the
   * finer functions already represent.
   *
   * **Evaluation.** On a leaf cell Q of level m, every truncated function that is nonzero on Q
   * is a combination of the (q+1)^dim B-splines of level m on Q: the truncations at levels
   * above m keep every B-spline of level m+1 over Q, since Q is not refined. The constructor
   * computes, per leaf cell, these functions and the small dense matrix of their coefficients
   * (leaf_functions(), leaf_coefficients()); evaluate() is then the level's tensor-product
   * evaluation and a product with that matrix, as ExtendedBSplineSpace does with its extension
   * matrices. A coefficient vector of level k is carried down to level k+1 only through the
   * B-splines that reach a refined cell of level k: the others are not truncated further and no
   * leaf cell finer than k lies in their support.
   *
   * The grids and domains are fixed for the object's life: a new refinement is a new object.
   */
  template <int dim>
  class HierarchicalBSplineSpace
  {
  public:
    /** A B-spline of one level: the level and its index in that level's BSplineSpace. */
    struct LevelFunction
    {
      unsigned int level;
      unsigned int index;
    };
    /** A cell of one level: the level and its index in that level's BSplineSpace. */
    struct LevelCell
    {
      unsigned int level;
      unsigned int cell;
    };

    /**
     * @param refined_cells refined_cells[l] = the cells of level l that are refined (Ω^{l+1}
     * as cells of level l), in any order; there are refined_cells.size() + 1 levels (an empty
     * last list is allowed and adds a level without functions).
     * Throws std::invalid_argument when a refined cell of level l >= 1 does not lie in Ω^l, or a
     * cell index is out of range.
     */
    HierarchicalBSplineSpace(const unsigned int                            degree,
                             const dealii::Point<dim>                     &lower,
                             const dealii::Point<dim>                     &upper,
                             const std::array<unsigned int, dim>          &n_cells,
                             const std::vector<std::vector<unsigned int>> &refined_cells);

    unsigned int
    degree() const;
    /** Levels (the base grid and its refinements): refined_cells.size() + 1. */
    unsigned int
    n_levels() const;
    /** The tensor-product B-splines of level @p level (cell size 2^-level of the base grid's). */
    const BSplineSpace<dim> &
    level_space(const unsigned int level) const;
    /** Whether cell @p cell of level @p level lies in Ω^level. */
    bool
    in_domain(const unsigned int level, const unsigned int cell) const;
    /** Whether cell @p cell of level @p level is refined (lies in Ω^{level+1}). */
    bool
    is_refined(const unsigned int level, const unsigned int cell) const;
    /** Per level but the last, its refined cells (increasing index): the constructor's input. */
    std::vector<std::vector<unsigned int>>
    refined_cells() const;

    unsigned int
    n_active_functions() const;
    /** Active function @p i: active functions are numbered level by level, index increasing. */
    const LevelFunction &
    active_function(const unsigned int i) const;
    /** The number of B-spline @p index of level @p level, or invalid_unsigned_int if inactive. */
    unsigned int
    active_function_number(const unsigned int level, const unsigned int index) const;

    /** Leaf cells, level by level, cell index increasing. */
    unsigned int
    n_leaf_cells() const;
    const LevelCell &
    leaf_cell(const unsigned int leaf) const;
    /**
     * The leaf cell holding @p p (on a cell face, the cell a BSplineSpace of its level picks).
     * Throws std::out_of_range outside the box.
     */
    unsigned int
    leaf_cell_containing(const dealii::Point<dim> &p) const;

    /** The active functions nonzero on leaf cell @p leaf (numbers, increasing). */
    const std::vector<unsigned int> &
    leaf_functions(const unsigned int leaf) const;
    /**
     * Row a: the coefficients of truncated function leaf_functions(leaf)[a] on the cell in the
     * (q+1)^dim B-splines of the cell's level, in the order of BSplineSpace::cell_functions().
     */
    const dealii::FullMatrix<double> &
    leaf_coefficients(const unsigned int leaf) const;

    /**
     * Values and gradients at @p p (in the closure of @p leaf) of the truncated functions
     * leaf_functions(@p leaf); @p values and @p gradients are resized to their number. Does not
     * allocate once the vectors (and a per-thread scratch space) have their size.
     */
    void
    evaluate(const dealii::Point<dim>            &p,
             const unsigned int                   leaf,
             std::vector<double>                 &values,
             std::vector<dealii::Tensor<1, dim>> &gradients) const;

    /**
     * The truncated function @p i written in the B-splines of the finest level, as pairs
     * (index, coefficient) with increasing index and nonzero coefficient. Costs the whole
     * chain of two-scale relations: for tests and output, not for assembly.
     */
    std::vector<std::pair<unsigned int, double>>
    finest_level_coefficients(const unsigned int i) const;

  private:
    /** The level-@p level cells in the support of B-spline @p index of that level. */
    std::vector<unsigned int>
    support_cells(const unsigned int level, const unsigned int index) const;
    /** Whether all of @p cells (of level @p level) satisfy @p flags[level]. */
    bool
    all_flagged(const std::vector<std::vector<bool>> &flags,
                const unsigned int                    level,
                const std::vector<unsigned int>      &cells) const;
    /**
     * The coefficients in the B-splines of level @p level + 1 of the function with coefficients
     * @p coarse of level @p level, with the B-splines whose support lies in Ω^{level+1} dropped.
     */
    std::vector<std::pair<unsigned int, double>>
    truncate_to_next_level(const unsigned int                                  level,
                           const std::vector<std::pair<unsigned int, double>> &coarse) const;
    /** Whether the support of B-spline @p index of level @p level meets a refined cell. */
    bool
    reaches_refined_cell(const unsigned int level, const unsigned int index) const;

    void
    mark_domains(const std::vector<std::vector<unsigned int>> &refined_cells);
    void
    select_active_functions();
    void
    number_leaf_cells();
    void
    build_leaf_coefficients();

    unsigned int                                    degree_;
    std::vector<std::unique_ptr<BSplineSpace<dim>>> spaces;
    /** Per level and cell: in Ω^level; refined (in Ω^{level+1}). */
    std::vector<std::vector<bool>> domain, refined;
    /**
     * Per level l < L-1 and direction, per B-spline I of level l, the nonzero entries (j, S_Ij)
     * of its row of the two-scale relation to level l+1.
     */
    std::vector<std::vector<std::vector<std::vector<std::pair<unsigned int, double>>>>> children;

    std::vector<LevelFunction>              active;
    std::vector<std::vector<unsigned int>>  active_number; // per level, per B-spline
    std::vector<LevelCell>                  leaves;
    std::vector<std::vector<unsigned int>>  leaf_number; // per level, per cell
    std::vector<std::vector<unsigned int>>  functions_of_leaf;
    std::vector<dealii::FullMatrix<double>> coefficients_of_leaf;
    /**
     * The same coefficients in compressed rows, for evaluate(): most rows of a leaf cell are a
     * single B-spline of its level with weight 1.
     */
    struct CompressedRows
    {
      std::vector<unsigned int> row_start;
      std::vector<unsigned int> column;
      std::vector<double>       weight;
    };
    std::vector<CompressedRows> compressed_coefficients;
  };


  /**
   * The refined cells (constructor argument) of the displacement space of a subdivision pair
   * whose chemical-potential space is @p mu: the same domains Ω^l on grids of half the cell size
   * (2 n_cells per direction at level 0), that is, per level l the 2^dim cells of u's level-l
   * grid inside each refined cell of μ's level-l grid. On every leaf cell of u of level l, the
   * leaf cell of μ that holds it has the same level and twice its size: μ stays one level coarser
   * than u everywhere, as on the uniform grid.
   */
  template <int dim>
  std::vector<std::vector<unsigned int>>
  subdivision_refinement(const HierarchicalBSplineSpace<dim> &mu);
} // namespace GelMPM

#endif

#ifndef gelmpm_bspline_extended_bspline_space_h
#define gelmpm_bspline_extended_bspline_space_h

#include <gelmpm/bspline/bspline_space.h>
#include <gelmpm/bspline/hierarchical_bspline_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <utility>
#include <vector>

namespace GelMPM
{
  /** Classification of background cells (paper §3.5). */
  enum class CellKind : unsigned char
  {
    interior = 0,
    boundary = 1,
    outer    = 2
  };

  /** Classification of control points (paper §3.5). */
  enum class ControlPointKind : unsigned char
  {
    interior = 0,
    boundary = 1,
    outer    = 2
  };


  /**
   * @brief Extended B-splines (paper §3.5, eq. (50)–(54)) of a BSplineSpace on the cells that
   * hold material.
   *
   * Cells: *outer* without material; *boundary* with material and at least one outer cell among
   * its 3^dim - 1 neighbours (faces, edges and corners; cells beyond the edge of the grid do not
   * count, since the open knot vector already ends the basis there without a cut); *interior*
   * otherwise. Control points: *interior* if the support of their function contains an interior
   * cell, *boundary* if it contains a boundary cell but no interior one, *outer* otherwise.
   *
   * The unknowns (DoFs) are the interior control points, numbered in increasing control-point
   * index. Each boundary control point k is extrapolated from a block I_k of (q+1)^dim interior
   * control points by tensor-product Lagrange weights E_ik (eq. (54)). The block is the one
   * *nearest* to k: smallest Euclidean index distance from k to the block (0 in a direction where
   * k lies within the block's range); ties are broken by the distance from k to the block centre,
   * then by the lexicographically smallest lower corner (x fastest), so the choice is
   * deterministic — at a corner this prefers the block diagonally adjacent to k over a shifted one
   * only when it is strictly closer. The extended functions are
   * Ñ_i = N_i + sum_{k: i in I_k} E_ik N_k (eq. (53)).
   *
   * With the extension switched off, every non-outer control point is a DoF (the plain B-spline
   * basis on the active cells), for comparison studies.
   *
   * Per active cell, the DoFs its extended functions touch and the matrix E_cell that maps the
   * cell's (q+1)^dim B-spline values to them are computed once at construction; evaluation is a
   * small dense product.
   */
  template <int dim>
  class ExtendedBSplineSpace
  {
  public:
    /**
     * @param cell_has_material One flag per cell of @p space.
     * @param exact_extrapolation_required Whether a boundary control point whose extrapolation
     * crosses the first or last q cells of the grid (where the B-spline coefficients of a
     * polynomial are not polynomials of the index, so the extrapolation is not exact) is an
     * error. A run whose body has moved next to the grid's edge (a pore closing on a plane of
     * symmetry) accepts them: counted by n_inexact_extrapolations().
     * Throws std::runtime_error when some boundary control point has no block of interior control
     * points (the body is thinner than q+1 interior cells somewhere), or, if required, when an
     * extrapolation is not exact.
     */
    ExtendedBSplineSpace(const BSplineSpace<dim> &space,
                         const std::vector<bool> &cell_has_material,
                         const bool               use_extension                = true,
                         const bool               exact_extrapolation_required = true);

    /**
     * The extended basis on a locally refined grid: the truncated hierarchical B-splines of
     * @p hierarchy, whose level 0 is the grid of the cells (cells stay level-0 cells: a refined
     * cell's DoFs are those of all its leaf cells, and evaluate() finds the leaf). The level-0
     * cells are classified as on the uniform grid (cell_kind()). The leaf cells are classified
     * on their own level: interior when they and all their neighbours of that level hold
     * material (a neighbour outside the level's refined domain is part of a coarser leaf, whose
     * flag it takes), boundary when they hold material next to one that does not. An active
     * function is interior when it is nonzero on an interior leaf, boundary when nonzero only on
     * boundary leaves with material. Interior functions are DoFs; with the extension, a boundary
     * function of level l is extrapolated from the nearest block of (q+1)^dim interior active
     * functions of level l, by the weights of eq. (54) in the indices of level l. This is exact
     * for polynomials of degree q, since a THB coefficient of a polynomial is the B-spline
     * coefficient of the function's level (preservation of coefficients). It needs such a block
     * at every level that meets the boundary: a refined region that reaches the body's boundary
     * must reach at least 2(q+1) cells of its finest level into the body; otherwise the
     * constructor throws std::runtime_error. Without the extension every boundary function is a
     * DoF (plain B-splines at every level). In this mode a "control point" i of
     * dof_of_control_point(), control_point_kind() and extrapolation_weights() is active function
     * i of @p hierarchy.
     */
    ExtendedBSplineSpace(const HierarchicalBSplineSpace<dim> &hierarchy,
                         const std::vector<bool>             &cell_has_material,
                         const std::vector<bool>             &leaf_has_material,
                         const bool                           use_extension,
                         const bool                           exact_extrapolation_required);

    /**
     * Number of control points: of the B-spline space, or of active functions of the hierarchy.
     */
    unsigned int
    n_control_points() const;

    /** Boundary control points extrapolated inexactly (0 unless allowed by the constructor). */
    unsigned int
    n_inexact_extrapolations() const;

    const BSplineSpace<dim> &
    space() const;
    CellKind
    cell_kind(const unsigned int cell) const;
    ControlPointKind
    control_point_kind(const unsigned int i) const;
    unsigned int
    n_dofs() const;
    /** DoF of control point @p i, or numbers::invalid_unsigned_int if it is not a DoF. */
    unsigned int
    dof_of_control_point(const unsigned int i) const;

    /** DoFs touched by the extended functions of a non-outer @p cell (sorted). */
    const std::vector<unsigned int> &
    cell_dofs(const unsigned int cell) const;

    /**
     * Values and gradients at @p p of the extended functions of cell_dofs(@p cell). @p values and
     * @p gradients must have cell_dofs(cell).size() entries, the scratch vectors
     * functions_per_cell() entries. No allocation.
     */
    void
    evaluate(const dealii::Point<dim>            &p,
             const unsigned int                   cell,
             std::vector<double>                 &values,
             std::vector<dealii::Tensor<1, dim>> &gradients,
             std::vector<double>                 &scratch_values,
             std::vector<dealii::Tensor<1, dim>> &scratch_gradients) const;

    /**
     * The leaf cells of @p cell on a refined grid are its *pieces* (one piece, the cell itself,
     * on a uniform grid): points in one piece share the functions that are nonzero on it, fewer
     * than the whole cell's on a refined cell. Assembly and sparsity patterns go by pieces.
     */
    unsigned int
    n_pieces(const unsigned int cell) const;
    /** The piece of @p cell nearest to @p p (p clamped into the cell); 0 on a uniform grid. */
    unsigned int
    piece_containing(const dealii::Point<dim> &p, const unsigned int cell) const;
    /** Whether the space is built over a refined grid (a hierarchy). */
    bool
    refined() const;
    /** The finest level of the leaf cells of @p cell (0 on a uniform grid). */
    unsigned int
    finest_level(const unsigned int cell) const;
    /** The leaf cell of the hierarchy that is piece @p piece of @p cell (refined grid only). */
    unsigned int
    leaf_of_piece(const unsigned int cell, const unsigned int piece) const;
    /** The DoFs whose extended functions are nonzero on piece @p piece of @p cell (sorted). */
    const std::vector<unsigned int> &
    cell_dofs(const unsigned int cell, const unsigned int piece) const;
    /**
     * Values and gradients at @p p (in the closure of the piece) of the extended functions of
     * cell_dofs(@p cell, @p piece); sizes as for evaluate() above with that list.
     */
    void
    evaluate(const dealii::Point<dim>            &p,
             const unsigned int                   cell,
             const unsigned int                   piece,
             std::vector<double>                 &values,
             std::vector<dealii::Tensor<1, dim>> &gradients,
             std::vector<double>                 &scratch_values,
             std::vector<dealii::Tensor<1, dim>> &scratch_gradients) const;

    /** The weights (interior control point i, E_ik) of boundary control point @p k. */
    const std::vector<std::pair<unsigned int, double>> &
    extrapolation_weights(const unsigned int k) const;

  private:
    void
    classify_cells(const std::vector<bool> &cell_has_material);
    void
    classify_control_points();
    void
    compute_extrapolation_weights();
    void
    build_cell_matrices();
    /**
     * The (q+1)^dim blocks of @p space all of whose functions are @p interior, flagged by the
     * index of their lower corner.
     */
    std::vector<bool>
    interior_blocks(const BSplineSpace<dim> &space, const std::vector<bool> &interior) const;
    /**
     * The weights (function of @p space, E_ik) that extrapolate function @p k from the nearest
     * block of interior functions (@p block_ok from interior_blocks()); @p level only names the
     * refinement level in messages. Throws as the constructors say.
     */
    std::vector<std::pair<unsigned int, double>>
    extrapolation_weights_from_nearest_block(const BSplineSpace<dim> &space,
                                             const std::vector<bool> &block_ok,
                                             const unsigned int       k,
                                             const unsigned int       level);
    /**
     * Per level of the hierarchy and cell of that level, whether it holds material: a leaf as
     * given, a refined cell when one of its leaves does, a cell outside its level's domain when
     * the coarser leaf it lies in does.
     */
    std::vector<std::vector<bool>>
    material_per_level(const std::vector<bool> &leaf_has_material) const;
    /**
     * The kinds of the active functions: interior when nonzero on an interior leaf cell (a leaf
     * with material whose neighbours of its level all hold material), boundary when nonzero on
     * a leaf with material only at boundary leaves, outer otherwise.
     */
    void
    classify_active_functions(const std::vector<bool> &leaf_has_material);
    void
    number_hierarchical_dofs();
    void
    build_leaf_matrices();

    const BSplineSpace<dim>                                  &space_;
    bool                                                      use_extension;
    bool                                                      exact_extrapolation_required;
    unsigned int                                              n_inexact = 0;
    std::vector<CellKind>                                     cell_kinds;
    std::vector<ControlPointKind>                             point_kinds;
    std::vector<unsigned int>                                 dof_index;
    unsigned int                                              n_dofs_ = 0;
    std::vector<std::vector<std::pair<unsigned int, double>>> weights;
    std::vector<std::vector<unsigned int>>                    dofs_of_cell;
    /**
     * E_cell in compressed rows: most rows of a cell are a single B-spline (weight 1), so the
     * dense product would spend its time on zeros.
     */
    struct CellMatrix
    {
      std::vector<unsigned int> row_start;
      std::vector<unsigned int> column;
      std::vector<double>       weight;
    };
    /** The product of the (q+1)^dim B-spline values and gradients with @p E, row by row. */
    static void
                            apply(const CellMatrix                          &E,
                                  const std::vector<double>                 &scratch_values,
                                  const std::vector<dealii::Tensor<1, dim>> &scratch_gradients,
                                  std::vector<double>                       &values,
                                  std::vector<dealii::Tensor<1, dim>>       &gradients);
    std::vector<CellMatrix> matrix_of_cell;

    /** The refinement, or nullptr on the uniform grid. */
    const HierarchicalBSplineSpace<dim> *hierarchy = nullptr;
    /** Per active function of the hierarchy: its DoF, kind and extrapolation weights. */
    std::vector<unsigned int>                                 function_dof;
    std::vector<ControlPointKind>                             function_kinds;
    std::vector<std::vector<std::pair<unsigned int, double>>> function_weights;
    /**
     * Per cell, its leaf cells and, per leaf, its DoFs, E in compressed rows (one row per DoF of
     * the leaf) and the positions of the leaf's DoFs in cell_dofs(cell).
     */
    std::vector<std::vector<unsigned int>>              leaves_of_cell;
    std::vector<std::vector<std::vector<unsigned int>>> leaf_dofs_of_cell;
    std::vector<std::vector<CellMatrix>>                leaf_matrices_of_cell;
    std::vector<std::vector<std::vector<unsigned int>>> leaf_rows_in_cell;
    /** Per leaf cell, its position in leaves_of_cell of its level-0 ancestor. */
    std::vector<unsigned int> piece_of_leaf;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_background_grid_h
#define gelmpm_scene_background_grid_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Background grid" section: the fixed Cartesian grid [lower, upper] with n_cells[d]
   * cells per direction that carries the displacement field (cell size h_u). The
   * chemical-potential grid is the same or twice as coarse (see DiscretisationSettings).
   */
  template <int dim>
  struct BackgroundGrid
  {
    dealii::Point<dim>            lower;
    dealii::Point<dim>            upper;
    std::array<unsigned int, dim> n_cells;
    /**
     * 'Coordinate system = axisymmetric' (2D only): x is the radius R >= 0, y the axis z, and the
     * scene is the meridian plane of a body of revolution (doc/axisymmetric.md). The grid's lower
     * x edge is then the axis R = 0.
     */
    bool axisymmetric = false;
    /**
     * 'Refinement boxes' and 'Refinement levels' (doc/architecture.md, "Local refinement"): the
     * grid is refined 'Refinement levels' times where it overlaps one of these boxes. The marking
     * is made on the grid of pairs of cells (cell size 2h, the chemical potential's with
     * subdivision): at level l, a cell of size 2h / 2^l is refined when it overlaps a box. None
     * by default.
     */
    std::vector<std::pair<dealii::Point<dim>, dealii::Point<dim>>> refinement_boxes;
    unsigned int                                                   refinement_levels = 0;
    /**
     * 'Refinement region': an expression in x, y (, z) of the initial configuration; a cell of
     * the grid of pairs whose parent is refined (or of level 0) is refined where it is <= 0 at
     * one of region_samples^dim points of the cell (corners included). Null: none.
     */
    std::shared_ptr<dealii::FunctionParser<dim>> refinement_region;
    /** Samples per direction of a cell for 'Refinement region'. */
    static constexpr unsigned int region_samples = 5;
    /**
     * Per level l < refinement_levels and cell of the grid of pairs at level l: whether
     * 'Refinement region' refines it (mark_region()). Empty without a region.
     */
    std::vector<std::vector<bool>> region_marked;
    /**
     * 'Refinement band' (0: none) and 'Refinement band pieces' (empty: every piece): the grid is
     * refined within this distance of the body's current surface, marked anew every step.
     */
    double                   refinement_band = 0.;
    std::vector<std::string> band_piece_names;
    /**
     * 'Refinement mu range' (0: none): the grid is refined where the points' mu (and the
     * prescribed mu of their surface points) in a cell spans more than this, marked anew every
     * step.
     */
    double refinement_mu_range = 0.;
    /**
     * 'Refinement mu gradient jump' (0: none): the grid is refined where the slope of mu (the
     * least-squares plane through a cell's points) changes from a cell to its neighbour by more
     * than this over a cell, marked anew every step.
     */
    double refinement_mu_gradient_jump = 0.;
    /**
     * 'Refinement obstacle band' (0: none) and 'Refinement obstacles' (empty: every rigid
     * obstacle): the grid is refined within this distance of the obstacles' current surfaces,
     * marked anew every step (Scene::flagged_cells()).
     */
    double                   obstacle_band = 0.;
    std::vector<std::string> band_obstacle_names;
    /**
     * 'Refinement moving region' (null: none): a level set in x and t of the current
     * configuration, marked anew every step (moving_region_cells()).
     */
    std::shared_ptr<dealii::FunctionParser<dim>> moving_region;

    /**
     * The cells of the grid of pairs at level @p level where 'Refinement moving region' is <= 0
     * at time @p t at one of region_samples^dim points (corners included); InputError where it
     * is not a number.
     */
    std::vector<bool>
    moving_region_cells(const unsigned int level, const double t) const;
    /**
     * 'Refinement material region' (null: none): a level set of the initial configuration; the
     * cells that hold a point whose X_0 lies in it are refined, marked anew every step.
     */
    std::shared_ptr<dealii::FunctionParser<dim>> material_region;
    /**
     * Per level l < refinement_levels and cell of the grid of pairs at level l: whether the band
     * or the mu range refines it (mark_moving()). Empty before the first marking and without
     * either.
     */
    std::vector<std::vector<bool>> moving_marked;

    /**
     * 'Refinement budget' (0: none): the most unknowns a step's moving refinement may give
     * (MaterialPointModel::reset_grid() drops its finest levels beyond it).
     */
    unsigned long refinement_budget = 0;
    /**
     * The levels the moving refinement marks: 'Refinement levels', lowered for the rest of the
     * run by drop_finest_moving_level().
     */
    unsigned int moving_levels = 0;

    /**
     * 'Refinement grading' (off by default): the refined domains are widened so that at most two
     * levels of functions are nonzero on any leaf cell (grade()). grading_reach is the reach of
     * a function's support beyond a cell, in cells of the grid of pairs of its level
     * (set_grading_reach(), from the degrees); graded_marked the union of every criterion's
     * marks, graded, per level and cell of the grid of pairs (empty: no grading needed).
     */
    bool                           refinement_grading = false;
    unsigned int                   grading_reach      = 0;
    std::vector<std::vector<bool>> graded_marked;

    /**
     * Grade the refinement with the reach @p cells (cells of the grid of pairs of a level within
     * which the functions of a cell of that level reach) and keep grading it as the marks change.
     */
    void
    set_grading_reach(const unsigned int cells);

    /** Replace the moving marks by @p marks (an earlier marking), graded anew. */
    void
    set_moving_marks(const std::vector<std::vector<bool>> &marks);

    /** Whether a band or a mu range is set: the refinement is marked anew every step. */
    bool
    moves() const;

    /** The entry that refines the grid, named in errors of the refined path. */
    std::string
    refinement_entry() const;

    /** The cell of the grid of pairs at level @p level that holds @p x (clamped into the grid). */
    unsigned int
    pair_cell_of(const dealii::Point<dim> &x, const unsigned int level) const;

    /**
     * The cells of the grid of pairs at level @p level whose box lies within 'Refinement band'
     * of one of the points @p surface.
     */
    std::vector<bool>
    band_cells(const unsigned int level, const std::vector<dealii::Point<dim>> &surface) const;

    /**
     * Mark the cells of the grid of pairs, at every level, whose box lies within
     * 'Refinement band' of one of the points @p surface (the surface points' current
     * positions, over all ranks), and the cells @p flagged[l][c] (cell c of level l: where the
     * points' mu spans more than 'Refinement mu range' or a point starts in 'Refinement material
     * region'; empty without either) together with the cells within @p buffer cells of those at
     * their level (so that the extension finds blocks of interior functions of every level: a
     * front one cell thick would not). Returns whether the marking changed.
     */
    bool
    mark_moving(const std::vector<dealii::Point<dim>> &surface,
                const std::vector<std::vector<bool>>  &flagged,
                const unsigned int                     buffer);

    /**
     * Clear the moving marks of the finest level that has some (a cell of a finer level has a
     * marked parent, so the domains still nest), and mark no finer levels than the remaining
     * ones for the rest of the run: a refinement that gained and lost a level every step would
     * split and merge its points every step, and merged points lose their children's
     * differences. Returns false if there were none.
     */
    bool
    drop_finest_moving_level();

    /** Whether some cells are refined. */
    bool
    refined() const;

    /**
     * Per level l < refinement_levels, the refined cells of the grid of pairs of cells at level
     * l (n_cells / 2 * 2^l cells per direction): HierarchicalBSplineSpace's refined_cells.
     */
    std::vector<std::vector<unsigned int>>
    refined_pair_cells() const;

    /** The cells per direction of the grid of pairs of cells at refinement level @p level. */
    std::array<unsigned int, dim>
    pair_cells(const unsigned int level) const;

    /** The centre of the cell @p c of the grid of pairs at level @p level, and half its
     * diagonal. */
    std::pair<dealii::Point<dim>, double>
    pair_cell_centre(const unsigned int level, const unsigned int c) const;

    /** The level of the leaf cell at @p x: how many times the grid is refined there. */
    unsigned int
    refinement_level(const dealii::Point<dim> &x) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section; throws InputError unless upper > lower and cells >= 1 in each direction.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    cell_size(const unsigned int d) const;

    /** The smallest of the base grid's cell sizes over the directions. */
    double
    smallest_cell_size() const;

    /** Throw InputError if @p cells (per direction) cannot fit in the machine's memory. */
    void
    check_memory(const std::vector<double> &cells) const;

    /** True if @p p lies in the closed box of the grid (with a round-off tolerance). */
    bool
    contains(const dealii::Point<dim> &p) const;

    /** Read 'Refinement boxes'; throws InputError where the refined path does not run yet. */
    void
    parse_refinement_boxes(const std::string &text);

    /** Read 'Refinement region' (empty: none); throws InputError if it cannot be parsed. */
    void
    parse_refinement_region(const std::string &text);

    /**
     * region_marked, level by level: a cell is marked when its parent is refined (by a box or
     * the region) and the region is <= 0 at one of its samples. Throws InputError if the
     * region is not a number at a sample.
     */
    void
    mark_region();

    /**
     * Whether @p level_set is <= 0 at one of region_samples^dim points of the cell @p c of the
     * grid of pairs at level @p level (corners included); InputError naming @p entry where it
     * is not a number (@p when: the time, for the message).
     */
    bool
    level_set_meets_cell(const dealii::Function<dim> &level_set,
                         const unsigned int           level,
                         const unsigned int           c,
                         const std::string           &entry,
                         const std::string           &when = "") const;

    /**
     * graded_marked from the boxes, the region and the moving marks: around every refined cell
     * of level l >= 1, the cells of level l within grading_reach have refined parents, so that
     * the refined domains are admissible of class 2 (Buffa & Giannelli 2016: every truncated
     * function nonzero on a leaf of level l is of level l or l - 1). Applied from the finest
     * level down, so that the parents it marks are graded in turn. Empty when off or with one
     * level (two levels always meet at most).
     */
    void
    grade();

    /** Whether the cell @p c of the grid of pairs at level @p l is refined by some criterion
     * (without grading). */
    bool
    marked_by_criteria(const unsigned int l, const unsigned int c) const;

    /** Whether the cell @p c of the grid of pairs at level @p l overlaps a refinement box. */
    bool
    pair_cell_in_box(const unsigned int l, const unsigned int c) const;

    /** The grid as a deal.II triangulation (GridGenerator::subdivided_hyper_rectangle). */
    void
    create_triangulation(dealii::Triangulation<dim> &triangulation) const;
  };
} // namespace GelMPM

#endif

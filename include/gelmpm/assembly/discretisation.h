#ifndef gelmpm_assembly_discretisation_h
#define gelmpm_assembly_discretisation_h

#include <gelmpm/bspline/bspline_space.h>
#include <gelmpm/bspline/extended_bspline_space.h>
#include <gelmpm/bspline/hierarchical_bspline_space.h>
#include <gelmpm/scene/background_grid.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Discretisation" section: which B-spline pair interpolates u and mu (paper §3.4,
   * §4.2 notation Qi–Qj and Qi–QjSD) and whether boundary functions are extended (§3.5).
   */
  struct DiscretisationSettings
  {
    /** Degree q_u of the displacement B-splines (cell size h of the background grid). */
    unsigned int displacement_degree = 2;
    /** Degree q_mu of the chemical-potential B-splines. */
    unsigned int chemical_potential_degree = 2;
    /** Subdivision stabilisation: mu on the grid of cell size 2h (eq. (46)–(49)). */
    bool subdivision = true;
    /** Extended B-splines against cut-cell ill-conditioning (eq. (50)–(54)). */
    bool extension = true;

    /** The pair's name in the paper's notation, e.g. "Q2-Q2SD". */
    std::string
    name() const;

    /**
     * How many cells of the grid of pairs (cell size 2h, the refinement's marking grid) the
     * B-splines nonzero on a cell reach beyond it, for u and mu, whichever reaches farther: a
     * degree-q function on cells of size h reaches q of them, ceil(q/2) cells of size 2h.
     */
    unsigned int
    support_reach_in_pair_cells() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };


  /**
   * @brief The two B-spline spaces of a run and, for the current step, their extended versions
   * on the cells that hold material.
   *
   * The displacement space lives on the background grid (cell size h); the chemical-potential
   * space on the same grid or, with subdivision, on the grid of cell size 2h over the same box, so
   * that coarse cell (i/2, j/2) covers fine cells (i, j). The grid is reset every step: reinit()
   * rebuilds the cell classification and the extended bases from where the volume points are.
   *
   * Global unknowns of the coupled system: dim components per displacement DoF (interleaved,
   * index dim*i + c) followed by the chemical-potential DoFs (index n_u_dofs() + j).
   */
  template <int dim>
  class DiscreteSpaces
  {
  public:
    /** Build the two spaces. Throws InputError when subdivision needs an even cell count. */
    DiscreteSpaces(const BackgroundGrid<dim> &grid, const DiscretisationSettings &settings);

    /**
     * Classify cells and build the extended spaces for this step. @p u_cell_has_material flags
     * the displacement-grid cells that hold at least one volume point; a mu cell holds material
     * when one of the displacement cells it covers does.
     *
     * The extended spaces are a function of the classification alone: when it is the one of the
     * last call (and the extrapolation rule the same), the spaces, their numbering of the
     * unknowns included, are kept. Returns whether they were rebuilt. On a refined grid a leaf
     * cell is taken to hold material when its base cell does (the two-argument form is exact).
     */
    bool
    reinit(const std::vector<bool> &u_cell_has_material);

    /**
     * The same on a refined grid: @p u_leaf_has_material flags the leaf cells of the
     * displacement hierarchy that hold a volume point (a mu leaf holds material when a u leaf
     * inside it does). On the uniform grid, the same as reinit(u_cell_has_material).
     */
    bool
    reinit(const std::vector<bool> &u_cell_has_material,
           const std::vector<bool> &u_leaf_has_material);

    /**
     * Whether the grid is locally refined ('Background grid/Refinement boxes'): u and mu are then
     * truncated hierarchical B-splines of one marking, mu one level coarser than u everywhere,
     * and u() and mu() their extended versions on the level-0 cells.
     */
    bool
    refined() const;

    /**
     * Build the hierarchies anew from @p grid's marking (a band that follows the surface); the
     * next reinit() then builds the extended spaces, their unknowns numbered anew.
     */
    void
    rebuild_hierarchies(const BackgroundGrid<dim> &grid);

    /** The displacement hierarchy (refined grids only). */
    const HierarchicalBSplineSpace<dim> &
    u_hierarchy() const;

    /**
     * Control points of mu's extended space: B-splines of the chemical-potential grid, or
     * active functions of its hierarchy on a refined grid (ExtendedBSplineSpace).
     */
    unsigned int
    n_mu_control_points() const;

    /**
     * From now on, accept boundary control points whose extrapolation is not exact because it
     * crosses the first or last q cells of the grid (ExtendedBSplineSpace). The initial body is
     * checked strictly: there a larger grid is the fix. Once the body has moved next to the
     * grid's edge, as a pore closing on a plane of symmetry does, stopping the run helps nobody.
     */
    void
    tolerate_inexact_extrapolation();

    /** Control points of this step's extended spaces extrapolated inexactly. */
    unsigned int
    n_inexact_extrapolations() const;

    const BSplineSpace<dim> &
    u_space() const;
    const BSplineSpace<dim> &
    mu_space() const;
    const ExtendedBSplineSpace<dim> &
    u() const;
    const ExtendedBSplineSpace<dim> &
    mu() const;

    /** The mu cell that covers displacement cell @p u_cell. */
    unsigned int
    mu_cell_of(const unsigned int u_cell) const;

    /**
     * Per displacement unknown (n_u_dofs() of them, components interleaved), the coordinate of
     * its component's direction at the Greville point of its control point: the coefficient of
     * the linear field x_c in component c. (Rigid-body modes for algebraic multigrid.)
     */
    std::vector<double>
    u_dof_greville_points() const;

    /** Whether the grid is the meridian plane of an axisymmetric scene (BackgroundGrid). */
    bool
    axisymmetric() const;

    /**
     * Axisymmetric scenes: the radial displacement unknowns of the control points on the axis
     * (the first B-spline in x, the only one that is nonzero at R = 0), sorted. Held at zero,
     * they make u_r = 0 on the axis exactly, which the hoop strain u_r/R requires. Empty
     * otherwise.
     */
    std::vector<dealii::types::global_dof_index>
    axis_unknowns() const;

    /**
     * Displacement functions taken twice or more this step: where the points in the support of
     * an extended u function form several parts of the material that are not connected there
     * (the two faces of a closing crease or pore, 'Contact/Self contact/Separate faces';
     * PointCache), the points of each further part use a copy of it, an unknown of its own.
     * Copy k of u DoF @p copy_of[k] is u DoF u().n_dofs() + k (its unknowns dim (n + k) + c).
     * Returns whether they changed.
     */
    bool
    set_u_copies(std::vector<unsigned int> copy_of);

    /** Per copy of a displacement function (set_u_copies()), the u DoF it copies. */
    const std::vector<unsigned int> &
    u_copies() const;

    /**
     * Number of displacement unknowns: dim per DoF of the extended u space and per copy of one
     * (set_u_copies()).
     */
    unsigned int
    n_u_dofs() const;
    /** Number of chemical-potential unknowns. */
    unsigned int
    n_mu_dofs() const;
    /** n_u_dofs() + n_mu_dofs(). */
    unsigned int
    n_dofs() const;

    /**
     * Smallest cell size of the displacement grid: on a refined grid that of the finest level.
     */
    double
    h_u() const;
    /** Smallest cell size of the chemical-potential grid (h_mu); the finest level's if refined. */
    double
    h_mu() const;
    /**
     * The smallest cell size of the displacement grid's level @p level (0: the grid as the scene
     * gives it; the only level of a uniform grid), h_u of the penalties at a point whose leaf
     * has that level (PointRecord::level).
     */
    double
    h_u(const unsigned int level) const;
    /** The same for the chemical-potential grid (h_mu of its Nitsche penalty). */
    double
    h_mu(const unsigned int level) const;

    /**
     * The cell with material in which a surface point at @p p is evaluated: the cell containing p
     * if it holds material, else the nearest of its neighbours that does (the point lies on a face
     * of, or just outside, the cells with volume points; the cell's polynomial pieces continue
     * the field there). numbers::invalid_unsigned_int if no neighbour holds material.
     */
    unsigned int
    active_u_cell_containing(const dealii::Point<dim> &p) const;

    const DiscretisationSettings &
    settings() const;

  private:
    /**
     * Calls @p f(dof, space, index) for every DoF of the u space: the B-spline space of the DoF's
     * function (its level's on a refined grid) and the function's multi-index in it.
     */
    template <typename F>
    void
    for_each_u_dof_function(const F &f) const;

    /** The two hierarchies of a refined grid, from its one marking. */
    void
    build_hierarchies(const BackgroundGrid<dim> &grid);

    DiscretisationSettings                         settings_;
    BSplineSpace<dim>                              u_space_;
    BSplineSpace<dim>                              mu_space_;
    std::unique_ptr<ExtendedBSplineSpace<dim>>     u_;
    std::unique_ptr<ExtendedBSplineSpace<dim>>     mu_;
    std::vector<bool>                              u_cell_has_material_;
    std::unique_ptr<HierarchicalBSplineSpace<dim>> u_hierarchy_;
    std::unique_ptr<HierarchicalBSplineSpace<dim>> mu_hierarchy_;
    std::vector<bool>                              u_leaf_has_material_;
    std::vector<unsigned int>                      u_copies_;
    bool                                           inexact_extrapolation_tolerated = false;
    bool                                           axisymmetric_;
    // The entry that refines the grid, named when the extension cannot reach a refined region.
    std::string refinement_entry_ = "Background grid/Refinement boxes";
    /** Whether the grid's refinement is graded (named in the extension's error). */
    bool graded_ = false;
    // The rule the current extended spaces were built with.
    bool built_tolerating_inexact_extrapolation = false;
  };
} // namespace GelMPM

#endif

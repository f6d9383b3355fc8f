#ifndef gelmpm_simulator_scene_h
#define gelmpm_simulator_scene_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/material_point_generator.h>
#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/geometry.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief What a scene file describes, as the discrete problem of its first step: the gel, the
   * background grid, the body, the boundary pieces, how points are placed, the discretisation,
   * Nitsche's and the contact settings; and from them the material points, the spaces and the
   * mixed system.
   *
   * The Simulator runs a Scene and the assembly tests examine one: both build it the same way
   * from a ParameterHandler, so that a test sees the set-up a run would have, not a copy of it
   * that may drift. The parts are public: they are the scene's data, each checked by its own
   * parse_parameters(), and the run and the tests read and drive them directly.
   *
   * Built in three stages, so that a caller may check its own sections in between: the
   * constructor parses the sections, create_material_points() builds the grid, the points and the
   * spaces (bad input is found there: a body outside the grid, a piece that selects nothing),
   * create_system() the mixed system on them.
   *
   * On several MPI ranks the background grid is a parallel::distributed::Triangulation (p4est)
   * and each rank holds the material points of the cells it owns; the cells are partitioned by
   * their material points (balance_partition()). On one rank it is a serial Triangulation, with
   * which every result of the one-rank runs was made.
   */
  template <int dim>
  class Scene
  {
  public:
    /**
     * Declare the scene's sections in @p prm; @p boundary_pieces are the names of the boundary
     * pieces (each gets a subsection of "Boundary conditions").
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &boundary_pieces,
                       const std::vector<std::string> &material_regions = {},
                       const std::vector<std::string> &obstacles        = {});

    /**
     * Parse and check the sections declared by declare_parameters(). Throws InputError. Files the
     * scene names ("Geometry/Mesh file") are taken relative to @p scene_directory (empty: the
     * current directory). The run is distributed over the ranks of @p communicator.
     */
    Scene(dealii::ParameterHandler       &prm,
          const std::vector<std::string> &boundary_pieces,
          const std::string              &scene_directory  = "",
          const MPI_Comm                  communicator     = MPI_COMM_WORLD,
          const std::vector<std::string> &material_regions = {},
          const std::vector<std::string> &obstacles        = {});

    /**
     * Create the triangulation of the background grid, the material points of the body in their
     * initial state and the discrete spaces. Throws InputError on a body the grid cannot hold.
     */
    void
    create_material_points();

    /**
     * Create the mixed system on the spaces (after create_material_points()), with the contact
     * terms of the "Contact" section when it is enabled.
     */
    void
    create_system();

    /**
     * Throw InputError (naming the obstacle's entry) unless every rigid obstacle of "Contact" is
     * finite at @p times (0 and the end time among them) and clear of the body at t = 0 (no
     * material point inside it beyond round-off), and no motion takes it so far into the body
     * that it would hold every material point of the initial body at one of @p times. Contact
     * acts at the body's surface points only: an obstacle that starts inside the body is never
     * pushed out of it (the first step fails, or a sphere wholly inside the gel never touches
     * it), and a body pressed to nothing cannot converge. After create_material_points().
     */
    void
    check_obstacles(const std::vector<double> &times);

    /**
     * Throw InputError ('Background grid/Cells') unless the extended bases can be built on the
     * initial configuration: the first step builds them, and here a grid too coarse for the body
     * is still bad input. After create_material_points().
     */
    void
    check_grid_resolves_body();

    /**
     * Throw InputError unless every boundary function is finite on its piece at times over
     * [0, @p end_time] (and a prescribed bath stays below the largest chemical potential with a
     * swollen equilibrium), and unless the obstacles pass check_obstacles() at those times. After
     * create_material_points(); the functions are left at t = 0.
     *
     * Returns the largest jump of a prescribed chemical potential at t = 0 away from the gel's
     * mu_0, in words (empty: none above a tenth of |mu_0|): a run that then fails early says it
     * (such a jump swells a layer thinner than a cell).
     */
    std::string
    check_boundary_values(const double end_time);

    /**
     * Throw InputError ('Boundary conditions') if no boundary condition and no contact plane
     * holds the body against a rigid motion: the tangent would be singular along it. After
     * create_material_points().
     */
    void
    check_rigid_motions() const;

    /** The volume points in each cell of the background grid, over all ranks. */
    std::vector<unsigned int>
    volume_points_per_cell() const;

    /**
     * On several ranks: partition the cells anew so that each rank holds about as many material
     * points, moving the points with their cells. Nothing on one rank.
     *
     * A cell's work is that of its points (their shape functions, their share of the tangent)
     * and a cell without points costs next to nothing; deal.II weighs every cell with
     * base_weight and adds added_weight(points).
     */
    void
    balance_partition();

    /**
     * The largest weight (as balance_partition() weighs cells) on a rank over the mean weight
     * per rank (1 on one rank): the run rebalances when it grows.
     */
    double
    imbalance() const;

    /** The weight p4est gives every cell (deal.II 9.4) before the weight a scene adds. */
    static constexpr unsigned int base_weight = 1000;

    /**
     * The weight added to a cell with @p n_points material points: as much as the base weight
     * per point, and four points' worth for the cell's block of the tangent.
     */
    static unsigned int
    added_weight(const unsigned int n_points)
    {
      return n_points > 0 ? base_weight * (n_points + 4) : 0;
    }

    /**
     * 'Background grid/Refinement band' and 'Refinement mu range': mark the grid anew round the
     * current surface points (those of 'Refinement band pieces'; over all ranks), where the
     * points' mu spans the range and round the material of 'Refinement material region', rebuild
     * the spaces' hierarchies when the marking changed, merge the volume points that now lie in
     * coarser leaves than their spacing (merge_points_to_leaves()) and split those in finer ones
     * (split_points_to_leaves()). Returns whether the marking changed. Nothing without either.
     * @p t_begin: the time the step starts at, of the prescribed mu.
     */
    bool
    update_moving_refinement(const double t_begin);

    /**
     * Go back to the marking before the last update_moving_refinement() (its hierarchies, and
     * the points split to its leaves; those merged stay merged): for a step whose new marking
     * the extension cannot build. Returns false if there is nothing to go back to.
     */
    bool
    keep_last_marking();

    /**
     * Drop the finest level of the moving refinement's marks, rebuild the hierarchies and merge
     * the points of the leaves that coarsen: for a step beyond 'Background grid/Refinement
     * budget'. Returns false if no moving marks are left to drop.
     */
    bool
    coarsen_moving_refinement();

    /** The body's own material (section "Material"), region 0 of regions. */
    FloryRehnerGel<dim> material;
    /** Every gel of the body, by region (MaterialRegions). */
    MaterialRegions<dim>        regions;
    BackgroundGrid<dim>         grid;
    Geometry<dim>               geometry;
    BoundaryConditions<dim>     boundary_conditions;
    MaterialPointGenerator<dim> generator;
    DiscretisationSettings      discretisation;
    NitscheSettings             nitsche;
    ContactSettings             contact;
    /**
     * The rigid obstacles of "Contact" ('Obstacles'), one object each: the contact term refers
     * to them and the system moves them to the end of each step (at t = 0 until the first).
     */
    std::vector<Obstacle<dim>> obstacles;

    MPI_Comm                                    communicator;
    std::unique_ptr<dealii::Triangulation<dim>> triangulation;
    dealii::MappingQ1<dim>                      mapping;
    dealii::Particles::ParticleHandler<dim>     particles;
    std::unique_ptr<DiscreteSpaces<dim>>        spaces;
    std::unique_ptr<MixedSystem<dim>>           system;

  private:
    /** The indices of 'Background grid/Refinement band pieces'; InputError on an unknown name. */
    std::vector<int>
    band_piece_indices() const;

    /** The current positions of the band's surface points, over all ranks (empty: no band). */
    std::vector<dealii::Point<dim>>
    band_surface_points() const;

    /**
     * The indices in obstacles of 'Background grid/Refinement obstacles' (all of them if it is
     * empty and 'Refinement obstacle band' is set); InputError on a name that is no obstacle.
     */
    std::vector<unsigned int>
    band_obstacle_indices() const;

    /**
     * Per level and cell of the grid of pairs, whether the mu of its points and the prescribed
     * mu of its surface points span more than 'Refinement mu range', mu's slope changes by
     * more than 'Refinement mu gradient jump' (flag_mu_gradient_jumps()), one of its points starts
     * in 'Refinement material region', or it lies within 'Refinement obstacle band' of an
     * obstacle's surface at @p t; over all ranks (empty: none of them is set).
     */
    std::vector<std::vector<bool>>
    flagged_cells(const double t);

    /**
     * Flag the cells of each level where mu's slope changes by more than 'Refinement mu gradient
     * jump' over a cell: the least-squares planes of mu through the points of two face
     * neighbours (volume points, and surface points with their piece's prescribed mu) differ in
     * gradient by g with |g| h above it; both are flagged. Over all ranks.
     */
    void
    flag_mu_gradient_jumps(std::vector<std::vector<bool>> &flagged) const;

    /**
     * The sums of the normal equations of the least-squares plane of mu per level and cell of
     * the grid of pairs (flag_mu_gradient_jumps()), over all ranks.
     */
    std::vector<std::vector<double>>
    mu_plane_sums() const;

    /**
     * Whether the point of @p properties is a surface point of a piece with a prescribed mu,
     * and then that mu at the time the boundary conditions are set to, into @p mu.
     */
    bool
    prescribed_mu(const dealii::ArrayView<const double> &properties, double &mu) const;

    /** Flag the cells of each level within 'Refinement obstacle band' of band_obstacles. */
    void
    flag_obstacle_band(std::vector<std::vector<bool>> &flagged) const;

    /** The moving refinement's marking before the last update (keep_last_marking()). */
    std::vector<std::vector<bool>> last_marking;

    /** band_piece_indices(), read once (empty: every surface point). */
    std::vector<int> band_pieces;

    /** band_obstacle_indices(), read once. */
    std::vector<unsigned int> band_obstacles;

    /**
     * Throw the InputError of a grid on which the extended bases cannot be built (@p reason, the
     * extension's words): naming the planes of symmetry too close to the grid's side and the
     * exact 'Background grid' entries that fix them where that is the cause.
     */
    void
    throw_unresolved_body(const std::string &reason) const;

    /** Throw InputError ('Material points/Points per cell') below 3 points per direction. */
    void
    check_points_per_cell() const;

    /**
     * Up to 64 surface points spread over each boundary piece (their X_0), the same on every
     * rank.
     */
    std::vector<std::vector<dealii::Point<dim>>>
    boundary_samples() const;

    /** The largest jump of a prescribed chemical potential at t = 0 at @p samples, in words. */
    std::string
    boundary_jump(const std::vector<std::vector<dealii::Point<dim>>> &samples) const;

    /** Throw InputError if @p obstacle holds a material point at t = 0 (gap above
     * @p tolerance). */
    void
    check_obstacle_start(Obstacle<dim> &obstacle, const double tolerance) const;

    /** Throw InputError if @p obstacle holds every material point of the initial body at one
     * of @p times. */
    void
    check_obstacle_path(Obstacle<dim>             &obstacle,
                        const std::vector<double> &times,
                        const double               tolerance) const;
  };
} // namespace GelMPM

#endif

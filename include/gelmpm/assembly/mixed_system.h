#ifndef gelmpm_assembly_mixed_system_h
#define gelmpm_assembly_mixed_system_h

#include <gelmpm/assembly/assemblers.h>
#include <gelmpm/assembly/contact.h>
#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/assembly/point_cache.h>
#include <gelmpm/assembly/point_projection.h>
#include <gelmpm/core/newton_system.h>
#include <gelmpm/core/non_physical_state.h>
#include <gelmpm/core/sparse_entries.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/material_regions.h>
#include <gelmpm/scene/obstacle.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/particles/particle_handler.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The coupled u–mu system of one time step on material points: residual and tangent of
   * the previously-converged Lagrangian weak form (paper eq. (26), (31)) with Nitsche terms
   * (eq. (32)), Neumann traction and solvent flux, assembled on the extended (and subdivided)
   * B-spline bases.
   *
   * Units (see FloryRehnerGel): stresses in G, mu in k_BT. The mu equation is the paper's H
   * multiplied by k_BT, so that the tangent is symmetric in these units:
   *   R_mu[q] = sum_p V_p [ -(k_BT/nu)(dJ - 1) q - dt m_p grad mu . grad q ]
   *           + sum_s A_s dt (k_BT/nu) (nu i) q                     (flux pieces)
   *           + sum_s A_s dt [ m (grad mu.N) q + s m (grad q.N)(mu - mubar)
   *                            - beta_mu (mu - mubar) q ]                  (prescribed mu)
   *           - s sum_s A_s (W : dP_n/dmu) q                         (prescribed u),
   * with m_p = FloryRehnerGel::mobility(F_n F_0) frozen over the step (§2.4) and
   * W = Pi (u - ubar) (x) N, Pi the projector of the constrained components (I for a fixed
   * piece, N(x)N for a normal one, T(x)T for a tangential one):
   *   R_u[w] = sum_p V_p P_n : grad w - sum_s A_s ((I - Pi) T_n) . w
   *          + sum_s A_s [ beta_u Pi(u - ubar).w - Pi(P_n N).w - s W : A_n : grad w ].
   * u - ubar uses the total displacement u = x_n - X_0 + du. The symmetric terms are the
   * gradient of a potential, so the exact tangent contains the third derivative of the energy
   * contracted with W; it is included (see assemble()) so that Newton converges quadratically and
   * the tangent equals the finite-difference Jacobian of the residual.
   *
   * The sign of the mu-symmetry term is the one that makes the tangent symmetric (s = 1); with
   * the sign printed in eq. (32) the mu block would be skew.
   *
   * Per step, setup() gathers the material points, classifies the cells, builds the extended
   * bases and caches every point's shape-function values and gradients (PointCache): they do not
   * change over the Newton iterations of a step (the grid is reset, points sit at x_n).
   *
   * The class holds the parts together: the point cache, the sparsity pattern of the global
   * tangent (NewtonSystem's matrix and residual), the boundary data of a step and the point
   * updates. Each term of the weak form is an assembler of its own (PointAssembler), and the
   * scene's terms are one list, built by setup_assemblers() with the terms the scene needs, in
   * the order of the sums; the class knows no term but contact, whose state and reactions it
   * reports, and the gel's contact with itself, whose state it reports. The projections are
   * PointProjection's; the error norms of a step are in mixed_system_errors.cc.
   *
   * On several MPI ranks each rank holds the material points of its cells and assembles them;
   * the classification, the spaces and their numbering, the residual and the Newton vectors are
   * the same on every rank (whole), the tangent is a distributed Trilinos matrix whose rows are
   * owned as owned_and_relevant_dofs() says (doc/architecture.md, "Distribution over MPI ranks").
   * Everything that sums or maximises over points (errors, increments, contact, n_points) is
   * reduced over the ranks, and every function that may fail on one rank's points fails on all.
   */
  template <int dim>
  class MixedSystem : public NewtonSystem
  {
  public:
    MixedSystem(const MaterialRegions<dim> &materials,
                BoundaryConditions<dim>    &boundary_conditions,
                const NitscheSettings      &nitsche,
                DiscreteSpaces<dim>        &spaces,
                const MPI_Comm              communicator = MPI_COMM_SELF);

    /**
     * Start a step: locate the points of @p particles, classify cells from the volume points,
     * rebuild the extended spaces, cache shape data and the sparsity pattern. Throws
     * std::runtime_error if a point lies outside the background grid.
     *
     * The extended spaces, the numbering of the unknowns and the sparsity pattern depend on the
     * classification alone (every cell with volume points is one block of assembly, and surface
     * points join such blocks): when it is the last step's, they are kept, and so is the matrix
     * object. Otherwise @p before_new_pattern is called before the matrix is re-initialised
     * (the owner of a factorisation of it releases it there). Returns whether the pattern is new.
     */
    bool
    setup(
      dealii::Particles::ParticleHandler<dim> &particles,
      const std::function<void()>             &before_new_pattern = [] {});

    /**
     * Evaluate the boundary data (ubar, traction, mubar, flux) at the end @p t_over_tau_d of
     * a step from the points' state at @p step_start for every surface point, and ubar also
     * at @p step_start; called once per attempt of a step.
     */
    void
    set_boundary_values(const double t_over_tau_d, const double step_start);

    /**
     * Assemble the residual (and, if @p with_matrix, the tangent) at the unknowns @p solution
     * (du then mu) for the physical time step @p dt. Throws NonPhysicalState if some point's
     * state leaves the physical range (J <= 1).
     */
    void
    assemble(const dealii::Vector<double> &solution,
             const double                  dt,
             const bool                    with_matrix) override;

    /** The displacement unknowns of the step's spaces, which come first. */
    unsigned int
    n_u_dofs() const override;

    /** Hold each surface point's seal by an impermeable obstacle (ContactAssembler::seals())
     * at its value at @p solution (PointRecord::seal; with @p hold false only counted); how
     * many changed, over all ranks. */
    unsigned int
    freeze_switches(const dealii::Vector<double> &solution, const bool hold = true) override;

    /** Let the seals follow the iterate again. */
    void
    release_switches() override;

    /** The classification (cells with volume points) the sparsity pattern was built for. */
    const std::vector<bool> &
    classification_of_pattern() const;

    /**
     * Overwrite the tangent's entries with @p entries (all rows, as the ranks'
     * LinearSolver::entries_of_factorization() together hold them) if the pattern is the one
     * built for @p classification; returns whether it did (a resumed run restoring the matrix
     * its next Newton iteration starts from). Each rank takes the rows it owns.
     */
    bool
    restore_tangent(const std::vector<bool> &classification, const SparseEntries &entries);

    /**
     * After convergence: move every material point by du, and update F_n F_0, V_n, N_n A_n
     * (eq. (34)) and mu on the points. Leaves the particles unsorted (the caller re-sorts).
     */
    void
    update_particles(const dealii::Vector<double> &solution);

    /**
     * Surface points whose own increment Delta F would have taken their state out of the
     * physical range and which took that of the nearest volume point of their block instead
     * (update_particles()), summed over this object's steps.
     */
    unsigned int
    n_borrowed_increments() const
    {
      return n_borrowed_increments_;
    }

    /**
     * Axisymmetric scenes: set the radial unknowns on the axis (DiscreteSpaces::axis_unknowns())
     * of @p solution to zero, as the first Newton iterate must have them. assemble() keeps them
     * there: their rows and columns of the tangent hold only the diagonal, their residual is
     * zero. Nothing in a Cartesian scene.
     */
    void
    hold_axis(dealii::Vector<double> &solution) const;

    /**
     * Particle-to-grid transfer of the chemical potential: the coefficients of the current mu
     * basis closest to the points' mu_n in the least-squares sense over the volume points
     * (L2 projection with the points as quadrature: M c = b, M_ij = sum_p V_p Ñ_i Ñ_j,
     * b_i = sum_p V_p Ñ_i mu_p). The coefficients of the last step evaluated at the moved points
     * would shift mu by grad mu . du at every point, and with it the stress by (k_BT/nu) grad mu .
     * du, a large false residual in the first Newton iteration of a step after a fast motion.
     */
    std::vector<double>
    mu_from_points() const;

    /**
     * How well the converged @p solution meets the weakly imposed conditions: the largest
     * |Pi (u - ubar)| over surface points with a prescribed displacement (component), and the
     * largest |mu - mubar| (in k_BT) over surface points with a prescribed chemical potential, at
     * the boundary values of the last set_boundary_values().
     */
    std::pair<double, double>
    dirichlet_errors(const dealii::Vector<double> &solution) const;

    /** The largest displacement increment |du(x_p)| over all material points for @p solution. */
    double
    largest_displacement_increment(const dealii::Vector<double> &solution) const;

    /**
     * The largest relative change |J_{n+1}/J_n - 1| of a volume point's volume ratio over the
     * step that ends in @p solution (with the hoop stretch in an axisymmetric scene).
     */
    double
    largest_volume_change(const dealii::Vector<double> &solution) const;

    /**
     * The largest distance |du(x_p) - @p ratio du_p,last| over all material points between the
     * displacement increment of @p solution and the point's increment in the last accepted step
     * scaled by @p ratio = dt / dt_last: the predictor-corrector difference of backward Euler,
     * about twice its local error (Delta t^2 |u''| against Delta t^2 |u''| / 2).
     */
    double
    largest_increment_deviation(const dealii::Vector<double> &solution, const double ratio) const;

    /** Root mean squares, weighted by V_n over the volume points, of the local errors of a step. */
    struct StepError
    {
      /** Of the displacement increment, in the scene's length unit. */
      double displacement;
      /** Of the change of mu, in k_BT. */
      double chemical_potential;
    };

    /**
     * The local error of the backward Euler step that ended in @p solution, estimated from its
     * difference to the linear predictor (the points' changes in the last accepted step scaled
     * by @p ratio = dt / dt_last): r / (2 r + 1) times that difference (doc/method.md, "Error
     * control"), its volume-weighted root mean square over the volume points or, with
     * @p largest, its largest value.
     */
    StepError
    local_error_estimate(const dealii::Vector<double> &solution,
                         const double                  ratio,
                         const bool                    largest = false) const;

    /**
     * The displacement coefficients (n_u_dofs(), interleaved as the unknowns) closest to
     * @p ratio times the points' increments of the last accepted step: the L2 projection of
     * mu_from_points() applied to each displacement component over the volume points. A first
     * Newton iterate that continues the motion of the last step.
     */
    std::vector<double>
    displacement_from_points(const double ratio) const;

    /**
     * The mass matrix of the chemical-potential basis integrated on the volume points,
     * M_ij = sum_p V_p Ñ_i(x_p) Ñ_j(x_p), dense: for analyses of small discretisations (the
     * inf-sup constant).
     */
    dealii::FullMatrix<double>
    mu_mass_matrix() const;

    /**
     * Keep the free surfaces behind the planes of symmetry of @p settings (the "Contact"
     * section); off until called. Builds the list of terms anew.
     */
    void
    set_contact(const ContactSettings &settings);

    /**
     * set_contact(), and keep the free surfaces out of the scene's rigid @p obstacles too: the
     * contact term reads them where they are (they must outlive the system), and
     * set_boundary_values() moves them to the time of the step's end.
     */
    void
    set_contact(const ContactSettings &settings, std::vector<Obstacle<dim>> &obstacles);

    /**
     * Add @p term to the end of the scene's terms (a term the scene file does not describe: a
     * test's, or one whose owner builds it). Kept when set_contact() builds the list anew; its
     * couplings (PointAssembler::add_cell_couplings()) enter the pattern at the next setup().
     */
    void
    add_term(std::unique_ptr<PointAssembler<dim>> term);

    /** The terms of the weak form, in the order of the sums (setup_assemblers(), add_term()). */
    const std::vector<const PointAssembler<dim> *> &
    assemblers() const;

    /**
     * The contact state of @p solution: the number of surface points on which the contact
     * condition is active, and the largest penetration max(g, 0) (0 without contact).
     */
    std::pair<unsigned int, double>
    contact_state(const dealii::Vector<double> &solution) const;

    /** The gel's contact with itself ('Contact/Self contact'; SelfContactAssembler::State). */
    struct SelfContactState
    {
      /** Surface points in active contact (each face's points count). */
      unsigned int points = 0;
      /** The sum of the pairs' normal forces, in G times length^(dim-1) (per unit thickness in
       * 2D, revolved in an axisymmetric scene). */
      double force = 0.;
      /** The area in contact (2D: length per unit thickness), each face counted once. */
      double area = 0.;
      /** The largest penetration of a point behind the surface. */
      double penetration = 0.;
      /** The initial position of that point. */
      dealii::Point<dim> deepest_X0;
    };

    /** The self-contact of @p solution with the step's pairs (all zero when off). */
    SelfContactState
    self_contact_state(const dealii::Vector<double> &solution) const;

    /**
     * Surface points behind the surface at @p solution that no pair of the step holds
     * (SelfContactAssembler::unseen_contacts(); 0 without self-contact).
     */
    unsigned int
    unseen_self_contacts(const dealii::Vector<double> &solution) const;

    /** What the boundary of one piece exerts on the body over a step. */
    struct PieceBalance
    {
      /**
       * The force on the body (traction, Nitsche and contact terms integrated over the piece's
       * surface points), in G times length^(dim-1) (per unit thickness in 2D).
       */
      dealii::Tensor<1, dim> force;
      /** The solvent volume that enters the body through the piece over the step. */
      double solvent_in = 0.;
    };

    /**
     * The force and the solvent inflow of each boundary piece for the converged @p solution of
     * a step of @p dt: the piece's surface terms of the residual tested with constant w and q.
     * At a converged state the forces of all pieces sum to zero and the inflows to the body's
     * change of solvent volume, both to the Newton tolerance. Collective.
     */
    std::vector<PieceBalance>
    boundary_balances(const dealii::Vector<double> &solution, const double dt) const;

    /** What the gel does to one rigid obstacle (ContactAssembler::rigid_obstacle()). */
    struct ObstacleReaction
    {
      /**
       * The force the gel exerts on the obstacle: the obstacle's contact terms of the residual
       * tested with w = e_k, summed over the surface points (minus its share of the pieces'
       * forces of boundary_balances()), in G times length^(dim-1) (per unit thickness in 2D).
       */
      dealii::Tensor<1, dim> force;
      /** The sum of PointRecord::measure over the points where its contact is active. */
      double area = 0.;
      /** The largest distance of such a point from the obstacle's axis (0 if none). */
      double radius = 0.;
    };

    /**
     * The reaction of each rigid obstacle for the converged @p solution, at the obstacle's
     * position of the step's end. Collective.
     */
    std::vector<ObstacleReaction>
    obstacle_reactions(const dealii::Vector<double> &solution) const;

    /** Number of material points of the last setup(), and how many take part in assembly. */
    unsigned int
    n_points() const;

    /** Displacement cells that hold volume points in this step. */
    unsigned int
    n_active_cells() const;

    const DiscreteSpaces<dim> &
    spaces() const;

    /** The points of the last setup(), their blocks and shape functions. */
    const PointCache<dim> &
    point_cache() const
    {
      return cache;
    }

    /**
     * Contract the volume points' tangent with the entries of A_n (@p generic true, the former
     * assembly, kept as the reference) instead of its structure (VolumeTermAssembler). The
     * environment variable GELMPM_GENERIC_VOLUME_TANGENT (any value) sets it at construction, to
     * time both with one binary (doc/performance.md, "Assembly at its flop limit").
     */
    void
    set_generic_volume_tangent(const bool generic)
    {
      tangent.generic_volume = generic;
    }

    /**
     * Take the displacement Nitsche tangent's third-derivative term by a central difference of A_n
     * (@p reference true, the former assembly, kept as the reference) instead of in closed form,
     * at the prescribed displacements and Nitsche contact (add_displacement_nitsche()). The
     * environment variable GELMPM_REFERENCE_NITSCHE_TANGENT (any value) sets it at construction,
     * to time both with one binary (doc/performance.md, "Assembly at its flop limit").
     */
    void
    set_reference_nitsche_tangent(const bool reference)
    {
      tangent.reference_nitsche = reference;
    }

  private:
    /** Add a block's local matrix to the tangent (the copier of the assembly). */
    void
    add_to_matrix(const AssemblyCopy &copy);

    /** Add the terms' systems beyond the blocks (pair terms, PointAssembler::
     * assemble_beyond_blocks()), after the blocks. */
    void
    add_beyond_blocks(const dealii::Vector<double> &solution,
                      const double                  dt,
                      const bool                    with_matrix);

    /** The order in which assemble() visits the blocks (the cells' Z-order in 3D). */
    std::vector<unsigned int>
    assembly_order() const;

    /**
     * The sparsity pattern of the step's tangent, with the couplings @p couplings between cells,
     * and the matrix and residual on it.
     */
    void
    build_sparsity_pattern(const std::vector<std::pair<unsigned int, unsigned int>> &couplings);

    /** The unknowns of the cell @p u_cell with volume points, sorted. */
    void
    unknowns_of_cell(const unsigned int                            u_cell,
                     std::vector<dealii::types::global_dof_index> &dofs) const;

    /**
     * On several ranks: the unknowns whose rows of the tangent this rank owns, and those its
     * points contribute to (which it writes, sent to their owners by compress()), with the
     * cells of @p couplings.
     */
    std::pair<dealii::IndexSet, dealii::IndexSet>
    owned_and_relevant_dofs(
      const std::vector<std::pair<unsigned int, unsigned int>> &couplings) const;

    /** The scene's terms anew (TermList::build()). */
    /**
     * The increment of a point's F for update_particles(): @p delta_F, but for a surface point
     * whose state it would take out of the physical range the nearest volume point's of its
     * block (counted in @p borrowed) if that one keeps it physical.
     */
    dealii::Tensor<2, dim>
    physical_or_borrowed_increment(const PointRecord<dim>       &r,
                                   const dealii::Tensor<2, dim> &delta_F,
                                   const dealii::Tensor<1, dim> &du,
                                   const dealii::Vector<double> &solution,
                                   std::atomic<unsigned int>    &borrowed) const;

    void
    build_terms();

    /** The block's local residual (and tangent) from the terms at its points. */
    void
    assemble_block(const PointBlock             &block,
                   const dealii::Vector<double> &solution,
                   const double                  dt,
                   const bool                    with_matrix,
                   AssemblyScratch<dim>         &scratch,
                   AssemblyCopy                 &copy) const;

    /** The surface terms at a surface point of a piece, in their order. */
    void
    add_surface_point(const PointRecord<dim> &point,
                      const double            dt,
                      const bool              with_matrix,
                      AssemblyScratch<dim>   &scratch,
                      AssemblyCopy           &copy) const;

    /** The message of a non-physical state at @p point: where, what kind, which piece and cell. */
    std::string
    describe_failure(const NonPhysicalState     &error,
                     const PointRecord<dim>     &point,
                     const AssemblyScratch<dim> &scratch,
                     const unsigned int          u_cell) const;

    const MaterialRegions<dim> &materials;
    BoundaryConditions<dim>    &boundary_conditions;
    const NitscheSettings      &nitsche;
    DiscreteSpaces<dim>        &spaces_;
    const MPI_Comm              communicator;

    PointCache<dim>      cache;
    unsigned int         n_borrowed_increments_ = 0;
    PointProjection<dim> projection;

    // How the terms form their tangents (they refer to it), the "Contact" section and the
    // scene's rigid obstacles (nullptr: none), which set_boundary_values() moves.
    TangentOptions              tangent;
    ContactSettings             contact_settings;
    std::vector<Obstacle<dim>> *obstacles = nullptr;

    // The terms of the weak form.
    TermList<dim> terms;

    // The classification (cells with volume points), the cells' holders and the terms' couplings
    // between cells the sparsity pattern was built for.
    std::vector<bool>                                  pattern_classification;
    std::vector<unsigned int>                          pattern_holder;
    std::vector<std::pair<unsigned int, unsigned int>> pattern_couplings;
    // On several ranks: the cells of this rank's blocks when the pattern was built.
    std::vector<unsigned int> pattern_block_cells;

    // Whether add_to_matrix() may write into the rows directly (one rank, sorted columns).
    bool rows_are_local_and_sorted = false;

    // Axisymmetric scenes: per unknown, whether it is a radial unknown on the axis (empty in a
    // Cartesian scene); rebuilt with the spaces at every setup().
    std::vector<bool> on_axis;

    /** Reduce a block's system to the diagonal in the rows and columns of the axis unknowns. */
    void
    hold_axis_in_block(AssemblyCopy &copy, const bool with_matrix) const;
  };
} // namespace GelMPM

#endif

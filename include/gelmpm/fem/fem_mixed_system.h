#ifndef gelmpm_fem_fem_mixed_system_h
#define gelmpm_fem_fem_mixed_system_h

#include <gelmpm/core/newton_system.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The coupled u–mu system of one time step on a conforming (body-fitted) finite-element
   * mesh of the gel's initial configuration Omega_0: the peer of the material point MixedSystem,
   * with the same equations, the same material (FloryRehnerGel) and the same frozen mobility
   * m_n of the paper's §2.4, but Taylor–Hood elements (FE_Q(k)^dim for u, FE_Q(k-1) for mu),
   * Gauss quadrature and strong Dirichlet conditions (AffineConstraints) instead of B-splines,
   * material points and Nitsche terms. Derivation in doc/fem_peer.md.
   *
   * Unknowns of a step, as for MixedSystem: the increment du = u_{n+1} - u_n (u measured from
   * Omega_0) and mu_{n+1}. The state is the converged u_n and mu_n only: F_n = I + grad_0 u_n is
   * re-evaluated at every quadrature point, F_p = F_n F_0 with F_0 = lambda_0 I.
   *
   * Two algebraically equivalent forms of the residual (units of FloryRehnerGel; the mu equation
   * is the paper's H times k_BT, so that the tangent is symmetric):
   *
   * - previously converged Lagrangian (paper eq. (26), (31)), integrated on Omega_n:
   *     R_u[w]  = int_{Omega_n} P_n(dF, mu; F_p) : grad_n w dV_n,
   *     R_mu[q] = int_{Omega_n} [ -(k_BT/nu)(dJ - 1) q - dt m_n grad_n mu . grad_n q ] dV_n,
   *   with dF = I + grad_n du, grad_n = F_n^{-T} grad_0 and dV_n = det F_n dV_0: the Gauss points
   *   of Omega_0 carried to Omega_n by x = X + u_n(X), i.e. the isoparametric mesh of Omega_n;
   * - total Lagrangian on Omega_0:
   *     R_u[w]  = int_{Omega_0} P_0(F_t, mu) : grad_0 w dV_0,   P_0 = P(F_t F_0) F_0^T / J_0,
   *     R_mu[q] = int_{Omega_0} [ -(k_BT/nu)(det F_t - det F_n) q
   *                               - dt m_n det F_n (F_n^T F_n)^{-1} grad_0 mu . grad_0 q ] dV_0,
   *   with F_t = I + grad_0 (u_n + du) = dF F_n.
   *
   * Since P_n : grad_n w dV_n = P_0 : grad_0 w dV_0 and (dJ - 1) dV_n = (det F_t - det F_n) dV_0
   * pointwise, the two give the same residual and tangent up to round-off; both are kept so that
   * this can be checked (tests/fem/fem_formulations).
   *
   * Materials: one gel for the whole mesh, or one per cell material_id (bonded regions, e.g. the
   * two layers of a bilayer). All gels share one solvent (k_BT/nu) and start in equilibrium with
   * one mu_0, each at its own lambda_0 (F_0 = lambda_0 I per cell), as MaterialRegions does for
   * the MPM (doc/own_scenes.md).
   *
   * Boundary conditions: displacement components held (du = 0 on them, so u = 0 relative to
   * Omega_0) on boundary ids of the triangulation or at single vertices, and prescribed mu on
   * boundary ids (constant, or changed per step with set_chemical_potential()); everything else
   * is traction free and impermeable. Constrained rows of the residual are zero and of the tangent
   * carry a diagonal entry, so Newton keeps the constrained values of the initial guess.
   */
  template <int dim>
  class FemMixedSystem : public NewtonSystem
  {
  public:
    /** Which of the two equivalent forms of the residual is assembled (see the class text). */
    enum class Formulation
    {
      previously_converged_lagrangian,
      total_lagrangian
    };

    /**
     * @p triangulation is the mesh of Omega_0 (kept by reference); @p u_degree >= 2 is the degree
     * of the displacement, mu gets u_degree - 1 (Taylor–Hood).
     */
    FemMixedSystem(const FloryRehnerGel<dim>        &material,
                   const dealii::Triangulation<dim> &triangulation,
                   const unsigned int                u_degree,
                   const Formulation                 formulation);

    /**
     * As above, with the gel of a cell given by its material_id: cell->material_id() indexes
     * @p materials (kept by reference, like the triangulation). Throws std::invalid_argument if
     * @p materials is empty, if the gels differ in k_BT/nu (one solvent) or in mu_0 (one initial
     * chemical potential; relative 1e-9), and setup() throws for a cell whose material_id has no
     * gel. One gel in @p materials is the one-material system (material_ids are then ignored).
     */
    FemMixedSystem(const std::vector<FloryRehnerGel<dim>> &materials,
                   const dealii::Triangulation<dim>       &triangulation,
                   const unsigned int                      u_degree,
                   const Formulation                       formulation);

    /** Hold the displacement components @p components (0..dim-1) on boundary @p id. */
    void
    constrain_displacement(const dealii::types::boundary_id id,
                           const std::vector<unsigned int> &components);

    /**
     * For the coming step, move the held displacement component @p component of boundary @p id
     * by @p delta (u_{n+1} = u_n + delta there); the component must have been held with
     * constrain_displacement(). Holds until changed; 0 after setup(). Used for prescribed
     * motions such as a punch: call it before initial_guess() of every step.
     */
    void
    set_displacement_increment(const dealii::types::boundary_id id,
                               const unsigned int               component,
                               const double                     delta);

    /**
     * Hold the displacement components @p components (0..dim-1) at the mesh vertex @p vertex
     * only (du = 0 there), e.g. a pin against rigid motion where no boundary face is short
     * enough to carry it. setup() throws std::invalid_argument if no vertex lies within 1e-10
     * times the smallest cell diameter of @p vertex.
     */
    void
    constrain_displacement_at_vertex(const dealii::Point<dim>        &vertex,
                                     const std::vector<unsigned int> &components);

    /** Prescribe mu/k_BT = @p mu_bar on boundary @p id for t > 0. */
    void
    prescribe_chemical_potential(const dealii::types::boundary_id id, const double mu_bar);

    /**
     * For the coming step, change the prescribed mu/k_BT on boundary @p id to @p mu_bar (a
     * boundary of prescribe_chemical_potential()): the value mu_{n+1} takes there, for
     * time-dependent data such as a ramp. Holds until changed. Like set_displacement_increment()
     * it acts through initial_guess(), since the Newton increments are homogeneous on
     * constrained rows: call it before initial_guess() of every step (run_fem_time_loop's
     * prescribe callback). Throws std::invalid_argument for a boundary without prescribed mu.
     */
    void
    set_chemical_potential(const dealii::types::boundary_id id, const double mu_bar);

    /**
     * Distribute the DoFs (displacement block first, then mu), build the constraints and the
     * sparsity pattern, and set the initial state u_0 = 0, mu = mu_0 of the material. Throws
     * std::invalid_argument for an unknown boundary id or component.
     */
    void
    setup();

    /**
     * The first Newton iterate of a step: du = 0, mu = mu_n, with the prescribed mu on its
     * boundaries.
     */
    void
    initial_guess(dealii::Vector<double> &solution) const;

    /**
     * Residual (and, if @p with_matrix, tangent) at the unknowns @p solution (du then mu) for the
     * physical time step @p dt. Throws NonPhysicalState if some quadrature point leaves the
     * physical range (J <= 1).
     */
    void
    assemble(const dealii::Vector<double> &solution,
             const double                  dt,
             const bool                    with_matrix) override;

    /** After convergence: u_n += du, mu_n = mu. */
    void
    update(const dealii::Vector<double> &solution);

    /**
     * The force on the body from the displacement conditions of boundary @p id (per unit
     * thickness in 2D): the consistent reaction, i.e. the displacement rows of the residual
     * assembled last, before the constraints zero them, summed per component over the DoFs of
     * the boundary's faces, for the components the boundary holds (constrain_displacement; the
     * others are zero: no condition, no force, and at a node shared with another boundary they
     * would carry that one's reaction). After a converged step (the residual at the converged
     * state) this is the force that holds the boundary where it is, e.g. the punch's on the gel:
     * the same sign as the MPM's `<piece>_force_*` (doc/statistics.md), the force the boundary
     * exerts on the body. Throws std::invalid_argument for an unknown boundary.
     */
    dealii::Tensor<1, dim>
    boundary_force(const dealii::types::boundary_id id) const;

    /** Mean of the displacement component @p component of u_n over boundary @p id. */
    double
    mean_boundary_displacement(const dealii::types::boundary_id id,
                               const unsigned int               component) const;

    /** The converged deformation F_n = I + grad_0 u_n over the quadrature points. */
    struct DeformationSummary
    {
      /** Smallest det F_n (volume ratio to Omega_0); <= 0 means an inverted cell. */
      double min_det_F = 0.;
      /** Largest ratio of the principal stretches of F_n, lambda_max/lambda_min: the distortion of
       * the mesh's cells relative to their shape in Omega_0 (1: undistorted). */
      double max_stretch_ratio = 0.;
      /** int det F_n dV_0: the volume of Omega_n. */
      double deformed_volume = 0.;
    };

    DeformationSummary
    deformation_summary() const;

    /** The converged fields at one point of a boundary. */
    struct BoundarySample
    {
      dealii::Point<dim>     X;  // position in Omega_0
      dealii::Tensor<1, dim> u;  // u_n
      double                 mu; // mu_n / k_BT
    };

    /**
     * The converged fields at @p per_face + 1 equally spaced points of every face of boundary
     * @p id (points shared by two faces appear twice), in cell order.
     */
    std::vector<BoundarySample>
    boundary_samples(const dealii::types::boundary_id id, const unsigned int per_face) const;

    /** |Omega_0|. */
    double
    volume() const;

    unsigned int
    n_dofs() const;
    unsigned int
    n_u_dofs() const override;
    unsigned int
    n_mu_dofs() const;

    /**
     * The homogeneous constraints of the Newton increments: the rows of matrix() that are
     * constrained hold only a diagonal entry (AffineConstraints puts |K_ii| of the cell matrices
     * there, positive whatever the block), which the signature of the tangent must account for
     * (FemSignatureCheck).
     */
    const dealii::AffineConstraints<double> &
    increment_constraints() const;

    /** The converged state: u_n (from Omega_0) then mu_n, in the DoF order of the system. */
    const dealii::Vector<double> &
    state() const;

    const dealii::DoFHandler<dim> &
    dof_handler() const;

  private:
    /** The gel of every material_id (one entry: the gel of every cell). */
    std::vector<const FloryRehnerGel<dim> *> materials;
    const dealii::Triangulation<dim>        &triangulation;
    const Formulation                        formulation;
    const dealii::FESystem<dim>              fe;
    dealii::DoFHandler<dim>                  dof_handler_;

    std::map<dealii::types::boundary_id, std::vector<bool>> displacement_constraints;
    std::map<dealii::types::boundary_id, double>            mu_constraints;
    /** Vertices with held displacement components (constrain_displacement_at_vertex). */
    std::vector<std::pair<dealii::Point<dim>, std::vector<bool>>> vertex_constraints;
    /** Per boundary with prescribed mu: its mu DoFs, set to mu_constraints in initial_guess(). */
    std::map<dealii::types::boundary_id, std::vector<dealii::types::global_dof_index>> mu_dofs;
    /** Per (boundary, component) held: its DoFs and the increment of the coming step. */
    std::map<std::pair<dealii::types::boundary_id, unsigned int>,
             std::pair<std::vector<dealii::types::global_dof_index>, double>>
      displacement_increments;

    /** Homogeneous constraints of the Newton increments; the prescribed values for the guess. */
    dealii::AffineConstraints<double> zero_constraints, constraints;

    unsigned int n_u_dofs_ = 0;

    dealii::Vector<double> state_;
    /** The residual assembled last without the constraints (for boundary_force()). */
    dealii::Vector<double> unconstrained_residual_;

    /** The gel of @p cell. */
    const FloryRehnerGel<dim> &
    material_of(const dealii::CellAccessor<dim, dim> &cell) const;
  };
} // namespace GelMPM

#endif

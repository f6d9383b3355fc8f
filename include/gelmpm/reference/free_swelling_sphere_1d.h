#ifndef gelmpm_reference_free_swelling_sphere_1d_h
#define gelmpm_reference_free_swelling_sphere_1d_h

#include <vector>

namespace GelMPM
{
  /**
   * @brief The project's own reference for a freely swelling gel sphere: the spherically symmetric
   * counterpart of ConstrainedSwelling1D (derivation in doc/free_swelling_sphere.md).
   *
   * A Flory-Rehner gel sphere occupies 0 <= R <= 1 in its initial configuration (lengths in R_0,
   * times in tau_d = R_0^2/D, mu in k_BT, stresses in k_BT/nu), initially stress-free at the
   * isotropic stretch lambda_0 from the dry state and at mu_0 = mu(lambda_0) of eq. (22). A point
   * at R moves to r(R, t); relative to the initial state the radial and hoop stretches are
   * lambda_r = dr/dR and lambda_theta = r/R, and J = lambda_0^3 lambda_r lambda_theta^2 relative
   * to the dry state. Unlike the layer, mechanical equilibrium does not tie mu to the stretch
   * pointwise; the two unknowns r(R, t) and mu(R, t) solve, in the reference coordinate R,
   *
   *   d/dR (R^2 s_r) - 2 R s_theta = 0                     (radial equilibrium),
   *   d/dt (lambda_r lambda_theta^2) = R^-2 d/dR (R^2 k d mu/dR),  k = (J - 1)/(lambda_0^3
   * lambda_r^2),
   *
   * with s_r, s_theta the nominal stresses of the energy per initial volume, r(0) = 0, no flux at
   * R = 0, s_r = 0 and mu = mu_b(t) at R = 1; mu_b = mu_top for t > 0 or, with a ramp t_r > 0, a
   * linear rise from mu_0 at t = 0 to mu_top at t_r.
   *
   * Discretisation: nodes R_i = 1 - (1 - i/n)^g graded towards the surface carry r_i (r_0 = 0);
   * each cell [R_k, R_k+1] carries one mu_k (a staggered, P1-P0 arrangement). Equilibrium is the
   * stationarity of the discrete energy sum_k W(lambda_r, lambda_theta, J, mu_k) V0_k in the r_i,
   * with lambda_r = (r_k+1 - r_k)/(R_k+1 - R_k), J = lambda_0^3 (r_k+1^3 - r_k^3)/(R_k+1^3 -
   * R_k^3) (the cell's exact volume ratio) and lambda_theta = (J/(lambda_0^3 lambda_r))^1/2 (the
   * hoop stretch that reproduces it), so that the traction-free surface is the natural condition
   * and a uniform dilation is an exact discrete solution. Solvent conservation is a finite-volume
   * balance per cell, d/dt (r_k+1^3 - r_k^3)/3 = F_k+1 - F_k with the fluxes F_i = R_i^2 k d mu/dR
   * on the nodes (F_0 = 0: the centre's face has no area). Variable-step BDF2 in time (a
   * backward-Euler start), steps growing geometrically; Newton's method on the coupled banded
   * system (LAPACK dgbsv) each step. Written from the closed-form equations, independently of the
   * MPM solver, of FloryRehnerGel and of ConstrainedSwelling1D.
   */
  class FreeSwellingSphere1D
  {
  public:
    struct Parameters
    {
      double       chi      = 0.1;
      double       N_nu     = 7.299e-3;
      double       lambda_0 = 1.2801;
      double       mu_top   = 0.;
      unsigned int n_cells  = 400;
      /** Exponent g of the node grading (1: uniform). */
      double grading = 2.;
      /** First time step and geometric growth factor of the steps. */
      double first_step = 1e-9;
      double growth     = 1.02;
      /** Time over which the bath's mu rises linearly from mu_0 to mu_top (0: a step at 0+). */
      double ramp = 0.;
    };

    explicit FreeSwellingSphere1D(const Parameters &parameters);

    /**
     * mu/kT of the stress-free isotropic state at the stretch @p lambda from the initial state
     * (eq. (22) at the stretch lambda_0 lambda from the dry state).
     */
    double
    chemical_potential(const double lambda) const;
    /** The free-swelling stretch from the initial state at @p mu (bisection). */
    double
    stretch_at(const double mu) const;
    /** mu/kT of the bath at time @p t (mu_top, or the ramp's value before its end). */
    double
    bath_chemical_potential(const double t) const;

    /**
     * Advances to time @p t (>= time()), landing exactly on it and on the end of the ramp on the
     * way. Throws on Newton failure.
     */
    void
    advance_to(const double t);

    double
    time() const;
    unsigned int
    n_steps() const;
    /** r(1, t): the outer radius in R_0. */
    double
    outer_radius() const;
    /**
     * The solvent taken up since t = 0, sum over the cells of the current minus the initial
     * volume (nu/(4 pi R_0^3) times the number of solvent molecules; each cell's J from its
     * stretches of the energy).
     */
    double
    solvent_uptake() const;
    /** The inward solvent flux through the surface, F_n = k d mu/dR at R = 1 (same units). */
    double
    surface_flux() const;
    /**
     * The time integral of surface_flux() over the steps taken, with the time stepping's own
     * weights (BDF2): equal to solvent_uptake() up to the Newton tolerance if the scheme
     * conserves solvent.
     */
    double
    absorbed_solvent() const;

    /** Nodes R_i (initial configuration, in R_0) and their current radii r_i. */
    const std::vector<double> &
    nodes() const;
    const std::vector<double> &
    radii() const;
    /** Cell centres (R_k + R_k+1)/2 and the cells' mu_k/kT. */
    std::vector<double>
    cell_centres() const;
    const std::vector<double> &
    chemical_potentials() const;
    /** The cells' radial and hoop stretches from the initial state. */
    std::vector<double>
    radial_stretches() const;
    std::vector<double>
    hoop_stretches() const;
    /**
     * The cells' nominal radial and hoop stresses s_r, s_theta (per initial area, in k_BT/nu):
     * the derivatives of the energy per initial volume by lambda_r and by one of the two hoop
     * stretches.
     */
    std::vector<double>
    radial_stresses() const;
    std::vector<double>
    hoop_stresses() const;

  private:
    /** The state of one cell from the radii of its two nodes. */
    struct Cell
    {
      double lambda_r, lambda_theta, J;
      double volume;
      /** dJ/dr_a, dJ/dr_b. */
      double dJ_a, dJ_b;
    };
    Cell
    cell(const unsigned int k, const double r_a, const double r_b) const;

    /** One BDF2 step (backward Euler if there is no previous step) of length @p dt. */
    void
    step(const double dt);

    Parameters          parameters;
    std::vector<double> R, centre, volume_0;
    std::vector<double> r, r_old;
    std::vector<double> mu;
    double              t = 0., dt_old = 0., dt_next;
    double              absorbed = 0., absorbed_old = 0.;
    unsigned int        steps = 0;
  };
} // namespace GelMPM

#endif

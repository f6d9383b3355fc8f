#ifndef gelmpm_reference_constrained_swelling_1d_h
#define gelmpm_reference_constrained_swelling_1d_h

#include <vector>

namespace GelMPM
{
  /**
   * @brief The project's own reference for constrained swelling (paper §4.1): the one-dimensional
   * nonlinear diffusion problem of a gel layer held in-plane, after Bouklas & Huang, solved by
   * finite differences (derivation in doc/constrained_swelling.md).
   *
   * The layer occupies 0 <= Y <= 1 in its initial configuration (lengths in h_0, times in
   * tau_d = h_0^2/D). Relative to the dry state F = diag(lambda_0, lambda_0 lambda, lambda_0).
   * Mechanical equilibrium with a traction-free top makes P_22 = 0 everywhere, which ties the
   * chemical potential to the stretch pointwise,
   *
   *   mu/kT = N nu (F_22^2 - 1)/J + ln(1 - 1/J) + 1/J + chi/J^2,   J = lambda_0^3 lambda,
   *
   * and solvent conservation becomes d lambda/dt = d/dY [ k(lambda) d mu/dY ] with
   * k = (J - 1)/(lambda_0^3 lambda^2). Boundary conditions: mu = mu_top at Y = 1 for t > 0 (or,
   * with a ramp t_r > 0, rising linearly from mu_0 = mu(lambda = 1) at t = 0 to mu_top at t_r), no
   * flux at Y = 0; initially lambda = 1.
   *
   * Discretisation: vertex-centred finite volumes on nodes graded towards the top (the early
   * boundary layer), Y_i = 1 - (1 - i/n)^g; variable-step BDF2 in time (one backward-Euler start
   * step) with steps growing geometrically; Newton's method on the tridiagonal system each step.
   * Everything here is written from the closed-form 1D equations, independently of the MPM
   * solver and of FloryRehnerGel, so that the two can check each other.
   */
  class ConstrainedSwelling1D
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
      /** Time over which mu on the top rises linearly from mu_0 to mu_top (0: a step at 0+). */
      double ramp = 0.;
    };

    explicit ConstrainedSwelling1D(const Parameters &parameters);

    /** mu/kT at P_22 = 0 as a function of the stretch lambda, and its derivative. */
    double
    chemical_potential(const double lambda) const;
    double
    chemical_potential_derivative(const double lambda) const;
    /** The stretch lambda at which chemical_potential(lambda) = @p mu (Newton, bracketed). */
    double
    stretch_at(const double mu) const;
    /** mu/kT prescribed on the top at time @p t (mu_top, or the ramp's value before its end). */
    double
    top_chemical_potential(const double t) const;
    /** The mobility k(lambda) and its derivative. */
    double
    mobility(const double lambda) const;
    double
    mobility_derivative(const double lambda) const;

    /** Advances to time @p t (>= time()), landing exactly on it. Throws on Newton failure. */
    void
    advance_to(const double t);

    double
    time() const;
    unsigned int
    n_steps() const;
    /** Delta h / h_0 = int_0^1 (lambda - 1) dY (trapezoidal rule on the nodes). */
    double
    thickness_change() const;
    /** Nodes Y_i (initial configuration, in h_0), stretches lambda_i, mu_i/kT. */
    const std::vector<double> &
    nodes() const;
    const std::vector<double> &
    stretches() const;
    std::vector<double>
    chemical_potentials() const;

  private:
    /** One BDF2 step (backward Euler if there is no previous step) of length @p dt. */
    void
    step(const double dt);

    Parameters          parameters;
    double              lambda_top;
    std::vector<double> Y, volume;
    std::vector<double> lambda, lambda_old;
    double              t = 0., dt_old = 0., dt_next;
    unsigned int        steps = 0;
  };
} // namespace GelMPM

#endif

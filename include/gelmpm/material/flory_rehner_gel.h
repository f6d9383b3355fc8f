#ifndef gelmpm_material_flory_rehner_gel_h
#define gelmpm_material_flory_rehner_gel_h

#include <gelmpm/core/non_physical_state.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <stdexcept>
#include <string>

namespace GelMPM
{
  /**
   * @brief The Flory–Rehner hydrogel of the paper's §2.2 in the mixed (F, mu) form, eq. (19), and
   * the rescaled quantities of the incremental (previously converged Lagrangian) formulation,
   * eq. (25)–(30). Pure functions of their arguments: no grid, no particles.
   *
   * Units: stresses in the units of the shear modulus G = N k_BT; the chemical potential `mu` is
   * mu/(k_BT); k_BT/nu = G/(N nu). Then
   *   W(F, mu) = G/2 (F:F - 2 ln J - 3) - (G/N nu)[(J-1) ln(J/(J-1)) + chi/J] - (G/N nu) mu (J-1)
   * per unit dry volume, and derivatives with respect to mu are with respect to mu/(k_BT).
   *
   * F is the deformation gradient from the dry state. In 2D the gel is in plane strain with a
   * three-dimensional dry reference whose out-of-plane stretch stays at lambda_0: F is the in-plane
   * 2x2 block, J = lambda_0 det F and F:F includes lambda_0^2; all tensors returned are in-plane.
   *
   * Every evaluation throws NonPhysicalState for J <= 1.
   */
  template <int dim>
  class FloryRehnerGel
  {
  public:
    /** Table 1: G = 1, chi = 0.1, N nu = 7.299e-3, D = 1, lambda_0 = 1.2801. */
    FloryRehnerGel();

    FloryRehnerGel(const double shear_modulus,
                   const double chi,
                   const double N_nu,
                   const double diffusivity,
                   const double lambda_0);

    /** Declare the section "Material". */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section "Material"; throws InputError on non-physical values. */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    shear_modulus() const;
    double
    chi() const;
    double
    N_nu() const;
    double
    diffusivity() const;
    /** Initial isotropic stretch of the pre-swollen, stress-free state. */
    double
    lambda_0() const;
    /** mu_0 = mu_0(lambda_0), eq. (22). */
    double
    mu_0() const;
    /** k_BT / nu = G / (N nu). */
    double
    kT_over_nu() const;

    /** J = det F (3D) or lambda_0 det F (2D). */
    double
    J(const dealii::Tensor<2, dim> &F) const;

    /**
     * J of the 2D state with the out-of-plane stretch F_33 = @p out_of_plane (an axisymmetric
     * scene's hoop stretch; lambda_0 gives J(F)): out_of_plane det F. In 3D det F.
     */
    double
    J(const dealii::Tensor<2, dim> &F, const double out_of_plane) const;

    /** W(F, mu), eq. (19). */
    double
    free_energy(const dealii::Tensor<2, dim> &F, const double mu) const;

    /** Nominal stress P = dW/dF. */
    dealii::Tensor<2, dim>
    stress(const dealii::Tensor<2, dim> &F, const double mu) const;

    /**
     * The in-plane nominal stress with the out-of-plane stretch @p out_of_plane (which enters
     * only through J when F is block diagonal): stress(F, mu) for lambda_0.
     */
    dealii::Tensor<2, dim>
    stress(const dealii::Tensor<2, dim> &F, const double mu, const double out_of_plane) const;

    /** dP/dF, A_iJkL = dP_iJ / dF_kL. */
    dealii::Tensor<4, dim>
    stress_tangent(const dealii::Tensor<2, dim> &F, const double mu) const;

    /** dP/dmu = -(G/N nu) J F^{-T}. */
    dealii::Tensor<2, dim>
    stress_mu_derivative(const dealii::Tensor<2, dim> &F) const;

    /** k_BT C = -dW/dmu = (G/N nu)(J - 1). */
    double
    concentration(const dealii::Tensor<2, dim> &F) const;

    /**
     * The solvent-transport coefficient of the incremental weak form with the symmetric
     * approximation M_n ~ m_n I of §2.4, m_n = C_n D/(k_BT), C_n = (J_p - 1)/(nu J_p), evaluated
     * at F_p = F_n F_0 (frozen over a step). In these units the coefficient multiplying
     * grad mu . grad q is (k_BT)^2 m_n = (G/N nu) D (J_p - 1)/J_p.
     */
    double
    mobility(const dealii::Tensor<2, dim> &F_p) const;

    /** mobility() of the 2D state with the out-of-plane stretch @p out_of_plane. */
    double
    mobility(const dealii::Tensor<2, dim> &F_p, const double out_of_plane) const;

    /** Incremental quantities for F = dF F_p, eq. (25)–(30). */
    struct Incremental
    {
      /** P_n = P(dF F_p) F_p^T / J_p. */
      dealii::Tensor<2, dim> P_n;
      /** A_n = dP_n/d(dF). */
      dealii::Tensor<4, dim> A_n;
      /** dP_n/dmu = -(G/N nu) dJ dF^{-T}. */
      dealii::Tensor<2, dim> dP_n_dmu;
      /** dJ = det dF (the out-of-plane stretch does not change in a step). */
      double delta_J;
      /** Total J = dJ J_p. */
      double J;
      /**
       * The structure of A_n, which the volume term's tangent contracts instead of its dim^4
       * entries (doc/performance.md, "Assembly at its flop limit"):
       *   A_n_iJkL = delta_ik S_JL + a dF^{-T}_iL dF^{-T}_kJ + b dF^{-T}_iJ dF^{-T}_kL,
       * with S = G F_p F_p^T / J_p (G the shear modulus). Set with the tangent only.
       */
      dealii::Tensor<2, dim> S;
      /** dF^{-T}, of the structure of A_n. */
      dealii::Tensor<2, dim> dFit;
      /** The coefficients a and b of the structure of A_n. */
      double a = 0., b = 0.;
      /**
       * db/d(ln J) = J db/dJ: the derivative of b along a direction W of dF is c dF^{-T}:W (and
       * that of a is -b dF^{-T}:W, since d ln J = dF^{-T}:W), so that the derivative of A_n along W
       * has a closed form (add_displacement_nitsche()). Set with the tangent only.
       */
      double c = 0.;
    };

    /**
     * P_n, A_n and dP_n/dmu at the increment @p delta_F from F_p = F_n F_0; without
     * @p with_tangent only P_n, dJ and J (A_n and dP_n/dmu are left zero), which is all a
     * residual needs.
     */
    Incremental
    incremental(const dealii::Tensor<2, dim> &delta_F,
                const double                  mu,
                const dealii::Tensor<2, dim> &F_p,
                const bool                    with_tangent = true) const;

    /**
     * The largest mu/(k_BT) at which the gel has a stress-free swollen state: in a bath above it
     * the gel absorbs solvent without bound. The supremum over the stretch s from the dry state
     * of mu(s) = -P_11(F, 0) / (dP_11/dmu) at F = s I, the bath in which that state is free of
     * stress:
     * - plane strain (2D, F_33 = lambda_0, J = lambda_0 s^2): mu(s) = N nu (s^2 - 1)/J + ln(1 -
     *   1/J) + 1/J + chi/J^2, which rises to N nu/lambda_0 (not N nu/lambda_0^3: s^2/J =
     *   1/lambda_0), unattained; 5.702e-3 for Table 1;
     * - isotropic (3D, and with @p axisymmetric the 2D gel of an axisymmetric scene, whose body
     *   of revolution swells in 3D): eq. (22), which tends to 0 from above and so has an interior
     *   maximum; 1.697e-3 for Table 1's chi and N nu, whatever lambda_0.
     * tests/material/swelling_limit checks both against a walk of the law in closed form: a
     * stress-free state at 0.999 times the limit, none at 1.001 times it.
     */
    double
    largest_swelling_chemical_potential(const bool axisymmetric = false) const;

    /** Eq. (22): mu_0/(k_BT) of the stress-free isotropic swelling lambda_0. */
    static double
    mu_0_from_lambda_0(const double lambda_0, const double chi, const double N_nu);

    /**
     * Inverse of eq. (22) on its increasing branch (bracketing and bisection with Newton
     * polishing). Throws InputError naming "Material/Initial chemical potential" when no
     * stretch gives @p mu_0.
     */
    static double
    lambda_0_from_mu_0(const double mu_0, const double chi, const double N_nu);

    /**
     * In-plane stretch lambda (total in-plane stretch lambda_0 lambda, F33 = lambda_0 in 2D) of
     * the stress-free state at chemical potential @p mu in plane strain: P_11 = 0. In 3D, the free
     * isotropic swelling stretch relative to lambda_0.
     */
    double
    plane_strain_free_swelling_stretch(const double mu) const;

    /** Stretch lambda of a layer constrained in-plane, F = diag(lambda_0, lambda_0 lambda
     * [, lambda_0]), at which P_22 = 0 (paper §4.1). */
    double
    constrained_swelling_stretch(const double mu) const;

  private:
    /** Throw InputError unless the initial stretch is a swelling equilibrium with mu_0 <= 0. */
    void
    check_initial_bath(const double stretch) const;

    /** d psi/dJ and d^2 psi/dJ^2 of the mixing and solvent part psi(J). */
    void
    volumetric_derivatives(const double J, const double mu, double &dpsi, double &d2psi) const;

    void
    check_physical(const double J) const;

    double shear_modulus_ = 1.;
    double chi_           = 0.1;
    double N_nu_          = 7.299e-3;
    double diffusivity_   = 1.;
    double lambda_0_      = 1.2801;
  };
} // namespace GelMPM

#endif

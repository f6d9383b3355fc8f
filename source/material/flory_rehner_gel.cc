#include <gelmpm/core/input_error.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace GelMPM
{
  namespace
  {
    std::string
    number(const double x, const int precision = 6)
    {
      std::ostringstream text;
      text.precision(precision);
      text << x;
      return text.str();
    }


    /** The fewest significant digits (at least 6) at which @p a and @p b print differently. */
    int
    distinguishing_precision(const double a, const double b)
    {
      int precision = 6;
      while (precision < 17 && number(a, precision) == number(b, precision))
        ++precision;
      return precision;
    }


    /** @p bound with the fewest digits (at least @p precision) that do not exceed it. */
    std::string
    number_not_above(const double bound, int precision)
    {
      while (precision < 17 && std::stod(number(bound, precision)) > bound)
        ++precision;
      return number(bound, precision);
    }
  } // namespace


  using dealii::Tensor;

  namespace
  {
    /**
     * Relative distance above the dry state (J = 1) at which a bracket for a swelling stretch
     * starts: the energy is undefined at J = 1 itself, and the stretch sought is far above it.
     */
    constexpr double above_dry_state = 1e-12;

    /** Root of a continuous function increasing on [lo, hi] with f(lo) < 0 < f(hi). */
    double
    bisect(const std::function<double(double)> &f, double lo, double hi)
    {
      for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
        {
          const double mid        = 0.5 * (lo + hi);
          (f(mid) < 0. ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }
  } // namespace


  template <int dim>
  FloryRehnerGel<dim>::FloryRehnerGel() = default;


  template <int dim>
  FloryRehnerGel<dim>::FloryRehnerGel(const double shear_modulus,
                                      const double chi,
                                      const double N_nu,
                                      const double diffusivity,
                                      const double lambda_0)
    : shear_modulus_(shear_modulus)
    , chi_(chi)
    , N_nu_(N_nu)
    , diffusivity_(diffusivity)
    , lambda_0_(lambda_0)
  {}


  template <int dim>
  void
  FloryRehnerGel<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Material");
    prm.declare_entry("Shear modulus",
                      "1",
                      Patterns::Double(),
                      "G = N k_BT, the shear modulus of the dry network; the unit of all stresses "
                      "of the scene (Table 1: 1 MPa, written as 1).");
    prm.declare_entry(
      "Flory-Huggins chi",
      "0.1",
      Patterns::Double(),
      "chi, the Flory-Huggins polymer-solvent interaction parameter (Table 1: 0.1). Accepted: "
      "0 <= chi <= chi_max, where with 'Initial state = stretch' chi_max makes the initial "
      "state the swollen equilibrium in pure solvent (mu_0 = 0).");
    prm.declare_entry("N nu",
                      "7.299e-3",
                      Patterns::Double(),
                      "N nu, the number of network strands per dry volume times the solvent "
                      "molecular volume (Table 1: 7.299e-3). Then k_BT/nu = G/(N nu).");
    prm.declare_entry("Diffusivity",
                      "1",
                      Patterns::Double(),
                      "D, the solvent diffusivity of Fick's law, eq. (20). With 'Time "
                      "stepping/Characteristic length' L it sets the time unit tau_d = L^2/D.");
    prm.declare_entry("Initial state",
                      "stretch",
                      Patterns::Selection("stretch|chemical potential"),
                      "How the stress-free initial state is given: by 'Initial stretch' lambda_0 "
                      "or by 'Initial chemical potential' mu_0/(k_BT); the other follows from "
                      "eq. (22).");
    prm.declare_entry("Initial stretch",
                      "1.2801",
                      Patterns::Double(),
                      "lambda_0 > 1, the isotropic stretch of the pre-swollen initial state "
                      "(Table 1: 1.2801). Used when 'Initial state = stretch'.");
    prm.declare_entry("Initial chemical potential",
                      "-0.1460",
                      Patterns::Double(),
                      "mu_0/(k_BT) of the initial state (Table 1: -0.1460; §4.2: 0). Used when "
                      "'Initial state = chemical potential'.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  FloryRehnerGel<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    shear_modulus_          = prm.get_double("Shear modulus");
    chi_                    = prm.get_double("Flory-Huggins chi");
    N_nu_                   = prm.get_double("N nu");
    diffusivity_            = prm.get_double("Diffusivity");
    const bool   by_stretch = (prm.get("Initial state") == "stretch");
    const double stretch    = prm.get_double("Initial stretch");
    const double mu0        = prm.get_double("Initial chemical potential");
    prm.leave_subsection();

    require(shear_modulus_ > 0.,
            "Material/Shear modulus",
            "must be positive",
            "give the shear modulus G = N k_BT > 0 (Table 1: 1)");
    require(N_nu_ > 0., "Material/N nu", "must be positive", "give N nu > 0 (Table 1: 7.299e-3)");
    require(diffusivity_ > 0.,
            "Material/Diffusivity",
            "must be positive, but is " + std::to_string(diffusivity_),
            "give the solvent diffusivity D > 0");
    require(std::isfinite(chi_), "Material/Flory-Huggins chi", "is not finite", "give a number");
    // Flory-Huggins theory (e.g. the solubility-parameter estimate chi = 0.34 + ...) gives
    // chi >= 0 for a polymer and a solvent without specific interactions.
    require(chi_ >= 0.,
            "Material/Flory-Huggins chi",
            "is negative (" + number(chi_) + "), outside the physical range chi >= 0",
            "give 0 <= chi (Table 1: 0.1)");
    if (by_stretch)
      {
        require(stretch > 1.,
                "Material/Initial stretch",
                "must be larger than 1 (a gel holds solvent), but is " + std::to_string(stretch),
                "give lambda_0 > 1 (Table 1: 1.2801)");
        lambda_0_ = stretch;
        check_initial_bath(stretch);
      }
    else
      lambda_0_ = lambda_0_from_mu_0(mu0, chi_, N_nu_);
  }


  template <int dim>
  void
  FloryRehnerGel<dim>::check_initial_bath(const double stretch) const
  {
    // The stress-free initial state is the equilibrium of the gel in a bath at mu_0 (eq. (22)); a
    // bath above pure solvent (mu_0 > 0) would be solvent under pressure.
    const double l6      = std::pow(stretch, 6);
    const double chi_max = chi_ - l6 * mu_0_from_lambda_0(stretch, chi_, N_nu_);
    // As many digits as it takes to tell chi from chi_max, and a bound that is one.
    const int digits = distinguishing_precision(chi_, chi_max);
    require(chi_ <= chi_max,
            "Material/Flory-Huggins chi",
            "is " + number(chi_, digits) + ", above chi_max = " + number(chi_max, digits) +
              " for 'Initial stretch' = " + number(stretch) + " and 'N nu' = " + number(N_nu_) +
              ": the initial state would be in equilibrium only with solvent above the pure "
              "solvent's chemical potential (mu_0/(k_BT) = " +
              number(mu_0_from_lambda_0(stretch, chi_, N_nu_)) + " > 0)",
            "give 0 <= chi <= " + number_not_above(chi_max, digits) +
              " or a smaller 'Initial stretch'");
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::largest_swelling_chemical_potential(const bool axisymmetric) const
  {
    const bool plane_strain = (dim == 2 && !axisymmetric);
    // mu(s) from the stress itself in plane strain, so that it cannot drift from the law the
    // solver assembles; isotropic swelling is eq. (22), the same law at F = s I in 3D.
    const auto mu_at = [&](const double s) {
      if (!plane_strain)
        return mu_0_from_lambda_0(s, chi_, N_nu_);
      Tensor<2, dim> F;
      for (unsigned int d = 0; d < dim; ++d)
        F[d][d] = s;
      return -stress(F, 0.)[0][0] / stress_mu_derivative(F)[0][0];
    };
    // The dry state, J = 1, and the limit of mu(s) for s -> infinity.
    const double dry     = plane_strain ? 1. / std::sqrt(lambda_0_) : 1.;
    double       largest = plane_strain ? N_nu_ / lambda_0_ : 0.;
    for (unsigned int k = 0; k <= 4000; ++k)
      largest = std::max(largest, mu_at(dry * (1. + std::pow(10., -6. + 10. * k / 4000.))));
    return largest;
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::shear_modulus() const
  {
    return shear_modulus_;
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::chi() const
  {
    return chi_;
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::N_nu() const
  {
    return N_nu_;
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::diffusivity() const
  {
    return diffusivity_;
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::lambda_0() const
  {
    return lambda_0_;
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::mu_0() const
  {
    return mu_0_from_lambda_0(lambda_0_, chi_, N_nu_);
  }
  template <int dim>
  double
  FloryRehnerGel<dim>::kT_over_nu() const
  {
    return shear_modulus_ / N_nu_;
  }


  template <int dim>
  void
  FloryRehnerGel<dim>::check_physical(const double J) const
  {
    if (!(J > 1.))
      {
        std::ostringstream message;
        message << "the gel state J = " << J
                << " is outside the physical range J > 1 (less solvent than none)";
        throw NonPhysicalState(message.str());
      }
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::J(const Tensor<2, dim> &F) const
  {
    return (dim == 2 ? lambda_0_ : 1.) * dealii::determinant(F);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::J(const Tensor<2, dim> &F, const double out_of_plane) const
  {
    return (dim == 2 ? out_of_plane : 1.) * dealii::determinant(F);
  }


  template <int dim>
  void
  FloryRehnerGel<dim>::volumetric_derivatives(const double J,
                                              const double mu,
                                              double      &dpsi,
                                              double      &d2psi) const
  {
    // psi(J) = -(G/N nu)[(J-1) ln(J/(J-1)) + chi/J + mu (J-1)]
    const double k = kT_over_nu();
    dpsi           = k * (std::log1p(-1. / J) + 1. / J + chi_ / (J * J) - mu);
    d2psi          = k * (1. / (J * (J - 1.)) - 1. / (J * J) - 2. * chi_ / (J * J * J));
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::free_energy(const Tensor<2, dim> &F, const double mu) const
  {
    const double J_ = J(F);
    check_physical(J_);
    const double FF = dealii::scalar_product(F, F) + (dim == 2 ? lambda_0_ * lambda_0_ : 0.);
    return 0.5 * shear_modulus_ * (FF - 2. * std::log(J_) - 3.) -
           kT_over_nu() * ((J_ - 1.) * std::log(J_ / (J_ - 1.)) + chi_ / J_ + mu * (J_ - 1.));
  }


  template <int dim>
  Tensor<2, dim>
  FloryRehnerGel<dim>::stress(const Tensor<2, dim> &F, const double mu) const
  {
    return stress(F, mu, lambda_0_);
  }


  template <int dim>
  Tensor<2, dim>
  FloryRehnerGel<dim>::stress(const Tensor<2, dim> &F,
                              const double          mu,
                              const double          out_of_plane) const
  {
    const double J_ = J(F, out_of_plane);
    check_physical(J_);
    double dpsi, d2psi;
    volumetric_derivatives(J_, mu, dpsi, d2psi);
    const Tensor<2, dim> F_inv_T = dealii::transpose(dealii::invert(F));
    return shear_modulus_ * (F - F_inv_T) + dpsi * J_ * F_inv_T;
  }


  template <int dim>
  Tensor<4, dim>
  FloryRehnerGel<dim>::stress_tangent(const Tensor<2, dim> &F, const double mu) const
  {
    const double J_ = J(F);
    check_physical(J_);
    double dpsi, d2psi;
    volumetric_derivatives(J_, mu, dpsi, d2psi);
    const Tensor<2, dim> Fit = dealii::transpose(dealii::invert(F));
    // A = G I(ik)I(JL) + (G - psi' J) F^-T_iL F^-T_kJ + (psi'' J + psi') J F^-T_iJ F^-T_kL
    const double   a = shear_modulus_ - dpsi * J_;
    const double   b = (d2psi * J_ + dpsi) * J_;
    Tensor<4, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int Jj = 0; Jj < dim; ++Jj)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            A[i][Jj][k][L] = (i == k && Jj == L ? shear_modulus_ : 0.) +
                             a * Fit[i][L] * Fit[k][Jj] + b * Fit[i][Jj] * Fit[k][L];
    return A;
  }


  template <int dim>
  Tensor<2, dim>
  FloryRehnerGel<dim>::stress_mu_derivative(const Tensor<2, dim> &F) const
  {
    const double J_ = J(F);
    check_physical(J_);
    return -kT_over_nu() * J_ * dealii::transpose(dealii::invert(F));
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::concentration(const Tensor<2, dim> &F) const
  {
    const double J_ = J(F);
    check_physical(J_);
    return kT_over_nu() * (J_ - 1.);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::mobility(const Tensor<2, dim> &F_p) const
  {
    return mobility(F_p, lambda_0_);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::mobility(const Tensor<2, dim> &F_p, const double out_of_plane) const
  {
    const double J_p = J(F_p, out_of_plane);
    check_physical(J_p);
    return kT_over_nu() * diffusivity_ * (J_p - 1.) / J_p;
  }


  template <int dim>
  typename FloryRehnerGel<dim>::Incremental
  FloryRehnerGel<dim>::incremental(const Tensor<2, dim> &delta_F,
                                   const double          mu,
                                   const Tensor<2, dim> &F_p,
                                   const bool            with_tangent) const
  {
    const Tensor<2, dim> F   = delta_F * F_p;
    const double         J_p = J(F_p);
    Incremental          result;
    result.delta_J = dealii::determinant(delta_F);
    result.J       = result.delta_J * J_p;
    check_physical(result.J);

    double dpsi, d2psi;
    volumetric_derivatives(result.J, mu, dpsi, d2psi);
    const Tensor<2, dim> Fit = dealii::transpose(dealii::invert(F));
    const Tensor<2, dim> P   = shear_modulus_ * (F - Fit) + dpsi * result.J * Fit;
    result.P_n               = P * dealii::transpose(F_p) / J_p;
    if (!with_tangent)
      return result;

    // A_n_iJkL = (1/J_p) A_iMkN F_p_JM F_p_LN; with G = F^-T F_p^T = dF^-T the pulled-back
    // inverse, A_n = [G I(ik) (F_p F_p^T)_JL + a G_iL G_kJ + b G_iJ G_kL] / J_p.
    const Tensor<2, dim> dFit = dealii::transpose(dealii::invert(delta_F));
    const Tensor<2, dim> C_p  = F_p * dealii::transpose(F_p);
    const double         a    = (shear_modulus_ - dpsi * result.J) / J_p;
    const double         b    = (d2psi * result.J + dpsi) * result.J / J_p;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int Jj = 0; Jj < dim; ++Jj)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            result.A_n[i][Jj][k][L] = (i == k ? shear_modulus_ * C_p[Jj][L] / J_p : 0.) +
                                      a * dFit[i][L] * dFit[k][Jj] + b * dFit[i][Jj] * dFit[k][L];
    result.dP_n_dmu = -kT_over_nu() * result.delta_J * dFit;
    result.S        = (shear_modulus_ / J_p) * C_p;
    result.dFit     = dFit;
    result.a        = a;
    result.b        = b;
    // b J_p = psi'' J^2 + psi' J, so J db/dJ = b + (psi''' J + 2 psi'') J^2 / J_p.
    const double Jt    = result.J;
    const double d3psi = kT_over_nu() * (-(2. * Jt - 1.) / (Jt * Jt * (Jt - 1.) * (Jt - 1.)) +
                                         2. / (Jt * Jt * Jt) + 6. * chi_ / (Jt * Jt * Jt * Jt));
    result.c           = b + (d3psi * Jt + 2. * d2psi) * Jt * Jt / J_p;
    return result;
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::mu_0_from_lambda_0(const double lambda_0,
                                          const double chi,
                                          const double N_nu)
  {
    const double l3 = lambda_0 * lambda_0 * lambda_0;
    return N_nu * (1. / lambda_0 - 1. / l3) + std::log1p(-1. / l3) + 1. / l3 + chi / (l3 * l3);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::lambda_0_from_mu_0(const double mu_0, const double chi, const double N_nu)
  {
    const auto f = [&](const double l) {
      return mu_0_from_lambda_0(l, chi, N_nu) - mu_0;
    };
    // Walk up the increasing branch of eq. (22) until it passes mu_0.
    double lo = 1. + 1e-14, hi = 1.001;
    require(f(lo) < 0.,
            "Material/Flory-Huggins chi",
            "is " + number(chi) + ": at 'Initial chemical potential' = " + number(mu_0) +
              " the gel would hold no solvent (eq. (22) has no swollen state)",
            "give a smaller chi (Table 1: 0.1) or a larger 'Initial chemical potential'");
    while (f(hi) < 0.)
      {
        const double next = hi * 1.05;
        if (next > 1e6 || mu_0_from_lambda_0(next, chi, N_nu) < mu_0_from_lambda_0(hi, chi, N_nu))
          throw InputError("Material/Initial chemical potential",
                           "has no stress-free swollen state (eq. (22) stays below " +
                             std::to_string(mu_0_from_lambda_0(hi, chi, N_nu)) + ")",
                           "give a smaller mu_0/(k_BT), e.g. 0 for a fully swollen gel");
        lo = hi;
        hi = next;
      }
    return bisect(f, lo, hi);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::plane_strain_free_swelling_stretch(const double mu) const
  {
    // F = lambda_0 lambda I (in-plane); J = lambda_0^3 lambda^dim' with dim' the in-plane count.
    const auto P11 = [&](const double l) {
      Tensor<2, dim> F;
      for (unsigned int d = 0; d < dim; ++d)
        F[d][d] = lambda_0_ * l;
      return stress(F, mu)[0][0];
    };
    double lo = std::pow(lambda_0_, -3. / dim) * (1. + above_dry_state), hi = 2.;
    while (P11(hi) < 0.)
      hi *= 2.;
    return bisect(P11, lo, hi);
  }


  template <int dim>
  double
  FloryRehnerGel<dim>::constrained_swelling_stretch(const double mu) const
  {
    const auto P22 = [&](const double l) {
      Tensor<2, dim> F;
      for (unsigned int d = 0; d < dim; ++d)
        F[d][d] = lambda_0_;
      F[1][1] = lambda_0_ * l;
      return stress(F, mu)[1][1];
    };
    double lo = std::pow(lambda_0_, -3.) * (1. + above_dry_state), hi = 2.;
    while (P22(hi) < 0.)
      hi *= 2.;
    return bisect(P22, lo, hi);
  }


  template class FloryRehnerGel<2>;
  template class FloryRehnerGel<3>;
} // namespace GelMPM

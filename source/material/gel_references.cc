#include <gelmpm/material/gel_references.h>

#include <deal.II/base/tensor.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace GelMPM
{
  namespace
  {
    /**
     * Relative distance above the dry state (J = 1) at which the walk for a swelling stretch
     * starts: the mixing energy is undefined at J = 1 and tends to -infinity above it.
     */
    constexpr double start_above_dry = 1e-12;

    /**
     * The first root above @p lo of a function that is negative at @p lo (the dry state) and
     * positive once the gel has swollen past its equilibrium: a walk up by factors 1.05 brackets
     * the first change of sign (a gel with a volume phase transition has several roots; the
     * first is the swelling branch the solver starts on), then TOMS 748 to the last bits.
     */
    double
    first_root_above(const std::function<double(double)> &f,
                     const double                         lo,
                     const std::string                   &what)
    {
      double a = lo, b = lo * 1.05;
      double fa = f(a), fb = f(b);
      while (!(fb >= 0.))
        {
          if (b > 1e6)
            throw std::domain_error(what + ": no swollen equilibrium (the gel would take up "
                                           "solvent without bound at this chemical potential)");
          a  = b;
          fa = fb;
          b *= 1.05;
          fb = f(b);
        }
      if (fb == 0.)
        return b;
      std::uintmax_t iterations = 200;
      const auto     bracket =
        boost::math::tools::toms748_solve(f,
                                          a,
                                          b,
                                          fa,
                                          fb,
                                          boost::math::tools::eps_tolerance<double>(52),
                                          iterations);
      return 0.5 * (bracket.first + bracket.second);
    }


    dealii::Tensor<2, 3>
    diagonal(const double a, const double b, const double c)
    {
      dealii::Tensor<2, 3> F;
      F[0][0] = a;
      F[1][1] = b;
      F[2][2] = c;
      return F;
    }


    dealii::Tensor<2, 2>
    diagonal(const double a, const double b)
    {
      dealii::Tensor<2, 2> F;
      F[0][0] = a;
      F[1][1] = b;
      return F;
    }


    /**
     * Lamé's constants of the spatial tangent c_ijkl = (1/J) F_jJ F_lL A_iJkL at the stress-free
     * diagonal state @p F of @p gel: lambda = c_0011, G_s = c_0101.
     */
    template <int dim>
    std::pair<double, double>
    spatial_lame_constants(const FloryRehnerGel<dim>    &gel,
                           const dealii::Tensor<2, dim> &F,
                           const double                  mu)
    {
      const auto   A = gel.stress_tangent(F, mu);
      const double J = gel.J(F);
      // F diagonal: c_ijkl = F_jj F_ll A_ijkl / J.
      const double lambda = F[0][0] * F[1][1] * A[0][0][1][1] / J;
      const double G_s    = F[1][1] * F[1][1] * A[0][1][0][1] / J;
      return {lambda, G_s};
    }
  } // namespace


  template <int dim>
  GelReferences::GelReferences(const FloryRehnerGel<dim> &gel)
    : gel_3d(gel.shear_modulus(), gel.chi(), gel.N_nu(), gel.diffusivity(), gel.lambda_0())
    , gel_2d(gel.shear_modulus(), gel.chi(), gel.N_nu(), gel.diffusivity(), gel.lambda_0())
  {}


  SwollenState
  GelReferences::free_swelling(const double mu, const SwellingKinematics kinematics) const
  {
    const double l0 = gel_3d.lambda_0();
    if (kinematics == SwellingKinematics::three_dimensional)
      {
        const auto P11 = [&](const double l) {
          return gel_3d.stress(diagonal(l, l, l), mu)[0][0];
        };
        const double l =
          first_root_above(P11, std::cbrt(1. + start_above_dry), "free swelling in 3D");
        return {l, l / l0, l * l * l};
      }
    // Plane strain: F_33 = lambda_0 (the 2D gel's), J = lambda_0 l^2.
    const auto P11 = [&](const double l) {
      return gel_2d.stress(diagonal(l, l), mu)[0][0];
    };
    const double l = first_root_above(P11,
                                      std::sqrt((1. + start_above_dry) / l0),
                                      "free swelling in plane strain");
    return {l, l / l0, l0 * l * l};
  }


  SwollenState
  GelReferences::constrained_swelling(const double mu) const
  {
    const double l0  = gel_3d.lambda_0();
    const auto   P22 = [&](const double s) {
      return gel_3d.stress(diagonal(l0, l0 * s, l0), mu)[1][1];
    };
    const double s = first_root_above(P22,
                                      (1. + start_above_dry) / (l0 * l0 * l0),
                                      "swelling of a laterally constrained film");
    return {l0 * s, s, l0 * l0 * l0 * s};
  }


  double
  GelReferences::constrained_swelling_chemical_potential(const double s) const
  {
    const double l0 = gel_3d.lambda_0();
    const auto   F  = diagonal(l0, l0 * s, l0);
    // P(F, mu) = P(F, 0) + mu dP/dmu.
    return -gel_3d.stress(F, 0.)[1][1] / gel_3d.stress_mu_derivative(F)[1][1];
  }


  double
  GelReferences::free_swelling_chemical_potential(const double             stretch_from_dry,
                                                  const SwellingKinematics kinematics) const
  {
    const double l = stretch_from_dry;
    if (kinematics == SwellingKinematics::three_dimensional)
      {
        const auto F = diagonal(l, l, l);
        return -gel_3d.stress(F, 0.)[0][0] / gel_3d.stress_mu_derivative(F)[0][0];
      }
    const auto F = diagonal(l, l);
    return -gel_2d.stress(F, 0.)[0][0] / gel_2d.stress_mu_derivative(F)[0][0];
  }


  DrainedModuli
  GelReferences::drained_moduli(const double mu, const SwellingKinematics kinematics) const
  {
    const SwollenState state = free_swelling(mu, kinematics);
    const double       l     = state.stretch_from_dry;
    DrainedModuli      moduli;
    double             mobility;
    if (kinematics == SwellingKinematics::three_dimensional)
      {
        const auto F                                = diagonal(l, l, l);
        std::tie(moduli.lame, moduli.shear_modulus) = spatial_lame_constants(gel_3d, F, mu);
        mobility                                    = gel_3d.mobility(F);
      }
    else
      {
        const auto F                                = diagonal(l, l);
        std::tie(moduli.lame, moduli.shear_modulus) = spatial_lame_constants(gel_2d, F, mu);
        mobility                                    = gel_2d.mobility(F);
      }
    const double lambda = moduli.lame, G = moduli.shear_modulus;
    moduli.poisson_ratio             = lambda / (2. * (lambda + G));
    moduli.young_modulus             = 2. * G * (1. + moduli.poisson_ratio);
    moduli.plane_strain_modulus      = 4. * G * (lambda + G) / (lambda + 2. * G);
    moduli.biaxial_modulus           = moduli.young_modulus / (1. - moduli.poisson_ratio);
    const double kT_over_nu          = gel_3d.kT_over_nu();
    moduli.permeability              = mobility / (kT_over_nu * kT_over_nu);
    moduli.consolidation_coefficient = moduli.permeability * (lambda + 2. * G);
    return moduli;
  }


  const FloryRehnerGel<3> &
  GelReferences::gel() const
  {
    return gel_3d;
  }


  double
  timoshenko_curvature(const double mismatch,
                       const double h_1,
                       const double h_2,
                       const double E_1,
                       const double E_2)
  {
    const double m = h_1 / h_2, n = E_1 / E_2, h = h_1 + h_2;
    return 6. * mismatch * (1. + m) * (1. + m) /
           (h * (3. * (1. + m) * (1. + m) + (1. + m * n) * (m * m + 1. / (m * n))));
  }


  template GelReferences::GelReferences(const FloryRehnerGel<2> &);
  template GelReferences::GelReferences(const FloryRehnerGel<3> &);
} // namespace GelMPM

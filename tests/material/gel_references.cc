// GelReferences (what gelmpm-reference prints) against independent references, each with its
// tolerance:
// - eq. (22) both ways: lambda_0 = 1.2801 <-> mu_0 = -0.14597453 (prm/free_swelling_cube.prm),
//   to 1e-6 each way;
// - free swelling at mu = 0: lambda_eq = 2.348902, J = 12.95969 (prm/free_swelling_cube.prm, 1e-6
//   and 1e-5), and the plane-strain J = 9.432 (doc/own_scenes.md section 7, 5e-4); both against
//   a bisection of the Flory-Rehner law in closed form (tests/flory_rehner_closed_form.h, written
//   without FloryRehnerGel) to 1e-10;
// - the bonded film at mu = 0: s = 2.73 (doc/own_scenes.md section 7, 5e-3) and the closed form's
//   bisection (1e-10); s = 2.4 is reached at mu = -0.0066 (same section, 5e-5);
// - the drained moduli at mu = 0 in 3D: G_s = 0.425731, nu = 0.233236, c = 0.0082425 D
//   (doc/indentation.md, 1e-6, 1e-6, 1e-7), and G_s, nu against central differences of the gel's
//   stress (simple shear; a uniaxial stretch with the lateral stress solved to zero), 1e-6; c
//   against 2 (1 - nu)/(1 - 2 nu) G_s kappa with those differences and kappa = (J - 1)/J N nu,
//   relative 1e-6; in plane strain E' and the lateral contraction nu/(1 - nu) against the same
//   differences with F_33 = lambda_0 (1e-6);
// - Timoshenko's formula: with equal thicknesses and moduli, m = n = 1 gives
//   kappa = 6 eps 4 / (h (12 + 2 * 2)) = 3 eps / (2 h) (relative 1e-14); and the bilayer of
//   prm/bilayer_actuator.prm (passive chi = 0.15, 0.2, 0.3, bath -0.04, layers 0.1 each) against
//   doc/own_scenes.md section 6's table of Timoshenko's curvature (0.03807, 0.08265, 0.19589;
//   from contrib/benchmarks/bilayer_reference.py) and mismatch (0.65 %, 1.41 %, 3.30 %) to their
//   printed digits.
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/material/gel_references.h>

#include <deal.II/base/tensor.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "../flory_rehner_closed_form.h"

using namespace dealii;
using GelMPM::FloryRehnerGel;
using GelMPM::GelReferences;
using GelMPM::SwellingKinematics;

namespace
{
  bool all_ok = true;

  void
  check(const std::string &what, const double value, const double expected, const double tolerance)
  {
    const bool ok = std::abs(value - expected) < tolerance;
    all_ok &= ok;
    std::ostringstream text;
    text << std::setprecision(8) << "  " << what << " = " << expected << " within " << tolerance
         << ": " << (ok ? "yes" : "no  FAIL (" + std::to_string(value) + ")");
    std::cout << text.str() << std::endl;
  }

  constexpr double N_nu = 7.299e-3;

  /** The Table 1 gel, or one with @p chi at the Table 1 mu_0 (as a region of that scene). */
  FloryRehnerGel<2>
  table_1_gel(const double chi = 0.1)
  {
    const double mu_0 = FloryRehnerGel<2>::mu_0_from_lambda_0(1.2801, 0.1, N_nu);
    return FloryRehnerGel<2>(1.,
                             chi,
                             N_nu,
                             1.,
                             FloryRehnerGel<2>::lambda_0_from_mu_0(mu_0, chi, N_nu));
  }

  Tensor<2, 3>
  diag3(const double a, const double b, const double c)
  {
    Tensor<2, 3> F;
    F[0][0] = a;
    F[1][1] = b;
    F[2][2] = c;
    return F;
  }

  /** Cauchy stress of @p gel at @p F. */
  template <int dim>
  Tensor<2, dim>
  cauchy(const FloryRehnerGel<dim> &gel, const Tensor<2, dim> &F, const double mu)
  {
    return gel.stress(F, mu) * transpose(F) / gel.J(F);
  }

  /**
   * The lateral strain e with sigma_11 = 0 (3D: also sigma_22) under the axial strain @p delta
   * (along the last in-plane axis) from the stress-free @p F0, by bisection: -e/delta is the
   * drained Poisson ratio (in plane strain, with F_33 fixed, nu/(1 - nu)); also the axial stress.
   */
  template <int dim>
  std::pair<double, double>
  uniaxial(const FloryRehnerGel<dim> &gel,
           const Tensor<2, dim>      &F0,
           const double               mu,
           const double               delta)
  {
    const auto F = [&](const double e) {
      Tensor<2, dim> G = F0;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        G[d][d] *= 1. + e;
      G[dim - 1][dim - 1] *= 1. + delta;
      return G;
    };
    const double e = GelMPMTests::bisect(
      [&](const double e) {
        return cauchy(gel, F(e), mu)[0][0];
      },
      -0.5 * std::abs(delta) - 1e-3,
      0.5 * std::abs(delta) + 1e-3);
    return {e, cauchy(gel, F(e), mu)[dim - 1][dim - 1]};
  }
} // namespace


int
main()
{
  const FloryRehnerGel<3> gel_3d; // Table 1: G 1, chi 0.1, N nu 7.299e-3, D 1, lambda_0 1.2801
  const GelReferences     table_1(gel_3d);
  const auto              three_d      = SwellingKinematics::three_dimensional;
  const auto              plane_strain = SwellingKinematics::plane_strain;
  using GelMPMTests::bisect;
  using GelMPMTests::stress_times_stretch;

  std::cout << "Eq. (22) both ways (prm/free_swelling_cube.prm):" << std::endl;
  check("mu_0 at lambda_0 = 1.2801",
        table_1.free_swelling_chemical_potential(1.2801, three_d),
        -0.14597453,
        1e-6);
  check("lambda_0 at mu_0 = -0.14597453",
        table_1.free_swelling(-0.14597453, three_d).stretch_from_dry,
        1.2801,
        1e-6);

  std::cout << "Free swelling at mu = 0:" << std::endl;
  const auto free_3d = table_1.free_swelling(0., three_d);
  check("lambda_eq (3D)", free_3d.stretch_from_dry, 2.348902, 1e-6);
  check("J_eq (3D)", free_3d.J, 12.95969, 1e-5);
  const double l_eq = bisect(
    [](const double l) {
      return stress_times_stretch(l, l * l * l, 0., 1., 0.1, N_nu);
    },
    1. + 1e-9,
    10.);
  check("lambda_eq (3D) against the closed form's bisection",
        free_3d.stretch_from_dry,
        l_eq,
        1e-10);
  const double l0         = 1.2801;
  const auto   free_plane = GelReferences(table_1_gel()).free_swelling(0., plane_strain);
  check("J_eq (plane strain)", free_plane.J, 9.432, 5e-4);
  const double a_eq = bisect(
    [&](const double a) {
      return stress_times_stretch(l0 * a, l0 * l0 * l0 * a * a, 0., 1., 0.1, N_nu);
    },
    std::pow(l0, -1.5) * (1. + 1e-9),
    10.);
  check("in-plane stretch / lambda_0 (plane strain) against the closed form's bisection",
        free_plane.stretch_from_initial,
        a_eq,
        1e-10);

  std::cout << "Bonded film:" << std::endl;
  const auto film = table_1.constrained_swelling(0.);
  check("s at mu = 0", film.stretch_from_initial, 2.73, 5e-3);
  const double s_eq = bisect(
    [&](const double s) {
      return stress_times_stretch(l0 * s, l0 * l0 * l0 * s, 0., 1., 0.1, N_nu);
    },
    (1. + 1e-9) / (l0 * l0 * l0),
    10.);
  check("s at mu = 0 against the closed form's bisection", film.stretch_from_initial, s_eq, 1e-10);
  const double mu_crease = table_1.constrained_swelling_chemical_potential(2.4);
  check("mu at s = 2.4", mu_crease, -0.0066, 5e-5);
  check("s at that mu", table_1.constrained_swelling(mu_crease).stretch_from_initial, 2.4, 1e-10);

  std::cout << "Drained moduli at mu = 0 (3D):" << std::endl;
  const auto   moduli = table_1.drained_moduli(0., three_d);
  const double l      = free_3d.stretch_from_dry;
  check("G_s (doc/indentation.md)", moduli.shear_modulus, 0.425731, 1e-6);
  check("nu (doc/indentation.md)", moduli.poisson_ratio, 0.233236, 1e-6);
  check("c / D (doc/indentation.md)", moduli.consolidation_coefficient, 0.0082425, 1e-7);
  const double gamma = 1e-4, delta = 1e-4;
  const auto   shear = [&](const double g) {
    Tensor<2, 3> F = diag3(l, l, l);
    F[0][1]        = g * l;
    return cauchy(gel_3d, F, 0.)[0][1];
  };
  const double G_fd = (shear(gamma) - shear(-gamma)) / (2. * gamma);
  check("G_s against simple shear", moduli.shear_modulus, G_fd, 1e-6);
  const double nu_fd = -(uniaxial(gel_3d, diag3(l, l, l), 0., delta).first -
                         uniaxial(gel_3d, diag3(l, l, l), 0., -delta).first) /
                       (2. * delta);
  check("nu against a uniaxial stretch", moduli.poisson_ratio, nu_fd, 1e-6);
  const double J     = free_3d.J;
  const double kappa = (J - 1.) / J * N_nu;
  const double c_fd  = 2. * (1. - nu_fd) / (1. - 2. * nu_fd) * G_fd * kappa;
  check("c / (2 (1 - nu)/(1 - 2 nu) G_s kappa)", moduli.consolidation_coefficient / c_fd, 1., 1e-6);

  std::cout << "Drained moduli at mu = 0 (plane strain, F_33 = lambda_0):" << std::endl;
  const FloryRehnerGel<2> gel_2d       = table_1_gel();
  const auto              moduli_plane = GelReferences(gel_2d).drained_moduli(0., plane_strain);
  Tensor<2, 2>            F0;
  F0[0][0] = F0[1][1] = free_plane.stretch_from_dry;
  const auto plus = uniaxial(gel_2d, F0, 0., delta), minus = uniaxial(gel_2d, F0, 0., -delta);
  check("E' against a uniaxial stretch",
        moduli_plane.plane_strain_modulus,
        (plus.second - minus.second) / (2. * delta),
        1e-6);
  check("nu/(1 - nu) against the lateral contraction",
        moduli_plane.poisson_ratio / (1. - moduli_plane.poisson_ratio),
        -(plus.first - minus.first) / (2. * delta),
        1e-6);

  std::cout << "Timoshenko's curvature:" << std::endl;
  check("equal layers: kappa h / eps",
        GelMPM::timoshenko_curvature(0.01, 0.3, 0.3, 2., 2.) * 0.6 / 0.01,
        1.5,
        1e-14);
  for (const auto &[chi, mismatch, curvature] : {std::tuple{0.15, 0.0065, 0.03807},
                                                 std::tuple{0.2, 0.0141, 0.08265},
                                                 std::tuple{0.3, 0.0330, 0.19589}})
    {
      const GelReferences active(table_1_gel()), passive(table_1_gel(chi));
      const double        a_1 = active.free_swelling(-0.04, plane_strain).stretch_from_initial;
      const double        a_2 = passive.free_swelling(-0.04, plane_strain).stretch_from_initial;
      const double        E_1 = active.drained_moduli(-0.04, plane_strain).plane_strain_modulus;
      const double        E_2 = passive.drained_moduli(-0.04, plane_strain).plane_strain_modulus;
      std::ostringstream  name;
      name << "bilayer, passive chi = " << chi;
      check(name.str() + ": mismatch", a_1 / a_2 - 1., mismatch, 5e-5);
      check(name.str() + ": curvature",
            GelMPM::timoshenko_curvature(a_1 / a_2 - 1., 0.1 * a_1, 0.1 * a_2, E_1, E_2),
            curvature,
            5e-6);
    }
  std::cout << (all_ok ? "all reference checks passed" : "SOME REFERENCE CHECKS FAILED")
            << std::endl;
  return all_ok ? 0 : 1;
}

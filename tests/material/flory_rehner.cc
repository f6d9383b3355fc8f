// FloryRehnerGel against independent references:
// - every derivative against central finite differences of the function it differentiates
//   (relative error < 1e-6) at states near the dry limit, at equilibrium, at J up to 50, in
//   compression and in shear, in 2D (plane strain) and 3D, for the total and the incremental form;
// - major symmetry of dP/dF (1e-12) and objectivity P(QF) = Q P(F) (1e-12);
// - 2D plane strain equals the 3D evaluation at F33 = lambda_0 (1e-12 relative);
// - the initial state of Table 1 and §4.2 (eq. (22) and its inverse), P = 0 there (1e-10);
// - the equilibrium stretches solve P_11 = 0 / P_22 = 0 (1e-10);
// - NonPhysicalState for J <= 1.
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

using namespace dealii;
using GelMPM::FloryRehnerGel;

namespace
{
  bool all_ok = true;

  void
  report(const std::string &what, const double error, const double tolerance)
  {
    const bool ok = error < tolerance;
    all_ok &= ok;
    std::ostringstream tol;
    tol << tolerance;
    std::cout << "  " << what << " < " << tol.str() << ": " << (ok ? "yes" : "no  FAIL")
              << std::endl;
  }

  template <int dim>
  std::vector<Tensor<2, dim>>
  states(const double lambda_0)
  {
    std::vector<Tensor<2, dim>> Fs;
    const auto                  diag = [&](const double a, const double b, const double c) {
      Tensor<2, dim> F;
      F[0][0] = a;
      F[1][1] = b;
      if (dim == 3)
        F[2][2] = c;
      return F;
    };
    const double l = lambda_0;
    Fs.push_back(diag(l, l, l));                         // free-swelling equilibrium
    const double near_dry = std::pow(1.01, 1. / 3.) / l; // J = 1.01
    Fs.push_back(diag(l * near_dry, l * near_dry, l * near_dry));
    Fs.push_back(diag(l * 2.5, l * 2.8, l * 2.6));  // J large
    Fs.push_back(diag(l * 0.9, l * 1.05, l * 1.0)); // compression in one direction
    Tensor<2, dim> sheared = diag(l * 1.3, l * 1.1, l * 1.2);
    sheared[0][1]          = 0.4;
    sheared[1][0]          = -0.2;
    Fs.push_back(sheared);
    return Fs;
  }

  template <int dim>
  void
  check_derivatives(const FloryRehnerGel<dim> &gel)
  {
    std::cout << dim << "D derivatives against central differences:" << std::endl;
    double err_P = 0., err_A = 0., err_dmu = 0., err_C = 0., err_Pn = 0., err_An = 0.,
           err_Pnmu = 0., sym = 0., objectivity = 0., J_max = 0.;
    const double   h   = 1e-6;
    const double   mu  = -0.05;
    auto           Fs  = states<dim>(gel.lambda_0());
    Tensor<2, dim> big = Fs[2];
    big *= std::pow(50. / gel.J(big), 1. / dim); // J = 50
    Fs.push_back(big);
    for (const auto &F : Fs)
      {
        J_max                     = std::max(J_max, gel.J(F));
        const Tensor<2, dim> P    = gel.stress(F, mu);
        const Tensor<4, dim> A    = gel.stress_tangent(F, mu);
        const Tensor<2, dim> dPdm = gel.stress_mu_derivative(F);
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            {
              Tensor<2, dim> dF;
              dF[k][L] = h * F.norm();
              const double dW =
                (gel.free_energy(F + dF, mu) - gel.free_energy(F - dF, mu)) / (2. * dF[k][L]);
              err_P         = std::max(err_P, std::abs(dW - P[k][L]) / P.norm());
              const auto dP = (gel.stress(F + dF, mu) - gel.stress(F - dF, mu)) / (2. * dF[k][L]);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int J = 0; J < dim; ++J)
                  {
                    err_A = std::max(err_A, std::abs(dP[i][J] - A[i][J][k][L]) / A.norm());
                    sym   = std::max(sym, std::abs(A[i][J][k][L] - A[k][L][i][J]) / A.norm());
                  }
            }
        const double hm  = 1e-4;
        const auto   dPm = (gel.stress(F, mu + hm) - gel.stress(F, mu - hm)) / (2. * hm);
        err_dmu          = std::max(err_dmu, (dPm - dPdm).norm() / dPdm.norm());
        const double dWm = (gel.free_energy(F, mu + hm) - gel.free_energy(F, mu - hm)) / (2. * hm);
        err_C = std::max(err_C, std::abs(-dWm - gel.concentration(F)) / gel.concentration(F));

        // Objectivity with a rotation about the out-of-plane axis.
        Tensor<2, dim> Q;
        const double   angle = 0.7;
        Q[0][0] = Q[1][1] = std::cos(angle);
        Q[0][1]           = -std::sin(angle);
        Q[1][0]           = std::sin(angle);
        if (dim == 3)
          Q[2][2] = 1.;
        objectivity =
          std::max(objectivity,
                   (gel.stress(Q * F, mu) - Q * P).norm() / P.norm() * (P.norm() > 1e-8 ? 1. : 0.));

        // Incremental form: F_p from the state list, dF a general increment.
        Tensor<2, dim> dFinc = unit_symmetric_tensor<dim>();
        dFinc[0][0] += 0.05;
        dFinc[1][0] += 0.03;
        dFinc[0][1] -= 0.02;
        const auto inc = gel.incremental(dFinc, mu, F);
        const auto Wn  = [&](const Tensor<2, dim> &D, const double m) {
          return gel.free_energy(D * F, m) / gel.J(F);
        };
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            {
              Tensor<2, dim> e;
              e[k][L]         = h;
              const double dW = (Wn(dFinc + e, mu) - Wn(dFinc - e, mu)) / (2. * h);
              err_Pn          = std::max(err_Pn, std::abs(dW - inc.P_n[k][L]) / inc.P_n.norm());
              const auto dPn =
                (gel.incremental(dFinc + e, mu, F).P_n - gel.incremental(dFinc - e, mu, F).P_n) /
                (2. * h);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int J = 0; J < dim; ++J)
                  err_An =
                    std::max(err_An, std::abs(dPn[i][J] - inc.A_n[i][J][k][L]) / inc.A_n.norm());
            }
        const auto dPnm =
          (gel.incremental(dFinc, mu + hm, F).P_n - gel.incremental(dFinc, mu - hm, F).P_n) /
          (2. * hm);
        err_Pnmu = std::max(err_Pnmu, (dPnm - inc.dP_n_dmu).norm() / inc.dP_n_dmu.norm());
      }
    std::cout << "  states up to J = " << std::setprecision(3) << J_max << std::endl;
    report("P vs dW/dF", err_P, 1e-6);
    report("dP/dF vs FD of P", err_A, 1e-6);
    report("dP/dmu vs FD of P", err_dmu, 1e-6);
    report("k_BT C vs -dW/dmu", err_C, 1e-6);
    report("P_n vs FD of W(dF F_p)/J_p", err_Pn, 1e-6);
    report("A_n vs FD of P_n", err_An, 1e-6);
    report("dP_n/dmu vs FD of P_n", err_Pnmu, 1e-6);
    report("major symmetry of dP/dF", sym, 1e-12);
    report("objectivity P(QF) - Q P(F)", objectivity, 1e-12);
  }
} // namespace


int
main()
{
  std::cout << std::setprecision(6);
  const FloryRehnerGel<2> gel2;
  const FloryRehnerGel<3> gel3;
  check_derivatives(gel2);
  check_derivatives(gel3);

  std::cout << "Plane strain against 3D with F33 = lambda_0:" << std::endl;
  {
    Tensor<2, 2> F2;
    F2[0][0] = 1.5;
    F2[0][1] = 0.2;
    F2[1][0] = -0.1;
    F2[1][1] = 1.7;
    Tensor<2, 3> F3;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        F3[i][j] = F2[i][j];
    F3[2][2]         = gel2.lambda_0();
    const double mu  = -0.1;
    const auto   P2  = gel2.stress(F2, mu);
    const auto   P3  = gel3.stress(F3, mu);
    const auto   A2  = gel2.stress_tangent(F2, mu);
    const auto   A3  = gel3.stress_tangent(F3, mu);
    double       e_P = 0., e_A = 0.;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        {
          e_P = std::max(e_P, std::abs(P2[i][j] - P3[i][j]) / P3.norm());
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = 0; l < 2; ++l)
              e_A = std::max(e_A, std::abs(A2[i][j][k][l] - A3[i][j][k][l]) / A3.norm());
        }
    report("energy", std::abs(gel2.free_energy(F2, mu) - gel3.free_energy(F3, mu)), 1e-12);
    report("stress", e_P, 1e-12);
    report("tangent", e_A, 1e-12);
  }

  std::cout << "Initial state, eq. (22):" << std::endl;
  {
    const double mu0 = FloryRehnerGel<2>::mu_0_from_lambda_0(1.2801, 0.1, 7.299e-3);
    std::cout << "  Table 1: lambda_0 = 1.2801 -> mu_0/kT = " << std::fixed << std::setprecision(4)
              << mu0 << std::endl;
    report("|mu_0 + 0.1460|", std::abs(mu0 + 0.1460), 5e-5);
    const double l0 = FloryRehnerGel<2>::lambda_0_from_mu_0(0., 0.1, 7.299e-3);
    std::cout << "  §4.2: mu_0 = 0 -> lambda_0 = " << l0 << std::endl;
    report("|lambda_0 - 2.3489|", std::abs(l0 - 2.3489), 5e-5);
    std::cout << std::scientific << std::setprecision(6);
    double round_trip = 0.;
    for (double l = 1.05; l < 2.3; l += 0.05)
      round_trip = std::max(round_trip,
                            std::abs(FloryRehnerGel<2>::lambda_0_from_mu_0(
                                       FloryRehnerGel<2>::mu_0_from_lambda_0(l, 0.1, 7.299e-3),
                                       0.1,
                                       7.299e-3) -
                                     l));
    report("round trip lambda -> mu -> lambda", round_trip, 1e-12);
    for (const double l : {1.2801, 2.3489})
      {
        const FloryRehnerGel<2> g2(1., 0.1, 7.299e-3, 1., l);
        const FloryRehnerGel<3> g3(1., 0.1, 7.299e-3, 1., l);
        Tensor<2, 2>            F2 = l * Tensor<2, 2>(unit_symmetric_tensor<2>());
        Tensor<2, 3>            F3 = l * Tensor<2, 3>(unit_symmetric_tensor<3>());
        report("|P| at F = lambda_0 I, mu_0 (2D), lambda_0 = " + std::to_string(l),
               g2.stress(F2, g2.mu_0()).norm(),
               1e-10);
        report("|P| at F = lambda_0 I, mu_0 (3D)", g3.stress(F3, g3.mu_0()).norm(), 1e-10);
        report("free swelling stretch at mu_0 is 1",
               std::abs(g2.plane_strain_free_swelling_stretch(g2.mu_0()) - 1.),
               1e-10);
        report("constrained stretch at mu_0 is 1",
               std::abs(g2.constrained_swelling_stretch(g2.mu_0()) - 1.),
               1e-10);
      }
    const double ls = gel2.plane_strain_free_swelling_stretch(0.);
    const double lc = gel2.constrained_swelling_stretch(0.);
    std::cout << std::fixed << std::setprecision(5) << "  at mu = 0: plane-strain free swelling "
              << ls << ", constrained " << lc << std::endl;
    Tensor<2, 2> Fs = gel2.lambda_0() * ls * Tensor<2, 2>(unit_symmetric_tensor<2>());
    Tensor<2, 2> Fc = gel2.lambda_0() * Tensor<2, 2>(unit_symmetric_tensor<2>());
    Fc[1][1] *= lc;
    report("P_11 at the plane-strain free swelling stretch",
           std::abs(gel2.stress(Fs, 0.)[0][0]),
           1e-10);
    report("P_22 at the constrained stretch", std::abs(gel2.stress(Fc, 0.)[1][1]), 1e-10);
  }

  std::cout << "Outside the physical range:" << std::endl;
  {
    bool         thrown = false;
    Tensor<2, 2> F      = 0.5 * Tensor<2, 2>(unit_symmetric_tensor<2>());
    try
      {
        gel2.stress(F, 0.);
      }
    catch (const GelMPM::NonPhysicalState &)
      {
        thrown = true;
      }
    all_ok &= thrown;
    std::cout << "  NonPhysicalState for J = " << gel2.J(F) << ": " << (thrown ? "yes" : "no  FAIL")
              << std::endl;
  }
  std::cout << (all_ok ? "all material checks passed" : "SOME MATERIAL CHECKS FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

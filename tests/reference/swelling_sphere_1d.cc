// The finite-difference reference of a freely swelling gel sphere (FreeSwellingSphere1D) checked on
// its own:
// - equilibrium: after 2000 tau_d the outer radius is the closed-form free-swelling stretch,
//   computed here by bisection on eq. (22), to 1e-5 (mu_top = 0: 1.834936; and mu_top = -0.05);
// - space-time convergence at second order: with cells and step growth refined together (n, 1 +
//   0.64/n; n = 50, 100, 200), the observed order of r(1, t) at t = 0.05 and 0.5 tau_d is within
//   2 +- 0.2 (measured 1.97 to 1.99); with the cells fixed (n = 50) and the step growth halved
//   (1.04, 1.02, 1.01), within 2 +- 0.3 at t = 0.5 (measured 1.92);
// - solvent conservation: the uptake (sum over the cells of (J - J_0)/lambda_0^3 V_0) equals the
//   surface flux integrated with the scheme's own BDF2 weights to 1e-10 (relative), equals
//   (r(1)^3 - 1)/3 to 1e-12, and its change from 0.01 to 1 tau_d equals the trapezoidal integral
//   of the surface flux sampled at 2000 log-spaced times to 1e-4 (relative);
// - early times: while the swollen skin is thin the sphere takes up per unit initial area what the
//   constrained layer (ConstrainedSwelling1D, an independent code) does: the ratio of the uptakes
//   is within 1 % of 1 at t = 1e-4 and 1e-3 tau_d (200 cells each).
#include <gelmpm/reference/constrained_swelling_1d.h>
#include <gelmpm/reference/free_swelling_sphere_1d.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using GelMPM::FreeSwellingSphere1D;

namespace
{
  FreeSwellingSphere1D::Parameters
  parameters(const unsigned int n_cells, const double growth)
  {
    FreeSwellingSphere1D::Parameters p;
    p.n_cells = n_cells;
    p.growth  = growth;
    return p;
  }

  /**
   * The isotropic free-swelling stretch from the initial state at @p mu (Table 1 material),
   * by bisection on mu(lambda) of eq. (22), written here independently of the class.
   */
  double
  closed_form_stretch(const double mu)
  {
    const double chi = 0.1, N_nu = 7.299e-3, lambda_0 = 1.2801;
    auto         mu_of = [&](const double l) {
      const double J = l * l * l;
      return N_nu * (1. / l - 1. / J) + std::log(1. - 1. / J) + 1. / J + chi / (J * J);
    };
    double lo = 1. + 1e-12, hi = 10.;
    for (unsigned int k = 0; k < 200; ++k)
      {
        const double mid            = 0.5 * (lo + hi);
        (mu_of(mid) < mu ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi) / lambda_0;
  }

  double
  radius_at(const FreeSwellingSphere1D::Parameters &p, const double t)
  {
    FreeSwellingSphere1D sphere(p);
    sphere.advance_to(t);
    return sphere.outer_radius();
  }

  /** The observed order of three solutions on successively halved discretisations. */
  double
  observed_order(const double coarse, const double medium, const double fine)
  {
    return std::log2(std::abs((coarse - medium) / (medium - fine)));
  }
} // namespace


int
main()
{
  std::cout << std::boolalpha;

  // Equilibrium.
  for (const double mu_top : {0., -0.05})
    {
      FreeSwellingSphere1D::Parameters p = parameters(50, 1.05);
      p.mu_top                           = mu_top;
      FreeSwellingSphere1D sphere(p);
      sphere.advance_to(2000.);
      const double closed_form = closed_form_stretch(mu_top);
      std::cout << "mu_top = " << mu_top << ": closed-form r/R_0 = " << std::fixed
                << std::setprecision(6) << closed_form << "; r(1, 2000 tau_d) equals it to 1e-5: "
                << (std::abs(sphere.outer_radius() - closed_form) < 1e-5)
                << "; the class's stretch_at agrees to 1e-12: "
                << (std::abs(sphere.stretch_at(mu_top) - closed_form) < 1e-12) << std::endl
                << std::defaultfloat;
    }

  // Space-time convergence.
  {
    bool orders_ok = true;
    for (const double t : {0.05, 0.5})
      {
        double r[3];
        for (unsigned int level = 0; level < 3; ++level)
          {
            const unsigned int n = 50u << level;
            r[level]             = radius_at(parameters(n, 1. + 0.64 / n), t);
          }
        const double p = observed_order(r[0], r[1], r[2]);
        std::cout << "t = " << t << ": observed space-time order " << std::fixed
                  << std::setprecision(1) << p << std::defaultfloat << std::endl;
        orders_ok &= std::abs(p - 2.) < 0.2;
      }
    std::cout << "space-time orders within 2 +- 0.2: " << orders_ok << std::endl;

    const double r_1 = radius_at(parameters(50, 1.04), 0.5),
                 r_2 = radius_at(parameters(50, 1.02), 0.5),
                 r_3 = radius_at(parameters(50, 1.01), 0.5);
    const double p   = observed_order(r_1, r_2, r_3);
    std::cout << "time order (n = 50, growth 1.04, 1.02, 1.01) " << std::fixed
              << std::setprecision(1) << p << std::defaultfloat
              << ", within 2 +- 0.3: " << (std::abs(p - 2.) < 0.3) << std::endl;
  }

  // Solvent conservation.
  {
    FreeSwellingSphere1D sphere(parameters(100, 1.02));
    sphere.advance_to(0.01);
    const double       uptake_start = sphere.solvent_uptake();
    const double       t_0 = 0.01, t_1 = 1.;
    const unsigned int n_samples = 2000;
    double             integral = 0., flux = sphere.surface_flux(), time = t_0;
    for (unsigned int k = 1; k <= n_samples; ++k)
      {
        const double t_next = t_0 * std::pow(t_1 / t_0, static_cast<double>(k) / n_samples);
        sphere.advance_to(t_next);
        const double flux_next = sphere.surface_flux();
        integral += 0.5 * (flux + flux_next) * (t_next - time);
        flux = flux_next;
        time = t_next;
      }
    const double uptake = sphere.solvent_uptake(), radius = sphere.outer_radius();
    std::cout << "uptake equals the BDF2 integral of the surface flux to 1e-10: "
              << (std::abs(sphere.absorbed_solvent() / uptake - 1.) < 1e-10) << std::endl;
    std::cout << "uptake equals (r^3 - 1)/3 to 1e-12: "
              << (std::abs(uptake - (radius * radius * radius - 1.) / 3.) < 1e-12) << std::endl;
    std::cout << "uptake from 0.01 to 1 tau_d equals the trapezoidal integral of the surface flux "
                 "to 1e-4: "
              << (std::abs(integral / (uptake - uptake_start) - 1.) < 1e-4) << std::endl;
  }

  // Early times against the constrained layer.
  {
    FreeSwellingSphere1D                      sphere(parameters(200, 1. + 0.64 / 200));
    GelMPM::ConstrainedSwelling1D::Parameters q;
    q.n_cells = 200;
    q.growth  = 1. + 0.64 / 200;
    GelMPM::ConstrainedSwelling1D layer(q);
    bool                          close = true;
    for (const double t : {1e-4, 1e-3})
      {
        sphere.advance_to(t);
        layer.advance_to(t);
        close &= std::abs(sphere.solvent_uptake() / layer.thickness_change() - 1.) < 0.01;
      }
    std::cout << "uptake per unit area within 1 % of the constrained layer's at 1e-4 and 1e-3 "
                 "tau_d: "
              << close << std::endl;
  }
  return 0;
}

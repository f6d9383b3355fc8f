#include <gelmpm/reference/free_swelling_sphere_1d.h>
#include <gelmpm/reference/numerical_tolerances.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

// LAPACK's banded solver (deal.II links LAPACK but wraps no banded solve).
extern "C" void
dgbsv_(const int *n,
       const int *kl,
       const int *ku,
       const int *nrhs,
       double    *ab,
       const int *ldab,
       int       *ipiv,
       double    *b,
       const int *ldb,
       int       *info);

namespace GelMPM
{
  namespace
  {

    /**
     * Half-bandwidths of the Jacobian in the unknowns' order mu_0, r_1, mu_1, r_2, ...,
     * mu_n-1, r_n: the balance of cell k reaches the radii of the nodes k - 1 to k + 2 and the
     * mu of the cells k - 1 to k + 1.
     */
    constexpr int half_band = 3;

    /** W_J: the derivative of the dry-volume energy by J at fixed F:F, and W_JJ. */
    double
    energy_J(const double J, const double mu, const double N_nu, const double chi)
    {
      return -N_nu / J + std::log(1. - 1. / J) + 1. / J + chi / (J * J) - mu;
    }

    double
    energy_JJ(const double J, const double N_nu, const double chi)
    {
      return N_nu / (J * J) + 1. / (J * J * (J - 1.)) - 2. * chi / (J * J * J);
    }
  } // namespace

  FreeSwellingSphere1D::FreeSwellingSphere1D(const Parameters &parameters)
    : parameters(parameters)
    , dt_next(parameters.first_step)
  {
    if (parameters.n_cells < 2 || parameters.grading < 1. || parameters.first_step <= 0. ||
        parameters.growth < 1. || !(parameters.ramp >= 0.) || parameters.lambda_0 <= 1.)
      throw std::invalid_argument("FreeSwellingSphere1D: need at least 2 cells, grading >= 1, "
                                  "a positive first step, growth >= 1, a ramp >= 0 and "
                                  "lambda_0 > 1");
    const unsigned int n = parameters.n_cells;
    R.resize(n + 1);
    for (unsigned int i = 0; i <= n; ++i)
      R[i] = 1. - std::pow(1. - static_cast<double>(i) / n, parameters.grading);
    R[0] = 0.;
    R[n] = 1.;
    centre.resize(n);
    volume_0.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        centre[k]   = 0.5 * (R[k] + R[k + 1]);
        volume_0[k] = (std::pow(R[k + 1], 3) - std::pow(R[k], 3)) / 3.;
      }
    r     = R;
    r_old = r;
    mu.assign(n, chemical_potential(1.));
  }


  double
  FreeSwellingSphere1D::chemical_potential(const double lambda) const
  {
    const double l = parameters.lambda_0 * lambda, J = l * l * l;
    return parameters.N_nu * (1. / l - 1. / J) + std::log(1. - 1. / J) + 1. / J +
           parameters.chi / (J * J);
  }


  double
  FreeSwellingSphere1D::stretch_at(const double mu_target) const
  {
    // mu(lambda) increases monotonically from -infinity at J = 1 (chi < 1/2): bisection.
    double lo = (1. + 1e-14) / parameters.lambda_0, hi = 2.;
    while (chemical_potential(hi) < mu_target)
      hi *= 2.;
    for (unsigned int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k)
      {
        const double mid                                = 0.5 * (lo + hi);
        (chemical_potential(mid) < mu_target ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }


  double
  FreeSwellingSphere1D::bath_chemical_potential(const double time) const
  {
    if (parameters.ramp > 0. && time < parameters.ramp)
      {
        const double mu_0 = chemical_potential(1.);
        return mu_0 + (parameters.mu_top - mu_0) * std::max(time, 0.) / parameters.ramp;
      }
    return parameters.mu_top;
  }


  FreeSwellingSphere1D::Cell
  FreeSwellingSphere1D::cell(const unsigned int k, const double r_a, const double r_b) const
  {
    const double l03 = std::pow(parameters.lambda_0, 3);
    Cell         c;
    c.lambda_r = (r_b - r_a) / (R[k + 1] - R[k]);
    c.volume   = (r_b * r_b * r_b - r_a * r_a * r_a) / 3.;
    c.J        = l03 * c.volume / volume_0[k];
    // The hoop stretch that reproduces the cell's volume with lambda_r: a uniform dilation is then
    // an exact discrete equilibrium.
    c.lambda_theta = std::sqrt(c.J / (l03 * c.lambda_r));
    c.dJ_a         = -l03 * r_a * r_a / volume_0[k];
    c.dJ_b         = l03 * r_b * r_b / volume_0[k];
    return c;
  }


  void
  FreeSwellingSphere1D::advance_to(const double t_end)
  {
    if (parameters.ramp > t * (1. + 1e-14) && parameters.ramp < t_end * (1. - 1e-14))
      advance_to(parameters.ramp);
    while (t < t_end * (1. - 1e-14))
      {
        // Land on t_end; keep the BDF2 step ratio below 2 (zero-stable up to 1 + sqrt 2).
        double dt = std::min(dt_next, t_end - t);
        if (dt_old > 0.)
          dt = std::min(dt, 2. * dt_old);
        if (t_end - t - dt < 1e-3 * dt)
          dt = t_end - t;
        const bool full = dt >= dt_next * (1. - ReferenceTolerances::relative_time_tolerance);
        step(dt);
        if (full)
          dt_next *= parameters.growth;
      }
    t = std::max(t, t_end);
  }


  void
  FreeSwellingSphere1D::step(const double dt)
  {
    const unsigned int n  = parameters.n_cells;
    const double       l0 = parameters.lambda_0, l03 = l0 * l0 * l0;
    const double       N_nu = parameters.N_nu, chi = parameters.chi;
    const double       mu_bath = bath_chemical_potential(t + dt);
    // BDF2 on non-uniform steps: (a y_{n+1} + b y_n + c y_{n-1}) / dt = f(y_{n+1}).
    double a = 1., b = -1., c = 0.;
    if (dt_old > 0.)
      {
        const double w = dt / dt_old;
        a              = (1. + 2. * w) / (1. + w);
        b              = -(1. + w);
        c              = w * w / (1. + w);
      }

    // Unknowns x_{2k} = mu_k, x_{2k+1} = r_{k+1}; the mechanical balance of node i is row
    // 2i - 1, the solvent balance of cell k row 2k.
    const int           size = 2 * n, kl = half_band, ku = half_band, ldab = 2 * kl + ku + 1;
    std::vector<double> band(static_cast<std::size_t>(ldab) * size), residual(size);
    std::vector<int>    pivots(size);
    auto                add = [&](const int row, const int column, const double value) {
      if (column < 0)
        return; // r_0 = 0 is not an unknown
      band[(kl + ku + row - column) + static_cast<std::size_t>(column) * ldab] += value;
    };
    auto r_column = [](const unsigned int i) {
      return static_cast<int>(2 * i) - 1;
    };
    auto mu_column = [](const unsigned int k) {
      return static_cast<int>(2 * k);
    };

    std::vector<double> r_next = r, mu_next = mu;
    // Per cell: the mobility k = (J - 1)/(lambda_0^3 lambda_r^2) and its derivatives by r_a, r_b.
    std::vector<double> kappa(n), dkappa_a(n), dkappa_b(n);
    bool                converged = false;
    for (unsigned int iteration = 0; iteration < 50 && !converged; ++iteration)
      {
        std::fill(band.begin(), band.end(), 0.);
        std::fill(residual.begin(), residual.end(), 0.);
        for (unsigned int k = 0; k < n; ++k)
          {
            const double r_a = r_next[k], r_b = r_next[k + 1];
            const Cell   s = cell(k, r_a, r_b);
            const double h = R[k + 1] - R[k];
            // The cell's energy E = (V0/lambda_0^3) W; g_a, g_b = dE/dr_a, dE/dr_b. Its elastic
            // part (c0/2) (lambda_r^2 + 2 q/lambda_r), q = V/V0 = lambda_r lambda_theta^2, has
            // the derivatives c0 [(lambda_r - q/lambda_r^2) e_j + f_j/lambda_r] with
            // e_j = d lambda_r/d r_j = -+1/h and f_j = dq/dr_j = -+r_j^2/V0.
            const double c0 = volume_0[k] * N_nu / l0, q = s.volume / volume_0[k];
            const double lr = s.lambda_r, e_a = -1. / h, e_b = 1. / h;
            const double f_a = -r_a * r_a / volume_0[k], f_b = r_b * r_b / volume_0[k];
            const double W_J  = energy_J(s.J, mu_next[k], N_nu, chi);
            const double W_JJ = energy_JJ(s.J, N_nu, chi);
            const double g_a  = c0 * ((lr - q / (lr * lr)) * e_a + f_a / lr) - W_J * r_a * r_a;
            const double g_b  = c0 * ((lr - q / (lr * lr)) * e_b + f_b / lr) + W_J * r_b * r_b;
            auto         elastic =
              [&](const double e_i, const double f_i, const double e_j, const double f_j) {
                return c0 * ((1. + 2. * q / (lr * lr * lr)) * e_i * e_j -
                             (f_i * e_j + f_j * e_i) / (lr * lr));
              };
            const double k_aa = elastic(e_a, f_a, e_a, f_a) - c0 * 2. * r_a / (volume_0[k] * lr) -
                                W_JJ * s.dJ_a * r_a * r_a - 2. * W_J * r_a;
            const double k_ab = elastic(e_a, f_a, e_b, f_b) - W_JJ * s.dJ_b * r_a * r_a;
            const double k_bb = elastic(e_b, f_b, e_b, f_b) + c0 * 2. * r_b / (volume_0[k] * lr) +
                                W_JJ * s.dJ_b * r_b * r_b + 2. * W_J * r_b;
            if (k > 0)
              {
                residual[r_column(k)] += g_a;
                add(r_column(k), r_column(k), k_aa);
                add(r_column(k), r_column(k + 1), k_ab);
                add(r_column(k), mu_column(k), r_a * r_a);
              }
            residual[r_column(k + 1)] += g_b;
            add(r_column(k + 1), r_column(k), k_ab);
            add(r_column(k + 1), r_column(k + 1), k_bb);
            add(r_column(k + 1), mu_column(k), -r_b * r_b);

            // The cell's solvent balance: the rate of its current volume.
            const double V_old   = (std::pow(r[k + 1], 3) - std::pow(r[k], 3)) / 3.;
            const double V_older = (std::pow(r_old[k + 1], 3) - std::pow(r_old[k], 3)) / 3.;
            residual[mu_column(k)] += (a * s.volume + b * V_old + c * V_older) / dt;
            add(mu_column(k), r_column(k), -a * r_a * r_a / dt);
            add(mu_column(k), r_column(k + 1), a * r_b * r_b / dt);

            const double lr2 = s.lambda_r * s.lambda_r;
            kappa[k]         = (s.J - 1.) / (l03 * lr2);
            dkappa_a[k] = s.dJ_a / (l03 * lr2) + 2. * (s.J - 1.) / (l03 * lr2 * s.lambda_r * h);
            dkappa_b[k] = s.dJ_b / (l03 * lr2) - 2. * (s.J - 1.) / (l03 * lr2 * s.lambda_r * h);
          }
        // Interior fluxes F_i = R_i^2 (k_{i-1} + k_i)/2 (mu_i - mu_{i-1})/(c_i - c_{i-1}) into
        // cell i - 1 from cell i: the balance of cell i - 1 loses F_i, that of cell i gains it.
        for (unsigned int i = 1; i < n; ++i)
          {
            const double w     = R[i] * R[i] / (centre[i] - centre[i - 1]);
            const double jump  = mu_next[i] - mu_next[i - 1];
            const double k_mid = 0.5 * (kappa[i - 1] + kappa[i]);
            const double F     = w * k_mid * jump;
            // dF by r_{i-1}, r_i, r_{i+1}, mu_{i-1}, mu_i.
            const double dF_r[3] = {0.5 * w * jump * dkappa_a[i - 1],
                                    0.5 * w * jump * (dkappa_b[i - 1] + dkappa_a[i]),
                                    0.5 * w * jump * dkappa_b[i]};
            for (const unsigned int row : {i - 1, i})
              {
                const double sign = row == i - 1 ? -1. : 1.;
                residual[mu_column(row)] += sign * F;
                for (unsigned int j = 0; j < 3; ++j)
                  add(mu_column(row), r_column(i - 1 + j), sign * dF_r[j]);
                add(mu_column(row), mu_column(i - 1), -sign * w * k_mid);
                add(mu_column(row), mu_column(i), sign * w * k_mid);
              }
          }
        // The surface flux into the last cell, with mu = mu_bath at R = 1.
        {
          const double w    = 1. / (1. - centre[n - 1]);
          const double jump = mu_bath - mu_next[n - 1];
          residual[mu_column(n - 1)] -= w * kappa[n - 1] * jump;
          add(mu_column(n - 1), r_column(n - 1), -w * jump * dkappa_a[n - 1]);
          add(mu_column(n - 1), r_column(n), -w * jump * dkappa_b[n - 1]);
          add(mu_column(n - 1), mu_column(n - 1), w * kappa[n - 1]);
        }

        const int one  = 1;
        int       info = 0;
        dgbsv_(&size,
               &kl,
               &ku,
               &one,
               band.data(),
               &ldab,
               pivots.data(),
               residual.data(),
               &size,
               &info);
        if (info != 0)
          throw std::runtime_error("FreeSwellingSphere1D: singular Jacobian at t = " +
                                   std::to_string(t));
        const std::vector<double> &update = residual;
        // Damp the step so that every cell keeps lambda_r > 0 and J > 1.
        double alpha = 1.;
        for (;;)
          {
            bool admissible = true;
            for (unsigned int k = 0; k < n && admissible; ++k)
              {
                const double r_a = k > 0 ? r_next[k] - alpha * update[r_column(k)] : 0.;
                const double r_b = r_next[k + 1] - alpha * update[r_column(k + 1)];
                admissible =
                  r_b > r_a && cell(k, r_a, r_b).J > 1. + ReferenceTolerances::above_dry_state;
              }
            if (admissible || alpha < 1e-10)
              break;
            alpha *= 0.5;
          }
        double largest = 0.;
        for (unsigned int k = 0; k < n; ++k)
          {
            mu_next[k] -= alpha * update[mu_column(k)];
            r_next[k + 1] -= alpha * update[r_column(k + 1)];
            largest = std::max({largest,
                                std::abs(update[mu_column(k)]),
                                std::abs(update[r_column(k + 1)]) / r_next[k + 1]});
          }
        converged = alpha == 1. && largest < 1e-12;
      }
    if (!converged)
      throw std::runtime_error("FreeSwellingSphere1D: Newton did not converge at t = " +
                               std::to_string(t) + " with dt = " + std::to_string(dt));
    r_old  = r;
    r      = r_next;
    mu     = mu_next;
    dt_old = dt;
    t += dt;
    ++steps;
    // The uptake's discrete law: a Q_{n+1} + b Q_n + c Q_{n-1} = dt F_{n+1}.
    const double absorbed_new = (dt * surface_flux() - b * absorbed - c * absorbed_old) / a;
    absorbed_old              = absorbed;
    absorbed                  = absorbed_new;
  }


  double
  FreeSwellingSphere1D::time() const
  {
    return t;
  }


  unsigned int
  FreeSwellingSphere1D::n_steps() const
  {
    return steps;
  }


  double
  FreeSwellingSphere1D::outer_radius() const
  {
    return r.back();
  }


  double
  FreeSwellingSphere1D::solvent_uptake() const
  {
    // Sum of (J - lambda_0^3)/lambda_0^3 V0 over the cells.
    const double l03 = std::pow(parameters.lambda_0, 3);
    double       sum = 0.;
    for (unsigned int k = 0; k < parameters.n_cells; ++k)
      sum += (cell(k, r[k], r[k + 1]).J - l03) / l03 * volume_0[k];
    return sum;
  }


  double
  FreeSwellingSphere1D::surface_flux() const
  {
    const unsigned int n = parameters.n_cells;
    const Cell         s = cell(n - 1, r[n - 1], r[n]);
    const double kappa = (s.J - 1.) / (std::pow(parameters.lambda_0, 3) * s.lambda_r * s.lambda_r);
    return kappa * (bath_chemical_potential(t) - mu[n - 1]) / (1. - centre[n - 1]);
  }


  double
  FreeSwellingSphere1D::absorbed_solvent() const
  {
    return absorbed;
  }


  const std::vector<double> &
  FreeSwellingSphere1D::nodes() const
  {
    return R;
  }


  const std::vector<double> &
  FreeSwellingSphere1D::radii() const
  {
    return r;
  }


  std::vector<double>
  FreeSwellingSphere1D::cell_centres() const
  {
    return centre;
  }


  const std::vector<double> &
  FreeSwellingSphere1D::chemical_potentials() const
  {
    return mu;
  }


  std::vector<double>
  FreeSwellingSphere1D::radial_stretches() const
  {
    std::vector<double> values(parameters.n_cells);
    for (unsigned int k = 0; k < values.size(); ++k)
      values[k] = cell(k, r[k], r[k + 1]).lambda_r;
    return values;
  }


  std::vector<double>
  FreeSwellingSphere1D::hoop_stretches() const
  {
    std::vector<double> values(parameters.n_cells);
    for (unsigned int k = 0; k < values.size(); ++k)
      values[k] = cell(k, r[k], r[k + 1]).lambda_theta;
    return values;
  }


  std::vector<double>
  FreeSwellingSphere1D::radial_stresses() const
  {
    // s_r = dW_0/d lambda_r with W_0 = W/lambda_0^3 and dJ/d lambda_r = J/lambda_r.
    std::vector<double> values(parameters.n_cells);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const Cell s = cell(k, r[k], r[k + 1]);
        values[k] =
          parameters.N_nu * s.lambda_r / parameters.lambda_0 +
          energy_J(s.J, mu[k], parameters.N_nu, parameters.chi) * s.lambda_theta * s.lambda_theta;
      }
    return values;
  }


  std::vector<double>
  FreeSwellingSphere1D::hoop_stresses() const
  {
    std::vector<double> values(parameters.n_cells);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const Cell s = cell(k, r[k], r[k + 1]);
        values[k] =
          parameters.N_nu * s.lambda_theta / parameters.lambda_0 +
          energy_J(s.J, mu[k], parameters.N_nu, parameters.chi) * s.lambda_r * s.lambda_theta;
      }
    return values;
  }
} // namespace GelMPM

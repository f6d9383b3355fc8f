#include <gelmpm/reference/constrained_swelling_1d.h>
#include <gelmpm/reference/numerical_tolerances.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

// LAPACK's tridiagonal solver (deal.II links LAPACK but wraps no tridiagonal solve).
extern "C" void
dgtsv_(const int *n,
       const int *nrhs,
       double    *dl,
       double    *d,
       double    *du,
       double    *b,
       const int *ldb,
       int       *info);

namespace GelMPM
{
  ConstrainedSwelling1D::ConstrainedSwelling1D(const Parameters &parameters)
    : parameters(parameters)
    , dt_next(parameters.first_step)
  {
    if (parameters.n_cells < 2 || parameters.grading < 1. || parameters.first_step <= 0. ||
        parameters.growth < 1. || !(parameters.ramp >= 0.))
      throw std::invalid_argument("ConstrainedSwelling1D: need at least 2 cells, grading >= 1, "
                                  "a positive first step, growth >= 1 and a ramp >= 0");
    const unsigned int n = parameters.n_cells;
    Y.resize(n + 1);
    for (unsigned int i = 0; i <= n; ++i)
      Y[i] = 1. - std::pow(1. - static_cast<double>(i) / n, parameters.grading);
    Y[n] = 1.;
    volume.resize(n);
    volume[0] = 0.5 * (Y[1] - Y[0]);
    for (unsigned int i = 1; i < n; ++i)
      volume[i] = 0.5 * (Y[i + 1] - Y[i - 1]);
    lambda_top = stretch_at(parameters.mu_top);
    lambda.assign(n + 1, 1.);
    lambda_old = lambda;
  }


  double
  ConstrainedSwelling1D::chemical_potential(const double lambda) const
  {
    const double l0 = parameters.lambda_0, J = l0 * l0 * l0 * lambda, F = l0 * lambda;
    return parameters.N_nu * (F * F - 1.) / J + std::log(1. - 1. / J) + 1. / J +
           parameters.chi / (J * J);
  }


  double
  ConstrainedSwelling1D::chemical_potential_derivative(const double lambda) const
  {
    const double l0 = parameters.lambda_0, l03 = l0 * l0 * l0, J = l03 * lambda;
    return parameters.N_nu / l03 * (l0 * l0 + 1. / (lambda * lambda)) +
           l03 * (1. / (J * J * (J - 1.)) - 2. * parameters.chi / (J * J * J));
  }


  double
  ConstrainedSwelling1D::stretch_at(const double mu) const
  {
    // mu(lambda) increases monotonically from -infinity at J = 1 (chi < 1/2): bisection.
    const double l03 = std::pow(parameters.lambda_0, 3);
    double       lo = (1. + 1e-14) / l03, hi = 2.;
    while (chemical_potential(hi) < mu)
      hi *= 2.;
    for (unsigned int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k)
      {
        const double mid                         = 0.5 * (lo + hi);
        (chemical_potential(mid) < mu ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }


  double
  ConstrainedSwelling1D::mobility(const double lambda) const
  {
    const double l03 = std::pow(parameters.lambda_0, 3);
    return (l03 * lambda - 1.) / (l03 * lambda * lambda);
  }


  double
  ConstrainedSwelling1D::mobility_derivative(const double lambda) const
  {
    const double l03 = std::pow(parameters.lambda_0, 3);
    return (2. - l03 * lambda) / (l03 * lambda * lambda * lambda);
  }


  double
  ConstrainedSwelling1D::top_chemical_potential(const double time) const
  {
    if (parameters.ramp > 0. && time < parameters.ramp)
      {
        const double mu_0 = chemical_potential(1.);
        return mu_0 + (parameters.mu_top - mu_0) * std::max(time, 0.) / parameters.ramp;
      }
    return parameters.mu_top;
  }


  void
  ConstrainedSwelling1D::advance_to(const double t_end)
  {
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
  ConstrainedSwelling1D::step(const double dt)
  {
    const unsigned int n = parameters.n_cells;
    // BDF2 on non-uniform steps: (a y_{n+1} + b y_n + c y_{n-1}) / dt = f(y_{n+1}).
    double a = 1., b = -1., c = 0.;
    if (dt_old > 0.)
      {
        const double w = dt / dt_old;
        a              = (1. + 2. * w) / (1. + w);
        b              = -(1. + w);
        c              = w * w / (1. + w);
      }

    // The Jacobian's sub-, main and super-diagonal.
    std::vector<double> lower(n), diagonal(n), upper(n), residual(n);

    std::vector<double> next = lambda;
    next[n]                  = parameters.ramp > 0. && t + dt < parameters.ramp
                                 ? stretch_at(top_chemical_potential(t + dt))
                                 : lambda_top;
    std::vector<double> mu(n + 1), dmu(n + 1), k(n + 1), dk(n + 1);
    bool                converged = false;
    for (unsigned int iteration = 0; iteration < 50 && !converged; ++iteration)
      {
        for (unsigned int i = 0; i <= n; ++i)
          {
            mu[i]  = chemical_potential(next[i]);
            dmu[i] = chemical_potential_derivative(next[i]);
            k[i]   = mobility(next[i]);
            dk[i]  = mobility_derivative(next[i]);
          }
        std::fill(lower.begin(), lower.end(), 0.);
        std::fill(upper.begin(), upper.end(), 0.);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double rate = (a * next[i] + b * lambda[i] + c * lambda_old[i]) / dt;
            residual[i]       = volume[i] * rate;
            diagonal[i]       = volume[i] * a / dt;
          }
        // Fluxes q_{i+1/2} = k_mid (mu_{i+1} - mu_i) / (Y_{i+1} - Y_i) between nodes i, i+1.
        for (unsigned int i = 0; i < n; ++i)
          {
            const double h     = Y[i + 1] - Y[i];
            const double k_mid = 0.5 * (k[i] + k[i + 1]);
            const double q     = k_mid * (mu[i + 1] - mu[i]) / h;
            const double dq_di = 0.5 * dk[i] * (mu[i + 1] - mu[i]) / h - k_mid * dmu[i] / h;
            const double dq_di1 =
              0.5 * dk[i + 1] * (mu[i + 1] - mu[i]) / h + k_mid * dmu[i + 1] / h;
            residual[i] -= q;
            diagonal[i] -= dq_di;
            if (i + 1 < n)
              {
                residual[i + 1] += q;
                upper[i] -= dq_di1;
                diagonal[i + 1] += dq_di1;
                lower[i] += dq_di;
              }
          }
        // dgtsv overwrites the diagonals and returns the update in place of the residual.
        const int size = n, one = 1;
        int       info = 0;
        dgtsv_(&size,
               &one,
               lower.data(),
               diagonal.data(),
               upper.data(),
               residual.data(),
               &size,
               &info);
        if (info != 0)
          throw std::runtime_error("ConstrainedSwelling1D: singular Jacobian at t = " +
                                   std::to_string(t));
        const std::vector<double> &update = residual;
        // Damp the step so that J stays above 1 (the mixing energy's domain).
        const double l03   = std::pow(parameters.lambda_0, 3);
        double       alpha = 1.;
        for (unsigned int i = 0; i < n; ++i)
          while (l03 * (next[i] - alpha * update[i]) <= 1. + ReferenceTolerances::above_dry_state)
            alpha *= 0.5;
        for (unsigned int i = 0; i < n; ++i)
          next[i] -= alpha * update[i];
        const double largest =
          std::abs(*std::max_element(update.begin(), update.end(), [](double x, double y) {
            return std::abs(x) < std::abs(y);
          }));
        converged = alpha == 1. && largest < 1e-13 * lambda_top;
      }
    if (!converged)
      throw std::runtime_error("ConstrainedSwelling1D: Newton did not converge at t = " +
                               std::to_string(t) + " with dt = " + std::to_string(dt));
    lambda_old = lambda;
    lambda     = next;
    dt_old     = dt;
    t += dt;
    ++steps;
  }


  double
  ConstrainedSwelling1D::time() const
  {
    return t;
  }


  unsigned int
  ConstrainedSwelling1D::n_steps() const
  {
    return steps;
  }


  double
  ConstrainedSwelling1D::thickness_change() const
  {
    double sum = 0.;
    for (unsigned int i = 0; i + 1 < Y.size(); ++i)
      sum += 0.5 * (Y[i + 1] - Y[i]) * (lambda[i] + lambda[i + 1] - 2.);
    return sum;
  }


  const std::vector<double> &
  ConstrainedSwelling1D::nodes() const
  {
    return Y;
  }


  const std::vector<double> &
  ConstrainedSwelling1D::stretches() const
  {
    return lambda;
  }


  std::vector<double>
  ConstrainedSwelling1D::chemical_potentials() const
  {
    std::vector<double> mu(lambda.size());
    for (unsigned int i = 0; i < lambda.size(); ++i)
      mu[i] = chemical_potential(lambda[i]);
    return mu;
  }
} // namespace GelMPM

// The error norms of a step of MixedSystem: how well a converged solution meets the weakly
// imposed conditions, the size of its increment and the local error estimate of the step.

#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/core/collective.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  using dealii::Tensor;


  template <int dim>
  std::pair<double, double>
  MixedSystem<dim>::dirichlet_errors(const dealii::Vector<double> &solution) const
  {
    double u_error = 0., mu_error = 0.;
    for (const auto &r : cache.points())
      {
        if (r.kind == PointKind::volume || r.piece < 0)
          continue;
        const auto [du, delta_F, mu] = cache.fields_at(r, solution);
        if (r.projector.norm_square() > 0.)
          u_error = std::max(u_error, (r.projector * (r.u_n + du - r.u_bar)).norm());
        if (boundary_conditions.piece(r.piece).chemical_potential_prescribed() &&
            !(terms.contact() != nullptr && terms.contact()->seals(r, du, delta_F, mu)))
          mu_error = std::max(mu_error, std::abs(mu - r.mu_bar));
      }
    return {dealii::Utilities::MPI::max(u_error, communicator),
            dealii::Utilities::MPI::max(mu_error, communicator)};
  }


  template <int dim>
  double
  MixedSystem<dim>::largest_displacement_increment(const dealii::Vector<double> &solution) const
  {
    double largest = 0.;
    for (const auto &r : cache.points())
      {
        const auto [du, delta_F, mu] = cache.fields_at(r, solution);
        largest                      = std::max(largest, du.norm());
      }
    return dealii::Utilities::MPI::max(largest, communicator);
  }


  template <int dim>
  double
  MixedSystem<dim>::largest_volume_change(const dealii::Vector<double> &solution) const
  {
    double largest = 0.;
    for (const auto &r : cache.points())
      if (r.kind == PointKind::volume)
        {
          const auto [du, delta_F, mu] = cache.fields_at(r, solution);
          // F_{n+1} = delta_F F_n; the hoop stretch goes as the radius r_n.
          const double hoop = r.axisymmetric() ? (r.radius + du[0]) / r.radius : 1.;
          largest           = std::max(largest, std::abs(hoop * dealii::determinant(delta_F) - 1.));
        }
    return dealii::Utilities::MPI::max(largest, communicator);
  }


  template <int dim>
  double
  MixedSystem<dim>::largest_increment_deviation(const dealii::Vector<double> &solution,
                                                const double                  ratio) const
  {
    double largest = 0.;
    for (const auto &r : cache.points())
      {
        const auto [du, delta_F, mu] = cache.fields_at(r, solution);
        largest                      = std::max(largest, (du - ratio * r.du_last).norm());
      }
    return dealii::Utilities::MPI::max(largest, communicator);
  }


  template <int dim>
  typename MixedSystem<dim>::StepError
  MixedSystem<dim>::local_error_estimate(const dealii::Vector<double> &solution,
                                         const double                  ratio,
                                         const bool                    largest) const
  {
    // Milne's device for backward Euler after a step of ratio r = dt / dt_last: the corrector
    // misses x(t + dt) by dt^2 x''/2 and the linear predictor x_n + r (x_n - x_{n-1}) by
    // -dt (dt + dt_last) x''/2, so the local error is r / (2 r + 1) times their difference.
    const double weight = ratio / (2. * ratio + 1.);
    double       volume = 0., u_sum = 0., mu_sum = 0., u_max = 0., mu_max = 0.;
    for (const auto &r : cache.points())
      if (r.kind == PointKind::volume)
        {
          const auto [du, delta_F, mu] = cache.fields_at(r, solution);
          const double mu_difference   = (mu - r.mu_n) - ratio * r.dmu_last;
          const double u_square        = (du - ratio * r.du_last).norm_square();
          volume += r.measure;
          u_sum += r.measure * u_square;
          mu_sum += r.measure * mu_difference * mu_difference;
          u_max  = std::max(u_max, u_square);
          mu_max = std::max(mu_max, mu_difference * mu_difference);
        }
    if (largest)
      return {weight * std::sqrt(dealii::Utilities::MPI::max(u_max, communicator)),
              weight * std::sqrt(dealii::Utilities::MPI::max(mu_max, communicator))};
    double sums[3] = {volume, u_sum, mu_sum};
    Collective::sum_in_place(communicator, sums, 3);
    volume = sums[0];
    u_sum  = sums[1];
    mu_sum = sums[2];
    if (!(volume > 0.))
      return {0., 0.};
    return {weight * std::sqrt(u_sum / volume), weight * std::sqrt(mu_sum / volume)};
  }


#define GELMPM_INSTANTIATE(dim)                                                                    \
  template std::pair<double, double> MixedSystem<dim>::dirichlet_errors(                           \
    const dealii::Vector<double> &) const;                                                         \
  template double MixedSystem<dim>::largest_displacement_increment(const dealii::Vector<double> &) \
    const;                                                                                         \
  template double MixedSystem<dim>::largest_volume_change(const dealii::Vector<double> &) const;   \
  template double MixedSystem<dim>::largest_increment_deviation(const dealii::Vector<double> &,    \
                                                                double) const;                     \
  template MixedSystem<dim>::StepError                                                             \
  MixedSystem<dim>::local_error_estimate(const dealii::Vector<double> &, double, bool) const;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

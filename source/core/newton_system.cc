#include <gelmpm/core/newton_system.h>

#include <cmath>

namespace GelMPM
{
  double
  NewtonSystem::residual_norm_u() const
  {
    double sum = 0.;
    for (unsigned int i = 0; i < n_u_dofs(); ++i)
      sum += residual_(i) * residual_(i);
    return std::sqrt(sum);
  }


  double
  NewtonSystem::residual_norm_mu() const
  {
    double sum = 0.;
    for (unsigned int i = n_u_dofs(); i < residual_.size(); ++i)
      sum += residual_(i) * residual_(i);
    return std::sqrt(sum);
  }
} // namespace GelMPM

#ifndef gelmpm_assembly_nitsche_settings_h
#define gelmpm_assembly_nitsche_settings_h

#include <deal.II/base/parameter_handler.h>

namespace GelMPM
{
  /**
   * The largest penalty (Nitsche and contact) accepted: the condition number of the tangent grows
   * in proportion to a penalty (doc/extremes.md: 7e14 at gamma_u = 1e6 on a coarse grid), and far
   * above this the linear solves keep no digit, so that every step fails without naming a cause.
   */
  constexpr double largest_penalty = 1e8;

  /**
   * @brief The "Nitsche" section: weak imposition of essential conditions on surface material
   * points (paper eq. (32), §3.1).
   *
   * Penalties beta_u = gamma_u G / h_u and beta_mu = gamma_mu m_n / h_mu. The symmetric variant
   * (s = 1) keeps the coupled tangent symmetric, which the stability analysis needs; the
   * skew-symmetric variant (s = -1) is coercive for any penalty but makes the tangent unsymmetric.
   */
  struct NitscheSettings
  {
    /** gamma_u (Table 1: 1000). */
    double displacement_penalty = 1000.;
    /** gamma_mu (Table 1: 25). */
    double chemical_potential_penalty = 25.;
    /** s = +1 (symmetric) or -1 (skew-symmetric). */
    double symmetry = 1.;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace GelMPM

#endif

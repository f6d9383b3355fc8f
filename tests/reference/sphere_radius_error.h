// The swelling sphere's radius against the spherical finite-volume reference, shared by the tests
// of the axisymmetric MPM on uniform and refined grids (mpm_vs_sphere_reference*.cc).
#ifndef gelmpm_tests_sphere_radius_error_h
#define gelmpm_tests_sphere_radius_error_h

#include <gelmpm/reference/free_swelling_sphere_1d.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace GelMPMTests
{
  /**
   * Against FreeSwellingSphere1D with prm/swelling_sphere.prm's ramp of 4 tau_d: prints whether
   * |r_MPM - r_ref| / R_0 stays within 0.5 % of the equilibrium change (r_eq - R_0)/R_0 at every
   * row of @p statistics with t >= 1 tau_d (and the worst if not), and returns r_eq/R_0.
   */
  inline double
  report_sphere_radius_error(const std::map<std::string, std::vector<double>> &statistics)
  {
    GelMPM::FreeSwellingSphere1D::Parameters parameters;
    parameters.ramp = 4.;
    GelMPM::FreeSwellingSphere1D reference(parameters);
    const double                 equilibrium = reference.stretch_at(0.);
    const auto                  &t           = statistics.at("t_over_tau_d");
    const auto                  &radius      = statistics.at("radius_over_R0");
    double                       worst = 0., worst_time = 0.;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] >= 1.)
        {
          reference.advance_to(t[i]);
          const double error = std::abs(radius[i] - reference.outer_radius()) / (equilibrium - 1.);
          if (error > worst)
            worst = error, worst_time = t[i];
        }
    std::cout << "max |r - r_ref| / (r_eq - R_0) for t >= 1 tau_d below 0.005: "
              << (worst <= 0.005 ? "true" : "false") << std::endl;
    if (worst > 0.005)
      std::cout << "  (" << worst << " at t = " << worst_time << ")" << std::endl;
    return equilibrium;
  }
} // namespace GelMPMTests

#endif

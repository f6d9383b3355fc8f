// The body-fitted finite-element peer (FemConstrainedSwelling, Taylor-Hood Q2-Q1) on constrained
// swelling (paper §4.1) against the finite-difference reference ConstrainedSwelling1D, on a coarse
// mesh of 1 x 16 cells (Table 1 material, initial step 8.75e-5, caps of eq. (64)). Asserted:
// - |Delta h_FE - Delta h_ref| <= 0.5% of the equilibrium Delta h for every step with
//   0.01 <= t/tau_d <= 1;
// - the total Lagrangian form on Omega_0 gives the same Delta h as the previously converged
//   Lagrangian form of eq. (26), (31) at every step to 1e-10 (the two are algebraically equal);
// - without caps, at t = 1e5 tau_d (far beyond the 1713 of §4.1: the last per mille of the
//   swelling relaxes slowly), Delta h/h_0 equals lambda(mu = 0) - 1 of
//   ConstrainedSwelling1D::stretch_at(0) to 1e-8 relative (a homogeneous state is exact in the FE
//   space).
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_constrained_swelling.h>
#include <gelmpm/reference/constrained_swelling_1d.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

using GelMPM::FemConstrainedSwelling;
using GelMPM::FemMixedSystem;

namespace
{
  struct Run
  {
    bool                completed;
    std::vector<double> t, dh;
    unsigned int        iterations;
  };

  Run
  run(const FemConstrainedSwelling::Parameters &parameters,
      const double                              end_time,
      const std::string                        &caps)
  {
    const GelMPM::FloryRehnerGel<2> material;
    const auto  settings      = GelMPM::fem_run_settings({{"Initial step", "8.75e-5"},
                                                          {"End time", GelMPM::entry_value(end_time)},
                                                          {"Step caps", caps}},
                                                   {});
    const auto &time_stepping = settings.time_stepping;
    const auto &newton        = settings.newton;

    FemConstrainedSwelling swelling(material, parameters);
    Run                    result;
    result.completed  = swelling.run(time_stepping,
                                    newton,
                                    GelMPM::LinearSolver(),
                                    [&](const FemConstrainedSwelling::Step &s) {
                                      result.t.push_back(s.t_over_tau_d);
                                      result.dh.push_back(s.delta_h_over_h0);
                                    });
    result.iterations = swelling.total_newton_iterations();
    return result;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  FemConstrainedSwelling::Parameters parameters;
  parameters.cells_x     = 1;
  parameters.cells_y     = 16;
  const std::string caps = "5: 0.0125, 20: 0.0625, 40: 0.125, 100: 0.625";

  const Run fe = run(parameters, 1., caps);
  std::cout << "previously converged form: run completed: " << fe.completed << std::endl;

  GelMPM::ConstrainedSwelling1D reference(GelMPM::ConstrainedSwelling1D::Parameters{});
  const double                  equilibrium = reference.stretch_at(0.) - 1.;
  double                        worst = 0., worst_time = 0.;
  for (unsigned int i = 0; i < fe.t.size(); ++i)
    {
      reference.advance_to(fe.t[i]);
      if (fe.t[i] >= 0.01)
        {
          const double error = std::abs(fe.dh[i] - reference.thickness_change()) / equilibrium;
          if (error > worst)
            worst = error, worst_time = fe.t[i];
        }
    }
  std::cout << "steps: more than 50: " << (fe.t.size() > 50) << std::endl;
  std::cout << "max |Delta h - Delta h_ref| / Delta h_eq for 0.01 <= t/tau_d <= 1 below 0.005: "
            << (worst <= 0.005) << std::endl;
  if (worst > 0.005)
    std::cout << "  (" << worst << " at t = " << worst_time << ")" << std::endl;
  std::cout << "Delta h/h_0 at t = 1 tau_d: " << std::fixed << std::setprecision(3) << fe.dh.back()
            << " (reference " << reference.thickness_change() << ")" << std::endl;

  parameters.formulation = FemMixedSystem<2>::Formulation::total_lagrangian;
  const Run total        = run(parameters, 1., caps);
  bool      same         = total.completed && total.t.size() == fe.t.size();
  double    difference   = 0.;
  for (unsigned int i = 0; same && i < fe.t.size(); ++i)
    {
      same       = same && std::abs(total.t[i] - fe.t[i]) <= 1e-12 * fe.t[i];
      difference = std::max(difference, std::abs(total.dh[i] - fe.dh[i]));
    }
  std::cout << "total Lagrangian form: same steps: " << same
            << ", same Delta h to 1e-10: " << (same && difference <= 1e-10) << std::endl;
  if (difference > 1e-10)
    std::cout << "  (" << std::scientific << difference << ")" << std::defaultfloat << std::endl;

  parameters.formulation = FemMixedSystem<2>::Formulation::previously_converged_lagrangian;
  const Run    drained   = run(parameters, 1e5, "");
  const double relative  = std::abs(drained.dh.back() - equilibrium) / equilibrium;
  std::cout << "t = 1e5 tau_d without caps: run completed: " << drained.completed
            << ", Delta h equals lambda(mu = 0) - 1 to 1e-8: " << (relative <= 1e-8) << std::endl;
  if (relative > 1e-8)
    std::cout << "  (" << std::scientific << relative << ")" << std::defaultfloat << std::endl;
  std::cout << "equilibrium Delta h/h_0: " << std::fixed << std::setprecision(4)
            << drained.dh.back() << " (analytic " << equilibrium << ")" << std::endl;
  return 0;
}

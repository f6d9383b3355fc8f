// Verification of the coupled MPM solver against the finite-difference reference: the scene
// prm/constrained_swelling.prm (paper §4.1) on a coarser grid (u on 20 x 60 cells of a 0.5 x 1.5
// grid, mu on 10 x 30, 3 x 3 points per cell) up to t = 2 tau_d. Asserted:
// - |Delta h_MPM - Delta h_ref| <= 0.5% of the equilibrium Delta h for every step with
//   t >= 0.01 tau_d (the full-resolution benchmark is held to 2% by the paper's criterion; this
//   coarse run measures 0.07%);
// - the log-log slope of Delta h over 0.01 <= t/tau_d <= 0.1 is 0.5 +- 0.05 (self-similar
//   swelling, Delta h ~ sqrt(t));
// - every step converged with the stable signature (n_dofs_u, n_dofs_mu, 0) is not asserted here
//   (tests/scenes/constrained_swelling_short does).
#include <gelmpm/reference/constrained_swelling_1d.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "../scene_run.h"


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The run's own progress output is not part of what this test compares.
  const auto run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/constrained_swelling.prm",
                           "results",
                           {"Background grid/Upper corner=0.5, 1.5",
                            "Background grid/Cells=20, 60",
                            "Material points/Points per cell=3",
                            "Time stepping/End time=2",
                            "Time stepping/Stop at times="});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  auto                          mpm = run.statistics;
  GelMPM::ConstrainedSwelling1D reference(GelMPM::ConstrainedSwelling1D::Parameters{});
  const double                  equilibrium = reference.stretch_at(0.) - 1.;
  const auto                   &t           = mpm["t_over_tau_d"];
  const auto                   &dh          = mpm["delta_h_over_h0"];
  double                        worst = 0., worst_time = 0.;
  double                        t_a = 0., dh_a = 0., t_b = 0., dh_b = 0.;
  for (unsigned int i = 0; i < t.size(); ++i)
    {
      reference.advance_to(t[i]);
      if (t[i] >= 0.01)
        {
          const double error = std::abs(dh[i] - reference.thickness_change()) / equilibrium;
          if (error > worst)
            worst = error, worst_time = t[i];
          if (t_a == 0.)
            t_a = t[i], dh_a = dh[i];
        }
      if (t[i] <= 0.1)
        t_b = t[i], dh_b = dh[i];
    }
  std::cout << "steps: more than 50: " << (t.size() > 50) << std::endl;
  std::cout << "max |Delta h - Delta h_ref| / Delta h_eq for t >= 0.01 tau_d below 0.005: "
            << (worst <= 0.005) << std::endl;
  if (worst > 0.005)
    std::cout << "  (" << worst << " at t = " << worst_time << ")" << std::endl;
  const double slope = std::log(dh_b / dh_a) / std::log(t_b / t_a);
  std::cout << "log-log slope over [0.01, 0.1] tau_d within 0.5 +- 0.05: "
            << (std::abs(slope - 0.5) <= 0.05) << std::endl;
  std::cout << "Delta h/h_0 at t = 2 tau_d: " << std::fixed << std::setprecision(3) << dh.back()
            << " (reference " << reference.thickness_change() << ")" << std::endl;
  return 0;
}

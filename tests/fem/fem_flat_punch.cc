// The body-fitted finite-element peer on the flat punch of paper §4.2 (FemFlatPunch, Taylor-Hood
// Q2-Q1 on n x n cells of the swollen gel), punch depth 0.05 H ramped over t_inc = 3.125e-6 tau_d
// and held to 2300 tau_d, against the physics of the two limits and against the MPM
// (prm/flat_punch.prm, discretisation (iv): Q2-Q2SD, h_u = 0.05H, same depth). Asserted:
// - undrained limit: at t_inc the gel's volume changed by less than 1e-3 (relative; the drained
//   change is 2e-2) in the FE model (8 x 8 and 16 x 16) and the MPM: solvent moves over a
//   diffusion length of 0.002 H in 3e-6 tau_d, and only the first layer of cells under the
//   mu = 0 surface drains (measured: -2.5e-4 on 8 x 8, -3.5e-7 on 16 x 16, 4e-6 in the MPM);
// - drained limit: at 2300 tau_d max |mu|/k_BT < 1e-8 in the FE model, the punch sits at
//   u_y = -0.05 H (to 1e-12) and the free top lies above it;
// - the volume lost by 2300 tau_d (solvent squeezed out under the punch, about 2.1 %) agrees
//   between 8 x 8 and 16 x 16 cells to 2 % of its value and between the MPM and the 16 x 16 FE
//   model to 6 % (measured: 1.2 % and 4.5 %; doc/fem_peer.md: the FE value converges at first
//   order under refinement, towards -2.08 %);
// - the scene's depth 0.09 H on 16 x 16 cells: the ramp reaches its end with the punch at
//   -0.09 H (to 1e-12), still undrained (|dV/V| < 1e-3; measured 3.0e-4). This mesh is far from
//   where it gives out (doc/fem_peer.md: it passes 0.15 H; measured here, a ramp to 0.15 H ends
//   at a largest stretch ratio of 5.8, against 2.2 at 0.09 H). The failure of the finer 32 x 32
//   mesh at this depth is documented there but not asserted: its path runs at the edge of what
//   that mesh survives, and whether the damped Newton gets through the ramp or stops at 0.0696 H
//   depends on the BLAS kernel and the number of threads.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_flat_punch.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

#include "../scene_run.h"

using GelMPM::FemFlatPunch;

namespace
{
  constexpr double t_inc = 3.125e-6;

  struct Run
  {
    GelMPM::FemRunResult result;
    double               volume_change_undrained = 0., volume_change_end = 0.;
    double               max_mu_end = 0., punch_error = 0., lowest_free_top = 0.;
    FemFlatPunch::Step   last;
  };

  Run
  run_fem(const unsigned int cells, const double depth, const double end_time)
  {
    const auto  material      = FemFlatPunch::scene_material();
    const auto  settings      = GelMPM::fem_run_settings({{"Initial step", "3.125e-7"},
                                                          {"End time", GelMPM::entry_value(end_time)},
                                                          {"Step caps", "3.125e-6: 3.125e-7"},
                                                          {"Stop at times", "3.125e-6"},
                                                          {"Minimum step", "1e-12"}},
                                                   {});
    const auto &time_stepping = settings.time_stepping;
    const auto &newton        = settings.newton;

    FemFlatPunch::Parameters parameters;
    parameters.cells = cells;
    parameters.depth = depth;
    FemFlatPunch punch(material, parameters);
    Run          run;
    run.result =
      punch.run(time_stepping, newton, GelMPM::LinearSolver(), [&](const FemFlatPunch::Step &s) {
        if (std::abs(s.t_over_tau_d - t_inc) < 1e-9 * t_inc)
          run.volume_change_undrained = s.relative_volume_change;
        run.volume_change_end = s.relative_volume_change;
        run.last              = s;
      });
    const auto &system = punch.system();
    for (unsigned int i = system.n_u_dofs(); i < system.n_dofs(); ++i)
      run.max_mu_end = std::max(run.max_mu_end, std::abs(system.state()(i)));
    run.lowest_free_top = 0.;
    for (const auto &sample : punch.top_samples(4))
      if (sample.X[0] <= parameters.punch_width)
        run.punch_error = std::max(run.punch_error, std::abs(sample.u[1] + depth));
      else
        run.lowest_free_top = std::min(run.lowest_free_top, sample.u[1]);
    return run;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  const Run coarse = run_fem(8, 0.05, 2300.);
  const Run fine   = run_fem(16, 0.05, 2300.);
  for (const auto *run : {&coarse, &fine})
    {
      std::cout << (run == &coarse ? "FE 8 x 8" : "FE 16 x 16")
                << ": run completed: " << run->result.completed << "; undrained |dV/V| below 1e-3: "
                << (std::abs(run->volume_change_undrained) < 1e-3)
                << "; drained max |mu| below 1e-8: " << (run->max_mu_end < 1e-8)
                << "; punch at -0.05 to 1e-12: " << (run->punch_error < 1e-12)
                << "; free top above the punch: " << (run->lowest_free_top > -0.05) << std::endl;
      if (!(std::abs(run->volume_change_undrained) < 1e-3 && run->max_mu_end < 1e-8))
        std::cout << "  (dV/V " << run->volume_change_undrained << ", max |mu| " << run->max_mu_end
                  << ")" << std::endl;
    }
  const double mesh_difference =
    std::abs(coarse.volume_change_end - fine.volume_change_end) / std::abs(fine.volume_change_end);
  std::cout << "drained dV/V of 8 x 8 and 16 x 16 within 2 %: " << (mesh_difference < 0.02)
            << "; 16 x 16: " << std::fixed << std::setprecision(1) << 100. * fine.volume_change_end
            << " %" << std::defaultfloat << std::endl;

  const auto mpm = GelMPMTests::run_scene(
    std::string(SOURCE_DIR) + "/../../prm/flat_punch.prm",
    "mpm_iv",
    {"Background grid/Cells=30, 30",
     "Boundary conditions/punch/Displacement value/Function expression=0; -0.05 * min(t / "
     "3.125e-6, 1)",
     "Observables/Volume ratio range=true"});
  const auto &t         = mpm.statistics.at("t_over_tau_d");
  const auto &J_mean    = mpm.statistics.at("J_mean");
  double      undrained = 0.;
  for (unsigned int i = 0; i < t.size(); ++i)
    if (std::abs(t[i] - t_inc) < 1e-9 * t_inc)
      undrained = J_mean[i] / J_mean[0] - 1.;
  const double drained = J_mean.back() / J_mean[0] - 1.;
  const double method_difference =
    std::abs(drained - fine.volume_change_end) / std::abs(fine.volume_change_end);
  std::cout << "MPM (iv): run completed: " << (mpm.status == 0)
            << "; undrained |dV/V| below 1e-3: " << (std::abs(undrained) < 1e-3)
            << "; drained dV/V within 6 % of FE 16 x 16: " << (method_difference < 0.06)
            << std::endl;
  if (!(method_difference < 0.06))
    std::cout << "  (MPM " << drained << ", FE " << fine.volume_change_end << ")" << std::endl;

  const Run deep = run_fem(16, 0.09, t_inc);
  std::cout << "FE 16 x 16 at the scene's depth 0.09: reaches the end of the ramp: "
            << deep.result.completed << "; punch at -0.09 to 1e-12: " << (deep.punch_error < 1e-12)
            << "; undrained |dV/V| below 1e-3: " << (std::abs(deep.volume_change_undrained) < 1e-3)
            << std::endl;
  if (!(deep.result.completed && std::abs(deep.volume_change_undrained) < 1e-3))
    std::cout << "  (depth " << -deep.last.punch_displacement << ", dV/V "
              << deep.volume_change_undrained << ")" << std::endl;
  return 0;
}

// gelmpm-fem-flat-punch: flat punch indentation of a swollen gel (paper §4.2, prm/flat_punch.prm)
// with the body-fitted finite-element peer of the MPM (FemMixedSystem: Taylor-Hood on a conforming
// mesh of the initial configuration, same equations, material, Newton test and time stepping;
// doc/fem_peer.md). Writes statistics.csv (one row per converged step, with the punch force and
// the mesh distortion) and the top surface (top_profile-NN.csv) at the stop times and at the end of
// the run.
//
//   gelmpm-fem-flat-punch [--set "Section/Entry=value"]... [--quiet] prm/flat_punch.prm
//
// The gel, the time stepping and Newton are the scene's (PeerInput); the mesh and the punch are
// the entries of 'FE peer'.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_flat_punch.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_input.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
  /** Write the top surface (initial x, u, mu) of the converged state to @p file_name. */
  void
  write_top_profile(const GelMPM::FemFlatPunch &punch, const std::string &file_name)
  {
    GelMPM::StatisticsFile profile;
    profile.open(file_name, {"X", "u_x", "u_y", "mu_over_kT"});
    for (const auto &sample : punch.top_samples(8))
      {
        profile.set("X", sample.X[0]);
        profile.set("u_x", sample.u[0]);
        profile.set("u_y", sample.u[1]);
        profile.set("mu_over_kT", sample.mu);
        profile.write_row();
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      GelMPM::PeerInput
        input(argc, argv, "gelmpm-fem-flat-punch", [](dealii::ParameterHandler &prm) {
          prm.declare_entry("Cells",
                            "20",
                            dealii::Patterns::Integer(1),
                            "Cells per direction of the gel [0, 1] x [0, 1] (lengths in H).");
          GelMPM::PeerInput::declare_degree(prm);
          prm.declare_entry("Punch width",
                            "0.25",
                            dealii::Patterns::Double(0.),
                            "Width of the punch from the left edge (the scene's punch piece).");
          prm.declare_entry("Depth",
                            "0.09",
                            dealii::Patterns::Double(0.),
                            "Final punch displacement into the gel (H).");
          prm.declare_entry("Ramp time",
                            "3.125e-6",
                            dealii::Patterns::Double(0.),
                            "The punch moves linearly over this time (tau_d), as the scene's "
                            "boundary function does.");
          GelMPM::PeerInput::declare_output_directory(prm,
                                                      "output/fem_flat_punch",
                                                      "statistics.csv and the top profiles");
        });
      if (input.help)
        {
          std::cout << input.usage(
            "Flat punch indentation of a swollen gel (paper §4.2) with the body-fitted "
            "Taylor-Hood finite-element peer of the MPM, for the scene prm/flat_punch.prm.");
          return 0;
        }
      input.require_one_gel();
      GelMPM::FemFlatPunch::Parameters parameters;
      std::string                      directory;
      {
        auto &prm              = input.peer_section();
        parameters.cells       = prm.get_integer("Cells");
        parameters.u_degree    = GelMPM::PeerInput::degree(prm);
        parameters.punch_width = prm.get_double("Punch width");
        parameters.depth       = prm.get_double("Depth");
        parameters.ramp_time   = prm.get_double("Ramp time");
        directory              = prm.get("Output directory");
        input.leave_peer_section();
      }
      const auto &time_stepping = input.time_stepping;
      const auto &newton        = input.newton;
      const auto &linear_solver = input.linear_solver;
      const auto &quiet         = input.quiet;
      const auto  end_time      = time_stepping.end_time;

      const auto           start    = std::chrono::steady_clock::now();
      const auto          &material = input.material;
      GelMPM::FemFlatPunch punch(material, parameters);
      const auto          &system = punch.system();
      std::cout << "gelmpm-fem-flat-punch: " << parameters.cells << " x " << parameters.cells
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
                << " mu), depth " << parameters.depth << " H, lambda_0 " << material.lambda_0()
                << std::endl;

      // Held to the end: neither a gelmpm run nor another peer writes there meanwhile.
      const auto lock = input.claim_output_directory(directory);

      const std::vector<std::string> columns = {"step",
                                                "t_over_tau_d",
                                                "dt",
                                                "newton_iterations",
                                                "attempts",
                                                "residual_u",
                                                "residual_mu",
                                                "punch_displacement",
                                                "punch_force_x",
                                                "punch_force_y",
                                                "min_det_F",
                                                "max_stretch_ratio",
                                                "relative_volume_change",
                                                "n_dofs"};
      GelMPM::StatisticsFile         statistics;
      statistics.open(directory + "/statistics.csv", columns);
      for (const auto &column : columns)
        statistics.set(column, 0.);
      statistics.set("min_det_F", 1.);
      statistics.set("max_stretch_ratio", 1.);
      statistics.set("n_dofs", system.n_dofs());
      statistics.write_row();

      // Top surface at each stop time that is reached and at the end.
      std::vector<double>    profile_times = time_stepping.stop_times;
      GelMPM::StatisticsFile profiles;
      profiles.open(directory + "/profiles.csv", {"index", "t_over_tau_d"});
      unsigned int n_profiles    = 0;
      double       last_time     = 0.;
      const auto   write_profile = [&](const double t) {
        char name[32];
        std::snprintf(name, sizeof(name), "top_profile-%02u.csv", n_profiles);
        write_top_profile(punch, directory + "/" + name);
        profiles.set("index", n_profiles);
        profiles.set("t_over_tau_d", t);
        profiles.write_row();
        ++n_profiles;
      };

      unsigned int n_steps = 0;
      const auto   result =
        punch.run(time_stepping, newton, linear_solver, [&](const GelMPM::FemFlatPunch::Step &s) {
          n_steps   = s.number;
          last_time = s.t_over_tau_d;
          statistics.set("step", s.number);
          statistics.set("t_over_tau_d", s.t_over_tau_d);
          statistics.set("dt", s.dt_over_tau_d);
          statistics.set("newton_iterations", s.newton_iterations);
          statistics.set("attempts", s.attempts);
          statistics.set("residual_u", s.residual_u);
          statistics.set("residual_mu", s.residual_mu);
          statistics.set("punch_displacement", s.punch_displacement);
          statistics.set("punch_force_x", s.punch_force[0]);
          statistics.set("punch_force_y", s.punch_force[1]);
          statistics.set("min_det_F", s.deformation.min_det_F);
          statistics.set("max_stretch_ratio", s.deformation.max_stretch_ratio);
          statistics.set("relative_volume_change", s.relative_volume_change);
          statistics.set("n_dofs", system.n_dofs());
          statistics.write_row();
          for (const double t : profile_times)
            if (std::abs(s.t_over_tau_d - t) <= 1e-9 * t)
              write_profile(s.t_over_tau_d);
          if (!quiet)
            std::cout << "  step " << std::setw(5) << s.number << "  t/tau_d = " << std::setw(11)
                      << std::setprecision(5) << s.t_over_tau_d << "  dt = " << std::setw(10)
                      << s.dt_over_tau_d << "  Newton " << std::setw(2) << s.newton_iterations
                      << "  punch " << std::setw(9) << s.punch_displacement << "  force "
                      << std::setw(10) << s.punch_force[1] << "  min det F " << std::setw(9)
                      << s.deformation.min_det_F << "  max stretch ratio "
                      << s.deformation.max_stretch_ratio << std::endl;
        });
      // The end state (or the last converged one) unless a stop time already wrote it.
      const bool end_written =
        std::any_of(profile_times.begin(), profile_times.end(), [&](const double t) {
          return std::abs(last_time - t) <= 1e-9 * t;
        });
      if (!end_written)
        write_profile(last_time);
      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!result.completed)
        {
          std::cerr << "gelmpm-fem-flat-punch: " << result.failure << "\n"
                    << "  kept: " << n_steps << " converged steps to t/tau_d = " << last_time
                    << " in " << directory << " (statistics.csv, top_profile-*.csv)" << std::endl;
          return 1;
        }
      std::cout << "gelmpm-fem-flat-punch: reached t/tau_d = " << end_time << " in " << n_steps
                << " steps, " << result.newton_iterations << " Newton iterations\n"
                << "  wall time " << std::setprecision(4) << wall << " s\n"
                << "  results: " << directory << "/statistics.csv, " << directory
                << "/top_profile-*.csv (times in profiles.csv)" << std::endl;
    }
  catch (const GelMPM::InputError &e)
    {
      std::cerr << "gelmpm-fem-flat-punch: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-flat-punch: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}

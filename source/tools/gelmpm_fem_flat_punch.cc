// gelmpm-fem-flat-punch: flat punch indentation of a swollen gel (paper §4.2, prm/flat_punch.prm)
// with the body-fitted finite-element peer of the MPM (FemMixedSystem: Taylor-Hood on a conforming
// mesh of the initial configuration, same equations, material, Newton test and time stepping;
// doc/fem_peer.md). Writes statistics.csv (one row per converged step, with the punch force and
// the mesh distortion) and the top surface (top_profile-NN.csv) at the stop times and at the end of
// the run.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_flat_punch.h>
#include <gelmpm/io/statistics_file.h>

#include <deal.II/base/mpi.h>

#include <boost/program_options.hpp>
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
  namespace po = boost::program_options;
  GelMPM::FemFlatPunch::Parameters parameters;
  double                           ramp_step, end_time, tolerance;
  unsigned int                     max_iterations;
  std::string                      stops, directory;
  bool                             quiet = false;
  po::options_description          options(
    "gelmpm-fem-flat-punch: flat punch indentation of a swollen gel (paper §4.2) with the "
             "body-fitted Taylor-Hood finite-element peer of the MPM.\nThe gel is [0, 1] x [0, 1] "
             "(lengths in H) of the swollen initial state (mu_0 = 0, Table 1 material otherwise), "
             "times in tau_d = H^2/D.\nOptions");
  // clang-format off
  options.add_options()
    ("help", "this text")
    ("cells", po::value(&parameters.cells)->default_value(20), "cells per direction (n x n)")
    ("degree", po::value(&parameters.u_degree)->default_value(2),
     "displacement degree k (mu: k - 1, Taylor-Hood)")
    ("punch-width", po::value(&parameters.punch_width)->default_value(0.25),
     "width of the punch from the left edge")
    ("depth", po::value(&parameters.depth)->default_value(0.09),
     "final punch displacement into the gel")
    ("ramp-time", po::value(&parameters.ramp_time)->default_value(3.125e-6),
     "the punch moves linearly over this time (tau_d)")
    ("ramp-step", po::value(&ramp_step)->default_value(3.125e-7),
     "the fixed time step during the ramp (tau_d); adaptive afterwards")
    ("stop-times", po::value(&stops)->default_value(""),
     "comma-separated times (tau_d) the stepping lands on; the top surface is written there "
     "(default: the end of the ramp and 0.1, as the scene)")
    ("end-time", po::value(&end_time)->default_value(2300.), "end of the run (tau_d)")
    ("tolerance", po::value(&tolerance)->default_value(1e-10),
     "Newton tolerance (as 'Newton/Tolerance' of gelmpm)")
    ("max-iterations", po::value(&max_iterations)->default_value(15),
     "Newton iterations before a step is cut")
    ("quiet", po::bool_switch(&quiet), "no line per step")
    ("output", po::value(&directory)->default_value("output/fem_flat_punch"), "output directory");
  // clang-format on

  try
    {
      po::variables_map vm;
      po::store(po::parse_command_line(argc, argv, options), vm);
      if (vm.count("help"))
        {
          std::cout << options << std::endl;
          return 0;
        }
      po::notify(vm);
      if (!(ramp_step > 0.))
        throw std::invalid_argument("--ramp-step must be positive");

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      // Like the scene, land on the end of the ramp (whatever --ramp-time is) and on 0.1 tau_d.
      if (!vm.count("stop-times") || vm["stop-times"].defaulted())
        stops = GelMPM::entry_value(parameters.ramp_time) + ", 0.1";
      // The scene's 'Step caps = t_inc: dt_ramp': a fixed step during the ramp.
      const auto settings =
        GelMPM::fem_run_settings({{"Initial step", GelMPM::entry_value(ramp_step)},
                                  {"End time", GelMPM::entry_value(end_time)},
                                  {"Step caps",
                                   GelMPM::entry_value(parameters.ramp_time) + ": " +
                                     GelMPM::entry_value(ramp_step)},
                                  {"Stop at times", stops}},
                                 {{"Tolerance", GelMPM::entry_value(tolerance)},
                                  {"Maximum iterations", std::to_string(max_iterations)}});
      const auto                &time_stepping = settings.time_stepping;
      const auto                &newton        = settings.newton;
      const GelMPM::LinearSolver linear_solver;

      const auto           start    = std::chrono::steady_clock::now();
      const auto           material = GelMPM::FemFlatPunch::scene_material();
      GelMPM::FemFlatPunch punch(material, parameters);
      const auto          &system = punch.system();
      std::cout << "gelmpm-fem-flat-punch: " << parameters.cells << " x " << parameters.cells
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
                << " mu), depth " << parameters.depth << " H, lambda_0 " << material.lambda_0()
                << std::endl;

      std::filesystem::create_directories(directory);
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
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-flat-punch: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}

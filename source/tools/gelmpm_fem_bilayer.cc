// gelmpm-fem-bilayer: the bilayer actuator of prm/bilayer_actuator.prm with the body-fitted
// finite-element peer of the MPM (FemMixedSystem with one gel per layer: Taylor-Hood on a
// conforming mesh of the initial configuration, same equations, materials, Newton test and time
// stepping; doc/fem_peer.md). Writes statistics.csv (one row per converged step, with the
// curvature of the lower surface) and the lower surface at the end (surface_bottom.csv).
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_bilayer.h>
#include <gelmpm/io/statistics_file.h>

#include <deal.II/base/mpi.h>

#include <boost/program_options.hpp>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

int
main(int argc, char **argv)
{
  namespace po = boost::program_options;
  GelMPM::FemBilayer::Parameters parameters;
  double                         end_time, tolerance;
  unsigned int                   max_iterations;
  std::string                    directory;
  bool                           quiet = false;
  po::options_description        options(
    "gelmpm-fem-bilayer: the bilayer actuator of prm/bilayer_actuator.prm (a bonded two-layer "
           "strip in a bath that bends) with the body-fitted Taylor-Hood finite-element peer of the "
           "MPM.\nHalf strip 0 < x < 2, 0 < y < 0.2 of the initial configuration; the upper layer is "
           "the Table 1 gel, the lower one (y < 0.1) has chi = --chi-passive; both start at the "
           "Table 1 mu_0, each at its own lambda_0 (eq. (22)). Times in tau_d = 0.2^2/D.\nOptions");
  // clang-format off
  options.add_options()
    ("help", "this text")
    ("cells", po::value(&parameters.cells)->default_value(8),
     "square cells through the thickness (even; 10 times as many along the half strip)")
    ("degree", po::value(&parameters.u_degree)->default_value(2),
     "displacement degree k (mu: k - 1, Taylor-Hood)")
    ("chi-passive", po::value(&parameters.chi_passive)->default_value(0.3),
     "Flory-Huggins chi of the lower (passive) layer")
    ("bath", po::value(&parameters.mu_bath)->default_value(-0.04),
     "mu/k_BT of the bath after the ramp")
    ("start", po::value(&parameters.mu_start)->default_value(-0.1459745),
     "mu/k_BT of the bath at t = 0 (the scene's, about the Table 1 mu_0)")
    ("ramp-time", po::value(&parameters.ramp_time)->default_value(1.),
     "the bath goes linearly from --start to --bath over this time (tau_d)")
    ("end-time", po::value(&end_time)->default_value(10.), "end of the run (tau_d)")
    ("tolerance", po::value(&tolerance)->default_value(1e-10),
     "Newton tolerance (as 'Newton/Tolerance' of gelmpm)")
    ("max-iterations", po::value(&max_iterations)->default_value(15),
     "Newton iterations before a step is cut")
    ("quiet", po::bool_switch(&quiet), "no line per step")
    ("output", po::value(&directory)->default_value("output/fem_bilayer"), "output directory");
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

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      // The scene's stepping: steps of at most 0.05 tau_d during the ramp, 0.5 after it.
      const std::string ramp     = GelMPM::entry_value(parameters.ramp_time);
      const auto        settings = GelMPM::fem_run_settings(
        {{"Characteristic length", GelMPM::entry_value(parameters.thickness)},
                {"Initial step", "1e-3"},
                {"End time", GelMPM::entry_value(end_time)},
                {"Step caps",
                 ramp + ": 0.05, " + GelMPM::entry_value(std::max(end_time, parameters.ramp_time)) +
                   ": 0.5"}},
        {{"Tolerance", GelMPM::entry_value(tolerance)},
                {"Maximum iterations", std::to_string(max_iterations)}});
      const GelMPM::LinearSolver linear_solver;

      const auto         start = std::chrono::steady_clock::now();
      GelMPM::FemBilayer bilayer(parameters);
      const auto        &system    = bilayer.system();
      const auto        &materials = bilayer.materials();
      std::cout << "gelmpm-fem-bilayer: " << 10 * parameters.cells << " x " << parameters.cells
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs; lambda_0 " << materials[0].lambda_0()
                << " (active, chi " << materials[0].chi() << "), " << materials[1].lambda_0()
                << " (passive, chi " << materials[1].chi() << "), mu_0 " << materials[0].mu_0()
                << std::endl;

      std::filesystem::create_directories(directory);
      const std::vector<std::string> columns = {"step",
                                                "t_over_tau_d",
                                                "dt",
                                                "newton_iterations",
                                                "attempts",
                                                "residual_u",
                                                "residual_mu",
                                                "bath_mu_over_kT",
                                                "curvature",
                                                "tip_deflection",
                                                "relative_volume_change",
                                                "n_dofs"};
      GelMPM::StatisticsFile         statistics;
      statistics.open(directory + "/statistics.csv", columns);
      for (const auto &column : columns)
        statistics.set(column, 0.);
      statistics.set("bath_mu_over_kT", bilayer.bath_chemical_potential(0.));
      statistics.set("n_dofs", system.n_dofs());
      statistics.write_row();

      unsigned int n_steps   = 0;
      double       last_time = 0., curvature = 0.;
      const auto   result =
        bilayer.run(settings.time_stepping,
                    settings.newton,
                    linear_solver,
                    [&](const GelMPM::FemBilayer::Step &s) {
                      n_steps   = s.number;
                      last_time = s.t_over_tau_d;
                      curvature = s.curvature;
                      statistics.set("step", s.number);
                      statistics.set("t_over_tau_d", s.t_over_tau_d);
                      statistics.set("dt", s.dt_over_tau_d);
                      statistics.set("newton_iterations", s.newton_iterations);
                      statistics.set("attempts", s.attempts);
                      statistics.set("residual_u", s.residual_u);
                      statistics.set("residual_mu", s.residual_mu);
                      statistics.set("bath_mu_over_kT",
                                     bilayer.bath_chemical_potential(s.t_over_tau_d));
                      statistics.set("curvature", s.curvature);
                      statistics.set("tip_deflection", s.tip_deflection);
                      statistics.set("relative_volume_change", s.relative_volume_change);
                      statistics.set("n_dofs", system.n_dofs());
                      statistics.write_row();
                      if (!quiet)
                        std::cout << "  step " << std::setw(4) << s.number
                                  << "  t/tau_d = " << std::setw(10) << std::setprecision(5)
                                  << s.t_over_tau_d << "  dt = " << std::setw(9) << s.dt_over_tau_d
                                  << "  Newton " << std::setw(2) << s.newton_iterations
                                  << "  curvature " << std::setw(10) << s.curvature << "  tip u_y "
                                  << s.tip_deflection << std::endl;
                    });

      // The lower surface of the last converged state: current x, y (as the MPM's
      // surface_bottom-*.csv) and the initial X.
      GelMPM::StatisticsFile surface;
      surface.open(directory + "/surface_bottom.csv", {"X", "x", "y"});
      const auto points = bilayer.lower_surface();
      // lower_surface() samples every face at 9 equally spaced points: X is uniform.
      const auto samples_X = [&](const unsigned int i) {
        return 0.5 * parameters.length * i / (points.size() - 1);
      };
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          surface.set("X", samples_X(i));
          surface.set("x", points[i][0]);
          surface.set("y", points[i][1]);
          surface.write_row();
        }

      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!result.completed)
        {
          std::cerr << "gelmpm-fem-bilayer: " << result.failure << "\n"
                    << "  kept: " << n_steps << " converged steps to t/tau_d = " << last_time
                    << " in " << directory << " (statistics.csv, surface_bottom.csv)" << std::endl;
          return 1;
        }
      std::cout << "gelmpm-fem-bilayer: reached t/tau_d = " << end_time << " in " << n_steps
                << " steps, " << result.newton_iterations << " Newton iterations\n"
                << "  curvature of the lower surface " << std::setprecision(8) << curvature
                << "\n  wall time " << std::setprecision(4) << wall << " s\n"
                << "  results: " << directory << "/statistics.csv, " << directory
                << "/surface_bottom.csv" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-bilayer: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}

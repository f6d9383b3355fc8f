// gelmpm-fem-swelling: constrained swelling of a gel layer (paper §4.1) with the body-fitted
// finite-element peer of the MPM (FemMixedSystem: Taylor-Hood on a conforming mesh of the initial
// configuration, same equations, material, Newton test and time stepping; doc/fem_peer.md).
// Writes statistics.csv (one row per converged step) and prints the wall time.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_constrained_swelling.h>
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
  GelMPM::FemConstrainedSwelling::Parameters parameters;
  double                                     initial_step, end_time, tolerance;
  unsigned int                               max_iterations;
  std::string                                caps, stops, directory, formulation;
  bool                                       quiet = false;
  po::options_description                    options(
    "gelmpm-fem-swelling: constrained swelling (paper §4.1) with the body-fitted Taylor-Hood "
                       "finite-element peer of the MPM.\nLengths in h_0 (initial thickness), times in "
                       "tau_d = h_0^2/D, Table 1 material.\nOptions");
  options.add_options()("help", "this text")("cells-y",
                                             po::value(&parameters.cells_y)->default_value(20),
                                             "cells across the thickness (y)")(
    "cells-x",
    po::value(&parameters.cells_x)->default_value(2),
    "cells across the width (x)")("width",
                                  po::value(&parameters.width)->default_value(0.2),
                                  "width of the layer")(
    "grading",
    po::value(&parameters.grading)->default_value(1.),
    "mesh grading towards the top, y_i = 1 - (1 - i/n)^g (1: uniform)")(
    "degree",
    po::value(&parameters.u_degree)->default_value(2),
    "displacement degree k (mu: k - 1, Taylor-Hood)")(
    "formulation",
    po::value(&formulation)->default_value("previously-converged"),
    "'previously-converged' (paper eq. (26), (31) on Omega_n) or 'total' (on Omega_0)")(
    "initial-step",
    po::value(&initial_step)->default_value(8.75e-5),
    "first time step (tau_d)")("caps",
                               po::value(&caps)->default_value(
                                 "5: 0.0125, 20: 0.0625, 40: 0.125, 100: 0.625"),
                               "step caps 'until: cap, ...' (tau_d; default paper eq. (64))")(
    "stop-times",
    po::value(&stops)->default_value(""),
    "comma-separated times (tau_d) the stepping lands on")(
    "end-time",
    po::value(&end_time)->default_value(1713.),
    "end of the run (tau_d)")("tolerance",
                              po::value(&tolerance)->default_value(1e-10),
                              "Newton tolerance (as 'Newton/Tolerance' of gelmpm)")(
    "max-iterations",
    po::value(&max_iterations)->default_value(15),
    "Newton iterations before a step is cut")("quiet", po::bool_switch(&quiet), "no line per step")(
    "output",
    po::value(&directory)->default_value("output/fem_swelling"),
    "output directory");

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
      if (formulation == "previously-converged")
        parameters.formulation =
          GelMPM::FemMixedSystem<2>::Formulation::previously_converged_lagrangian;
      else if (formulation == "total")
        parameters.formulation = GelMPM::FemMixedSystem<2>::Formulation::total_lagrangian;
      else
        throw std::invalid_argument("--formulation: '" + formulation +
                                    "' is neither 'previously-converged' nor 'total'");

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      const auto settings =
        GelMPM::fem_run_settings({{"Initial step", GelMPM::entry_value(initial_step)},
                                  {"End time", GelMPM::entry_value(end_time)},
                                  {"Step caps", caps},
                                  {"Stop at times", stops}},
                                 {{"Tolerance", GelMPM::entry_value(tolerance)},
                                  {"Maximum iterations", std::to_string(max_iterations)}});
      const auto                &time_stepping = settings.time_stepping;
      const auto                &newton        = settings.newton;
      const GelMPM::LinearSolver linear_solver;

      const auto                      start = std::chrono::steady_clock::now();
      const GelMPM::FloryRehnerGel<2> material;
      GelMPM::FemConstrainedSwelling  swelling(material, parameters);
      const auto                     &system = swelling.system();
      std::cout << "gelmpm-fem-swelling: " << parameters.cells_x << " x " << parameters.cells_y
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
                << " mu), " << formulation << " form" << std::endl;

      std::filesystem::create_directories(directory);
      GelMPM::StatisticsFile statistics;
      statistics.open(directory + "/statistics.csv",
                      {"step",
                       "t_over_tau_d",
                       "dt",
                       "newton_iterations",
                       "attempts",
                       "residual_u",
                       "residual_mu",
                       "delta_h_over_h0",
                       "n_dofs"});
      statistics.set("step", 0);
      statistics.set("t_over_tau_d", 0.);
      statistics.set("dt", 0.);
      statistics.set("newton_iterations", 0);
      statistics.set("attempts", 0);
      statistics.set("delta_h_over_h0", 0.);
      statistics.set("n_dofs", system.n_dofs());
      statistics.write_row();

      unsigned int n_steps = 0;
      const bool   ok      = swelling.run(time_stepping,
                                   newton,
                                   linear_solver,
                                   [&](const GelMPM::FemConstrainedSwelling::Step &s) {
                                     n_steps = s.number;
                                     statistics.set("step", s.number);
                                     statistics.set("t_over_tau_d", s.t_over_tau_d);
                                     statistics.set("dt", s.dt_over_tau_d);
                                     statistics.set("newton_iterations", s.newton_iterations);
                                     statistics.set("attempts", s.attempts);
                                     statistics.set("residual_u", s.residual_u);
                                     statistics.set("residual_mu", s.residual_mu);
                                     statistics.set("delta_h_over_h0", s.delta_h_over_h0);
                                     statistics.set("n_dofs", system.n_dofs());
                                     statistics.write_row();
                                     if (!quiet)
                                       std::cout << "  step " << std::setw(5) << s.number
                                                 << "  t/tau_d = " << std::setw(11)
                                                 << std::setprecision(5) << s.t_over_tau_d
                                                 << "  dt = " << std::setw(10) << s.dt_over_tau_d
                                                 << "  Newton " << std::setw(2)
                                                 << s.newton_iterations
                                                 << "  Delta h/h_0 = " << std::setprecision(6)
                                                 << s.delta_h_over_h0 << std::endl;
                                   });
      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!ok)
        {
          std::cerr << "gelmpm-fem-swelling: " << swelling.failure() << std::endl;
          return 1;
        }
      std::cout << "gelmpm-fem-swelling: reached t/tau_d = " << end_time << " in " << n_steps
                << " steps, " << swelling.total_newton_iterations()
                << " Newton iterations; Delta h/h_0 = " << std::setprecision(8)
                << system.mean_boundary_displacement(3, 1) / parameters.height << "\n"
                << "  wall time " << std::setprecision(4) << wall << " s\n"
                << "  results: " << directory << "/statistics.csv" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-swelling: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}

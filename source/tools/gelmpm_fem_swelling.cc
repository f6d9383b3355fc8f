// gelmpm-fem-swelling: constrained swelling of a gel layer (paper §4.1) with the body-fitted
// finite-element peer of the MPM (FemMixedSystem: Taylor-Hood on a conforming mesh of the initial
// configuration, same equations, material, Newton test and time stepping; doc/fem_peer.md).
// Writes statistics.csv (one row per converged step) and prints the wall time.
//
//   gelmpm-fem-swelling [--set "Section/Entry=value"]... [--quiet] prm/constrained_swelling.prm
//
// The gel, the time stepping and Newton are the scene's (PeerInput); the mesh is 'FE peer'.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_constrained_swelling.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_input.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      GelMPM::PeerInput input(argc, argv, "gelmpm-fem-swelling", [](dealii::ParameterHandler &prm) {
        prm.declare_entry("Cells",
                          "2, 20",
                          dealii::Patterns::List(dealii::Patterns::Integer(1), 2, 2),
                          "Cells across the width (x) and the thickness (y) of the layer.");
        prm.declare_entry("Width",
                          "0.2",
                          dealii::Patterns::Double(0.),
                          "Width of the layer (lengths in the initial thickness h_0).");
        prm.declare_entry("Grading",
                          "1",
                          dealii::Patterns::Double(0.),
                          "Mesh grading towards the top, y_i = 1 - (1 - i/n)^g (1: uniform).");
        GelMPM::PeerInput::declare_degree(prm);
        prm.declare_entry("Formulation",
                          "previously-converged",
                          dealii::Patterns::Selection("previously-converged|total"),
                          "'previously-converged' (paper eq. (26), (31) on Omega_n) or 'total' "
                          "(on Omega_0).");
        GelMPM::PeerInput::declare_output_directory(prm, "output/fem_swelling", "statistics.csv");
      });
      if (input.help)
        {
          std::cout << input.usage(
            "Constrained swelling (paper §4.1) with the body-fitted Taylor-Hood finite-element "
            "peer of the MPM, for the scene prm/constrained_swelling.prm.");
          return 0;
        }
      input.require_one_gel();
      GelMPM::FemConstrainedSwelling::Parameters parameters;
      std::string                                directory, formulation;
      {
        auto      &prm      = input.peer_section();
        const auto cells    = GelMPM::get_double_list(prm, "Cells", "FE peer/Cells", 2);
        parameters.cells_x  = static_cast<unsigned int>(cells[0]);
        parameters.cells_y  = static_cast<unsigned int>(cells[1]);
        parameters.width    = prm.get_double("Width");
        parameters.grading  = prm.get_double("Grading");
        parameters.u_degree = GelMPM::PeerInput::degree(prm);
        formulation         = prm.get("Formulation");
        directory           = prm.get("Output directory");
        input.leave_peer_section();
      }
      parameters.formulation =
        formulation == "total"
          ? GelMPM::FemMixedSystem<2>::Formulation::total_lagrangian
          : GelMPM::FemMixedSystem<2>::Formulation::previously_converged_lagrangian;
      const auto &time_stepping = input.time_stepping;
      const auto &newton        = input.newton;
      const auto &linear_solver = input.linear_solver;
      const auto &quiet         = input.quiet;
      const auto  end_time      = time_stepping.end_time;

      const auto                     start    = std::chrono::steady_clock::now();
      const auto                    &material = input.material;
      GelMPM::FemConstrainedSwelling swelling(material, parameters);
      const auto                    &system = swelling.system();
      std::cout << "gelmpm-fem-swelling: " << parameters.cells_x << " x " << parameters.cells_y
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
                << " mu), " << formulation << " form" << std::endl;

      // Held to the end: neither a gelmpm run nor another peer writes there meanwhile.
      const auto lock = input.claim_output_directory(directory);

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
  catch (const GelMPM::InputError &e)
    {
      std::cerr << "gelmpm-fem-swelling: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-swelling: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}

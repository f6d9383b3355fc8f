// gelmpm-fem-swelling: constrained swelling of a gel layer (paper §4.1) with the body-fitted
// finite-element peer of the MPM (FemMixedSystem: Taylor-Hood on a conforming mesh of the initial
// configuration, same equations, material, Newton test and time stepping; doc/fem_peer.md).
// Writes statistics.csv (one row per converged step) and prints the wall time.
//
//   gelmpm-fem-swelling [--set "Section/Entry=value"]... [--quiet] prm/constrained_swelling.prm
//
// The gel, the time stepping and Newton are the scene's (PeerInput); the mesh is 'FE peer'.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_constrained_swelling.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_driver.h>

#include <chrono>
#include <iomanip>
#include <iostream>

namespace
{
  using GelMPM::FemConstrainedSwelling;


  void
  declare_peer(dealii::ParameterHandler &prm)
  {
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
  }


  /** The layer of 'FE peer', its formulation's name and the output directory. */
  FemConstrainedSwelling::Parameters
  read_peer(GelMPM::PeerInput &input, std::string &formulation, std::string &directory)
  {
    FemConstrainedSwelling::Parameters parameters;
    auto                              &prm = input.peer_section();
    const auto cells    = GelMPM::get_double_list(prm, "Cells", "FE peer/Cells", 2);
    parameters.cells_x  = static_cast<unsigned int>(cells[0]);
    parameters.cells_y  = static_cast<unsigned int>(cells[1]);
    parameters.width    = prm.get_double("Width");
    parameters.grading  = prm.get_double("Grading");
    parameters.u_degree = GelMPM::PeerInput::degree(prm);
    formulation         = prm.get("Formulation");
    directory           = prm.get("Output directory");
    input.leave_peer_section();
    parameters.formulation =
      formulation == "total"
        ? GelMPM::FemMixedSystem<2>::Formulation::total_lagrangian
        : GelMPM::FemMixedSystem<2>::Formulation::previously_converged_lagrangian;
    return parameters;
  }


  int
  run(GelMPM::PeerInput &input)
  {
    std::string formulation, directory;
    const auto  parameters = read_peer(input, formulation, directory);

    const auto             start = std::chrono::steady_clock::now();
    FemConstrainedSwelling swelling(input.material, parameters);
    const auto            &system = swelling.system();
    std::cout << "gelmpm-fem-swelling: " << parameters.cells_x << " x " << parameters.cells_y
              << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
              << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
              << " mu), " << formulation << " form" << std::endl;

    // Held to the end: neither a gelmpm run nor another peer writes there meanwhile.
    const auto lock = input.claim_output_directory(directory);

    GelMPM::StatisticsFile statistics;
    statistics.open(directory + "/statistics.csv",
                    GelMPM::peer_statistics_columns({"delta_h_over_h0", "n_dofs"}));
    statistics.set("step", 0);
    statistics.set("t_over_tau_d", 0.);
    statistics.set("dt", 0.);
    statistics.set("newton_iterations", 0);
    statistics.set("attempts", 0);
    statistics.set("delta_h_over_h0", 0.);
    statistics.set("n_dofs", system.n_dofs());
    statistics.write_row();

    unsigned int n_steps = 0;
    const bool   ok      = swelling.run(input.time_stepping,
                                 input.newton,
                                 input.linear_solver,
                                 [&](const FemConstrainedSwelling::Step &s) {
                                   n_steps = s.number;
                                   GelMPM::set_step_columns(statistics, s);
                                   statistics.set("delta_h_over_h0", s.delta_h_over_h0);
                                   statistics.set("n_dofs", system.n_dofs());
                                   statistics.write_row();
                                   if (!input.quiet)
                                     std::cout << "  step " << std::setw(5) << s.number
                                               << "  t/tau_d = " << std::setw(11)
                                               << std::setprecision(5) << s.t_over_tau_d
                                               << "  dt = " << std::setw(10) << s.dt_over_tau_d
                                               << "  Newton " << std::setw(2) << s.newton_iterations
                                               << "  Delta h/h_0 = " << std::setprecision(6)
                                               << s.delta_h_over_h0 << std::endl;
                                 });
    const double wall    = GelMPM::seconds_since(start);
    if (!ok)
      {
        std::cerr << "gelmpm-fem-swelling: " << swelling.failure() << std::endl;
        return 1;
      }
    std::cout << "gelmpm-fem-swelling: reached t/tau_d = " << input.time_stepping.end_time << " in "
              << n_steps << " steps, " << swelling.total_newton_iterations()
              << " Newton iterations; Delta h/h_0 = " << std::setprecision(8)
              << system.mean_boundary_displacement(3, 1) / parameters.height << "\n"
              << "  wall time " << std::setprecision(4) << wall << " s\n"
              << "  results: " << directory << "/statistics.csv" << std::endl;
    return 0;
  }


  const GelMPM::PeerTool tool = {
    "gelmpm-fem-swelling",
    "Constrained swelling (paper §4.1) with the body-fitted Taylor-Hood finite-element peer of "
    "the MPM, for the scene prm/constrained_swelling.prm.",
    declare_peer};
} // namespace


int
main(int argc, char **argv)
{
  return GelMPM::run_peer_tool(argc, argv, tool, run);
}

// gelmpm-fem-bilayer: the bilayer actuator of prm/bilayer_actuator.prm with the body-fitted
// finite-element peer of the MPM (FemMixedSystem with one gel per layer: Taylor-Hood on a
// conforming mesh of the initial configuration, same equations, materials, Newton test and time
// stepping; doc/fem_peer.md). Writes statistics.csv (one row per converged step, with the
// curvature of the lower surface) and the lower surface at the end (surface_bottom.csv).
//
//   gelmpm-fem-bilayer [--set "Section/Entry=value"]... [--quiet] prm/bilayer_actuator.prm
//
// The gels (the scene's and its one region), the time stepping and Newton are the scene's
// (PeerInput); the mesh and the bath are the entries of 'FE peer'.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_bilayer.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_driver.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace
{
  using GelMPM::FemBilayer;


  void
  declare_peer(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Cells",
                      "8",
                      dealii::Patterns::Integer(2),
                      "Square cells through the thickness (even; 10 times as many along the "
                      "half strip 0 < x < 2, 0 < y < 0.2 of the initial configuration).");
    GelMPM::PeerInput::declare_degree(prm);
    prm.declare_entry("Bath",
                      "-0.04",
                      dealii::Patterns::Double(),
                      "mu/k_BT of the bath after the ramp (the scene's boundary function).");
    prm.declare_entry("Start",
                      "-0.1459745",
                      dealii::Patterns::Double(),
                      "mu/k_BT of the bath at t = 0 (the scene's boundary function).");
    prm.declare_entry("Ramp time",
                      "1",
                      dealii::Patterns::Double(0.),
                      "The bath goes linearly from 'Start' to 'Bath' over this time (tau_d).");
    GelMPM::PeerInput::declare_output_directory(prm,
                                                "output/fem_bilayer",
                                                "statistics.csv and surface_bottom.csv");
  }


  /** The strip and bath of 'FE peer', and the output directory. */
  FemBilayer::Parameters
  read_peer(GelMPM::PeerInput &input, std::string &directory)
  {
    FemBilayer::Parameters parameters;
    auto                  &prm = input.peer_section();
    parameters.cells           = prm.get_integer("Cells");
    parameters.u_degree        = GelMPM::PeerInput::degree(prm);
    parameters.mu_bath         = prm.get_double("Bath");
    parameters.mu_start        = prm.get_double("Start");
    parameters.ramp_time       = prm.get_double("Ramp time");
    directory                  = prm.get("Output directory");
    input.leave_peer_section();
    return parameters;
  }


  /** InputError unless the scene is the bilayer's: two gels, tau_d of the strip's thickness. */
  void
  require_bilayer_scene(const GelMPM::PeerInput &input, const FemBilayer::Parameters &parameters)
  {
    GelMPM::require(input.regions.size() == 2,
                    "Material/Regions",
                    "names " + std::to_string(input.regions.size() - 1) +
                      " region(s), but the bilayer has two layers: the scene's gel above and "
                      "one region below",
                    "give the scene of the bilayer (prm/bilayer_actuator.prm)");
    const double length = input.time_stepping.characteristic_length;
    GelMPM::require(std::abs(length - parameters.thickness) <= 1e-12,
                    "Time stepping/Characteristic length",
                    "is " + GelMPM::entry_value(length) + ", but the peer's strip is " +
                      GelMPM::entry_value(parameters.thickness) +
                      " thick, the length of tau_d in the scene",
                    "give the scene of the bilayer (prm/bilayer_actuator.prm)");
  }


  /** The lower surface of the last converged state: current x, y (as the MPM's
   * surface_bottom-*.csv) and the initial X. */
  void
  write_lower_surface(const FemBilayer             &bilayer,
                      const FemBilayer::Parameters &parameters,
                      const std::string            &file_name)
  {
    GelMPM::StatisticsFile surface;
    surface.open(file_name, {"X", "x", "y"});
    const auto points = bilayer.lower_surface();
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        // lower_surface() samples every face at 9 equally spaced points: X is uniform.
        surface.set("X", 0.5 * parameters.length * i / (points.size() - 1));
        surface.set("x", points[i][0]);
        surface.set("y", points[i][1]);
        surface.write_row();
      }
  }


  void
  print_step(const FemBilayer::Step &s)
  {
    std::cout << "  step " << std::setw(4) << s.number << "  t/tau_d = " << std::setw(10)
              << std::setprecision(5) << s.t_over_tau_d << "  dt = " << std::setw(9)
              << s.dt_over_tau_d << "  Newton " << std::setw(2) << s.newton_iterations
              << "  curvature " << std::setw(10) << s.curvature << "  tip u_y " << s.tip_deflection
              << std::endl;
  }


  int
  run(GelMPM::PeerInput &input)
  {
    std::string directory;
    const auto  parameters = read_peer(input, directory);
    require_bilayer_scene(input, parameters);

    const auto  start = std::chrono::steady_clock::now();
    FemBilayer  bilayer(parameters, {input.regions[0], input.regions[1]});
    const auto &system    = bilayer.system();
    const auto &materials = bilayer.materials();
    std::cout << "gelmpm-fem-bilayer: " << 10 * parameters.cells << " x " << parameters.cells
              << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
              << system.n_dofs() << " DoFs; lambda_0 " << materials[0].lambda_0()
              << " (active, chi " << materials[0].chi() << "), " << materials[1].lambda_0()
              << " (passive, chi " << materials[1].chi() << "), mu_0 " << materials[0].mu_0()
              << std::endl;

    // Held to the end: neither a gelmpm run nor another peer writes there meanwhile.
    const auto lock = input.claim_output_directory(directory);

    const auto columns = GelMPM::peer_statistics_columns(
      {"bath_mu_over_kT", "curvature", "tip_deflection", "relative_volume_change", "n_dofs"});
    GelMPM::StatisticsFile statistics;
    statistics.open(directory + "/statistics.csv", columns);
    for (const auto &column : columns)
      statistics.set(column, 0.);
    statistics.set("bath_mu_over_kT", bilayer.bath_chemical_potential(0.));
    statistics.set("n_dofs", system.n_dofs());
    statistics.write_row();

    unsigned int n_steps   = 0;
    double       last_time = 0., curvature = 0.;
    const auto   result =
      bilayer.run(input.time_stepping,
                  input.newton,
                  input.linear_solver,
                  [&](const FemBilayer::Step &s) {
                    n_steps   = s.number;
                    last_time = s.t_over_tau_d;
                    curvature = s.curvature;
                    GelMPM::set_step_columns(statistics, s);
                    statistics.set("bath_mu_over_kT",
                                   bilayer.bath_chemical_potential(s.t_over_tau_d));
                    statistics.set("curvature", s.curvature);
                    statistics.set("tip_deflection", s.tip_deflection);
                    statistics.set("relative_volume_change", s.relative_volume_change);
                    statistics.set("n_dofs", system.n_dofs());
                    statistics.write_row();
                    if (!input.quiet)
                      print_step(s);
                  });
    write_lower_surface(bilayer, parameters, directory + "/surface_bottom.csv");

    const double wall = GelMPM::seconds_since(start);
    if (!result.completed)
      {
        std::cerr << "gelmpm-fem-bilayer: " << result.failure << "\n"
                  << "  kept: " << n_steps << " converged steps to t/tau_d = " << last_time
                  << " in " << directory << " (statistics.csv, surface_bottom.csv)" << std::endl;
        return 1;
      }
    std::cout << "gelmpm-fem-bilayer: reached t/tau_d = " << input.time_stepping.end_time << " in "
              << n_steps << " steps, " << result.newton_iterations << " Newton iterations\n"
              << "  curvature of the lower surface " << std::setprecision(8) << curvature
              << "\n  wall time " << std::setprecision(4) << wall << " s\n"
              << "  results: " << directory << "/statistics.csv, " << directory
              << "/surface_bottom.csv" << std::endl;
    return 0;
  }


  const GelMPM::PeerTool tool = {"gelmpm-fem-bilayer",
                                 "The bilayer actuator (a bonded two-layer strip in a bath that "
                                 "bends) with the body-fitted Taylor-Hood finite-element peer of "
                                 "the MPM, for the scene prm/bilayer_actuator.prm: the upper layer "
                                 "is the scene's gel, the lower one its region (Material/Regions, "
                                 "one region).",
                                 declare_peer,
                                 /* one_gel = */ false};
} // namespace


int
main(int argc, char **argv)
{
  return GelMPM::run_peer_tool(argc, argv, tool, run);
}

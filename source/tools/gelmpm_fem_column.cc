// gelmpm-fem-column: the onset of swell-induced buckling of a gel column (paper §4.3,
// prm/column_buckling.prm) with the body-fitted finite-element peer of the MPM (FemColumn:
// Taylor-Hood on a conforming n x 8n mesh of the initial configuration, same equations, material,
// Newton test and step control; doc/fem_peer.md). Prints per converged step the time, the step,
// the Newton iterations and the signature of the tangent against the signature of a stable state,
// and at the end the bracket(s) of the loss of stability found by retaking steps (StepControl).
//
//   gelmpm-fem-column [--set "Section/Entry=value"]... [--quiet] prm/column_buckling.prm
//
// The gel, the time stepping, Newton and the stability rules are the scene's (PeerInput); the
// mesh is 'FE peer/Cells' and 'Degree'.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_column.h>
#include <gelmpm/simulator/peer_driver.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
  using GelMPM::FemColumn;


  /** "(n_+, n_-, n_0)". */
  std::string
  format(const GelMPM::Inertia &inertia)
  {
    std::ostringstream text;
    text << "(" << inertia.n_positive << ", " << inertia.n_negative << ", " << inertia.n_zero
         << ")";
    return text.str();
  }


  void
  declare_peer(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Cells",
                      "4",
                      dealii::Patterns::Integer(1),
                      "Cells across the width of the column [0, 1] x [0, 8] (lengths in H): "
                      "n x 8n square cells.");
    GelMPM::PeerInput::declare_degree(prm);
    prm.declare_entry("Ramp time",
                      "0.75",
                      dealii::Patterns::Double(0.),
                      "t_inc (tau_d): mu on the sides rises linearly from mu_0 to 0 over this "
                      "time, as the scene's boundary function does.");
  }


  /** The column of 'FE peer' and the scene's stability rules. */
  FemColumn::Parameters
  read_peer(GelMPM::PeerInput &input)
  {
    FemColumn::Parameters parameters;
    auto                 &prm = input.peer_section();
    parameters.cells          = prm.get_integer("Cells");
    parameters.u_degree       = GelMPM::PeerInput::degree(prm);
    parameters.ramp_time      = prm.get_double("Ramp time");
    input.leave_peer_section();
    parameters.drained_onset = input.stability.drained_onset;
    return parameters;
  }


  /** InputError unless the scene's tau_d is that of the peer's column. */
  void
  require_column_scene(const GelMPM::PeerInput &input, const FemColumn &column)
  {
    const double length = input.time_stepping.characteristic_length;
    GelMPM::require(
      std::abs(length - column.characteristic_length()) <= 1e-12 * column.characteristic_length(),
      "Time stepping/Characteristic length",
      "is " + GelMPM::entry_value(length) + ", but the peer's column has half-width " +
        GelMPM::entry_value(column.characteristic_length()) + ", the length of tau_d in the scene",
      "give the scene of the column (prm/column_buckling.prm)");
  }


  void
  print_step(const FemColumn::Step &s, const bool drained_onset)
  {
    std::cout << "  step " << std::setw(4) << s.number << "  t/tau_d = " << std::setw(10)
              << std::setprecision(6) << s.t_over_tau_d << "  dt = " << std::setw(10)
              << s.dt_over_tau_d << "  Newton " << std::setw(2) << s.newton_iterations
              << "  attempts " << s.attempts << "  dV/V " << std::setw(10)
              << s.relative_volume_change << "  signature " << format(s.signature.measured)
              << " stable " << format(s.signature.expected)
              << (s.signature.stable() ? "" : "  UNSTABLE");
    if (drained_onset)
      std::cout << "  K_uu " << format(s.signature.drained_measured)
                << (s.signature.drained_stable() ? "" : "  INDEFINITE");
    std::cout << std::endl;
  }


  int
  run(GelMPM::PeerInput &input)
  {
    const auto  parameters = read_peer(input);
    const auto  start      = std::chrono::steady_clock::now();
    const auto &material   = input.material;
    FemColumn   column(material, parameters);
    const auto &system = column.system();
    require_column_scene(input, column);

    std::cout << "gelmpm-fem-column: " << parameters.cells << " x " << 8 * parameters.cells
              << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
              << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
              << " mu), lambda_0 " << material.lambda_0() << ", mu_0 " << material.mu_0()
              << ", to t/tau_d = " << input.time_stepping.end_time << std::endl;

    unsigned int n_steps = 0;
    const auto   result  = column.run(input.time_stepping,
                                   input.newton,
                                   input.linear_solver,
                                   input.stability.bisection_tolerance,
                                   input.stability.unstable_step,
                                   [&](const FemColumn::Step &s) {
                                     n_steps = s.number;
                                     if (!input.quiet)
                                       print_step(s, parameters.drained_onset);
                                   });
    const double wall    = GelMPM::seconds_since(start);

    for (const auto &onset : result.onsets)
      std::cout << "gelmpm-fem-column: loss of stability between t/tau_d = " << std::setprecision(8)
                << onset.t_stable << " and " << onset.t_unstable << std::endl;
    if (result.onsets.empty())
      std::cout << "gelmpm-fem-column: no loss of stability bracketed" << std::endl;
    if (!result.completed)
      {
        std::cerr << "gelmpm-fem-column: " << result.failure << " (after " << n_steps
                  << " converged steps, at t/tau_d = " << result.t_over_tau_d << ")" << std::endl;
        return 1;
      }
    std::cout << "gelmpm-fem-column: reached t/tau_d = " << result.t_over_tau_d << " in " << n_steps
              << " steps, " << result.newton_iterations << " Newton iterations; wall time "
              << std::setprecision(4) << wall << " s" << std::endl;
    return 0;
  }


  const GelMPM::PeerTool tool = {
    "gelmpm-fem-column",
    "The onset of swell-induced buckling of a gel column (paper §4.3) with the body-fitted "
    "Taylor-Hood finite-element peer of the MPM, for the scene prm/column_buckling.prm.",
    declare_peer};
} // namespace


int
main(int argc, char **argv)
{
  return GelMPM::run_peer_tool(argc, argv, tool, run);
}

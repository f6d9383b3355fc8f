// gelmpm-fem-column: the onset of swell-induced buckling of a gel column (paper §4.3,
// prm/column_buckling.prm) with the body-fitted finite-element peer of the MPM (FemColumn:
// Taylor-Hood on a conforming n x 8n mesh of the initial configuration, same equations, material,
// Newton test and step control; doc/fem_peer.md). Prints per converged step the time, the step,
// the Newton iterations and the signature of the tangent against the signature of a stable state,
// and at the end the bracket(s) of the loss of stability found by retaking steps (StepControl).
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_column.h>

#include <deal.II/base/mpi.h>

#include <boost/program_options.hpp>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
  /** "(n_+, n_-, n_0)". */
  std::string
  format(const GelMPM::Inertia &inertia)
  {
    std::ostringstream text;
    text << "(" << inertia.n_positive << ", " << inertia.n_negative << ", " << inertia.n_zero
         << ")";
    return text.str();
  }
} // namespace


int
main(int argc, char **argv)
{
  namespace po = boost::program_options;
  GelMPM::FemColumn::Parameters parameters;
  double       end_time, step_cap, initial_step, bisection_tolerance, unstable_step, tolerance;
  unsigned int max_iterations;
  bool         quiet = false;
  std::string  criterion;
  po::options_description options(
    "gelmpm-fem-column: the onset of swell-induced buckling of a gel column (paper §4.3) with "
    "the body-fitted Taylor-Hood finite-element peer of the MPM.\nThe column is [0, 1] x [0, 8] "
    "(lengths in H) of the pre-swollen initial state (Table 1 material, lambda_0 = 1.2801), "
    "times in tau_d = (H/2)^2/D.\nOptions");
  // clang-format off
  options.add_options()
    ("help", "this text")
    ("cells", po::value(&parameters.cells)->default_value(4),
     "cells across the width (n x 8n square cells)")
    ("degree", po::value(&parameters.u_degree)->default_value(2),
     "displacement degree k (mu: k - 1, Taylor-Hood)")
    ("ramp-time", po::value(&parameters.ramp_time)->default_value(0.75),
     "t_inc: mu on the sides rises linearly from mu_0 to 0 over this time (tau_d)")
    ("end-time", po::value(&end_time)->default_value(0.4), "end of the run (tau_d)")
    ("initial-step", po::value(&initial_step)->default_value(0.02), "first step (tau_d)")
    ("step-cap", po::value(&step_cap)->default_value(0.02),
     "largest step over the whole run (tau_d; 0: none)")
    ("bisection-tolerance", po::value(&bisection_tolerance)->default_value(1e-3),
     "width to which a loss of stability is bracketed (tau_d; 0: not bracketed)")
    ("unstable-step", po::value(&unstable_step)->default_value(0.),
     "largest step while the state is unstable (tau_d; 0: no cap)")
    ("tolerance", po::value(&tolerance)->default_value(1e-10),
     "Newton tolerance (as 'Newton/Tolerance' of gelmpm)")
    ("max-iterations", po::value(&max_iterations)->default_value(15),
     "Newton iterations before a step is cut")
    ("onset-criterion", po::value(&criterion)->default_value("tangent"),
     "what brackets the onset: 'tangent' (the signature of the tangent leaves (n_u, n_mu, 0)) "
     "or 'drained' (K_uu becomes indefinite, independent of the step; doc/method.md)")
    ("quiet", po::bool_switch(&quiet), "no line per step");
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
      if (criterion != "tangent" && criterion != "drained")
        throw std::invalid_argument("--onset-criterion must be 'tangent' or 'drained', not '" +
                                    criterion + "'");
      parameters.drained_onset = criterion == "drained";
      if (!(end_time > 0.))
        throw std::invalid_argument("--end-time must be positive");
      if (step_cap < 0. || bisection_tolerance < 0. || unstable_step < 0.)
        throw std::invalid_argument(
          "--step-cap, --bisection-tolerance and --unstable-step must not be negative");

      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      const auto                      start = std::chrono::steady_clock::now();
      const GelMPM::FloryRehnerGel<2> material; // Table 1
      GelMPM::FemColumn               column(material, parameters);
      const auto                     &system = column.system();

      // Land on the end of the ramp, where the boundary data has a kink.
      const std::string stops =
        parameters.ramp_time < end_time ? GelMPM::entry_value(parameters.ramp_time) : "";
      const std::string caps =
        step_cap > 0. ? GelMPM::entry_value(end_time) + ": " + GelMPM::entry_value(step_cap) : "";
      const auto settings =
        GelMPM::fem_run_settings({{"Characteristic length",
                                   GelMPM::entry_value(column.characteristic_length())},
                                  {"Initial step", GelMPM::entry_value(initial_step)},
                                  {"End time", GelMPM::entry_value(end_time)},
                                  {"Step caps", caps},
                                  {"Stop at times", stops}},
                                 {{"Tolerance", GelMPM::entry_value(tolerance)},
                                  {"Maximum iterations", std::to_string(max_iterations)}});

      std::cout << "gelmpm-fem-column: " << parameters.cells << " x " << 8 * parameters.cells
                << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
                << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
                << " mu), lambda_0 " << material.lambda_0() << ", mu_0 " << material.mu_0()
                << ", to t/tau_d = " << end_time << std::endl;

      unsigned int n_steps    = 0;
      const auto   print_step = [&](const GelMPM::FemColumn::Step &s) {
        n_steps = s.number;
        if (quiet)
          return;
        std::cout << "  step " << std::setw(4) << s.number << "  t/tau_d = " << std::setw(10)
                  << std::setprecision(6) << s.t_over_tau_d << "  dt = " << std::setw(10)
                  << s.dt_over_tau_d << "  Newton " << std::setw(2) << s.newton_iterations
                  << "  attempts " << s.attempts << "  dV/V " << std::setw(10)
                  << s.relative_volume_change << "  signature " << format(s.signature.measured)
                  << " stable " << format(s.signature.expected)
                  << (s.signature.stable() ? "" : "  UNSTABLE");
        if (parameters.drained_onset)
          std::cout << "  K_uu " << format(s.signature.drained_measured)
                    << (s.signature.drained_stable() ? "" : "  INDEFINITE");
        std::cout << std::endl;
      };
      const auto   result = column.run(settings.time_stepping,
                                     settings.newton,
                                     GelMPM::LinearSolver(),
                                     bisection_tolerance,
                                     unstable_step,
                                     print_step);
      const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      for (const auto &onset : result.onsets)
        std::cout << "gelmpm-fem-column: loss of stability between t/tau_d = "
                  << std::setprecision(8) << onset.t_stable << " and " << onset.t_unstable
                  << std::endl;
      if (result.onsets.empty())
        std::cout << "gelmpm-fem-column: no loss of stability bracketed" << std::endl;
      if (!result.completed)
        {
          std::cerr << "gelmpm-fem-column: " << result.failure << " (after " << n_steps
                    << " converged steps, at t/tau_d = " << result.t_over_tau_d << ")" << std::endl;
          return 1;
        }
      std::cout << "gelmpm-fem-column: reached t/tau_d = " << result.t_over_tau_d << " in "
                << n_steps << " steps, " << result.newton_iterations
                << " Newton iterations; wall time " << std::setprecision(4) << wall << " s"
                << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-fem-column: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}

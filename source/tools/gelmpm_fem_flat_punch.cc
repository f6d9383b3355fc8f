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
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_flat_punch.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_driver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>

namespace
{
  using GelMPM::FemFlatPunch;


  void
  declare_peer(dealii::ParameterHandler &prm)
  {
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
  }


  /** The gel and punch of 'FE peer', and the output directory. */
  FemFlatPunch::Parameters
  read_peer(GelMPM::PeerInput &input, std::string &directory)
  {
    FemFlatPunch::Parameters parameters;
    auto                    &prm = input.peer_section();
    parameters.cells             = prm.get_integer("Cells");
    parameters.u_degree          = GelMPM::PeerInput::degree(prm);
    parameters.punch_width       = prm.get_double("Punch width");
    parameters.depth             = prm.get_double("Depth");
    parameters.ramp_time         = prm.get_double("Ramp time");
    directory                    = prm.get("Output directory");
    input.leave_peer_section();
    return parameters;
  }


  /** Write the top surface (initial x, u, mu) of the converged state to @p file_name. */
  void
  write_top_profile(const FemFlatPunch &punch, const std::string &file_name)
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


  /** The top profiles of a run: top_profile-NN.csv, listed with their times in profiles.csv. */
  class TopProfiles
  {
  public:
    TopProfiles(const FemFlatPunch &punch, const std::string &directory)
      : punch(punch)
      , directory(directory)
    {
      list.open(directory + "/profiles.csv", {"index", "t_over_tau_d"});
    }

    /** The profile of the converged state at time @p t. */
    void
    write(const double t)
    {
      char name[32];
      std::snprintf(name, sizeof(name), "top_profile-%02u.csv", n_profiles);
      write_top_profile(punch, directory + "/" + name);
      list.set("index", n_profiles);
      list.set("t_over_tau_d", t);
      list.write_row();
      ++n_profiles;
    }

  private:
    const FemFlatPunch    &punch;
    std::string            directory;
    GelMPM::StatisticsFile list;
    unsigned int           n_profiles = 0;
  };


  /** Whether @p t is one of @p times. */
  bool
  is_one_of(const double t, const std::vector<double> &times)
  {
    return std::any_of(times.begin(), times.end(), [&](const double s) {
      return std::abs(t - s) <= 1e-9 * s;
    });
  }


  void
  set_punch_columns(GelMPM::StatisticsFile &statistics, const FemFlatPunch::Step &s)
  {
    GelMPM::set_step_columns(statistics, s);
    statistics.set("punch_displacement", s.punch_displacement);
    statistics.set("punch_force_x", s.punch_force[0]);
    statistics.set("punch_force_y", s.punch_force[1]);
    statistics.set("min_det_F", s.deformation.min_det_F);
    statistics.set("max_stretch_ratio", s.deformation.max_stretch_ratio);
    statistics.set("relative_volume_change", s.relative_volume_change);
  }


  void
  print_step(const FemFlatPunch::Step &s)
  {
    std::cout << "  step " << std::setw(5) << s.number << "  t/tau_d = " << std::setw(11)
              << std::setprecision(5) << s.t_over_tau_d << "  dt = " << std::setw(10)
              << s.dt_over_tau_d << "  Newton " << std::setw(2) << s.newton_iterations << "  punch "
              << std::setw(9) << s.punch_displacement << "  force " << std::setw(10)
              << s.punch_force[1] << "  min det F " << std::setw(9) << s.deformation.min_det_F
              << "  max stretch ratio " << s.deformation.max_stretch_ratio << std::endl;
  }


  int
  run(GelMPM::PeerInput &input)
  {
    std::string directory;
    const auto  parameters = read_peer(input, directory);

    const auto   start    = std::chrono::steady_clock::now();
    const auto  &material = input.material;
    FemFlatPunch punch(material, parameters);
    const auto  &system = punch.system();
    std::cout << "gelmpm-fem-flat-punch: " << parameters.cells << " x " << parameters.cells
              << " cells, Q" << parameters.u_degree << "-Q" << parameters.u_degree - 1 << ", "
              << system.n_dofs() << " DoFs (" << system.n_u_dofs() << " u, " << system.n_mu_dofs()
              << " mu), depth " << parameters.depth << " H, lambda_0 " << material.lambda_0()
              << std::endl;

    // Held to the end: neither a gelmpm run nor another peer writes there meanwhile.
    const auto lock = input.claim_output_directory(directory);

    const auto             columns = GelMPM::peer_statistics_columns({"punch_displacement",
                                                                      "punch_force_x",
                                                                      "punch_force_y",
                                                                      "min_det_F",
                                                                      "max_stretch_ratio",
                                                                      "relative_volume_change",
                                                                      "n_dofs"});
    GelMPM::StatisticsFile statistics;
    statistics.open(directory + "/statistics.csv", columns);
    for (const auto &column : columns)
      statistics.set(column, 0.);
    statistics.set("min_det_F", 1.);
    statistics.set("max_stretch_ratio", 1.);
    statistics.set("n_dofs", system.n_dofs());
    statistics.write_row();

    // Top surface at each stop time that is reached and at the end.
    const std::vector<double> &profile_times = input.time_stepping.stop_times;
    TopProfiles                profiles(punch, directory);
    unsigned int               n_steps   = 0;
    double                     last_time = 0.;
    const auto                 result    = punch.run(input.time_stepping,
                                  input.newton,
                                  input.linear_solver,
                                  [&](const FemFlatPunch::Step &s) {
                                    n_steps   = s.number;
                                    last_time = s.t_over_tau_d;
                                    set_punch_columns(statistics, s);
                                    statistics.set("n_dofs", system.n_dofs());
                                    statistics.write_row();
                                    if (is_one_of(s.t_over_tau_d, profile_times))
                                      profiles.write(s.t_over_tau_d);
                                    if (!input.quiet)
                                      print_step(s);
                                  });
    // The end state (or the last converged one) unless a stop time already wrote it.
    if (!is_one_of(last_time, profile_times))
      profiles.write(last_time);
    const double wall = GelMPM::seconds_since(start);
    if (!result.completed)
      {
        std::cerr << "gelmpm-fem-flat-punch: " << result.failure << "\n"
                  << "  kept: " << n_steps << " converged steps to t/tau_d = " << last_time
                  << " in " << directory << " (statistics.csv, top_profile-*.csv)" << std::endl;
        return 1;
      }
    std::cout << "gelmpm-fem-flat-punch: reached t/tau_d = " << input.time_stepping.end_time
              << " in " << n_steps << " steps, " << result.newton_iterations
              << " Newton iterations\n"
              << "  wall time " << std::setprecision(4) << wall << " s\n"
              << "  results: " << directory << "/statistics.csv, " << directory
              << "/top_profile-*.csv (times in profiles.csv)" << std::endl;
    return 0;
  }


  const GelMPM::PeerTool tool = {
    "gelmpm-fem-flat-punch",
    "Flat punch indentation of a swollen gel (paper §4.2) with the body-fitted Taylor-Hood "
    "finite-element peer of the MPM, for the scene prm/flat_punch.prm.",
    declare_peer};
} // namespace


int
main(int argc, char **argv)
{
  return GelMPM::run_peer_tool(argc, argv, tool, run);
}

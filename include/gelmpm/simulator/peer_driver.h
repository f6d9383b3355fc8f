#ifndef gelmpm_simulator_peer_driver_h
#define gelmpm_simulator_peer_driver_h

#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/peer_input.h>

#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief What tells one body-fitted peer tool from another on its command line: its name,
   * its description, its entries of 'FE peer', and whether its body is one gel.
   */
  struct PeerTool
  {
    /** The executable, which begins every message: "gelmpm-fem-swelling". */
    std::string name;
    /** The first paragraph of --help: the benchmark and the scene it is compared with. */
    std::string description;
    /** Declares the tool's entries of 'FE peer' (called inside the subsection). */
    std::function<void(dealii::ParameterHandler &)> declare_peer;
    /** The body is the scene's one gel: a scene with material regions is refused. */
    bool one_gel = true;
  };


  /**
   * The main() of a peer tool (gelmpm-fem-swelling, -flat-punch, -column, -bilayer): MPI, the
   * command line and the scene file read and checked by PeerInput, --help, and @p run, the
   * tool's model on the checked input, which returns the exit status (0, or 1 if the run
   * stopped early; it prints why).
   *
   * One place for what every peer answers alike: bad input (InputError, from PeerInput or from
   * @p run) is one line "<tool>: <message>" on stderr and exit status 2 with nothing written; any
   * other error is "<tool>: <what>" and status 1.
   */
  int
  run_peer_tool(int                                    argc,
                char                                 **argv,
                const PeerTool                        &tool,
                const std::function<int(PeerInput &)> &run);

  /** The wall-clock seconds since @p start, as the peers report their run's time. */
  double
  seconds_since(const std::chrono::steady_clock::time_point start);

  /**
   * The columns of a peer's statistics.csv: those every peer's step has (step, t_over_tau_d,
   * dt, newton_iterations, attempts, residual_u, residual_mu), then @p own.
   */
  std::vector<std::string>
  peer_statistics_columns(const std::vector<std::string> &own);

  /**
   * Set the columns of peer_statistics_columns() that every peer's step has, from @p step (a
   * FemStep of the fem module: its number, time, step, Newton iterations, attempts and scaled
   * residuals).
   */
  template <class Step>
  void
  set_step_columns(StatisticsFile &statistics, const Step &step)
  {
    statistics.set("step", step.number);
    statistics.set("t_over_tau_d", step.t_over_tau_d);
    statistics.set("dt", step.dt_over_tau_d);
    statistics.set("newton_iterations", step.newton_iterations);
    statistics.set("attempts", step.attempts);
    statistics.set("residual_u", step.residual_u);
    statistics.set("residual_mu", step.residual_mu);
  }
} // namespace GelMPM

#endif

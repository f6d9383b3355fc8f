#include <gelmpm/core/input_error.h>
#include <gelmpm/simulator/peer_driver.h>

#include <deal.II/base/mpi.h>

#include <exception>
#include <iostream>

namespace GelMPM
{
  int
  run_peer_tool(int                                    argc,
                char                                 **argv,
                const PeerTool                        &tool,
                const std::function<int(PeerInput &)> &run)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    try
      {
        PeerInput input(argc, argv, tool.name, tool.declare_peer);
        if (input.help)
          {
            std::cout << input.usage(tool.description);
            return 0;
          }
        if (tool.one_gel)
          input.require_one_gel();
        return run(input);
      }
    catch (const InputError &e)
      {
        std::cerr << tool.name << ": " << e.what() << std::endl;
        return 2;
      }
    catch (const std::exception &e)
      {
        std::cerr << tool.name << ": " << e.what() << std::endl;
        return 1;
      }
  }


  double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }


  std::vector<std::string>
  peer_statistics_columns(const std::vector<std::string> &own)
  {
    std::vector<std::string> columns =
      {"step", "t_over_tau_d", "dt", "newton_iterations", "attempts", "residual_u", "residual_mu"};
    columns.insert(columns.end(), own.begin(), own.end());
    return columns;
  }
} // namespace GelMPM

// Shared by the tests that run a whole scene in-process: the scene is read with overrides (the
// output directory and test mode first), its own progress output is captured rather than compared,
// and its statistics.csv is read back.
#ifndef gelmpm_tests_scene_run_h
#define gelmpm_tests_scene_run_h

#include <gelmpm/core/parameters.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/simulator.h>

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace GelMPMTests
{
  /** What a scene run left: its exit status and the columns of its statistics.csv. */
  struct SceneRun
  {
    int                                        status = 1;
    std::map<std::string, std::vector<double>> statistics;
    /** What the run wrote to its log (std::cout). */
    std::string log;
  };

  /**
   * Run the scene @p scene_file of dimension @p dim into @p directory (test mode, no particle
   * output) with the further @p overrides ("Section/Entry=value"). The scene's log is kept, not
   * printed.
   */
  template <int dim = 2>
  inline SceneRun
  run_scene(const std::string              &scene_file,
            const std::string              &directory,
            const std::vector<std::string> &overrides)
  {
    std::vector<GelMPM::ParameterOverride> parsed;
    for (const auto &text : std::vector<std::string>{"Output/Directory=" + directory,
                                                     "Output/Test mode=true",
                                                     "Output/Write particles=false"})
      parsed.push_back(GelMPM::ParameterOverride::parse(text));
    for (const auto &text : overrides)
      parsed.push_back(GelMPM::ParameterOverride::parse(text));

    std::ostringstream log;
    auto *const        cout_buffer = std::cout.rdbuf(log.rdbuf());
    SceneRun           run;
    try
      {
        run.status = GelMPM::run_scene_file<dim>(scene_file, parsed);
      }
    catch (...)
      {
        std::cout.rdbuf(cout_buffer);
        throw;
      }
    std::cout.rdbuf(cout_buffer);
    run.log        = log.str();
    run.statistics = GelMPM::read_statistics(directory + "/statistics.csv");
    return run;
  }


  /**
   * Print "@p what: 1" if @p ok, else "@p what: 0" and the @p value against the @p expected one;
   * returns @p ok.
   */
  inline bool
  report(const std::string &what, const bool ok, const double value, const double expected)
  {
    std::cout << what << ": " << ok << std::endl;
    if (!ok)
      std::cout << "  (" << value << " against " << expected << ")" << std::endl;
    return ok;
  }


  /**
   * The single loss of stability of a run's @p directory/stability.csv: prints whether there is
   * exactly one and, if so, whether it is at most @p width wide; returns {t_stable, t_unstable},
   * or {-1, -1} if there is not exactly one.
   */
  inline std::pair<double, double>
  single_bracket(const std::string &directory, const double width)
  {
    const auto brackets = GelMPM::read_statistics(directory + "/stability.csv");
    const bool one      = brackets.count("t_stable") && brackets.at("t_stable").size() == 1;
    std::cout << "one onset bracketed: " << one << std::endl;
    if (!one)
      return {-1., -1.};
    const double t_stable = brackets.at("t_stable")[0], t_unstable = brackets.at("t_unstable")[0];
    std::cout << "bracket at most " << width
              << " tau_d wide: " << (t_unstable - t_stable <= width * (1. + 1e-9)) << std::endl;
    return {t_stable, t_unstable};
  }


  /** The times (t_over_tau_d) of the rows of @p event in the events.csv of @p directory. */
  inline std::vector<double>
  event_times(const std::string &directory, const std::string &event)
  {
    std::ifstream       in(directory + "/events.csv");
    std::string         line;
    std::vector<double> times;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::istringstream fields(line);
        std::string        name, time, t_over_tau_d;
        std::getline(fields, name, ',');
        std::getline(fields, time, ',');
        std::getline(fields, t_over_tau_d, ',');
        if (name == event)
          times.push_back(std::stod(t_over_tau_d));
      }
    return times;
  }
} // namespace GelMPMTests

#endif

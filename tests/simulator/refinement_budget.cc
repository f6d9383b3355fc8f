// 'Background grid/Refinement budget' bounds the unknowns of a moving refinement: §4.1 refined
// twice where mu's front is (prm/constrained_swelling_front.prm with 'Refinement levels = 2'),
// 10 steps of 0.01 tau_d. Unlimited, the front's second level gives a step more unknowns than
// 90 % of the unlimited run's largest count; with that as the budget every step stays within it,
// the run drops the second level where needed and still refines (more unknowns than the uniform
// grid's wherever the unlimited run has more; the front's refinement ends by the 9th step). The
// limited run's swelling (delta_h/h_0) lies between the uniform grid's and the unlimited run's or
// within 1 % of the latter.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  GelMPMTests::SceneRun
  run(const std::string &directory, const std::vector<std::string> &more)
  {
    std::vector<std::string> overrides = {"Background grid/Refinement levels=2",
                                          "Time stepping/Initial step=0.01",
                                          "Time stepping/Growth factor=1",
                                          "Time stepping/Step caps=",
                                          "Time stepping/Stop at times=",
                                          "Time stepping/End time=0.1"};
    overrides.insert(overrides.end(), more.begin(), more.end());
    return GelMPMTests::run_scene(std::string(SOURCE_DIR) +
                                    "/../../prm/constrained_swelling_front.prm",
                                  directory,
                                  overrides);
  }


  /** Total unknowns (u and mu) per step, the initial row left out. */
  std::vector<double>
  unknowns(const GelMPMTests::SceneRun &r)
  {
    const auto         &u = r.statistics.at("n_dofs_u"), &mu = r.statistics.at("n_dofs_mu");
    std::vector<double> total;
    for (unsigned int i = 1; i < u.size(); ++i)
      total.push_back(u[i] + mu[i]);
    return total;
  }


  double
  uptake(const GelMPMTests::SceneRun &r)
  {
    return r.statistics.at("delta_h_over_h0").back();
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               free = run("free", {});
  const auto         uniform = run("uniform", {"Background grid/Refinement mu range=0"});
  const auto         n_free = unknowns(free), n_uniform = unknowns(uniform);
  const unsigned int budget =
    static_cast<unsigned int>(0.9 * *std::max_element(n_free.begin(), n_free.end()));
  const auto limited =
    run("limited", {"Background grid/Refinement budget=" + std::to_string(budget)});
  const auto n_limited = unknowns(limited);
  std::cout << std::boolalpha << "runs completed: "
            << (free.status == 0 && uniform.status == 0 && limited.status == 0) << std::endl;
  std::cout << "steps: " << n_free.size() << " / " << n_uniform.size() << " / " << n_limited.size()
            << std::endl;
  std::cout << "the unlimited run exceeds the budget at a step: "
            << std::any_of(n_free.begin(),
                           n_free.end(),
                           [&](double n) {
                             return n > budget;
                           })
            << std::endl;
  bool within = n_limited.size() == n_free.size(), refined = within, dropped = within;
  for (unsigned int i = 0; i < n_limited.size() && i < n_uniform.size(); ++i)
    {
      within &= n_limited[i] <= budget;
      if (n_free[i] > n_uniform[i])
        refined &= n_limited[i] > n_uniform[i];
      if (n_free[i] > budget)
        dropped &= n_limited[i] < n_free[i];
    }
  std::cout << "every step of the limited run within the budget: " << within << std::endl;
  std::cout << "the limited run refines where the unlimited one does: " << refined << std::endl;
  std::cout << "it has fewer unknowns where the unlimited run exceeds the budget: " << dropped
            << std::endl;
  const double lo = std::min(uptake(uniform), uptake(free)),
               hi = std::max(uptake(uniform), uptake(free));
  const double u  = uptake(limited);
  std::cout << "its swelling between the uniform and the unlimited run's (or within 1 % of the "
               "latter): "
            << ((u >= lo && u <= hi) || std::abs(u / uptake(free) - 1.) < 0.01) << std::endl;
  return 0;
}

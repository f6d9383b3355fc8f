// 'Background grid/Refinement region' marks the cells a box marks when it is the box's level
// set: prm/constrained_swelling_refined.prm (§4.1, the cell pairs of 0.9 <= y <= 1.2 halved once)
// with 'Refinement boxes' replaced by 'Refinement region = max(abs(y - 1.05) - 0.149, abs(x -
// 0.25) - 0.3)' (<= 0 at a sample of every pair cell the box overlaps, > 0 at every sample of the
// others, the cells touching the box's edges included) runs the same hierarchy with the same
// split points: to 0.01 tau_d its statistics are the box's, every column equal (the same
// arithmetic on the same data), with more unknowns than the uniform grid's. A region that
// marks two rows of pair cells more (0.149 -> 0.151: the rows touching y = 0.9 and y = 1.2 then
// have a sample inside) changes the unknowns: the comparison can fail.
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  GelMPMTests::SceneRun
  run(const std::string &directory, const std::vector<std::string> &refinement)
  {
    std::vector<std::string> overrides = {"Time stepping/End time=0.01"};
    overrides.insert(overrides.end(), refinement.begin(), refinement.end());
    return GelMPMTests::run_scene(std::string(SOURCE_DIR) +
                                    "/../../prm/constrained_swelling_refined.prm",
                                  directory,
                                  overrides);
  }


  /**
   * Whether every column but the wall time is equal in @p a and @p b (empty cells, read as NaN,
   * in the same places).
   */
  bool
  same_statistics(const GelMPMTests::SceneRun &a, const GelMPMTests::SceneRun &b)
  {
    if (a.statistics.size() != b.statistics.size())
      return false;
    for (const auto &[column, values] : a.statistics)
      {
        if (column == "wall_time")
          continue;
        if (!b.statistics.count(column) || b.statistics.at(column).size() != values.size())
          return false;
        const auto &other = b.statistics.at(column);
        for (unsigned int i = 0; i < values.size(); ++i)
          if (!(values[i] == other[i] || (std::isnan(values[i]) && std::isnan(other[i]))))
            return false;
      }
    return true;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string region    = "Background grid/Refinement region=max(abs(y - 1.05) - 0.149, "
                                "abs(x - 0.25) - 0.3)";
  const auto        box       = run("box", {});
  const auto        by_region = run("region", {"Background grid/Refinement boxes=", region});
  const auto        wider     = run("wider",
                         {"Background grid/Refinement boxes=",
                                     "Background grid/Refinement region=max(abs(y - 1.05) - 0.151, abs(x - "
                                                "0.25) - 0.3)"});
  const auto        uniform   = run("uniform", {"Background grid/Refinement boxes="});
  std::cout << std::boolalpha << "runs completed: "
            << (box.status == 0 && by_region.status == 0 && wider.status == 0 &&
                uniform.status == 0)
            << std::endl;
  const bool same = same_statistics(box, by_region);
  std::cout << "the region's statistics are the box's: " << same << std::endl;
  const auto first_u = [](const GelMPMTests::SceneRun &r) {
    return r.statistics.at("n_dofs_u").back();
  };
  std::cout << "displacement unknowns at the last step, box / region / wider region / uniform: "
            << first_u(box) << " / " << first_u(by_region) << " / " << first_u(wider) << " / "
            << first_u(uniform) << std::endl;
  const bool refined       = first_u(by_region) > first_u(uniform);
  const bool wider_differs = first_u(wider) > first_u(by_region);
  std::cout << "the region refines (more unknowns than the uniform grid): " << refined << std::endl;
  std::cout << "the wider region marks more cells: " << wider_differs << std::endl;
  return (box.status == 0 && by_region.status == 0 && same && refined && wider_differs) ? 0 : 1;
}

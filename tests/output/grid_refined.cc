// Output/Write grid on a locally refined grid: prm/constrained_swelling_refined.prm (the §4.1
// layer, 0.2 x 1 in a 0.5 x 4 grid of 20 x 160 cells, the cells of 0.9 <= y <= 1.2 halved once, 6 x
// 6 points per cell at every level) runs one step with the grid written at t = 0; the .vtu file is
// read back with VTK. Checked, in closed form: the field refinement_level is 1 on the 20 x 12 base
// cells whose centres lie in the box and 0 on the other 3,080; the refined cells with material
// (8 x 4 of them) hold 4 x 36 = 144 volume points each (the points of a refined cell are split),
// the other 8 x 36 cells with material 36. The same scene without 'Refinement boxes' writes no
// refinement_level field (a uniform run does no work for it). The surface points are split as
// the volume points: the top y = 1 (in the box) holds 8 cells x 6 x 2 = 96 of them, each of
// length 0.2/96, where the uniform grid holds 48 (particles-00000.vtu of each run).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <utility>

#include "../scene_run.h"
#include "../vtu_reader.h"

namespace
{
  struct Counts
  {
    bool         has_level   = false;
    unsigned int level_right = 0, level_wrong = 0, refined_144 = 0, plain_36 = 0, other = 0;
  };

  Counts
  count(const std::string &file_name)
  {
    const auto file = GelMPMTests::read_vtu(file_name);
    Counts     c;
    c.has_level = file.array("refinement_level") != nullptr;
    for (const auto &cell : file.cells)
      {
        double y = 0.;
        for (const std::size_t id : cell)
          y += file.points[id][1] / cell.size();
        const bool   in_box   = y > 0.9 && y < 1.2;
        const long   n_points = std::lround(file.field("n_volume_points")(cell[0]));
        const double level    = c.has_level ? file.field("refinement_level")(cell[0]) : 0.;
        (std::lround(level) == (in_box ? 1 : 0) ? c.level_right : c.level_wrong) += 1;
        if (n_points == 144 && in_box)
          ++c.refined_144;
        else if (n_points == 36 && !in_box)
          ++c.plain_36;
        else if (n_points != 0)
          ++c.other;
      }
    return c;
  }

  /** The surface points on the top y = 1 at t = 0 and the sum of their lengths. */
  std::pair<unsigned int, double>
  top_points(const std::string &file_name)
  {
    const auto   file = GelMPMTests::read_vtu(file_name);
    unsigned int n    = 0;
    double       sum  = 0.;
    for (std::size_t i = 0; i < file.points.size(); ++i)
      if (std::lround(file.field("kind")(i)) != 0 && std::abs(file.points[i][1] - 1.) < 1e-9)
        {
          ++n;
          sum += file.field("measure")(i);
        }
    return {n, sum};
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string scene = std::string(SOURCE_DIR) + "/../../prm/constrained_swelling_refined.prm";
  const std::vector<std::string> one_step = {"Output/Write grid=true",
                                             "Output/Write particles=true",
                                             "Time stepping/End time=8.75e-5",
                                             "Time stepping/Stop at times="};
  const auto                     refined  = GelMPMTests::run_scene(scene, "refined", one_step);
  auto                           uniform_overrides = one_step;
  uniform_overrides.push_back("Background grid/Refinement boxes=");
  const auto uniform = GelMPMTests::run_scene(scene, "uniform", uniform_overrides);
  std::cout << std::boolalpha << "runs completed: " << (refined.status == 0 && uniform.status == 0)
            << std::endl;

  const Counts r = count("refined/grid-00000.vtu");
  std::cout << "refinement_level written: " << r.has_level << std::endl;
  std::cout << "level 1 on the 240 cells in the box, 0 on the other 3080: "
            << (r.level_right == 3200 && r.level_wrong == 0) << std::endl;
  std::cout << "144 volume points in each of the 32 refined cells with material, 36 in each of "
               "the other 288: "
            << (r.refined_144 == 32 && r.plain_36 == 288 && r.other == 0) << std::endl;
  if (r.level_right != 3200 || r.refined_144 != 32 || r.plain_36 != 288 || r.other != 0)
    std::cout << "  (" << r.level_right << " levels right, " << r.refined_144 << ", " << r.plain_36
              << ", " << r.other << ")" << std::endl;
  const Counts u = count("uniform/grid-00000.vtu");
  std::cout << "no refinement_level on the uniform grid: " << !u.has_level << std::endl;
  const auto [n_refined, length_refined] = top_points("refined/particles-00000.vtu");
  const auto [n_uniform, length_uniform] = top_points("uniform/particles-00000.vtu");
  std::cout << "surface points on the top: 96 on the refined grid, 48 on the uniform one: "
            << (n_refined == 96 && n_uniform == 48) << std::endl;
  std::cout << "their lengths sum to the top's 0.2 on both (to 1e-6, the .vtu stores floats): "
            << (std::abs(length_refined - 0.2) < 1e-6 && std::abs(length_uniform - 0.2) < 1e-6)
            << std::endl;
  if (n_refined != 96 || n_uniform != 48 || std::abs(length_refined - 0.2) >= 1e-6)
    std::cout << "  (" << n_refined << ", " << n_uniform << "; " << length_refined << ", "
              << length_uniform << ")" << std::endl;
  return 0;
}

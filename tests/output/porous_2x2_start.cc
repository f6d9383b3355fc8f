// The outlines of the 2 x 2 lattice's pores (prm/porous_gel_2x2.prm, doc/porous_gel.md, "Two by
// two cells") at its start: 5 x 5 points per cell, to 0.2 tau_d (three steps, before any
// bifurcation). The pores are quarter holes at the corners (1, 3, 7, 9), half holes at the middles
// of the edges (2, 8 on the bottom and top, 4, 6 on the left and right) and a whole hole at the
// centre (5). Asserted from statistics.csv and events.csv:
// - no pore reads as creased (pore_creases_k = 0 at every step, no 'crease' event): the half hole
//   on the right edge, whose arc crosses the angle +-pi round its centre, once read as creased at
//   t = 0, the chord across its gap taken for a sharp corner;
// - the corner pores and the centre pore are round: |pore_ratio_k - 1| < 1e-4 at the end;
// - the half pores are mirror images: pore_ratio_2 = pore_ratio_8 and pore_ratio_4 = pore_ratio_6
//   (1e-6), and a bottom one turned by 90 degrees is a left one: pore_ratio_2 pore_ratio_4 = 1
//   (1e-4).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "../scene_run.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto run = GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/porous_gel_2x2.prm",
                                          "results",
                                          {"Material points/Points per cell=5",
                                           "Time stepping/End time=0.2",
                                           "Output/Interval steps=0"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;
  const auto &s       = run.statistics;
  bool        creased = false;
  for (unsigned int k = 1; k <= 9; ++k)
    for (const double c : s.at("pore_creases_" + std::to_string(k)))
      creased = creased || c != 0.;
  std::ifstream events("results/events.csv");
  std::string   line;
  while (std::getline(events, line))
    creased = creased || line.rfind("crease,", 0) == 0;
  std::cout << "no pore reads as creased: " << !creased << std::endl;

  const auto ratio = [&s](const unsigned int k) {
    return s.at("pore_ratio_" + std::to_string(k)).back();
  };
  bool round = true;
  for (const unsigned int k : {1u, 3u, 5u, 7u, 9u})
    round = round && std::abs(ratio(k) - 1.) < 1e-4;
  std::cout << "corner and centre pores round: " << round << std::endl;
  std::cout << "half pores mirror images: "
            << (std::abs(ratio(2) - ratio(8)) < 1e-6 && std::abs(ratio(4) - ratio(6)) < 1e-6)
            << std::endl;
  std::cout << "bottom half pore = left one turned: " << (std::abs(ratio(2) * ratio(4) - 1.) < 1e-4)
            << std::endl;
  return 0;
}

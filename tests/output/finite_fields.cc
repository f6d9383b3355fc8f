// No NaN or inf in what ParaView reads: the default scene (prm/constrained_swelling.prm, §4.1) is
// run to t = 0.01 tau_d, past its first two output times (0.001197 and 0.008589 tau_d, where the
// principal stretches of nearly isotropic points used to come out as NaN from a slightly negative
// eigenvalue of F F^T), and every point-data array of every particles-*.vtu is read back with VTK
// and checked to hold finite values only (the Cauchy stress, written only where J > 1, included).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"
#include "../vtu_reader.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/constrained_swelling.prm",
                           "results",
                           {"Time stepping/End time=0.01", "Output/Write particles=true"});
  std::cout << std::boolalpha << "run completed: " << (run.status == 0) << std::endl;

  std::vector<std::string> files;
  for (const auto &entry : std::filesystem::directory_iterator("results"))
    if (entry.path().extension() == ".vtu")
      files.push_back(entry.path().string());
  std::cout << "particle files written: at least 3: " << (files.size() >= 3) << std::endl;

  unsigned int non_finite = 0, arrays = 0;
  for (const auto &file : files)
    {
      for (const auto &[name, array] : GelMPMTests::read_vtu(file).point_data)
        {
          ++arrays;
          unsigned int bad = 0;
          for (const double value : array.values)
            bad += !std::isfinite(value);
          if (bad > 0)
            std::cout << "  " << file << ": " << name << " has " << bad << " non-finite values"
                      << std::endl;
          non_finite += bad;
        }
    }
  std::cout << "point-data arrays read: " << (arrays > 0) << std::endl;
  std::cout << "every value finite: " << (non_finite == 0) << std::endl;
  return 0;
}

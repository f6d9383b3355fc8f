// Moving refinement that follows what the scene names, checked on the same block and times:
// 'Background grid/Refinement obstacle band' refines the grid round a rigid obstacle's current
// surface and follows it: a ball of radius 0.15 hovering 0.05 above the top of a block
// (0 <= x <= 5, 0 <= y <= 1; h = 0.1) and moving along x by 2 per unit time, band 0.1, one
// level. The marked cells are widened by q + 2 = 4 cell pairs (0.8) of level 0, as every moving
// mark is, so the refined stretch of the top reaches about 1.2 either side of the ball.
// - At t = 0 (the ball over x = 1.3) the top at x = 0.5 and 1.3 lies in refined cells, at
//   x = 3.3 and 4.0 in unrefined ones; marked at t = 1 (the ball over x = 3.3), the other way
//   round.
// - The points follow: every refined cell with material holds the scene's points per cell at
//   its level (the volume points are split where the ball arrives and merged where it has
//   gone; surface points stay split), so the body's volume is the same to round-off (1e-12)
//   and the number of volume points is the same at both times (the ball's band over a flat
//   top covers as many cells).
// - 'Refinement obstacles' naming an obstacle that does not exist is an InputError naming the
//   entry.
// 'Background grid/Refinement moving region = abs(x - 1.3 - 2 t) - 0.05' (a strip under the
// ball, a level set in x and t) marks the same stretches at both times, and keeps the volume
// points' number and volume likewise.
#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
  const std::vector<std::string> pieces = {"top", "rest"}, obstacles = {"ball"};


  std::unique_ptr<GelMPM::Scene<2>>
  scene(dealii::ParameterHandler &prm, const std::string &refinement)
  {
    GelMPM::Scene<2>::declare_parameters(prm, pieces, {}, obstacles);
    prm.parse_input_from_string(R"(
      subsection Background grid
        set Lower corner = 0, 0
        set Upper corner = 5, 1.6
        set Cells = 50, 16
        )" + refinement + R"(
      end
      subsection Geometry
        set Boxes = 0, 0 : 5, 1
      end
      subsection Material points
        set Points per cell = 3
      end
      subsection Boundary conditions
        subsection top
          set Selector = ny > 0.5
        end
        subsection rest
          set Selector = ny < 0.5
          set Displacement = fixed
        end
      end
      subsection Contact
        set Method = penalty
        subsection ball
          set Shape = sphere
          set Center = 1.3, 1.2
          set Radius = 0.15
          subsection Motion
            set Function expression = 2 * t; 0
          end
        end
      end)");
    auto s = std::make_unique<GelMPM::Scene<2>>(prm,
                                                pieces,
                                                "",
                                                MPI_COMM_WORLD,
                                                std::vector<std::string>(),
                                                obstacles);
    s->create_material_points();
    return s;
  }


  /** The volume points' number and their summed V_0. */
  std::pair<unsigned int, double>
  volume(const GelMPM::Scene<2> &s)
  {
    std::pair<unsigned int, double> v{0, 0.};
    for (const auto &particle : s.particles)
      if (GelMPM::kind_of(particle.get_properties()) == GelMPM::PointKind::volume)
        {
          ++v.first;
          v.second += particle.get_properties()[GelMPM::PropertyLayout<2>::measure_0];
        }
    return v;
  }


  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /** The checks of the marks at t = 0 and t = 1 for the grid entries @p refinement. */
  bool
  check_follows(const std::string &refinement)
  {
    dealii::ParameterHandler prm;
    const auto               s     = scene(prm, refinement);
    const auto               level = [&s](const double x) {
      return s->grid.refinement_level(dealii::Point<2>(x, 0.99));
    };
    std::cout << "t = 0: levels at the top under x = 0.5, 1.3, 3.3, 4.0: " << level(0.5) << ", "
              << level(1.3) << ", " << level(3.3) << ", " << level(4.) << std::endl;
    bool ok               = report("refined round the ball only",
                     level(0.5) == 1 && level(1.3) == 1 && level(3.3) == 0 && level(4.) == 0);
    const auto [n_0, v_0] = volume(*s);
    s->update_moving_refinement(1.);
    std::cout << "t = 1: levels at the top under x = 0.5, 1.3, 3.3, 4.0: " << level(0.5) << ", "
              << level(1.3) << ", " << level(3.3) << ", " << level(4.) << std::endl;
    ok &= report("the refinement followed the ball",
                 level(0.5) == 0 && level(1.3) == 0 && level(3.3) == 1 && level(4.) == 1);
    const auto [n_1, v_1] = volume(*s);
    std::cout << "volume points " << n_0 << " -> " << n_1 << std::endl;
    ok &= report("as many volume points, the volume to 1e-12",
                 n_1 == n_0 && n_1 > 5000 && std::abs(v_1 - v_0) <= 1e-12 * v_0);
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << "obstacle band" << std::endl;
  bool ok = check_follows("set Refinement obstacle band = 0.1");
  std::cout << "moving region" << std::endl;
  ok &= check_follows("set Refinement moving region = abs(x - 1.3 - 2 * t) - 0.05");

  dealii::ParameterHandler other;
  try
    {
      scene(other, "set Refinement obstacle band = 0.1\n set Refinement obstacles = hand");
      ok &= report("an unknown obstacle is refused", false);
    }
  catch (const GelMPM::InputError &e)
    {
      const std::string what = e.what();
      std::cout << "  " << what.substr(0, what.find(':')) << std::endl;
      ok &= report("an unknown obstacle is refused, naming the entry",
                   what.find("Refinement obstacles") != std::string::npos);
    }
  std::cout << (ok ? "moving marks checks passed" : "MOVING MARKS CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

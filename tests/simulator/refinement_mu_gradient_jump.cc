// 'Background grid/Refinement mu gradient jump': the grid is refined where the slope of mu
// changes from a cell pair to its neighbour, not where mu merely varies. On a block
// 0 <= x <= 5, 0 <= y <= 3 (h = 0.1, cell pairs 0.2) the points' mu is set to a field and the
// moving refinement marked at t = 0 (threshold 0.01, q + 2 = 4 cell pairs round a flagged one):
// - a kink mu = mu_0 + 0.1 |x - 2.5| (two levels): level 2 at the kink (the slopes -0.1 and 0.1
//   meet on a face of level 1: a jump of 0.2 over 0.1), level 1 within the level-0 buffer
//   (x = 1.7), level 0 far from it (x = 0.5, 4.5);
// - a kink across y, mu = mu_0 + 0.1 |y - 1.5|: refined at y = 1.5, not at y = 0.1 or 2.9;
// - a linear mu = mu_0 + 0.1 x: refined nowhere (the planes' gradients agree to round-off), while
//   'Refinement mu range = 0.01' (the control) refines it everywhere (a cell pair spans 0.02).
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
  const std::vector<std::string> pieces = {"top", "rest"};


  std::unique_ptr<GelMPM::Scene<2>>
  scene(dealii::ParameterHandler &prm, const std::string &refinement)
  {
    GelMPM::Scene<2>::declare_parameters(prm, pieces, {}, {});
    prm.parse_input_from_string(R"(
      subsection Background grid
        set Lower corner = 0, 0
        set Upper corner = 5, 3.6
        set Cells = 50, 36
        )" + refinement + R"(
      end
      subsection Geometry
        set Boxes = 0, 0 : 5, 3
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
      end)");
    auto s = std::make_unique<GelMPM::Scene<2>>(prm,
                                                pieces,
                                                "",
                                                MPI_COMM_WORLD,
                                                std::vector<std::string>(),
                                                std::vector<std::string>());
    s->create_material_points();
    return s;
  }


  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /**
   * The levels at @p probes after setting every point's mu to @p field and marking at t = 0
   * with the grid entries @p refinement.
   */
  std::vector<unsigned int>
  levels(const std::string                                     &refinement,
         const std::function<double(const dealii::Point<2> &)> &field,
         const std::vector<dealii::Point<2>>                   &probes)
  {
    dealii::ParameterHandler prm;
    const auto               s = scene(prm, refinement);
    for (auto &particle : s->particles)
      particle.get_properties()[GelMPM::PropertyLayout<2>::mu] = field(particle.get_location());
    s->update_moving_refinement(0.);
    std::vector<unsigned int> result;
    for (const auto &p : probes)
      result.push_back(s->grid.refinement_level(p));
    std::cout << "  levels:";
    for (const unsigned int l : result)
      std::cout << ' ' << l;
    std::cout << std::endl;
    return result;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             mu_0 = -0.14597453;
  const std::string                        jump = "set Refinement mu gradient jump = 0.01\n";
  bool                                     ok   = true;

  std::cout << "kink across x at x = 2.5, two levels; probes x = 2.5, 1.7, 0.5, 4.5" << std::endl;
  ok &= report("level 2 at the kink, 1 in its buffer, 0 far from it",
               levels(jump + "set Refinement levels = 2",
                      [&](const dealii::Point<2> &x) {
                        return mu_0 + 0.1 * std::abs(x[0] - 2.5);
                      },
                      {{2.5, 1.}, {1.7, 1.}, {0.5, 1.}, {4.5, 1.}}) ==
                 std::vector<unsigned int>({2, 1, 0, 0}));

  std::cout << "kink across y at y = 1.5; probes y = 1.5, 0.1, 2.9" << std::endl;
  ok &=
    report("refined at the kink only",
           levels(jump,
                  [&](const dealii::Point<2> &x) {
                    return mu_0 + 0.1 * std::abs(x[1] - 1.5);
                  },
                  {{2.5, 1.5}, {2.5, 0.1}, {2.5, 2.9}}) == std::vector<unsigned int>({1, 0, 0}));

  const auto linear = [&](const dealii::Point<2> &x) {
    return mu_0 + 0.1 * x[0];
  };
  const std::vector<dealii::Point<2>> spread = {{0.5, 1.}, {2.5, 1.5}, {4.5, 2.5}};
  std::cout << "linear mu; probes (0.5, 1), (2.5, 1.5), (4.5, 2.5)" << std::endl;
  ok &= report("the gradient jump refines nowhere",
               levels(jump, linear, spread) == std::vector<unsigned int>({0, 0, 0}));
  ok &= report("the mu range (control) refines everywhere",
               levels("set Refinement mu range = 0.01\n", linear, spread) ==
                 std::vector<unsigned int>({1, 1, 1}));
  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}

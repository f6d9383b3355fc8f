// Contact of the gel with itself ('Contact/Self contact'): two blocks of one body pressed together
// (self_contact_blocks_scene.prm) reproduce the obstacle block's closed form
// (tests/simulator/obstacle_block: a rigid plane pressing a W x H block by delta = 0.01 H, here
// each block pressed by delta through the other). The lower block stands on rollers, the upper
// block's top is moved down by the gap (0.2, 2.4 cells) plus 2 delta in the first step, then held.
// At the start of that step no displacement function is nonzero on both blocks, so the contact
// term alone presses one on the other (afterwards they share cells, and the functions nonzero on
// both are copied for one of them: 'Contact/Self contact/Separate faces').
// In plane strain and axisymmetric (self_contact_blocks_axisymmetric_scene.prm: two cylinders on
// the axis, the 3D block's state and closed form, revolved areas):
// - with self-contact, the run completes; the top's reaction is the undrained closed form
//   P_bb W / lambda_0^2 within 0.5 % after the first step and at the end; the self-contact force
//   (the sum of the pairs' forces) equals it after the first step (1e-6: Newton's tolerance and
//   the penalty's, both far below), also at the end, when the faces share cells (on the refined
//   grids within 2 %: a face's share below 1 % of a function keeps it tied); the contact
//   length lies between 0.9 and 1 of the top's current
//   width W a / lambda_0 (axisymmetric: the area between 0.85 and 1 of pi (W a / lambda_0)^2; the
//   faces' end points touch or not by a hair); penetration below 1e-3 h (sigma_n/beta_s with the
//   default penalty 100: 3e-4 h measured); events.csv has one
//   'self_contact' row, at the end of the first step;
// - the same in plane strain and axisymmetric on a grid refined once round the contact (a box over
//   both facing sides), with the scene's settings;
// - the blocks 0.02 (0.24 cells) apart, the top moved by 0.03: the faces share the grid's
//   functions from the start; separated, the reaction is the closed form within 0.5 % and the
//   self-contact force equals it (1e-6); tied (Separate faces = false) no point touches and the
//   reaction is more than twice the closed form (measured: 2.96 times);
// - the same in plane strain and axisymmetric by Nitsche's method ('Method = nitsche', gamma_s =
//   1000): the force is then sum A_s (sigma_n - beta_s g) / 2, and the penetration the
//   stabilisation leaves 1/10 of the penalty's (measured: the reaction 0.097 % and 0.075 % from
//   the closed form against the penalty's 0.24 % and 0.085 %);
// - the same in 3D (self_contact_blocks_3d_scene.prm: the cubes of the 3D obstacle block, each
//   point against the tangent plane of the nearest facing point): measured -0.0059081 against
//   -0.0059183 (0.17 %), by Nitsche's method (not run here: 20 s) -0.0059141 (0.07 %);
// - without it (Method = none), the upper block passes into the lower one: the top's reaction
//   stays below 1e-6 of the closed form.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../scene_run.h"

namespace
{
  constexpr double G = 1., lambda_0 = 1.2801;
  constexpr double W = 0.5, H = 0.5, delta = 0.005, h = 1. / 12.;

  using GelMPMTests::report;


  /**
   * The checks of the blocks' scene @p scene_file (@p name: plane strain or axisymmetric): the
   * undrained closed form of the obstacle block with the top's current area @p area.
   */
  void
  check_blocks(const std::string              &name,
               const std::string              &scene_file,
               const double                    expected,
               const double                    area,
               const double                    smallest_share,
               const std::vector<std::string> &overrides = {})
  {
    const bool  refined   = std::any_of(overrides.begin(), overrides.end(), [](const auto &entry) {
      return entry.find("Refinement") != std::string::npos;
    });
    std::string directory = "self_contact_blocks_" + name;
    std::replace(directory.begin(), directory.end(), ' ', '_');
    std::replace(directory.begin(), directory.end(), ',', '_');
    std::vector<std::string> settings = {"Newton/Tolerance=1e-10"};
    settings.insert(settings.end(), overrides.begin(), overrides.end());
    const auto run = name.find("3D") == std::string::npos
                       ? GelMPMTests::run_scene<2>(scene_file, directory, settings)
                       : GelMPMTests::run_scene<3>(scene_file, directory, settings);
    std::cout << name << ": run completed: " << (run.status == 0) << std::endl;
    const auto &top =
      run.statistics.at(name.find("3D") == std::string::npos ? "top_force_y" : "top_force_z");
    const auto &force = run.statistics.at("self_contact_force");
    report(name + ": reaction within 0.5% of the closed form after the first step",
           std::abs(top[1] - expected) <= 5e-3 * std::abs(expected),
           top[1],
           expected);
    report(name + ": and at the end",
           std::abs(top.back() - expected) <= 5e-3 * std::abs(expected),
           top.back(),
           expected);
    report(name + ": force = -reaction after the first step (1e-6)",
           std::abs(force[1] + top[1]) <= 1e-6 * std::abs(top[1]),
           force[1],
           -top[1]);
    // Once they share cells, the faces are separated: no tie carries part of the load, but for
    // the functions of which a face holds less than 1 % (the fine level's tails on the refined
    // grid: measured 1.5 % of the load).
    report(name + ": and at the end (" + (refined ? "2e-2" : "1e-6") + ")",
           std::abs(force.back() + top.back()) <= (refined ? 2e-2 : 1e-6) * std::abs(top.back()),
           force.back(),
           -top.back());
    const double contact = run.statistics.at("self_contact_area")[1];
    report(name + ": contact area between " + std::to_string(smallest_share).substr(0, 4) +
             " and 1 of the top's",
           contact >= smallest_share * area && contact <= (1. + 1e-6) * area,
           contact,
           area);
    const double penetration = run.statistics.at("self_contact_penetration")[1];
    report(name + ": penetration below 1e-3 h",
           penetration > 0. && penetration < 1e-3 * h,
           penetration,
           1e-3 * h);
    const auto times = GelMPMTests::event_times(directory, "self_contact");
    report(name + ": one self_contact event, after the first step",
           times.size() == 1 && std::abs(times[0] - 1e-3) < 1e-9,
           times.empty() ? -1. : times[0],
           1e-3);
  }


  /**
   * The blocks 0.02 (0.24 h) apart, the top moved down by the gap and 2 delta in the first step:
   * the faces share the grid's functions from the start. Separated, the reaction is the closed
   * form @p expected; tied by the grid (Separate faces = false), no point ever touches and the
   * grid compresses both blocks and the gap between them as one body.
   */
  void
  check_close_blocks(const std::string &scene_file, const double expected)
  {
    // The displacement extrapolated from the points: the projection with copies.
    const std::vector<std::string> close = {
      "Newton/Tolerance=1e-10",
      "Newton/Initial displacement=extrapolated",
      "Geometry/Boxes=0, 0 : 0.5, 0.5; 0, 0.52 : 0.5, 1.02",
      "Boundary conditions/top/Displacement value/Function expression=0; -0.03 * min(t / 1e-3, "
      "1)"};
    const auto apart = GelMPMTests::run_scene<2>(scene_file, "self_contact_blocks_close", close);
    auto       tied_settings = close;
    tied_settings.push_back("Contact/Self contact/Separate faces=false");
    const auto tied =
      GelMPMTests::run_scene<2>(scene_file, "self_contact_blocks_tied", tied_settings);
    const auto &top   = apart.statistics.at("top_force_y");
    const auto &force = apart.statistics.at("self_contact_force");
    std::cout << "close: runs completed: " << (apart.status == 0 && tied.status == 0) << std::endl;
    report("close: reaction within 0.5% of the closed form at the end",
           std::abs(top.back() - expected) <= 5e-3 * std::abs(expected),
           top.back(),
           expected);
    report("close: force = -reaction at the end (1e-6)",
           std::abs(force.back() + top.back()) <= 1e-6 * std::abs(top.back()),
           force.back(),
           -top.back());
    const double tied_top = tied.statistics.at("top_force_y").back();
    report("close, tied: more than twice the closed form, no point in contact",
           std::abs(tied_top) > 2. * std::abs(expected) &&
             tied.statistics.at("self_contact_points").back() == 0.,
           tied_top,
           2. * expected);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  // The undrained closed forms of tests/simulator/obstacle_block: the force of the top piece on
  // the body (downwards) and the top's current area; an axisymmetric block deforms as the 3D one.
  const double J_0 = std::pow(lambda_0, 3);
  // Nitsche's method with the point's own traction; its stabilisation needs gamma_s = 1000 (with
  // the penalty's 100 the blocks' run stops at its third step).
  const std::vector<std::string> nitsche = {"Contact/Self contact/Method=nitsche",
                                            "Contact/Self contact/Penalty=1000"};
  const double                   b       = lambda_0 * (1. - delta / H);
  {
    const double a = J_0 / (b * lambda_0);
    check_blocks("plane strain",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_scene.prm",
                 G * (b * b - a * a) / b * W / (lambda_0 * lambda_0),
                 W * a / lambda_0,
                 0.9);
    // The same on a grid refined once round the contact and both blocks' facing sides, with the
    // scene's settings: the search distance (3 cells) and the step's motion (2.5 cells, 'Largest
    // increment' 5) count in cells of the grid as given, not of the finest level.
    check_close_blocks(std::string(SOURCE_DIR) + "/self_contact_blocks_scene.prm",
                       G * (b * b - a * a) / b * W / (lambda_0 * lambda_0));
    check_blocks("plane strain, Nitsche",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_scene.prm",
                 G * (b * b - a * a) / b * W / (lambda_0 * lambda_0),
                 W * a / lambda_0,
                 0.9,
                 nitsche);
    check_blocks("plane strain, refined",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_scene.prm",
                 G * (b * b - a * a) / b * W / (lambda_0 * lambda_0),
                 W * a / lambda_0,
                 0.9,
                 {"Background grid/Refinement boxes=0, 0.25 : 0.75, 1"});
  }
  {
    const double a = std::sqrt(J_0 / b);
    check_blocks("axisymmetric",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_axisymmetric_scene.prm",
                 G * (b * b - a * a) / b * M_PI * W * W / (lambda_0 * lambda_0),
                 M_PI * std::pow(W * a / lambda_0, 2),
                 0.85);
    check_blocks("axisymmetric, Nitsche",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_axisymmetric_scene.prm",
                 G * (b * b - a * a) / b * M_PI * W * W / (lambda_0 * lambda_0),
                 M_PI * std::pow(W * a / lambda_0, 2),
                 0.85,
                 nitsche);
    check_blocks("axisymmetric, refined",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_axisymmetric_scene.prm",
                 G * (b * b - a * a) / b * M_PI * W * W / (lambda_0 * lambda_0),
                 M_PI * std::pow(W * a / lambda_0, 2),
                 0.85,
                 {"Background grid/Refinement boxes=0, 0.25 : 0.75, 1"});
  }
  {
    // The cubes of the 3D obstacle block, the faces point to the tangent plane of the nearest
    // facing point.
    const double a = std::sqrt(J_0 / b);
    check_blocks("3D",
                 std::string(SOURCE_DIR) + "/self_contact_blocks_3d_scene.prm",
                 G * (b * b - a * a) / b * W * W / (lambda_0 * lambda_0),
                 std::pow(W * a / lambda_0, 2),
                 0.85,
                 // Two steps: the second after the faces share cells and take copies.
                 {"Time stepping/End time=2e-3"});
  }
  {
    const std::string scene = std::string(SOURCE_DIR) + "/self_contact_blocks_scene.prm";
    const auto        run =
      GelMPMTests::run_scene<2>(scene,
                                "self_contact_blocks_off",
                                {"Newton/Tolerance=1e-10", "Contact/Self contact/Method=none"});
    const double a        = J_0 / (b * lambda_0);
    const double expected = G * (b * b - a * a) / b * W / (lambda_0 * lambda_0);
    std::cout << "without: run completed: " << (run.status == 0) << std::endl;
    const double top = run.statistics.at("top_force_y")[1];
    report("without: the blocks pass into each other, no reaction (below 1e-6 of the closed form)",
           std::abs(top) < 1e-6 * std::abs(expected),
           top,
           0.);
  }
  return 0;
}

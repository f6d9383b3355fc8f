// Rigid obstacles with a prescribed motion ('Contact/Obstacles'):
//
// 1. A rigid plane pressed onto a gel block (obstacle_block_scene.prm, 2D plane strain, penalty;
//    obstacle_block_3d_scene.prm, 3D, Nitsche): rollers at the left side (and y = 0 in 3D) and
//    the bottom, the other sides free; the plane moves the top down by delta = 0.01 H and holds.
//    The block's state is homogeneous, F = diag(a, b, lambda_0) (3D: diag(a, a, b)) from the dry
//    state with b = lambda_0 (1 - delta/H), and the plane's reaction press_force_y equals
//    -P_bb W/lambda_0^2 (2D, per unit initial thickness; 3D: W^2/lambda_0^2) within 0.5%:
//    - undrained (every side impermeable, so J = lambda_0^3 at every time): the lateral
//      P_aa = 0 fixes the chemical potential, and P_bb = G (b^2 - a^2)/b with a = J/(b lambda_0)
//      (3D: a^2 = J/b), the incompressible neo-Hookean solid;
//    - drained (the right side, and y = W in 3D, in a bath at mu_0, held to 100 tau_d): mu =
//      mu_0 everywhere, a from P_aa(a) = 0 by bisection on the Flory-Rehner law, then P_bb.
//    The closed forms are computed here (tests/flory_rehner_closed_form.h), independently of the
//    solver and of the material class. Also: the contact area is the top's current area W a /
//    lambda_0 (3D: (W a/lambda_0)^2) within 1e-4, the reaction is the force of the pressed top
//    piece with the opposite sign (1e-10), and the sum of the other pieces' forces (1e-8: the
//    Newton tolerance).
//    With the bath on the pressed top instead: a permeable plane lets the block drain through
//    it (the drained closed form), an impermeable one ('Permeable = false') seals it, so that
//    the block keeps the undrained reaction and its solvent volume (to 1e-8) until 100 tau_d
//    although the bath is prescribed on the top piece.
//    The same as an axisymmetric scene (obstacle_block_axisymmetric_scene.prm: the block is a
//    cylinder of radius W, its left side the axis): the state and the closed forms are the 3D
//    block's, the areas the revolved ones (pi W^2 instead of W^2).
// 2. A rigid circle (2D, penalty) pressed into the same block's top at the plane of symmetry:
//    its reaction in x and y equals the sum of the forces of the pieces it does not touch within
//    1e-8 of its force, and it is in contact over part of the top only.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../flory_rehner_closed_form.h"
#include "../scene_run.h"

namespace
{
  constexpr double G = 1., chi = 0.1, N_nu = 7.299e-3, lambda_0 = 1.2801;
  constexpr double W = 0.5, H = 0.5, delta = 0.005;

  double
  stress_times_stretch(const double stretch, const double J, const double mu)
  {
    return GelMPMTests::stress_times_stretch(stretch, J, mu, G, chi, N_nu);
  }

  using GelMPMTests::report;

  /** Where the pressed block of check_press() meets the bath. */
  enum class Bath
  {
    /** Nowhere: every side impermeable. */
    none,
    /** On the free side(s), not pressed. */
    sides,
    /** On the pressed top, under a permeable plane. */
    top,
    /** On the pressed top, under an impermeable plane ('Permeable = false'). */
    sealed_top
  };

  /** The plane-press checks of one run of dimension @p dim with the bath @p bath. */
  template <int dim>
  void
  check_press(const Bath bath_at, const bool axisymmetric = false)
  {
    // A bath anywhere but under the sealing plane drains the block.
    const bool        drained = bath_at == Bath::sides || bath_at == Bath::top;
    const std::string name    = std::string(axisymmetric ? "axisymmetric"
                                         : dim == 2   ? "2D"
                                                      : "3D") +
                             (bath_at == Bath::top          ? " bath on the top"
                              : bath_at == Bath::sealed_top ? " sealed bath on the top"
                              : drained                     ? " drained"
                                                            : " undrained");
    // An axisymmetric block deforms as the 3D one.
    const bool   three_dimensional = dim == 3 || axisymmetric;
    const double J_0               = std::pow(lambda_0, 3);
    const double mu_0              = stress_times_stretch(lambda_0, J_0, 0.) / (G / N_nu * J_0);
    const double b                 = lambda_0 * (1. - delta / H);
    double       a, P_bb;
    if (!drained)
      {
        a    = !three_dimensional ? J_0 / (b * lambda_0) : std::sqrt(J_0 / b);
        P_bb = G * (b * b - a * a) / b;
      }
    else
      {
        const auto J = [&](const double s) {
          return !three_dimensional ? s * b * lambda_0 : s * s * b;
        };
        a = GelMPMTests::bisect(
          [&](const double s) {
            return stress_times_stretch(s, J(s), mu_0);
          },
          0.9 * lambda_0,
          1.1 * lambda_0);
        P_bb = stress_times_stretch(b, J(a), mu_0) / b;
      }
    // P_bb per dry area; the top's dry area W/lambda_0 by 1/lambda_0 of the unit initial
    // thickness (2D), (W/lambda_0)^2 (3D).
    const double revolution = axisymmetric ? M_PI : 1.;
    const double expected =
      -P_bb * revolution * std::pow(W, three_dimensional ? 2 : 1) / (lambda_0 * lambda_0);
    const double area = revolution * std::pow(W * a / lambda_0, three_dimensional ? 2 : 1);

    std::ostringstream bath;
    bath.precision(17);
    bath << mu_0;
    std::vector<std::string> overrides = {"Newton/Tolerance=1e-10"};
    std::vector<std::string> baths     = {"right"};
    if (dim == 3)
      baths.push_back("front");
    if (bath_at == Bath::top || bath_at == Bath::sealed_top)
      baths = {"top"};
    if (bath_at == Bath::sealed_top)
      overrides.push_back("Contact/press/Permeable=false");
    if (bath_at != Bath::none)
      {
        for (const auto &piece : baths)
          {
            overrides.push_back("Boundary conditions/" + piece + "/Chemical potential=prescribed");
            overrides.push_back("Boundary conditions/" + piece +
                                "/Chemical potential value/Function expression=" + bath.str());
          }
        overrides.push_back("Time stepping/End time=100");
        overrides.push_back("Time stepping/Growth factor=2");
      }
    const auto run =
      GelMPMTests::run_scene<dim>(std::string(SOURCE_DIR) +
                                    (axisymmetric ? "/obstacle_block_axisymmetric_scene.prm"
                                     : dim == 2   ? "/obstacle_block_scene.prm"
                                                  : "/obstacle_block_3d_scene.prm"),
                                  "obstacle_block",
                                  overrides);
    std::cout << name << ": run completed: " << (run.status == 0) << std::endl;
    const std::string axis   = dim == 2 ? "y" : "z";
    const double      force  = run.statistics.at("press_force_" + axis).back();
    const double      top    = run.statistics.at("top_force_" + axis).back();
    double            others = 0.;
    for (const std::string piece : {"left", "bottom", "right", "back", "front"})
      if (run.statistics.count(piece + "_force_" + axis))
        others += run.statistics.at(piece + "_force_" + axis).back();
    report(name + ": reaction within 0.5% of the closed form",
           std::abs(force - expected) <= 5e-3 * expected,
           force,
           expected);
    const double measured_area = run.statistics.at("press_contact_area").back();
    report(name + ": contact area within 1e-4 of the top's area",
           std::abs(measured_area - area) <= 1e-4 * area,
           measured_area,
           area);
    report(name + ": reaction = -(force of the pressed piece) to 1e-10",
           std::abs(force + top) <= 1e-10 * force,
           force,
           -top);
    report(name + ": reaction = sum of the other pieces' forces to 1e-8",
           std::abs(force - others) <= 1e-8 * force,
           force,
           others);
    if (bath_at == Bath::sealed_top)
      {
        // No solvent through the sealed top: the body's solvent stays what it was.
        const auto  &solvent = run.statistics.at("solvent_volume");
        const double change  = std::abs(solvent.back() - solvent.front());
        report(name + ": solvent volume unchanged to 1e-8 of it",
               change <= 1e-8 * solvent.front(),
               change,
               0.);
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  check_press<2>(Bath::none);
  check_press<2>(Bath::sides);
  check_press<3>(Bath::none);
  check_press<3>(Bath::sides);
  check_press<2>(Bath::none, true);
  check_press<2>(Bath::sides, true);
  check_press<2>(Bath::top);
  check_press<2>(Bath::sealed_top);

  // 2. The circle.
  {
    const auto run = GelMPMTests::run_scene<2>(
      std::string(SOURCE_DIR) + "/obstacle_block_scene.prm",
      "obstacle_circle",
      {"Newton/Tolerance=1e-10",
       "Contact/press/Shape=sphere",
       "Contact/press/Center=0, 0.75",
       "Contact/press/Radius=0.25",
       "Contact/press/Motion/Function expression=0; -0.02 * min(t / 1e-3, 1)"});
    std::cout << "circle: run completed: " << (run.status == 0) << std::endl;
    for (const std::string axis : {"x", "y"})
      {
        const double force  = run.statistics.at("press_force_" + axis).back();
        double       others = 0.;
        for (const std::string piece : {"left", "bottom", "right"})
          others += run.statistics.at(piece + "_force_" + axis).back();
        const double scale = std::abs(run.statistics.at("press_force_y").back());
        report("circle: reaction along " + axis + " = sum of the other pieces' forces to 1e-8",
               scale > 0. && std::abs(force - others) <= 1e-8 * scale,
               force,
               others);
      }
    const double radius = run.statistics.at("press_contact_radius").back();
    report("circle: contact over part of the top only", radius > 0. && radius < 0.2, radius, 0.);
  }
  return 0;
}

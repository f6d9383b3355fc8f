// Faces closed by swelling (doc/method.md, "Faces closed by swelling"): two blocks of one gel on
// rollers at their outer ends swell across the gap between them until they press on each other
// (self_contact_swelling_gap_scene.prm, plane strain, h = W/5, to 1500 tau_d), against
// - the closed form at equilibrium: each block homogeneous, F = diag(a, b, lambda_0) with
//   b = lambda_0 (1 + g/2W) from the held ends and a from the free side (P_aa = 0) at mu = 0,
//   the held end's force P_bb W/lambda_0^2 (the obstacle block's drained closed form at mu = 0,
//   tests/flory_rehner_closed_form.h), within 2 % (measured 1.32 %; the lower block alone
//   against a rigid plane, 0.70 %: the MPM's own error at these stretches; W/10 and W/20 in
//   doc/method.md);
// - the lower block alone against a rigid plane at the gap's middle
//   (self_contact_swelling_gap_half_scene.prm), the blocks' plane of symmetry: its force within
//   1 % (measured 0.63 %), and the steps in which each run's faces first touch overlap (the
//   half's 17.70-22.08 tau_d, the blocks' 18.95-21.30);
// and the self-contact force equal to the held end's (1e-3; measured 7e-5), one self_contact
// event, the penetration below 1e-2 h (measured 3.4e-4 = 3.4e-3 h).
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>

#include "../flory_rehner_closed_form.h"
#include "../scene_run.h"

namespace
{
  constexpr double G = 1., chi = 0.1, N_nu = 7.299e-3, lambda_0 = 1.2801;
  constexpr double W = 0.5, gap = 0.8, h = 0.1;

  using GelMPMTests::report;


  /** The held end's force at equilibrium in the bath mu = 0 (plane strain, per unit thickness). */
  double
  closed_form_force()
  {
    const double b = lambda_0 * (1. + gap / (2. * W));
    const auto   J = [b](const double a) {
      return a * b * lambda_0;
    };
    const auto Pa = [&](const double a) {
      return GelMPMTests::stress_times_stretch(a, J(a), 0., G, chi, N_nu);
    };
    const double a    = GelMPMTests::bisect(Pa, (1. + 1e-12) / (b * lambda_0), 10.);
    const double P_bb = GelMPMTests::stress_times_stretch(b, J(a), 0., G, chi, N_nu) / b;
    return P_bb * W / (lambda_0 * lambda_0);
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             expected = closed_form_force();
  const auto                               half =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/self_contact_swelling_gap_half_scene.prm",
                           "self_contact_swelling_gap_half",
                           {});
  const auto whole =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/self_contact_swelling_gap_scene.prm",
                           "self_contact_swelling_gap",
                           {});
  std::cout << "runs completed: " << (half.status == 0 && whole.status == 0) << std::endl;

  // The half's plane presses its top: its bottom carries the force.
  const double half_force  = -half.statistics.at("bottom_force_y").back();
  const double whole_force = whole.statistics.at("top_force_y").back();
  report("the half's force within 1 % of the closed form",
         std::abs(half_force - expected) <= 1e-2 * std::abs(expected),
         half_force,
         expected);
  report("the two blocks' force within 2 % of the closed form",
         std::abs(whole_force - expected) <= 2e-2 * std::abs(expected),
         whole_force,
         expected);
  report("and within 1 % of the half's",
         std::abs(whole_force - half_force) <= 1e-2 * std::abs(half_force),
         whole_force,
         half_force);
  const double contact = whole.statistics.at("self_contact_force").back();
  report("the self-contact force equal to the held end's (1e-3)",
         std::abs(contact + whole_force) <= 1e-3 * std::abs(whole_force),
         contact,
         -whole_force);
  const double penetration = whole.statistics.at("self_contact_penetration").back();
  report("penetration below 1e-2 h",
         penetration > 0. && penetration < 1e-2 * h,
         penetration,
         1e-2 * h);

  // First contact, bracketed by the steps (the last row without a point in contact and the
  // first with one): the two runs take different steps, of 2-4 tau_d there, so the brackets must
  // overlap rather than the rows agree.
  const auto first_contact = [](const GelMPMTests::SceneRun &run, const std::string &column) {
    const auto &t      = run.statistics.at("t_over_tau_d");
    const auto &points = run.statistics.at(column);
    for (unsigned int i = 1; i < t.size(); ++i)
      if (points[i] > 0.)
        return std::pair<double, double>{t[i - 1], t[i]};
    return std::pair<double, double>{-1., -1.};
  };
  const auto touch       = first_contact(half, "contact_points");
  const auto whole_touch = first_contact(whole, "self_contact_points");
  report("the blocks' first contact within the steps that bracket the half's",
         touch.second > 0. && whole_touch.second > 0. &&
           std::max(touch.first, whole_touch.first) <= std::min(touch.second, whole_touch.second),
         whole_touch.second,
         touch.second);
  std::cout << "one self_contact event: "
            << (GelMPMTests::event_times("self_contact_swelling_gap", "self_contact").size() == 1)
            << std::endl;
  return 0;
}

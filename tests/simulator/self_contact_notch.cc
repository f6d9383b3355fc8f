// A notch that closes as the gel swells (contrib/benchmarks/closing_slit.py; doc/method.md, "The
// other face as tangent planes"): a plane-strain block 2 x 1 on rollers at its bottom and outer
// sides, a notch h/2 wide and 0.5 deep from the middle of its top, the bath on the top and in the
// notch (self_contact_notch_scene.prm: the self-contact's defaults, separated faces against the
// tangent planes of the other face's points), to 0.15 tau_d, against the left half on rollers
// below the notch's root and pressed by a rigid plane at the notch's middle, its plane of symmetry
// (self_contact_notch_half_scene.prm: the obstacles' penalty contact):
// - both runs reach 0.15 tau_d (with 'Other face = segments' the block stopped at 0.124 tau_d);
// - the faces first touch in a step after the half's first contact and by 1.5 times its time
//   (measured: 0.0426 against 0.0333 tau_d; the steps up to there are the same in both runs, the
//   weak copies' ties holding the faces back);
// - the self-contact force at the end within 35 % of the plane's force on the half (measured
//   0.236 against 0.190, +24 %; +5.4 % at 1 tau_d, doc/method.md);
// - the penetration below 0.02 h (measured 4.2e-4 = 0.0068 h) and one self_contact event.
#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <string>

#include "../scene_run.h"

namespace
{
  constexpr double h = 0.0625, end_time = 0.15;

  using GelMPMTests::report;

  /** The time of the first row with a point in contact, or -1. */
  double
  first_contact(const GelMPMTests::SceneRun &run, const std::string &column)
  {
    const auto &t      = run.statistics.at("t_over_tau_d");
    const auto &points = run.statistics.at(column);
    for (unsigned int i = 1; i < t.size(); ++i)
      if (points[i] > 0.)
        return t[i];
    return -1.;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               half =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/self_contact_notch_half_scene.prm",
                           "self_contact_notch_half",
                           {});
  const auto whole =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/self_contact_notch_scene.prm",
                           "self_contact_notch",
                           {});
  const double half_end  = half.statistics.at("t_over_tau_d").back();
  const double whole_end = whole.statistics.at("t_over_tau_d").back();
  report("the half reaches 0.15 tau_d",
         half.status == 0 && std::abs(half_end - end_time) < 1e-9,
         half_end,
         end_time);
  report("the whole block reaches 0.15 tau_d",
         whole.status == 0 && std::abs(whole_end - end_time) < 1e-9,
         whole_end,
         end_time);

  const double touch       = first_contact(half, "contact_points");
  const double whole_touch = first_contact(whole, "self_contact_points");
  report("the faces touch after the half's first contact, by 1.5 times its time",
         touch > 0. && whole_touch > touch && whole_touch <= 1.5 * touch,
         whole_touch,
         touch);
  const double plane   = half.statistics.at("mid_force_x").back();
  const double contact = whole.statistics.at("self_contact_force").back();
  report("the self-contact force within 35 % of the plane's on the half",
         plane > 0. && std::abs(contact - plane) <= 0.35 * plane,
         contact,
         plane);
  double penetration = 0.;
  for (const double p : whole.statistics.at("self_contact_penetration"))
    penetration = std::max(penetration, p);
  report("penetration below 0.02 h",
         penetration > 0. && penetration < 0.02 * h,
         penetration,
         0.02 * h);
  std::cout << "one self_contact event: "
            << (GelMPMTests::event_times("self_contact_notch", "self_contact").size() == 1)
            << std::endl;
  return 0;
}

// The pore shape measures against closed forms: the largest Menger curvature of points on a circle
// of radius 2 is 1/2 (1e-12); the largest turning angle of points on a circle is the angle they
// subtend, and of a polyline with a corner the corner's angle (1e-12); a polyline that passes
// through itself is found, a spiral that does not is not; sharp corners are counted once per run
// of consecutive sharp points.
#include <gelmpm/geometry/pore_geometry.h>

#include <cmath>
#include <iostream>

using dealii::Point;
using namespace GelMPM;

namespace
{
  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }
} // namespace


int
main()
{
  bool ok = true;

  std::vector<Point<2>> arc;
  const unsigned int    n = 50;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double angle = 0.5 * M_PI * i / (n - 1);
      arc.emplace_back(2. * std::cos(angle), 2. * std::sin(angle));
    }
  ok &= report("curvature of a quarter circle of radius 2 is 0.5",
               std::abs(PoreGeometry::largest_curvature(arc) - 0.5) < 1e-12);
  ok &= report("turning along it is the angle between points, pi/98",
               std::abs(PoreGeometry::largest_turning(arc) - 0.5 * M_PI / (n - 1)) < 1e-12);
  ok &= report("the arc does not cross itself", !PoreGeometry::self_intersects(arc));

  // A straight run that turns by 120 degrees at one point: a crease.
  const std::vector<Point<2>> corner = {Point<2>(0., 0.),
                                        Point<2>(1., 0.),
                                        Point<2>(2., 0.),
                                        Point<2>(2. + std::cos(2. * M_PI / 3.),
                                                 std::sin(2. * M_PI / 3.))};
  ok &= report("a corner of 120 degrees turns by 2 pi/3",
               std::abs(PoreGeometry::largest_turning(corner) - 2. * M_PI / 3.) < 1e-12);
  ok &= report("it has one sharp corner beyond 60 degrees",
               PoreGeometry::sharp_corners(corner, M_PI / 3.) == 1);
  ok &= report("the arc has none", PoreGeometry::sharp_corners(arc, M_PI / 3.) == 0);
  ok &= report("straight pieces have no curvature but at the corner",
               PoreGeometry::largest_curvature(corner) > 0.5);

  // A loop: the fifth segment crosses the first.
  const std::vector<Point<2>> loop = {Point<2>(0., 0.),
                                      Point<2>(2., 0.),
                                      Point<2>(2., 1.),
                                      Point<2>(1., 1.),
                                      Point<2>(1., -1.)};
  ok &= report("a loop crosses itself", PoreGeometry::self_intersects(loop));
  ok &= report("its three consecutive right angles make one sharp corner",
               PoreGeometry::sharp_corners(loop, M_PI / 3.) == 1);
  const std::vector<Point<2>> steps = {Point<2>(0., 0.),
                                       Point<2>(1., 0.),
                                       Point<2>(2., 0.),
                                       Point<2>(2., 1.),
                                       Point<2>(2., 2.),
                                       Point<2>(3., 2.)};
  ok &= report("a step with a straight point between its right angles has two",
               PoreGeometry::sharp_corners(steps, M_PI / 3.) == 2);

  std::vector<Point<2>> spiral;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double angle = 0.1 * i;
      spiral.emplace_back((1. + 0.1 * angle) * std::cos(angle),
                          (1. + 0.1 * angle) * std::sin(angle));
    }
  ok &= report("an outward spiral of three turns does not cross itself",
               !PoreGeometry::self_intersects(spiral));

  std::cout << (ok ? "pore geometry checks passed" : "PORE GEOMETRY CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

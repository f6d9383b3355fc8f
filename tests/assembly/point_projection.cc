// The particle-to-grid projections that start a step (doc/method.md, "Error-controlled steps"):
// MixedSystem::displacement_from_points() and mu_from_points() are L2 projections over the volume
// points onto the step's (extended, cut) B-spline bases, so fields the bases contain are
// reproduced exactly. On the assembly scene (Q2-Q2SD, cut box, extended B-splines):
// - each point's last increment is set to a quadratic field du(x) and its mu to a linear one; the
//   projections, scaled by a ratio of 2, written back to the points by update_particles(), give
//   2 du(x_p) and mu(x_p) at every point, volume and surface (largest error < 1e-10);
// - largest_increment_deviation() of that solution is < 1e-10 with the same ratio, and equals
//   max_p |du(x_p)|, computed directly from the points, with the ratio 1 (the predictor is then
//   half the motion): the predictor-corrector difference measures what it says.
#include <gelmpm/particles/property_layout.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "scene_fixture.h"

using namespace dealii;
using Layout = GelMPM::PropertyLayout<2>;

namespace
{
  Tensor<1, 2>
  motion(const Point<2> &x)
  {
    return Tensor<1, 2>({0.01 + 0.02 * x[0] - 0.01 * x[1] * x[1], -0.03 + 0.015 * x[0] * x[1]});
  }

  double
  chemical_potential(const Point<2> &x)
  {
    return -0.1 + 0.03 * x[0] - 0.02 * x[1];
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;
  SceneFixture scene;
  auto        &system = *scene.system;

  double largest_motion = 0.;
  for (auto &particle : scene.particles)
    {
      const Point<2> x     = particle.get_location();
      auto           props = particle.get_properties();
      for (unsigned int d = 0; d < 2; ++d)
        props[Layout::increment + d] = motion(x)[d];
      props[Layout::mu] = chemical_potential(x);
      largest_motion    = std::max(largest_motion, motion(x).norm());
    }
  system.setup(scene.particles);

  const double   ratio = 2.;
  const auto     u     = system.displacement_from_points(ratio);
  const auto     mu    = system.mu_from_points();
  const auto    &sp    = system.spaces();
  Vector<double> solution(sp.n_dofs());
  for (unsigned int i = 0; i < sp.n_u_dofs(); ++i)
    solution(i) = u[i];
  for (unsigned int j = 0; j < sp.n_mu_dofs(); ++j)
    solution(sp.n_u_dofs() + j) = mu[j];
  std::cout << "projections sized as the unknowns: "
            << (u.size() == sp.n_u_dofs() && mu.size() == sp.n_mu_dofs()) << std::endl;

  const double deviation = system.largest_increment_deviation(solution, ratio);
  const double halved    = system.largest_increment_deviation(solution, 1.);
  std::cout << "deviation from the scaled motion < 1e-10: " << (deviation < 1e-10) << std::endl;
  std::cout << "with the ratio 1 the deviation is the largest motion: "
            << (std::abs(halved - largest_motion) < 1e-10) << std::endl;

  // update_particles() evaluates the fields at the points (and moves them): compare there.
  std::vector<Point<2>> before;
  for (const auto &particle : scene.particles)
    before.push_back(particle.get_location());
  system.update_particles(solution);
  double       u_error = 0., mu_error = 0.;
  unsigned int p = 0;
  for (const auto &particle : scene.particles)
    {
      const Point<2> x     = before[p++];
      const auto     props = particle.get_properties();
      for (unsigned int d = 0; d < 2; ++d)
        u_error = std::max(u_error, std::abs(props[Layout::increment + d] - ratio * motion(x)[d]));
      mu_error = std::max(mu_error, std::abs(props[Layout::mu] - chemical_potential(x)));
    }
  std::cout << "the projected motion at every point is the scaled motion (1e-10): "
            << (u_error < 1e-10) << std::endl;
  std::cout << "the projected mu at every point is the points' mu (1e-10): " << (mu_error < 1e-10)
            << std::endl;
  if (!(u_error < 1e-10 && mu_error < 1e-10))
    std::cout << "  errors " << u_error << ", " << mu_error << std::endl;
  return 0;
}

// The fits and relief measures of 'Observables/Shape pieces' on synthetic point sets, against
// closed forms (tolerances far above round-off; the fits use no BLAS kernel):
// - an arc of 100 degrees of a circle of radius R = 2.5 about (1, -3): curvature 1/R, its centre
//   at distance -R, residual 0 (1e-12); oriented by normals pointing away from the centre its
//   curvature is +1/R (convex), by normals towards it -1/R (a concave face), and the distances
//   change sign with it;
// - points on a line and on a plane: fit_sphere() is well posed there, curvature 0 (1e-12),
//   residual 0, the same as fit_plane(); a cap of a sphere of radius 0.8: curvature 1/R (1e-12);
// - a circle with m = 12 bumps, r = R + a cos(m theta), 360 points: the smooth shape is the
//   circle, the relief's amplitude a (1e-9), its wavelength L/m exactly (L the polyline's length;
//   the resampled relief has period L/m, so its transform lives on multiples of m; 1e-9), its
//   skewness 0 (1e-9);
// - a sinusoid y = a cos(2 pi x / lambda) over 7 wavelengths, 281 points: the smooth shape is the
//   line y = mean, amplitude a (1e-9), wavelength L/7 within 0.5% of lambda (L the polyline's
//   length: the wavelength is along the current surface, 1.1% longer than lambda at this slope;
//   Hann window and parabolic interpolation: 0.1% measured), skewness within 0.05 of 0, dips and
//   crests equally curved (ratio 1, 1e-9: the profile is the same upside down);
// - narrow cusped dips between flat crests (y = -D exp(-|x - x_k| / w), w = lambda/12, the body
//   below): skewness below -1 (-1.84) and dips more than twice as curved as the crests (8.3), as
//   creases; the wavelength is their spacing along the surface, L/7 (0.5%).
#include <gelmpm/geometry/shape_fit.h>

#include <cmath>
#include <iostream>
#include <vector>

using dealii::Point;
using dealii::Tensor;
using namespace GelMPM;

namespace
{
  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }

  bool
  close(const double value, const double expected, const double tolerance)
  {
    return std::abs(value - expected) <= tolerance;
  }

  /** Points of @p shape at the parameters k/(n-1) (open) or k/n (closed), k = 0 ... n-1. */
  template <typename Shape>
  std::vector<Point<2>>
  sampled(const unsigned int n, const bool closed, const Shape &shape)
  {
    std::vector<Point<2>> points;
    for (unsigned int k = 0; k < n; ++k)
      points.push_back(shape(k / (closed ? n : n - 1.)));
    return points;
  }

  /** The length of the open polyline @p curve. */
  double
  length_of(const std::vector<Point<2>> &curve)
  {
    double length = 0.;
    for (unsigned int i = 1; i < curve.size(); ++i)
      length += curve[i].distance(curve[i - 1]);
    return length;
  }

  /**
   * The distances from @p shape, oriented by the outward normals: +y (a top face, the body
   * below), or with @p radial away from the origin.
   */
  std::vector<double>
  distances(ShapeFit::Hypersphere<2>     shape,
            const std::vector<Point<2>> &points,
            const bool                   radial = false)
  {
    std::vector<Tensor<1, 2>> normals;
    for (const auto &x : points)
      normals.push_back(radial ? Tensor<1, 2>(x) : Tensor<1, 2>({0., 1.}));
    shape.orient(points, normals);
    std::vector<double> d;
    for (const auto &x : points)
      d.push_back(shape.distance(x));
    return d;
  }
} // namespace


int
main()
{
  bool ok = true;

  std::cout << "An arc of a circle:" << std::endl;
  {
    const double   R = 2.5;
    const Point<2> centre(1., -3.);
    const auto     arc = sampled(40, false, [&](const double t) {
      const double angle = (0.2 + t * 100. / 180.) * M_PI;
      return Point<2>(centre[0] + R * std::cos(angle), centre[1] + R * std::sin(angle));
    });
    auto           fit = ShapeFit::fit_sphere(arc);
    ok &= report("  curvature 1/R", close(std::abs(fit.curvature()), 1. / R, 1e-12));
    ok &= report("  the centre at distance -R", close(std::abs(fit.distance(centre)), R, 1e-12));
    ok &= report("  residual 0", ShapeFit::rms_distance(fit, arc) < 1e-12);
    std::vector<Tensor<1, 2>> away, towards;
    for (const auto &x : arc)
      {
        away.push_back(x - centre);
        towards.push_back(centre - x);
      }
    fit.orient(arc, away);
    const bool convex =
      close(fit.curvature(), 1. / R, 1e-12) && fit.distance(centre + 1.1 * (arc[5] - centre)) > 0.;
    fit.orient(arc, towards);
    const bool concave =
      close(fit.curvature(), -1. / R, 1e-12) && fit.distance(centre + 1.1 * (arc[5] - centre)) < 0.;
    ok &= report("  normals away from the centre: +1/R, positive outside", convex);
    ok &= report("  normals towards it: -1/R, positive inside", concave);
    ok &= report("  the smooth shape is the circle",
                 close(std::abs(ShapeFit::smooth_shape(arc).curvature()), 1. / R, 1e-12));
  }

  std::cout << "Lines, planes and a sphere:" << std::endl;
  {
    const auto line = sampled(25, false, [](const double t) {
      return Point<2>(-1. + 3. * t, 0.5 + 1.2 * t);
    });
    const auto fit  = ShapeFit::fit_sphere(line);
    const auto flat = ShapeFit::fit_plane(line);
    ok &= report("  a line: fitted curvature 0, residual 0",
                 std::abs(fit.curvature()) < 1e-12 && ShapeFit::rms_distance(fit, line) < 1e-12);
    ok &= report("  the same as the least-squares line",
                 close(std::abs(fit.distance(Point<2>(0., 0.))),
                       std::abs(flat.distance(Point<2>(0., 0.))),
                       1e-12));

    std::vector<Point<3>> plane, cap;
    const double          R = 0.8;
    for (unsigned int i = 0; i < 9; ++i)
      for (unsigned int j = 0; j < 9; ++j)
        {
          const double u = i / 8. - 0.5, v = j / 8. - 0.5;
          plane.emplace_back(u, v, 0.3 * u - 0.2 * v + 2.);
          const double polar = 0.9 * std::sqrt(u * u + v * v), azimuth = std::atan2(v, u);
          cap.emplace_back(R * std::sin(polar) * std::cos(azimuth) + 0.1,
                           R * std::sin(polar) * std::sin(azimuth),
                           R * std::cos(polar) - 4.);
        }
    const auto plane_fit = ShapeFit::fit_sphere(plane);
    ok &= report("  a plane: fitted curvature 0, residual 0",
                 std::abs(plane_fit.curvature()) < 1e-12 &&
                   ShapeFit::rms_distance(plane_fit, plane) < 1e-12);
    const auto cap_fit = ShapeFit::fit_sphere(cap);
    ok &= report("  a spherical cap: curvature 1/R, residual 0",
                 close(std::abs(cap_fit.curvature()), 1. / R, 1e-12) &&
                   ShapeFit::rms_distance(cap_fit, cap) < 1e-12);
  }

  std::cout << "A circle with 12 bumps:" << std::endl;
  {
    const double       R = 1.3, a = 0.02;
    const unsigned int m     = 12;
    const auto         curve = sampled(360, true, [&](const double t) {
      const double theta = -2. * M_PI * t; // clockwise: the body on the right
      const double r     = R + a * std::cos(m * theta);
      return Point<2>(r * std::cos(theta), r * std::sin(theta));
    });
    const auto         shape = ShapeFit::smooth_shape(curve);
    ok &= report("  the smooth shape is a circle of radius about R",
                 close(std::abs(shape.curvature()), 1. / R, 1e-3 / R));
    const double length = length_of(curve) + curve.back().distance(curve.front());
    const auto   relief = ShapeFit::undulation(curve, distances(shape, curve, true), true);
    ok &= report("  amplitude a", close(relief.amplitude, a, 1e-9));
    ok &= report("  wavelength L/m", close(relief.wavelength, length / m, 1e-9));
    ok &= report("  skewness 0", std::abs(relief.skewness) < 1e-9);
  }

  std::cout << "A sinusoid over 7 wavelengths:" << std::endl;
  {
    const double lambda = 0.3, a = 0.01;
    const auto   curve = sampled(281, false, [&](const double t) {
      const double x = 7. * lambda * t;
      return Point<2>(x, a * std::cos(2. * M_PI * x / lambda));
    });
    const auto   shape = ShapeFit::smooth_shape(curve);
    ok &= report("  the smooth shape is the line y = mean",
                 shape.curvature() == 0. && std::abs(std::abs(shape.b[1]) - 1.) < 1e-12);
    const auto relief = ShapeFit::undulation(curve, distances(shape, curve), false);
    ok &= report("  amplitude a", close(relief.amplitude, a, 1e-9));
    ok &= report("  wavelength L/7 within 0.5%",
                 close(relief.wavelength, length_of(curve) / 7., 5e-3 * lambda));
    ok &= report("  skewness within 0.05 of 0", std::abs(relief.skewness) < 0.05);
    ok &= report("  dips as curved as crests",
                 close(ShapeFit::dip_crest_curvature_ratio(curve, false, 0.), 1., 1e-9));
  }

  std::cout << "Narrow dips between flat crests:" << std::endl;
  {
    const double lambda = 0.3, depth = 0.02, width = lambda / 12.;
    const auto   curve  = sampled(281, false, [&](const double t) {
      const double x     = 7. * lambda * t;
      const double phase = std::fmod(x, lambda) - 0.5 * lambda;
      return Point<2>(x, -depth * std::exp(-std::abs(phase) / width));
    });
    const auto   shape  = ShapeFit::smooth_shape(curve);
    const auto   relief = ShapeFit::undulation(curve, distances(shape, curve), false);
    const auto   ratio  = ShapeFit::dip_crest_curvature_ratio(curve, false, 0.);
    ok &= report("  skewness below -1", relief.skewness < -1.);
    ok &= report("  dips more than twice as curved as the crests", ratio > 2.);
    ok &= report("  wavelength: their spacing along the surface, L/7, within 0.5%",
                 close(relief.wavelength, length_of(curve) / 7., 5e-3 * lambda));
  }

  std::cout << (ok ? "all shape checks passed" : "SOME SHAPE CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

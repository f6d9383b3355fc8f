// The surface measures of 'Observables/Surface pieces' on synthetic pieces, against closed forms:
// - the order along the surface is recovered from shuffled points, for a flat piece, a piece with
//   two corners (three faces of a box) and two circles in one piece (each closed); s_0 is the
//   initial arc length;
// - a flat piece has no relief and no fold; a smooth cosine dip of depth A has relief A (1e-12),
//   its largest Menger curvature is that of the circle through the three lowest points (1e-12,
//   within 3% of A pi^2 / (2 w^2)) and no fold;
// - a hairpin whose flanks come 0.2 h close (points 5 h apart along it) is one fold, two
//   hairpins two; flanks 0.8 h apart are none;
// - a circle flattened until its sides touch is one fold (across its first point), a 2:1
//   ellipse none;
// - a prolate trochoid (lambda = 1.5) loops once per period: three crossings over three periods
//   are three folds with the approach criterion off, a curtate one (lambda = 0.5) none.
#include <gelmpm/geometry/pore_geometry.h>
#include <gelmpm/geometry/surface_geometry.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

using dealii::Point;
using dealii::Tensor;
using namespace GelMPM;
using SurfaceGeometry::SurfacePoint;

namespace
{
  const double h        = 0.1;
  const double approach = 0.75 * h; // the defaults: 'Fold approach distance' 0.75 h_u,
  const double arc      = 3. * h;   // 'Fold arc length' 3 h_u
  const double gap      = 2. * h;   // what Observables uses to join points into a curve

  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }

  /** The same points in another order, fixed by a seed (mt19937 is the same everywhere). */
  std::vector<SurfacePoint>
  shuffled(std::vector<SurfacePoint> points, const unsigned int seed)
  {
    std::mt19937 random(seed);
    for (unsigned int i = points.size(); i > 1; --i)
      std::swap(points[i - 1], points[random() % i]);
    return points;
  }

  /**
   * Points X_0 = (s, 0) at s = k h/2, k = 0 ... n - 1, on the top face of a body (normal +y),
   * now at @p current(s).
   */
  std::vector<SurfacePoint>
  flat_piece(const unsigned int n, const std::function<Point<2>(double)> &current)
  {
    std::vector<SurfacePoint> points;
    for (unsigned int k = 0; k < n; ++k)
      {
        SurfacePoint p;
        const double s = 0.5 * h * k;
        p.X_0          = Point<2>(s, 0.);
        p.normal_0     = Tensor<1, 2>({0., 0.5 * h});
        p.x            = current(s);
        p.mu           = k;
        points.push_back(p);
      }
    return points;
  }

  /**
   * The current position of the point at s of an initially straight surface folded into a
   * hairpin at each s = a in @p entrances (ascending): down by a depth D, round a half circle of
   * radius r, up again 2 r further along x, the surface unstretched.
   */
  Point<2>
  hairpins(const double s, const std::vector<double> &entrances, const double D, const double r)
  {
    const double half    = M_PI * r;
    double       x_shift = 0.; // how much shorter along x than along s the surface is so far
    for (const double a : entrances)
      {
        if (s <= a)
          break;
        const double l = s - a, x = a - x_shift;
        if (l <= D)
          return Point<2>(x, -l);
        if (l <= D + half)
          {
            const double theta = M_PI + (l - D) / r;
            return Point<2>(x + r + r * std::cos(theta), -D + r * std::sin(theta));
          }
        if (l <= 2. * D + half)
          return Point<2>(x + 2. * r, -D + (l - D - half));
        x_shift += 2. * D + half - 2. * r;
      }
    return Point<2>(s - x_shift, 0.);
  }


  /** Whether @p polyline is the flat piece of n points in order: ascending s (the body on the
   * right of the tangent), s_0 the distance from the first. */
  bool
  flat_order(const SurfaceGeometry::Polyline &polyline, const unsigned int n)
  {
    bool ok = polyline.points.size() == n && polyline.n_curves() == 1 && !polyline.closed[0];
    for (unsigned int i = 0; ok && i < n; ++i)
      ok = polyline.points[i].mu == i && std::abs(polyline.s_0[i] - 0.5 * h * i) < 1e-12 &&
           polyline.points[i].X_0[0] == 0.5 * h * i;
    return ok;
  }

  std::vector<Point<2>>
  positions(const std::vector<SurfacePoint> &points)
  {
    std::vector<Point<2>> x;
    for (const auto &p : points)
      x.push_back(p.x);
    return x;
  }
} // namespace


int
main()
{
  bool ok = true;

  // A flat piece, stretched by 10% and moved: no relief, no fold.
  {
    const auto points   = flat_piece(41, [](const double s) {
      return Point<2>(1.1 * s + 0.3, 0.2);
    });
    const auto polyline = SurfaceGeometry::order_along_surface(shuffled(points, 1), gap);
    ok &= report("a shuffled flat piece is ordered along the surface (one open curve)",
                 flat_order(polyline, 41));
    std::vector<Tensor<1, 2>> normals(points.size(), Tensor<1, 2>({0., 0.055}));
    ok &= report("it has no relief", SurfaceGeometry::relief(positions(points), normals) < 1e-12);
    ok &= report("and no fold", SurfaceGeometry::count_folds(polyline, approach, arc) == 0);
    ok &= report("nor turning or curvature",
                 PoreGeometry::largest_turning(polyline.current_curve(0)) < 1e-12 &&
                   PoreGeometry::largest_curvature(polyline.current_curve(0)) < 1e-12);
  }

  // A smooth dip y = -A (1 + cos(pi x / w)) / 2 for |x| < w, sampled symmetrically about x = 0.
  {
    const double A = h, w = 4. * h, dx = 0.5 * h;
    const auto   depth = [&](const double x) {
      return std::abs(x) < w ? -0.5 * A * (1. + std::cos(M_PI * x / w)) : 0.;
    };
    std::vector<SurfacePoint> points;
    std::vector<Tensor<1, 2>> normals;
    for (int k = -40; k <= 40; ++k)
      {
        SurfacePoint p;
        p.X_0      = Point<2>(k * dx, 0.);
        p.normal_0 = Tensor<1, 2>({0., 1.});
        p.x        = Point<2>(k * dx, depth(k * dx));
        points.push_back(p);
        // N_n A_n = (-y', 1) dx, the outward normal times the element's current length.
        const double slope =
          std::abs(k * dx) < w ? 0.5 * A * M_PI / w * std::sin(M_PI * k * dx / w) : 0.;
        normals.push_back(Tensor<1, 2>({-slope * dx, dx}));
      }
    const auto polyline = SurfaceGeometry::order_along_surface(shuffled(points, 2), gap);
    ok &= report("a shuffled dipped piece is ordered along its initial surface",
                 polyline.points.size() == 81 && polyline.n_curves() == 1 &&
                   polyline.points.front().X_0[0] == -40 * dx &&
                   polyline.points.back().X_0[0] == 40 * dx &&
                   std::abs(polyline.s_0.back() - 80 * dx) < 1e-12);
    ok &= report("its relief is the depth A of the dip",
                 std::abs(SurfaceGeometry::relief(positions(points), normals) - A) < 1e-12);
    ok &= report("it has no fold", SurfaceGeometry::count_folds(polyline, approach, arc) == 0);
    // The circle through (-dx, b), (0, 0), (dx, b) has the radius (dx^2 + b^2) / (2 b).
    const double b        = 0.5 * A * (1. - std::cos(M_PI * dx / w));
    const double menger   = 2. * b / (dx * dx + b * b);
    const double smooth   = A * M_PI * M_PI / (2. * w * w);
    const double measured = PoreGeometry::largest_curvature(polyline.current_curve(0));
    ok &= report("its largest curvature is that of the circle through the lowest three points",
                 std::abs(measured - menger) < 1e-12 * menger);
    ok &= report("within 3% of the dip's curvature A pi^2 / (2 w^2) at its bottom",
                 std::abs(measured - smooth) < 0.03 * smooth);
    ok &= report("its largest turning is 2 atan(b / dx), at the bottom",
                 std::abs(PoreGeometry::largest_turning(polyline.current_curve(0)) -
                          2. * std::atan(b / dx)) < 1e-12);
  }

  // Hairpins: flanks 3 h deep, 2 r apart. With 2 r = 0.2 h the points at s = a + 0.5 h and
  // s = a + 5.5 h + pi r (more than 5 h apart along the surface) lie 0.2 h apart.
  {
    const double a = 10. * h, D = 3. * h;
    const auto   fold = hairpins(a + 0.5 * h, {a}, D, 0.1 * h)
                        .distance(hairpins(a + 2. * D - 0.5 * h + M_PI * 0.1 * h, {a}, D, 0.1 * h));
    ok &= report("two points of the narrow hairpin 5 h apart along it are 0.2 h apart",
                 std::abs(fold - 0.2 * h) < 1e-12);
    for (const double r : {0.1 * h, 0.4 * h})
      {
        const auto points   = flat_piece(61, [&](const double s) {
          return hairpins(s, {a}, D, r);
        });
        const auto polyline = SurfaceGeometry::order_along_surface(shuffled(points, 3), gap);
        ok &= report("the shuffled hairpin (2 r = " + std::to_string(2. * r / h).substr(0, 3) +
                       " h) is ordered by its initial positions",
                     flat_order(polyline, 61));
        const unsigned int expected = r < 0.25 * h ? 1 : 0;
        ok &= report("  and has " + std::to_string(expected) + " fold(s)",
                     SurfaceGeometry::count_folds(polyline, approach, arc) == expected);
      }
    const auto points = flat_piece(121, [&](const double s) {
      return hairpins(s, {a, 4. * a}, D, 0.1 * h);
    });
    ok &=
      report("two hairpins 3 apart along the surface are two folds",
             SurfaceGeometry::count_folds(SurfaceGeometry::order_along_surface(shuffled(points, 4),
                                                                               gap),
                                          approach,
                                          arc) == 2);
  }

  // Three faces of the box [0, 2] x [0, 1] (right, top, left; outward normals), one point per
  // element of length h/4 = 0.025: clockwise from the bottom of the left face to the bottom of
  // the right one, turning by 45 degrees twice at each corner.
  {
    std::vector<SurfacePoint> points;
    const auto                add = [&](const Point<2> &X, const Tensor<1, 2> &normal) {
      SurfacePoint p;
      p.X_0      = X;
      p.normal_0 = normal;
      p.x        = X;
      p.mu       = points.size();
      points.push_back(p);
    };
    const double e = 0.025;
    for (unsigned int k = 0; k < 40; ++k)
      add(Point<2>(2., (k + 0.5) * e), Tensor<1, 2>({e, 0.}));
    for (unsigned int k = 0; k < 80; ++k)
      add(Point<2>(2. - (k + 0.5) * e, 1.), Tensor<1, 2>({0., e}));
    for (unsigned int k = 0; k < 40; ++k)
      add(Point<2>(0., 1. - (k + 0.5) * e), Tensor<1, 2>({-e, 0.}));
    const auto polyline = SurfaceGeometry::order_along_surface(shuffled(points, 5), gap);
    bool       in_order =
      polyline.points.size() == points.size() && polyline.n_curves() == 1 && !polyline.closed[0];
    for (unsigned int i = 0; in_order && i < points.size(); ++i)
      in_order = polyline.points[i].mu == points.size() - 1 - i;
    ok &= report("three faces of a box are ordered round its corners", in_order);
    ok &= report("  s_0 at the end is 4 - 3 e + 2 sqrt(2) e/2",
                 std::abs(polyline.s_0.back() - (4. - 3. * e + std::sqrt(2.) * e)) < 1e-12);
    ok &= report("  the largest turning is pi/4",
                 std::abs(PoreGeometry::largest_turning(polyline.current_curve(0)) - M_PI / 4.) <
                   1e-12);
  }

  // Circles: 64 points on the unit circle with outward normals, and a second circle of radius
  // 0.5 about (3, 0) in the same piece.
  {
    const unsigned int        n = 64;
    std::vector<SurfacePoint> points;
    for (const auto &[centre, radius] :
         {std::make_pair(Point<2>(0., 0.), 1.), std::make_pair(Point<2>(3., 0.), 0.5)})
      for (unsigned int k = 0; k < n; ++k)
        {
          // Counter-clockwise from (-R, 0), the lexicographically first point (k = 0).
          const double angle = M_PI + 2. * M_PI * k / n;
          SurfacePoint p;
          p.normal_0 = Tensor<1, 2>({std::cos(angle), std::sin(angle)});
          p.X_0      = centre + radius * p.normal_0;
          p.x        = p.X_0;
          p.mu       = points.size();
          points.push_back(p);
        }
    const auto polyline = SurfaceGeometry::order_along_surface(shuffled(points, 6), gap);
    bool       in_order = polyline.points.size() == 2 * n && polyline.n_curves() == 2 &&
                    polyline.closed[0] && polyline.closed[1];
    // Clockwise (the body on the right) from (-R, 0).
    for (unsigned int i = 0; in_order && i < 2 * n; ++i)
      in_order = polyline.points[i].mu == (i / n) * n + (n - i % n) % n;
    ok &= report("two shuffled circles are two closed curves, each clockwise", in_order);
    ok &= report("  of lengths 64 chords, 2 R sin(pi/64) each",
                 std::abs(polyline.length_0[0] - 2. * n * std::sin(M_PI / n)) < 1e-12 &&
                   std::abs(polyline.length_0[1] - n * std::sin(M_PI / n)) < 1e-12);
    ok &= report("  turning by 2 pi/64 at every point, the first and last included",
                 std::abs(PoreGeometry::largest_turning(polyline.current_curve(0)) -
                          2. * M_PI / n) < 1e-12);
    ok &= report("  with no fold", SurfaceGeometry::count_folds(polyline, approach, arc) == 0);
    std::vector<Point<2>>     x;
    std::vector<Tensor<1, 2>> normals;
    for (unsigned int k = 0; k < n; ++k)
      {
        x.push_back(points[k].x);
        normals.push_back(points[k].normal_0);
      }
    ok &= report("  and no relief (the normals of a closed curve cancel)",
                 SurfaceGeometry::relief(x, normals) == 0.);

    // The unit circle flattened into an ellipse of half-height b.
    for (const double b : {0.05 * h, 0.5})
      {
        std::vector<SurfacePoint> flattened(points.begin(), points.begin() + n);
        for (auto &p : flattened)
          p.x = Point<2>(p.X_0[0], b * p.X_0[1]);
        const unsigned int expected = b < h ? 1 : 0;
        ok &= report("the circle flattened to half-height " + std::to_string(b).substr(0, 5) +
                       " has " + std::to_string(expected) + " fold(s)",
                     SurfaceGeometry::count_folds(
                       SurfaceGeometry::order_along_surface(shuffled(flattened, 7), gap),
                       approach,
                       arc) == expected);
      }
  }

  // Trochoids x = s - lambda rho sin(s/rho), y = lambda rho (1 - cos(s/rho)) over three periods
  // from s = pi rho: loops (crossings) at s = 2 pi rho, 4 pi rho, 6 pi rho for lambda > 1.
  for (const double lambda : {1.5, 0.5})
    {
      const double       rho      = 2. * h;
      const auto         n        = static_cast<unsigned int>(6. * M_PI * rho / (0.5 * h));
      const auto         points   = flat_piece(n, [&](const double s) {
        const double t = s / rho + M_PI;
        return Point<2>(rho * t - lambda * rho * std::sin(t), lambda * rho * (1. - std::cos(t)));
      });
      const auto         polyline = SurfaceGeometry::order_along_surface(points, gap);
      const unsigned int expected = lambda > 1. ? 3 : 0;
      ok &= report("the trochoid with lambda = " + std::to_string(lambda).substr(0, 3) +
                     " crosses itself " + std::to_string(expected) + " times: as many folds",
                   SurfaceGeometry::count_folds(polyline, 1e-9 * h, arc) == expected);
    }

  std::cout << (ok ? "surface geometry checks passed" : "SURFACE GEOMETRY CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}

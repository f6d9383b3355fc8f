#include <gelmpm/geometry/pair_gap.h>
#include <gelmpm/geometry/pore_geometry.h>
#include <gelmpm/geometry/surface_geometry.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

namespace GelMPM
{
  namespace SurfaceGeometry
  {
    namespace
    {
      /**
       * Whether two segments pq and rs cross at a point interior to both (as
       * PoreGeometry::self_intersects(): touching ends do not count).
       */
      bool
      segments_cross(const dealii::Point<2> &p,
                     const dealii::Point<2> &q,
                     const dealii::Point<2> &r,
                     const dealii::Point<2> &s)
      {
        const auto cross = [](const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b) {
          return a[0] * b[1] - a[1] * b[0];
        };
        const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
        const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
        return d1 * d2 < 0. && d3 * d4 < 0.;
      }

      /** The distance from @p x to the segment from @p a to @p b. */
      double
      distance_to_segment(const dealii::Point<2> &x,
                          const dealii::Point<2> &a,
                          const dealii::Point<2> &b)
      {
        const dealii::Tensor<1, 2> ab     = b - a;
        const double               length = ab.norm_square();
        const double along = length > 0. ? std::clamp((x - a) * ab / length, 0., 1.) : 0.;
        return x.distance(a + along * ab);
      }

      /**
       * The walk of order_along_surface() over points sorted by X_0: which point may follow
       * which, and the nearest one that may.
       */
      class Walk
      {
      public:
        Walk(const std::vector<SurfacePoint> &points, const double largest_gap)
          : points(points)
          , largest_gap(largest_gap)
        {
          for (const auto &p : points)
            {
              const double norm = p.normal_0.norm();
              tangents.push_back(
                norm > 0. ? dealii::Tensor<1, 2>({p.normal_0[1] / norm, -p.normal_0[0] / norm})
                          : dealii::Tensor<1, 2>());
            }
        }

        /**
         * Whether @p j may follow @p i along the surface (@p direction +1) or precede it (-1):
         * within the largest gap, ahead (or behind) along the mean tangent of the two, and with
         * a tangent that does not turn back.
         */
        bool
        follows(const unsigned int i, const unsigned int j, const int direction) const
        {
          const auto d = points[j].X_0 - points[i].X_0;
          return i != j && d.norm() <= largest_gap && tangents[i] * tangents[j] > -0.9 &&
                 direction * (d * (tangents[i] + tangents[j])) > 0.;
        }

        /**
         * The nearest point not @p taken that may follow @p i in @p direction; -1 if none. The
         * points are sorted by their first coordinate, so only those within the largest gap of
         * it along x are looked at.
         */
        int
        nearest(const unsigned int i, const int direction, const std::vector<bool> &taken) const
        {
          const double x_i           = points[i].X_0[0];
          auto         first         = std::lower_bound(points.begin(),
                                        points.end(),
                                        x_i - largest_gap,
                                        [](const SurfacePoint &p, const double x) {
                                          return p.X_0[0] < x;
                                        });
          int          best          = -1;
          double       best_distance = std::numeric_limits<double>::max();
          for (unsigned int j = first - points.begin();
               j < points.size() && points[j].X_0[0] <= x_i + largest_gap;
               ++j)
            if (!taken[j] && follows(i, j, direction))
              {
                const double distance = points[i].X_0.distance(points[j].X_0);
                if (distance < best_distance)
                  {
                    best          = j;
                    best_distance = distance;
                  }
              }
          return best;
        }

      private:
        const std::vector<SurfacePoint>  &points;
        const double                      largest_gap;
        std::vector<dealii::Tensor<1, 2>> tangents;
      };
    } // namespace


    template <int dim>
    double
    relief(const std::vector<dealii::Point<dim>>     &positions,
           const std::vector<dealii::Tensor<1, dim>> &normal_areas)
    {
      if (positions.empty())
        return 0.;
      dealii::Tensor<1, dim> normal;
      double                 area = 0.;
      for (const auto &n : normal_areas)
        {
          normal += n;
          area += n.norm();
        }
      if (!(normal.norm() > 0.1 * area))
        return 0.;
      normal /= normal.norm();
      dealii::Tensor<1, dim> mean;
      for (const auto &x : positions)
        mean += x;
      mean /= positions.size();
      double lowest = std::numeric_limits<double>::max(), highest = -lowest;
      for (const auto &x : positions)
        {
          const double height = (x - mean) * normal;
          lowest              = std::min(lowest, height);
          highest             = std::max(highest, height);
        }
      return highest - lowest;
    }


    std::vector<dealii::Point<2>>
    Polyline::current_curve(const unsigned int c) const
    {
      std::vector<dealii::Point<2>> curve;
      const unsigned int            begin = curve_begin[c], end = curve_begin[c + 1];
      if (closed[c])
        curve.push_back(points[end - 1].x);
      for (unsigned int i = begin; i < end; ++i)
        curve.push_back(points[i].x);
      if (closed[c])
        curve.push_back(points[begin].x);
      return curve;
    }


    Polyline
    order_along_surface(std::vector<SurfacePoint> points, const double largest_gap)
    {
      std::sort(points.begin(), points.end(), [](const SurfacePoint &a, const SurfacePoint &b) {
        return std::make_tuple(a.X_0[0], a.X_0[1], a.x[0], a.x[1], a.mu) <
               std::make_tuple(b.X_0[0], b.X_0[1], b.x[0], b.x[1], b.mu);
      });
      const unsigned int n = points.size();
      const Walk         walk(points, largest_gap);

      // Curves by the nearest-neighbour walk, forwards then backwards from the first point left.
      std::vector<std::deque<unsigned int>> curves;
      std::vector<bool>                     taken(n, false);
      for (unsigned int start = 0; start < n; ++start)
        if (!taken[start])
          {
            std::deque<unsigned int> curve = {start};
            taken[start]                   = true;
            for (int j; (j = walk.nearest(curve.back(), +1, taken)) >= 0;)
              {
                curve.push_back(j);
                taken[j] = true;
              }
            for (int j; (j = walk.nearest(curve.front(), -1, taken)) >= 0;)
              {
                curve.push_front(j);
                taken[j] = true;
              }
            curves.push_back(std::move(curve));
          }

      const auto is_closed = [&](const std::deque<unsigned int> &curve) {
        return curve.size() >= 3 && walk.follows(curve.back(), curve.front(), +1);
      };
      // A curve that begins where another ends continues it (the walk stopped short at a point
      // it had stepped over).
      for (bool joined = true; joined;)
        {
          joined = false;
          for (unsigned int a = 0; a < curves.size() && !joined; ++a)
            if (!curves[a].empty() && !is_closed(curves[a]))
              for (unsigned int b = 0; b < curves.size() && !joined; ++b)
                if (b != a && !curves[b].empty() && !is_closed(curves[b]) &&
                    walk.follows(curves[a].back(), curves[b].front(), +1))
                  {
                    curves[a].insert(curves[a].end(), curves[b].begin(), curves[b].end());
                    curves[b].clear();
                    joined = true;
                  }
        }
      // Points stepped over that made curves of their own go where they add the least length.
      std::vector<bool> closed(curves.size());
      for (unsigned int c = 0; c < curves.size(); ++c)
        closed[c] = is_closed(curves[c]);
      for (unsigned int a = 0; a < curves.size(); ++a)
        {
          if (curves[a].empty() || curves[a].size() > 2)
            continue;
          std::deque<unsigned int> left;
          for (const unsigned int p : curves[a])
            {
              const auto  &X        = points[p].X_0;
              double       best     = std::numeric_limits<double>::max();
              int          best_c   = -1;
              unsigned int best_pos = 0;
              for (unsigned int c = 0; c < curves.size(); ++c)
                {
                  const auto &curve = curves[c];
                  if (curve.size() < 3)
                    continue;
                  const unsigned int n_segments = curve.size() - (closed[c] ? 0 : 1);
                  for (unsigned int k = 0; k < n_segments; ++k)
                    {
                      const auto  &P     = points[curve[k]].X_0;
                      const auto  &Q     = points[curve[(k + 1) % curve.size()]].X_0;
                      const double added = X.distance(P) + X.distance(Q) - P.distance(Q);
                      if (X.distance(P) <= largest_gap && X.distance(Q) <= largest_gap &&
                          added < best)
                        {
                          best     = added;
                          best_c   = c;
                          best_pos = k + 1;
                        }
                    }
                }
              if (best_c >= 0)
                curves[best_c].insert(curves[best_c].begin() + best_pos, p);
              else
                left.push_back(p);
            }
          curves[a] = left;
        }

      Polyline polyline;
      for (unsigned int c = 0; c < curves.size(); ++c)
        {
          if (curves[c].empty())
            continue;
          polyline.curve_begin.push_back(polyline.points.size());
          for (const unsigned int p : curves[c])
            {
              double s = 0.;
              if (!polyline.points.empty())
                s = polyline.s_0.back() + polyline.points.back().X_0.distance(points[p].X_0);
              polyline.points.push_back(points[p]);
              polyline.s_0.push_back(s);
            }
          const bool         is_closed_curve = closed[c];
          const unsigned int begin           = polyline.curve_begin.back();
          polyline.closed.push_back(is_closed_curve);
          polyline.length_0.push_back(
            polyline.s_0.back() - polyline.s_0[begin] +
            (is_closed_curve ? polyline.points.back().X_0.distance(polyline.points[begin].X_0)
                             : 0.));
        }
      polyline.curve_begin.push_back(polyline.points.size());
      return polyline;
    }


    unsigned int
    count_folds(const Polyline &polyline, const double approach_distance, const double arc_length)
    {
      const unsigned int        n = polyline.points.size();
      std::vector<unsigned int> curve_of(n);
      for (unsigned int c = 0; c < polyline.n_curves(); ++c)
        for (unsigned int i = polyline.curve_begin[c]; i < polyline.curve_begin[c + 1]; ++i)
          curve_of[i] = c;
      const auto &s = polyline.s_0;
      // How far apart two places are along the surface is measured on the current surface: a
      // crease's flanks were close along the initial surface when the surface layer has since
      // swollen or stretched (a slit of depth d has 2d of current surface between its flanks).
      std::vector<double> s_now(n, 0.), length_now(polyline.n_curves(), 0.);
      for (unsigned int c = 0; c < polyline.n_curves(); ++c)
        {
          const unsigned int begin = polyline.curve_begin[c], end = polyline.curve_begin[c + 1];
          for (unsigned int i = begin + 1; i < end; ++i)
            s_now[i] = s_now[i - 1] + polyline.points[i - 1].x.distance(polyline.points[i].x);
          length_now[c] = end > begin ? s_now[end - 1] : 0.;
          if (polyline.closed[c] && end > begin)
            length_now[c] += polyline.points[end - 1].x.distance(polyline.points[begin].x);
        }
      const auto current_arc = [&](const unsigned int i, const unsigned int j) {
        const double direct = std::abs(s_now[j] - s_now[i]);
        return polyline.closed[curve_of[i]] ? std::min(direct, length_now[curve_of[i]] - direct)
                                            : direct;
      };

      // The stretch of surface between two places [s_i, s_j] (s_i <= s_j, both in the list's
      // order); on a closed curve the shorter way round, which may run past its end:
      // [s_j, s_i + L].
      const auto stretch = [&](const double s_i, const double s_j, const unsigned int c) {
        if (polyline.closed[c] && polyline.length_0[c] - (s_j - s_i) < s_j - s_i)
          return std::make_pair(s_j, s_i + polyline.length_0[c]);
        return std::make_pair(s_i, s_j);
      };

      std::vector<std::pair<double, double>> folded;
      // Segments (first point, second point, s at each end): a closed curve's last segment
      // returns to its first point, at s_0 of its first point plus its length.
      struct Segment
      {
        unsigned int a, b;
        double       s_a, s_b;
      };
      std::vector<Segment> segments;
      for (unsigned int c = 0; c < polyline.n_curves(); ++c)
        {
          const unsigned int begin = polyline.curve_begin[c], end = polyline.curve_begin[c + 1];
          for (unsigned int i = begin; i + 1 < end; ++i)
            segments.push_back({i, i + 1, s[i], s[i + 1]});
          if (polyline.closed[c])
            segments.push_back({end - 1, begin, s[end - 1], s[begin] + polyline.length_0[c]});
        }
      // A point close to a segment of another curve, or of a stretch of its own curve far from it
      // along the surface. Point to segment, not point to point: the points on the two flanks of a
      // closed crease need not face each other.
      for (unsigned int i = 0; i < n; ++i)
        for (const auto &segment : segments)
          {
            if (segment.a == i || segment.b == i ||
                !(distance_to_segment(polyline.points[i].x,
                                      polyline.points[segment.a].x,
                                      polyline.points[segment.b].x) < approach_distance))
              continue;
            const unsigned int j = segment.a;
            if (curve_of[i] != curve_of[j])
              folded.emplace_back(std::min(s[i], s[j]), std::max(s[i], s[j]));
            else if (current_arc(i, segment.a) > arc_length &&
                     current_arc(i, segment.b) > arc_length)
              folded.push_back(stretch(std::min(s[i], s[j]), std::max(s[i], s[j]), curve_of[i]));
          }

      for (unsigned int k = 0; k < segments.size(); ++k)
        for (unsigned int l = k + 1; l < segments.size(); ++l)
          {
            const auto &p = segments[k], &q = segments[l];
            if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b ||
                !segments_cross(polyline.points[p.a].x,
                                polyline.points[p.b].x,
                                polyline.points[q.a].x,
                                polyline.points[q.b].x))
              continue;
            if (curve_of[p.a] != curve_of[q.a])
              folded.emplace_back(p.s_a, q.s_b);
            else
              {
                // From the start of the one to the end of the other, the shorter way round.
                const unsigned int c = curve_of[p.a];
                if (polyline.closed[c] && (polyline.length_0[c] - (q.s_b - p.s_a)) < q.s_b - p.s_a)
                  folded.emplace_back(q.s_a, p.s_b + polyline.length_0[c]);
                else
                  folded.emplace_back(p.s_a, q.s_b);
              }
          }

      // Stretches that overlap, or that are closer along the surface than the criterion tells
      // places apart, are one fold.
      std::sort(folded.begin(), folded.end());
      std::vector<std::pair<double, double>> merged;
      for (const auto &interval : folded)
        if (!merged.empty() && interval.first <= merged.back().second + arc_length)
          merged.back().second = std::max(merged.back().second, interval.second);
        else
          merged.push_back(interval);
      unsigned int folds = merged.size();
      // On a closed curve the last fold may run past the end into the first ones.
      for (unsigned int c = 0; c < polyline.n_curves(); ++c)
        {
          if (!polyline.closed[c])
            continue;
          const double begin = s[polyline.curve_begin[c]], end = begin + polyline.length_0[c];
          std::vector<unsigned int> on_curve;
          for (unsigned int k = 0; k < merged.size(); ++k)
            if (merged[k].first >= begin && merged[k].first < end)
              on_curve.push_back(k);
          if (on_curve.size() < 2)
            continue;
          const double wrapped = merged[on_curve.back()].second - polyline.length_0[c];
          for (unsigned int k = 0; k + 1 < on_curve.size(); ++k)
            if (merged[on_curve[k]].first <= wrapped + arc_length)
              --folds;
        }
      return folds;
    }


    template double
    relief<2>(const std::vector<dealii::Point<2>> &, const std::vector<dealii::Tensor<1, 2>> &);
    template double
    relief<3>(const std::vector<dealii::Point<3>> &, const std::vector<dealii::Tensor<1, 3>> &);
  } // namespace SurfaceGeometry


  using dealii::Point;
  using dealii::Tensor;


  PointSegmentGap
  point_segment_gap(const Point<2> &x_s, const Point<2> &x_a, const Point<2> &x_b)
  {
    // With d = x_s - x_a, e = x_b - x_a, L = |e|, t = e / L and R the rotation by +90 degrees:
    // g = d . R e / L. Its derivatives in (d, e) are mapped to (x_s, x_a, x_b) by
    // d = x_s - x_a, e = x_b - x_a.
    PointSegmentGap    result;
    const Tensor<1, 2> d = x_s - x_a, e = x_b - x_a;
    const double       L = e.norm();
    const Tensor<1, 2> t = e / L;
    const Tensor<1, 2> n({-t[1], t[0]});
    const Tensor<1, 2> RTd({d[1], -d[0]}); // R^T d
    const double       R[2][2] = {{0., -1.}, {1., 0.}};
    const double       g       = d * n;
    const Tensor<1, 2> g_d     = n;
    const Tensor<1, 2> g_e     = (RTd - g * t) / L;
    const Tensor<2, 2> I       = dealii::unit_symmetric_tensor<2>();
    Tensor<2, 2>       H_de, H_ee; // H_dd = 0
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        {
          H_de[i][j] = (R[i][j] - n[i] * t[j]) / L;
          H_ee[i][j] =
            (-(RTd[i] * t[j] + t[i] * RTd[j]) - g * I[i][j] + 3. * g * t[i] * t[j]) / (L * L);
        }
    result.g      = g;
    result.xi     = d * t / L;
    result.normal = n;
    // The coefficients of x_s, x_a, x_b in d and in e.
    const double in_d[3] = {1., -1., 0.}, in_e[3] = {0., -1., 1.};
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int i = 0; i < 2; ++i)
        {
          result.gradient[2 * k + i] = in_d[k] * g_d[i] + in_e[k] * g_e[i];
          for (unsigned int l = 0; l < 3; ++l)
            for (unsigned int j = 0; j < 2; ++j)
              result.hessian[2 * k + i][2 * l + j] = in_d[k] * in_e[l] * H_de[i][j] +
                                                     in_e[k] * in_d[l] * H_de[j][i] +
                                                     in_e[k] * in_e[l] * H_ee[i][j];
        }
    return result;
  }


  template <int dim>
  PairGap<dim>
  point_plane_gap(const Point<dim> &x_s, const Point<dim> &x_a, const Tensor<1, dim> &normal)
  {
    // g = (x_s - x_a) . n with n fixed: linear, dg/dx_s = n, dg/dx_a = -n, no second derivative.
    PairGap<dim>         result;
    const Tensor<1, dim> d = x_s - x_a;
    result.g               = d * normal;
    result.xi              = (d - result.g * normal).norm();
    result.normal          = normal;
    for (unsigned int i = 0; i < dim; ++i)
      {
        result.gradient[i]       = normal[i];
        result.gradient[dim + i] = -normal[i];
      }
    return result;
  }


  NormalDerivatives<3>
  normal_derivatives(const Point<3> &, const Point<3> &)
  {
    return {};
  }


  /** A segment's unit normal n = R e / |e| (e = x_b - x_a, R the rotation by +90 degrees). */
  NormalDerivatives<2>
  normal_derivatives(const Point<2> &x_a, const Point<2> &x_b)
  {
    // With t = e / L: dn_i/de_j = (R_ij - n_i t_j) / L and
    // d2n_i/de_j de_k = (3 n_i t_j t_k - R_ij t_k - R_ik t_j - delta_jk n_i) / L^2.
    const Tensor<1, 2>   e = x_b - x_a;
    const double         L = e.norm();
    const Tensor<1, 2>   t = e / L;
    const Tensor<1, 2>   n({-t[1], t[0]});
    const double         R[2][2] = {{0., -1.}, {1., 0.}};
    const double         in_e[3] = {0., -1., 1.};
    NormalDerivatives<2> result;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int j = 0; j < 2; ++j)
          {
            result.first[i][2 * m + j] = in_e[m] * (R[i][j] - n[i] * t[j]) / L;
            for (unsigned int l = 0; l < 3; ++l)
              for (unsigned int k = 0; k < 2; ++k)
                result.second[i][2 * m + j][2 * l + k] = in_e[m] * in_e[l] *
                                                         (3. * n[i] * t[j] * t[k] - R[i][j] * t[k] -
                                                          R[i][k] * t[j] - (j == k ? n[i] : 0.)) /
                                                         (L * L);
          }
    return result;
  }


  /** For each of the points @p x, the others within @p radius, in increasing order (by
   * buckets of the radius). */
  template <int dim>
  std::vector<std::vector<unsigned int>>
  points_within(const std::vector<Point<dim>> &x, const double radius)
  {
    using Key      = std::array<long, dim>;
    const auto key = [radius](const Point<dim> &y) {
      Key k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = static_cast<long>(std::floor(y[d] / radius));
      return k;
    };
    std::map<Key, std::vector<unsigned int>> buckets;
    for (unsigned int p = 0; p < x.size(); ++p)
      buckets[key(x[p])].push_back(p);
    std::vector<std::vector<unsigned int>> within(x.size());
    for (unsigned int p = 0; p < x.size(); ++p)
      {
        const Key k = key(x[p]);
        for (unsigned int shift = 0;
             shift < dealii::Utilities::pow(3u, static_cast<unsigned int>(dim));
             ++shift)
          {
            Key          next = k;
            unsigned int code = shift;
            for (unsigned int d = 0; d < dim; ++d, code /= 3)
              next[d] += static_cast<long>(code % 3) - 1;
            const auto bucket = buckets.find(next);
            if (bucket != buckets.end())
              for (const unsigned int q : bucket->second)
                if (q != p && (x[p] - x[q]).norm() <= radius)
                  within[p].push_back(q);
          }
        std::sort(within[p].begin(), within[p].end());
      }
    return within;
  }

  template std::vector<std::vector<unsigned int>>
  points_within(const std::vector<Point<2>> &, const double);
  template std::vector<std::vector<unsigned int>>
  points_within(const std::vector<Point<3>> &, const double);
  template PairGap<2>
  point_plane_gap(const Point<2> &, const Point<2> &, const Tensor<1, 2> &);
  template PairGap<3>
  point_plane_gap(const Point<3> &, const Point<3> &, const Tensor<1, 3> &);
} // namespace GelMPM

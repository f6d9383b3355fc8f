#include <gelmpm/geometry/pore_geometry.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  namespace PoreGeometry
  {
    namespace
    {
      double
      cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /** Whether segments pq and rs cross at a point interior to both (touching ends do not
       * count: neighbouring points may coincide in a closed contact). */
      bool
      segments_cross(const dealii::Point<2> &p,
                     const dealii::Point<2> &q,
                     const dealii::Point<2> &r,
                     const dealii::Point<2> &s)
      {
        const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
        const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
        return d1 * d2 < 0. && d3 * d4 < 0.;
      }

      /** The angle (0 ... pi) between the segments before and after point @p i. */
      double
      turning_at(const std::vector<dealii::Point<2>> &polyline, const unsigned int i)
      {
        const auto a = polyline[i] - polyline[i - 1];
        const auto b = polyline[i + 1] - polyline[i];
        if (a.norm() == 0. || b.norm() == 0.)
          return 0.;
        return std::atan2(std::abs(cross(a, b)), a * b);
      }
    } // namespace


    double
    largest_curvature(const std::vector<dealii::Point<2>> &polyline)
    {
      double largest = 0.;
      for (unsigned int i = 1; i + 1 < polyline.size(); ++i)
        {
          const auto   a       = polyline[i] - polyline[i - 1];
          const auto   b       = polyline[i + 1] - polyline[i];
          const auto   c       = polyline[i + 1] - polyline[i - 1];
          const double lengths = a.norm() * b.norm() * c.norm();
          if (lengths > 0.)
            largest = std::max(largest, 2. * std::abs(cross(a, b)) / lengths);
        }
      return largest;
    }


    double
    largest_turning(const std::vector<dealii::Point<2>> &polyline)
    {
      double largest = 0.;
      for (unsigned int i = 1; i + 1 < polyline.size(); ++i)
        largest = std::max(largest, turning_at(polyline, i));
      return largest;
    }


    unsigned int
    sharp_corners(const std::vector<dealii::Point<2>> &polyline, const double angle)
    {
      unsigned int corners  = 0;
      bool         in_sharp = false;
      for (unsigned int i = 1; i + 1 < polyline.size(); ++i)
        {
          const bool sharp = turning_at(polyline, i) > angle;
          corners += sharp && !in_sharp;
          in_sharp = sharp;
        }
      return corners;
    }


    bool
    self_intersects(const std::vector<dealii::Point<2>> &polyline)
    {
      const unsigned int n = polyline.size();
      for (unsigned int i = 0; i + 1 < n; ++i)
        for (unsigned int j = i + 2; j + 1 < n; ++j)
          if (segments_cross(polyline[i], polyline[i + 1], polyline[j], polyline[j + 1]))
            return true;
      return false;
    }
  } // namespace PoreGeometry
} // namespace GelMPM

// A body where a level set is negative; the 2D contour of its boundary. (The 3D surface is in
// level_set_body_3d.cc.)

#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/scene/expression.h>
#include <gelmpm/scene/level_set_body.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    using P = dealii::Point<2>;
    using T = dealii::Tensor<1, 2>;

    std::string
    variable_names(const int dim)
    {
      return dim == 2 ? "x,y" : "x,y,z";
    }


    /** phi sampled on a grid over a box: (n[0] + 1) x (n[1] + 1) samples. */
    struct Samples
    {
      P                           lower;
      std::array<unsigned int, 2> n;
      std::array<double, 2>       step;
      std::vector<double>         values;

      P
      point(const unsigned int i, const unsigned int j) const
      {
        return P(lower[0] + i * step[0], lower[1] + j * step[1]);
      }

      double
      value(const unsigned int i, const unsigned int j) const
      {
        return values[j * (n[0] + 1) + i];
      }
    };


    /**
     * phi on a grid of [@p lower, @p upper] twice as fine as the elements (@p spacing): the
     * contour between samples is only a first guess, which the projection moves onto the zero
     * set. Throws InputError if phi < 0 on the edge of the box.
     */
    Samples
    sample_level_set(const LevelSetBody<2> &body,
                     const double           spacing,
                     const P               &lower,
                     const P               &upper)
    {
      Samples samples;
      samples.lower = lower;
      for (unsigned int d = 0; d < 2; ++d)
        {
          samples.n[d] =
            std::max(2u,
                     static_cast<unsigned int>(std::ceil((upper[d] - lower[d]) / (0.5 * spacing))));
          samples.step[d] = (upper[d] - lower[d]) / samples.n[d];
        }
      const auto &n = samples.n;
      samples.values.resize((n[0] + 1) * (n[1] + 1));
      for (unsigned int j = 0; j <= n[1]; ++j)
        for (unsigned int i = 0; i <= n[0]; ++i)
          {
            const double v = body.level_set(samples.point(i, j));
            // A contour crossing the grid's edge would be open there: the body would be cut
            // off by the grid.
            require(!(v < 0.) || (i > 0 && j > 0 && i < n[0] && j < n[1]),
                    "Geometry/Level set",
                    "is negative on the edge of the background grid, e.g. at " +
                      format_point(samples.point(i, j)) + ": the body reaches outside the grid",
                    "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the "
                    "body");
            samples.values[j * (n[0] + 1) + i] = v;
          }
      return samples;
    }


    /**
     * The segments of the contour that marching squares find: where the zero set crosses each
     * sampling edge it crosses (linear interpolation), and for each crossing the next one along
     * the contour.
     */
    struct ContourSegments
    {
      std::map<std::size_t, std::size_t> next;
      std::map<std::size_t, P>           crossing;
    };


    /**
     * Marching squares. Edges are numbered: horizontal (i, j)-(i+1, j) first, then vertical
     * (i, j)-(i, j+1). A sampling cell's crossings, walked counter-clockwise, alternate between
     * leaving the body (in -> out) and entering it; each contour segment runs from a leaving to
     * an entering crossing, so that the body lies on its left and the contours run
     * counter-clockwise around the body (clockwise around holes).
     */
    ContourSegments
    march_squares(const LevelSetBody<2> &body, const Samples &samples)
    {
      const auto &n          = samples.n;
      const auto  horizontal = [&](const unsigned int i, const unsigned int j) {
        return static_cast<std::size_t>(j) * n[0] + i;
      };
      const auto vertical = [&](const unsigned int i, const unsigned int j) {
        return static_cast<std::size_t>(n[0]) * (n[1] + 1) +
               static_cast<std::size_t>(j) * (n[0] + 1) + i;
      };
      ContourSegments segments;
      auto           &next     = segments.next;
      auto           &crossing = segments.crossing;
      for (unsigned int j = 0; j < n[1]; ++j)
        for (unsigned int i = 0; i < n[0]; ++i)
          {
            const std::array<std::pair<unsigned int, unsigned int>, 4> corner = {
              {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
            const std::array<std::size_t, 4> edge = {
              {horizontal(i, j), vertical(i + 1, j), horizontal(i, j + 1), vertical(i, j)}};
            std::array<bool, 4> in;
            for (unsigned int k = 0; k < 4; ++k)
              in[k] = samples.value(corner[k].first, corner[k].second) < 0.;
            // Crossings in counter-clockwise order, with whether they leave the body.
            std::vector<std::pair<std::size_t, bool>> cuts;
            for (unsigned int k = 0; k < 4; ++k)
              {
                const unsigned int l = (k + 1) % 4;
                if (in[k] == in[l])
                  continue;
                const double va   = samples.value(corner[k].first, corner[k].second),
                             vb   = samples.value(corner[l].first, corner[l].second);
                const P a         = samples.point(corner[k].first, corner[k].second),
                        b         = samples.point(corner[l].first, corner[l].second);
                crossing[edge[k]] = a + (va / (va - vb)) * (b - a);
                cuts.emplace_back(edge[k], in[k]);
              }
            if (cuts.size() == 2)
              next[cuts[0].second ? cuts[0].first : cuts[1].first] =
                cuts[0].second ? cuts[1].first : cuts[0].first;
            else if (cuts.size() == 4)
              {
                // A saddle: the value at the centre decides whether the two inside corners
                // are connected (the segments cut off the outside corners) or not.
                const bool centre_in =
                  body.level_set(samples.point(i, j) +
                                 0.5 * T({samples.step[0], samples.step[1]})) < 0.;
                for (unsigned int k = 0; k < 4; ++k)
                  if (cuts[k].second)
                    next[cuts[k].first] = cuts[(k + (centre_in ? 1 : 3)) % 4].first;
              }
          }
      return segments;
    }


    /** The closed contours through the @p segments, their crossings projected onto the zero set. */
    std::vector<std::vector<P>>
    closed_contours(const LevelSetBody<2> &body,
                    const ContourSegments &segments,
                    const double           max_shift)
    {
      std::vector<std::vector<P>> loops;
      std::set<std::size_t>       done;
      for (const auto &[start, ignored] : segments.next)
        {
          (void)ignored;
          if (done.count(start))
            continue;
          std::vector<P> loop;
          for (std::size_t e = start;;)
            {
              done.insert(e);
              loop.push_back(body.project_onto_zero_set(segments.crossing.at(e), max_shift));
              const auto found = segments.next.find(e);
              if (found == segments.next.end())
                throw std::logic_error("level set: a contour is not closed");
              e = found->second;
              if (e == start)
                break;
            }
          loops.push_back(std::move(loop));
        }
      return loops;
    }


    /**
     * Where the lines through @p p and @p q normal to @p n_p and @p n_q meet; nothing if they are
     * (almost) parallel.
     */
    std::optional<P>
    tangent_intersection(const P &p, const T &n_p, const P &q, const T &n_q)
    {
      // (x - p).n_p = 0 and (x - q).n_q = 0.
      const double det = n_p[0] * n_q[1] - n_p[1] * n_q[0];
      if (std::abs(det) < 1e-3)
        return std::nullopt;
      const double bp = n_p * p, bq = n_q * q;
      return P((bp * n_q[1] - bq * n_p[1]) / det, (n_p[0] * bq - n_q[0] * bp) / det);
    }


    /**
     * The corner between the contour points @p a and @p b whose tangent lines meet at
     * @p estimate: the tangent lines at the samples miss the corner of curved branches by
     * (sample distance)^2 x curvature, so they are redone (three times at most) at points of
     * each branch close to the estimate (close, but not so close that the difference quotients
     * of the gradient straddle the corner).
     */
    P
    refine_corner(const LevelSetBody<2> &body,
                  const P               &a,
                  const P               &b,
                  const P               &estimate_at_samples,
                  const double           max_shift)
    {
      const double delta    = 1e-4 * max_shift;
      P            estimate = estimate_at_samples;
      for (unsigned int refinement = 0; refinement < 3; ++refinement)
        {
          std::array<P, 2> q;
          std::array<T, 2> n;
          bool             refined = true;
          for (unsigned int side = 0; side < 2; ++side)
            {
              const P     &sample = side == 0 ? a : b;
              const double away   = sample.distance(estimate);
              if (away <= 1e-2 * max_shift)
                {
                  refined = false;
                  break;
                }
              q[side]   = body.project_onto_zero_set(estimate + (1e-2 * max_shift / away) *
                                                                (sample - estimate),
                                                   max_shift);
              const T g = body.gradient(q[side], delta);
              n[side]   = g / g.norm();
            }
          if (!refined)
            break;
          const auto better = tangent_intersection(q[0], n[0], q[1], n[1]);
          if (!better || better->distance(estimate_at_samples) > max_shift)
            break;
          estimate = *better;
        }
      return estimate;
    }


    /** A closed contour as a polyline, with the points that are corners of the contour. */
    struct Polyline
    {
      std::vector<P>    points;
      std::vector<bool> is_corner;

      /** Append @p x, or mark the last point a corner if @p x coincides with it. */
      void
      add(const P &x, const bool corner, const double max_shift)
      {
        if (!points.empty() && points.back().distance(x) <= 1e-9 * max_shift)
          is_corner.back() = is_corner.back() || corner;
        else
          {
            points.push_back(x);
            is_corner.push_back(corner);
          }
      }
    };


    /**
     * The contour @p loop with its kinks (a level set like max(phi_1, phi_2) has corners): where
     * the normals of neighbouring points differ by more than 30 degrees, the corner is where
     * their tangent lines meet, added between them. Elements end at corners, so that none
     * straddles one with a chord that cuts it short. (A smooth contour turns by 30 degrees
     * between two samples only where its radius of curvature is below the element length,
     * which the elements cannot resolve anyway.)
     */
    Polyline
    contour_with_corners(const LevelSetBody<2> &body,
                         const std::vector<P>  &loop,
                         const double           max_shift)
    {
      const double   delta = 1e-4 * max_shift;
      std::vector<T> normal(loop.size());
      for (std::size_t k = 0; k < loop.size(); ++k)
        {
          const T g = body.gradient(loop[k], delta);
          normal[k] = g.norm() > 0. ? g / g.norm() : T();
        }
      Polyline polyline;
      for (std::size_t k = 0; k < loop.size(); ++k)
        {
          polyline.add(loop[k], false, max_shift);
          const std::size_t l = (k + 1) % loop.size();
          if (normal[k] * normal[l] >= std::cos(M_PI / 6.))
            continue;
          const auto corner = tangent_intersection(loop[k], normal[k], loop[l], normal[l]);
          if (!corner || corner->distance(loop[k]) > max_shift ||
              corner->distance(loop[l]) > max_shift)
            continue;
          polyline.add(refine_corner(body, loop[k], loop[l], *corner, max_shift), true, max_shift);
        }
      auto &points    = polyline.points;
      auto &is_corner = polyline.is_corner;
      if (points.size() > 1 && points.front().distance(points.back()) <= 1e-9 * max_shift)
        {
          is_corner.front() = is_corner.front() || is_corner.back();
          points.pop_back();
          is_corner.pop_back();
        }
      return polyline;
    }


    /**
     * The piece of the polyline @p points from @p begin to @p end (corners, or the whole closed
     * contour if @p closed) divided into elements of equal length along it, at most @p spacing.
     */
    void
    add_piece_elements(const LevelSetBody<2>                         &body,
                       const std::vector<P>                          &points,
                       const std::size_t                              begin,
                       const std::size_t                              end,
                       const bool                                     closed,
                       const double                                   spacing,
                       const double                                   max_shift,
                       std::vector<typename Body<2>::SurfaceElement> &elements)
    {
      std::vector<double> arc(end - begin + 1, 0.);
      for (std::size_t k = begin; k < end; ++k)
        arc[k - begin + 1] = arc[k - begin] + points[k].distance(points[k + 1]);
      const double length = arc.back();
      // The polyline is a little shorter than the contour (by the relative amount
      // (step * curvature)^2 / 24): 1 % more elements keep each below the spacing.
      const unsigned int m =
        std::max(closed ? 3u : 1u,
                 static_cast<unsigned int>(std::ceil(1.01 * length / spacing - 1e-9)));
      const auto at = [&](const double s) {
        const std::size_t k =
          std::min<std::size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin() - 1,
                                end - begin - 1);
        const double piece = arc[k + 1] - arc[k];
        const double w     = piece > 0. ? (s - arc[k]) / piece : 0.;
        return body.project_onto_zero_set(points[begin + k] +
                                            w * (points[begin + k + 1] - points[begin + k]),
                                          max_shift);
      };
      // The ends of a piece are its corners, where the projection is not defined.
      std::vector<P> ends(m + 1);
      ends[0] = closed ? at(0.) : points[begin];
      ends[m] = closed ? ends[0] : points[end];
      for (unsigned int k = 1; k < m; ++k)
        ends[k] = at(k * length / m);
      for (unsigned int k = 0; k < m; ++k)
        {
          const T chord = ends[k + 1] - ends[k];
          // The integral of the outward normal over the contour between two points is the
          // chord rotated clockwise, whatever the contour's shape between them.
          elements.push_back({at((k + 0.5) * length / m),
                              T({chord[1], -chord[0]}),
                              dealii::numbers::invalid_boundary_id,
                              {},
                              {}});
        }
    }


    /**
     * The elements of a closed contour: started at a corner if there is one, cut at its corners
     * into pieces, each divided by add_piece_elements().
     */
    void
    add_contour_elements(const LevelSetBody<2>                         &body,
                         Polyline                                       polyline,
                         const double                                   spacing,
                         const double                                   max_shift,
                         std::vector<typename Body<2>::SurfaceElement> &elements)
    {
      auto             &points    = polyline.points;
      auto             &is_corner = polyline.is_corner;
      const std::size_t first =
        std::find(is_corner.begin(), is_corner.end(), true) - is_corner.begin();
      const bool closed = first == is_corner.size();
      std::rotate(points.begin(), points.begin() + (closed ? 0 : first), points.end());
      std::rotate(is_corner.begin(), is_corner.begin() + (closed ? 0 : first), is_corner.end());
      points.push_back(points.front());
      is_corner.push_back(!closed);

      for (std::size_t begin = 0; begin + 1 < points.size();)
        {
          std::size_t end = begin + 1;
          while (end + 1 < points.size() && !is_corner[end])
            ++end;
          add_piece_elements(body, points, begin, end, closed, spacing, max_shift, elements);
          begin = end;
        }
    }


    /** 2D: the closed contours of the zero set in [@p lower, @p upper], cut into elements. */
    std::vector<typename Body<2>::SurfaceElement>
    contour_elements(const LevelSetBody<2> &body,
                     const double           spacing,
                     const P               &lower,
                     const P               &upper)
    {
      const Samples samples   = sample_level_set(body, spacing, lower, upper);
      const double  max_shift = 2. * std::max(samples.step[0], samples.step[1]);
      std::vector<typename Body<2>::SurfaceElement> elements;
      for (const auto &loop : closed_contours(body, march_squares(body, samples), max_shift))
        add_contour_elements(body,
                             contour_with_corners(body, loop, max_shift),
                             spacing,
                             max_shift,
                             elements);
      return elements;
    }
  } // namespace


  template <int dim>
  LevelSetBody<dim>::LevelSetBody(const std::string &expression, const std::string &constants)
    : expression(expression)
  {
    const auto values =
      parse_expression_constants(constants, variable_names(dim), "Geometry/Level set constants");
    auto parser = std::make_shared<dealii::FunctionParser<dim>>(1);
    try
      {
        const QuietCerr quiet;
        parser->initialize(variable_names(dim), expression, values);
        // The parser compiles lazily: evaluate once to surface syntax errors here.
        (void)parser->value(dealii::Point<dim>());
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("Geometry/Level set",
                         "'" + expression + "' cannot be parsed: " + describe(e),
                         "write an expression in " + variable_names(dim) +
                           " (and the 'Level set constants'), negative inside the body");
      }
    phi = parser;
  }


  template <int dim>
  BodySource
  LevelSetBody<dim>::source() const
  {
    return BodySource::level_set;
  }


  template <int dim>
  std::string
  LevelSetBody<dim>::entry() const
  {
    return "Geometry/Level set";
  }


  template <int dim>
  bool
  LevelSetBody<dim>::inside(const dealii::Point<dim> &p) const
  {
    return level_set(p) < 0.;
  }


  template <int dim>
  void
  LevelSetBody<dim>::check_volume_points(const unsigned long n_points,
                                         const bool,
                                         const unsigned long n_samples) const
  {
    require(n_points > 0,
            "Geometry/Level set",
            "is negative nowhere inside the background grid (at none of the " +
              std::to_string(n_samples) + " sub-cell centres), so there is no body",
            "check the sign (the body is where the expression is negative) and the position "
            "against 'Background grid'");
  }


  template <int dim>
  double
  LevelSetBody<dim>::level_set(const dealii::Point<dim> &p) const
  {
    const double value = phi->value(p);
    if (!std::isfinite(value))
      throw InputError("Geometry/Level set",
                       "'" + expression + "' is not a number at " + format_point(p),
                       "write an expression that is finite in the whole background grid");
    return value;
  }


  template <int dim>
  dealii::Tensor<1, dim>
  LevelSetBody<dim>::gradient(const dealii::Point<dim> &p, const double delta) const
  {
    dealii::Tensor<1, dim> gradient;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dealii::Point<dim> plus = p, minus = p;
        plus[d] += delta;
        minus[d] -= delta;
        gradient[d] = (level_set(plus) - level_set(minus)) / (2. * delta);
      }
    return gradient;
  }


  template <int dim>
  dealii::Point<dim>
  LevelSetBody<dim>::project_onto_zero_set(const dealii::Point<dim> &p,
                                           const double              max_shift) const
  {
    // Newton's method for phi(p + s grad phi / |grad phi|) = 0, the gradient re-evaluated at
    // each iterate: quadratic convergence from the marching-squares estimate, which lies within
    // a sampling cell of the contour. The finite-difference step only affects the rate.
    const double       delta = 1e-4 * max_shift;
    dealii::Point<dim> x     = p;
    for (unsigned int k = 0; k < 30; ++k)
      {
        const double                 value = level_set(x);
        const dealii::Tensor<1, dim> slope = gradient(x, delta);
        const double                 g2    = slope.norm_square();
        if (!(g2 > 0.))
          return p;
        const dealii::Tensor<1, dim> step = (value / g2) * slope;
        x -= step;
        if (x.distance(p) > max_shift)
          return p;
        if (step.norm() <= 1e-14 * max_shift)
          break;
      }
    return x;
  }


  template <int dim>
  std::vector<typename LevelSetBody<dim>::SurfaceElement>
  LevelSetBody<dim>::surface_elements(const double              spacing,
                                      const dealii::Point<dim> &lower,
                                      const dealii::Point<dim> &upper) const
  {
    if constexpr (dim == 2)
      return contour_elements(*this, spacing, lower, upper);
    else
      return surface_elements_3d(spacing, lower, upper);
  }


  template class LevelSetBody<2>;
  template class LevelSetBody<3>;
} // namespace GelMPM

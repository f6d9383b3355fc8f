#include <gelmpm/core/input_error.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/scene/geometry.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    std::vector<double>
    parse_numbers(const std::string &text,
                  const unsigned int n,
                  const std::string &entry,
                  const std::string &item)
    {
      const auto parts = dealii::Utilities::split_string_list(text, ',');
      require(parts.size() == n,
              entry,
              "has the item '" + item + "' with " + std::to_string(parts.size()) +
                " numbers where " + std::to_string(n) + " are expected",
              "give " + std::to_string(n) + " comma-separated number(s) there, e.g. '" +
                std::string(n == 1 ? "0.2" : (n == 2 ? "0.5, 0.5" : "0.5, 0.5, 0.5")) + "'");
      std::vector<double> values;
      for (const auto &p : parts)
        try
          {
            values.push_back(dealii::Utilities::string_to_double(p));
          }
        catch (...)
          {
            throw InputError(entry,
                             "has the non-number '" + p + "' in '" + item + "'",
                             "give numbers");
          }
      for (const double v : values)
        require(std::isfinite(v),
                entry,
                "has a number that is not finite in '" + item + "'",
                "give finite numbers");
      return values;
    }
  } // namespace


  template <int dim>
  void
  Geometry<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Boxes",
                      dim == 2 ? "0, 0 : 1, 1" : "0, 0, 0 : 1, 1, 1",
                      dealii::Patterns::Anything(),
                      "The body in its initial configuration is the union of these boxes, each "
                      "'lower corner : upper corner' (coordinates separated by commas), boxes "
                      "separated by ';'. Example: '0, 0 : 0.2, 1'.");
    prm.declare_entry("Holes",
                      "",
                      dealii::Patterns::Anything(),
                      "Balls removed from the boxes, each 'centre : radius', separated by ';'. "
                      "Example (§4.4, quarter holes at the corners of a cell of size a): "
                      "'0, 0 : R; a, 0 : R; 0, a : R; a, a : R'. Empty: no holes.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  Geometry<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    const std::string box_text  = prm.get("Boxes");
    const std::string hole_text = prm.get("Holes");
    prm.leave_subsection();

    boxes.clear();
    holes.clear();
    for (const auto &item : dealii::Utilities::split_string_list(box_text, ';'))
      {
        const auto corners = dealii::Utilities::split_string_list(item, ':');
        require(corners.size() == 2,
                "Geometry/Boxes",
                "has the item '" + item + "' that is not 'lower corner : upper corner'",
                "write e.g. '0, 0 : 0.2, 1'");
        const auto         lo = parse_numbers(corners[0], dim, "Geometry/Boxes", item);
        const auto         hi = parse_numbers(corners[1], dim, "Geometry/Boxes", item);
        dealii::Point<dim> lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = lo[d];
            upper[d] = hi[d];
            require(upper[d] > lower[d],
                    "Geometry/Boxes",
                    "has the box '" + item + "' whose upper corner is not above its lower corner",
                    "list the lower corner first");
          }
        add_box(lower, upper);
      }
    require(!boxes.empty(), "Geometry/Boxes", "is empty", "give at least one box");
    for (const auto &item : dealii::Utilities::split_string_list(hole_text, ';'))
      {
        const auto parts = dealii::Utilities::split_string_list(item, ':');
        require(parts.size() == 2,
                "Geometry/Holes",
                "has the item '" + item + "' that is not 'centre : radius'",
                "write e.g. '0.5, 0.5 : 0.2'");
        const auto c = parse_numbers(parts[0], dim, "Geometry/Holes", item);
        const auto r = parse_numbers(parts[1], 1, "Geometry/Holes", item);
        require(r[0] > 0.,
                "Geometry/Holes",
                "has a non-positive radius in '" + item + "'",
                "give radius > 0");
        dealii::Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = c[d];
        add_hole(centre, r[0]);
      }
  }


  template <int dim>
  void
  Geometry<dim>::add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper)
  {
    boxes.emplace_back(lower, upper);
  }


  template <int dim>
  void
  Geometry<dim>::add_hole(const dealii::Point<dim> &centre, const double radius)
  {
    holes.emplace_back(centre, radius);
  }


  template <int dim>
  bool
  Geometry<dim>::inside(const dealii::Point<dim> &p) const
  {
    for (const auto &[centre, radius] : holes)
      if (p.distance(centre) < radius)
        return false;
    return inside_boxes(p);
  }


  template <int dim>
  bool
  Geometry<dim>::inside_boxes(const dealii::Point<dim> &p) const
  {
    for (const auto &[lower, upper] : boxes)
      {
        bool in = true;
        for (unsigned int d = 0; d < dim; ++d)
          in &= (p[d] >= lower[d] && p[d] <= upper[d]);
        if (in)
          return true;
      }
    return false;
  }


  template <int dim>
  bool
  Geometry<dim>::on_boundary(const dealii::Point<dim>     &p,
                             const dealii::Tensor<1, dim> &normal) const
  {
    double size = 0.;
    for (const auto &[lower, upper] : boxes)
      size = std::max(size, lower.distance(upper));
    const double eps = 1e-9 * size;
    return inside(p - eps * normal) && !inside(p + eps * normal);
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::surface_elements(const double spacing) const
  {
    if (dim != 2)
      throw std::logic_error("surface material points are implemented in 2D only");
    std::vector<SurfaceElement> elements;
    using P = dealii::Point<dim>;
    using T = dealii::Tensor<1, dim>;

    // Box edges, split where hole circles cross them.
    for (const auto &[lower, upper] : boxes)
      {
        const P corners[4] = {P(lower[0], lower[1]),
                              P(upper[0], lower[1]),
                              P(upper[0], upper[1]),
                              P(lower[0], upper[1])};
        for (unsigned int e = 0; e < 4; ++e)
          {
            const P             a = corners[e], b = corners[(e + 1) % 4];
            const T             t = (b - a) / a.distance(b);
            const T             n({t[1], -t[0]}); // outward for counter-clockwise corners
            const double        L      = a.distance(b);
            std::vector<double> breaks = {0., L};
            for (const auto &[centre, radius] : holes)
              {
                // |a + s t - c|^2 = r^2
                const T      ac   = a - centre;
                const double bq   = ac * t;
                const double disc = bq * bq - (ac * ac - radius * radius);
                if (disc > 0.)
                  for (const double s : {-bq - std::sqrt(disc), -bq + std::sqrt(disc)})
                    if (s > 0. && s < L)
                      breaks.push_back(s);
              }
            std::sort(breaks.begin(), breaks.end());
            for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
              {
                const double length = breaks[k + 1] - breaks[k];
                if (length <= relative_position_tolerance * L)
                  continue;
                const unsigned int m =
                  std::max(1u, static_cast<unsigned int>(std::ceil(length / spacing - 1e-9)));
                for (unsigned int j = 0; j < m; ++j)
                  {
                    const P c = a + (breaks[k] + (j + 0.5) * length / m) * t;
                    if (on_boundary(c, n))
                      elements.push_back({c, (length / m) * n});
                  }
              }
          }
      }

    // Hole arcs, split where box edges cross them; the body's outward normal points into the hole.
    for (const auto &[centre, radius] : holes)
      {
        std::vector<double> breaks = {0., 2. * M_PI};
        for (const auto &[lower, upper] : boxes)
          for (unsigned int d = 0; d < dim; ++d)
            for (const double line : {lower[d], upper[d]})
              {
                const double offset = (line - centre[d]) / radius;
                if (std::abs(offset) >= 1.)
                  continue;
                for (const double sign : {-1., 1.})
                  {
                    // Point on the circle with coordinate d equal to line.
                    const double other = sign * std::sqrt(1. - offset * offset);
                    double angle = (d == 0) ? std::atan2(other, offset) : std::atan2(offset, other);
                    if (angle < 0.)
                      angle += 2. * M_PI;
                    breaks.push_back(angle);
                  }
              }
        std::sort(breaks.begin(), breaks.end());
        for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
          {
            const double span = breaks[k + 1] - breaks[k];
            if (span <= relative_position_tolerance) // radians
              continue;
            const unsigned int m =
              std::max(1u, static_cast<unsigned int>(std::ceil(span * radius / spacing - 1e-9)));
            for (unsigned int j = 0; j < m; ++j)
              {
                const double t0 = breaks[k] + j * span / m, t1 = t0 + span / m,
                             tm = 0.5 * (t0 + t1);
                const P c       = centre + radius * T({std::cos(tm), std::sin(tm)});
                const T n({-std::cos(tm), -std::sin(tm)});
                // Exact integral of the (inward-radial) normal over the arc.
                const T normal_area({-radius * (std::sin(t1) - std::sin(t0)),
                                     radius * (std::cos(t1) - std::cos(t0))});
                if (on_boundary(c, n))
                  elements.push_back({c, normal_area});
              }
          }
      }
    return elements;
  }


  template class Geometry<2>;
  template class Geometry<3>;
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/scene/box_body.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  template <int dim>
  std::pair<dealii::Tensor<1, dim>, dealii::Tensor<1, dim>>
  BoxBody<dim>::Cylinder::frame() const
  {
    // The coordinate axis least aligned with the cylinder's, made orthogonal to it.
    unsigned int least = 0;
    for (unsigned int d = 1; d < dim; ++d)
      if (std::abs(axis[d]) < std::abs(axis[least]))
        least = d;
    dealii::Tensor<1, dim> e1, e2;
    e1[least] = 1.;
    e1 -= (e1 * axis) * axis;
    e1 /= e1.norm();
    if constexpr (dim == 3)
      e2 = dealii::cross_product_3d(axis, e1);
    return {e1, e2};
  }


  template <int dim>
  void
  BoxBody<dim>::add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper)
  {
    boxes.emplace_back(lower, upper);
  }


  template <int dim>
  void
  BoxBody<dim>::add_hole(const dealii::Point<dim> &centre, const double radius)
  {
    holes.emplace_back(centre, radius);
  }


  template <int dim>
  void
  BoxBody<dim>::add_cylinder(const dealii::Point<dim>     &centre,
                             const double                  radius,
                             const dealii::Tensor<1, dim> &axis)
  {
    cylinders.push_back({centre, radius, axis / axis.norm()});
  }


  template <int dim>
  bool
  BoxBody<dim>::empty() const
  {
    return boxes.empty();
  }


  template <int dim>
  BodySource
  BoxBody<dim>::source() const
  {
    return BodySource::boxes;
  }


  template <int dim>
  std::string
  BoxBody<dim>::entry() const
  {
    return "Geometry/Boxes";
  }


  template <int dim>
  bool
  BoxBody<dim>::inside(const dealii::Point<dim> &p) const
  {
    for (const auto &[centre, radius] : holes)
      if (p.distance(centre) < radius)
        return false;
    for (const auto &cylinder : cylinders)
      if (cylinder.distance_to_axis(p) < cylinder.radius)
        return false;
    return inside_boxes(p);
  }


  template <int dim>
  bool
  BoxBody<dim>::inside_boxes(const dealii::Point<dim> &p) const
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
  void
  BoxBody<dim>::check_volume_points(const unsigned long n_points,
                                    const bool          any_in_boxes,
                                    const unsigned long n_samples) const
  {
    require(n_points > 0 || !any_in_boxes,
            "Geometry/Holes",
            "leaves nothing of the body: the holes remove the whole body (no volume point of "
            "'Geometry/Boxes' lies outside them)",
            "make the holes smaller or move them off the body ('Geometry/Boxes')");
    Body<dim>::check_volume_points(n_points, any_in_boxes, n_samples);
  }


  template <int dim>
  double
  BoxBody<dim>::face_tolerance() const
  {
    double size = 0.;
    for (const auto &[lower, upper] : boxes)
      size = std::max(size, lower.distance(upper));
    return 1e-9 * size;
  }


  template <int dim>
  bool
  BoxBody<dim>::on_boundary(const dealii::Point<dim> &p, const dealii::Tensor<1, dim> &normal) const
  {
    const double eps = face_tolerance();
    return inside(p - eps * normal) && !inside(p + eps * normal);
  }


  template <int dim>
  bool
  BoxBody<dim>::on_earlier_box_face(const unsigned int            box,
                                    const dealii::Point<dim>     &p,
                                    const dealii::Tensor<1, dim> &normal) const
  {
    unsigned int a = 0;
    for (unsigned int d = 1; d < dim; ++d)
      if (std::abs(normal[d]) > std::abs(normal[a]))
        a = d;
    const double eps = face_tolerance();
    for (unsigned int j = 0; j < box; ++j)
      {
        const auto &[lower, upper] = boxes[j];
        const double plane         = normal[a] > 0. ? upper[a] : lower[a];
        bool         on            = std::abs(p[a] - plane) <= eps;
        for (unsigned int d = 0; d < dim && on; ++d)
          on = d == a || (p[d] >= lower[d] - eps && p[d] <= upper[d] + eps);
        if (on)
          return true;
      }
    return false;
  }


  template <int dim>
  std::vector<typename BoxBody<dim>::SurfaceElement>
  BoxBody<dim>::surface_elements(const double spacing,
                                 const dealii::Point<dim> &,
                                 const dealii::Point<dim> &) const
  {
    if (dim == 3)
      return surface_elements_3d(spacing);
    std::vector<SurfaceElement> elements;
    add_box_edges(spacing, elements);
    add_hole_arcs(spacing, elements);
    return elements;
  }


  template <int dim>
  void
  BoxBody<dim>::add_box_edges(const double spacing, std::vector<SurfaceElement> &elements) const
  {
    using P = dealii::Point<dim>;
    using T = dealii::Tensor<1, dim>;

    // Box edges, split where hole circles cross them.
    for (unsigned int box = 0; box < boxes.size(); ++box)
      {
        const auto &[lower, upper] = boxes[box];
        const P corners[4]         = {P(lower[0], lower[1]),
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
                    if (on_boundary(c, n) && !on_earlier_box_face(box, c, n))
                      elements.push_back(this->element(c, (length / m) * n));
                  }
              }
          }
      }
  }


  template <int dim>
  void
  BoxBody<dim>::add_hole_arcs(const double spacing, std::vector<SurfaceElement> &elements) const
  {
    using P = dealii::Point<dim>;
    using T = dealii::Tensor<1, dim>;

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
                  elements.push_back(this->element(c, normal_area));
              }
          }
      }
  }


  template class BoxBody<2>;
  template class BoxBody<3>;
} // namespace GelMPM

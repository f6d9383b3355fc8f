// The boundary of a 3D box body cut into surface elements: box faces, ball and cylinder holes.

#include <gelmpm/scene/box_body.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

namespace GelMPM
{
  namespace
  {
    // The two-point Gauss rule on [0, 1].
    const double gauss_nodes[2] = {0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)};

    // Distance from p to the surface of the box [lower, upper].
    template <int dim>
    double
    distance_to_box_surface(const dealii::Point<dim> &p,
                            const dealii::Point<dim> &lower,
                            const dealii::Point<dim> &upper)
    {
      double outside = 0., inside = -std::numeric_limits<double>::max();
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double excess = std::max(lower[d] - p[d], p[d] - upper[d]);
          inside              = std::max(inside, excess);
          outside += std::pow(std::max(excess, 0.), 2);
        }
      return inside <= 0. ? -inside : std::sqrt(outside);
    }
  } // namespace


  template <int dim>
  bool
  BoxBody<dim>::near_cut(const dealii::Point<dim> &p,
                         const double              radius,
                         const int                 own_hole,
                         const bool                boxes_too) const
  {
    if (boxes_too)
      for (const auto &[lower, upper] : boxes)
        if (distance_to_box_surface(p, lower, upper) <= radius)
          return true;
    for (unsigned int h = 0; h < holes.size(); ++h)
      if (static_cast<int>(h) != own_hole &&
          std::abs(p.distance(holes[h].first) - holes[h].second) <= radius)
        return true;
    for (unsigned int h = 0; h < cylinders.size(); ++h)
      if (static_cast<int>(h + holes.size()) != own_hole &&
          std::abs(cylinders[h].distance_to_axis(p) - cylinders[h].radius) <= radius)
        return true;
    return false;
  }


  template <int dim>
  void
  BoxBody<dim>::add_patch(std::vector<SurfaceElement> &elements,
                          const PatchMap              &map,
                          const std::array<double, 4> &range,
                          const int                    own_hole,
                          const bool                   boxes_cut) const
  {
    const auto [s0, s1, t0, t1] = range;
    // Whether another part of the boundary crosses the patch: then it is resolved by k x k
    // sub-patches, each kept if its centre lies on the boundary.
    dealii::Point<dim>     mid, corner;
    dealii::Tensor<1, dim> density;
    map(0.5 * (s0 + s1), 0.5 * (t0 + t1), mid, density);
    double reach = 0.;
    for (const double s : {s0, s1})
      for (const double t : {t0, t1})
        {
          map(s, t, corner, density);
          reach = std::max(reach, mid.distance(corner));
        }
    const unsigned int k = near_cut(mid, 1.5 * reach, own_hole, boxes_cut) ? 8 : 1;

    dealii::Tensor<1, dim>          normal_area;
    double                          weight = 0., s_mean = 0., t_mean = 0.;
    std::vector<dealii::Point<dim>> kept;
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < k; ++j)
        {
          const double           sa = s0 + (s1 - s0) * i / k, sb = s0 + (s1 - s0) * (i + 1) / k;
          const double           ta = t0 + (t1 - t0) * j / k, tb = t0 + (t1 - t0) * (j + 1) / k;
          dealii::Point<dim>     x;
          dealii::Tensor<1, dim> sub_normal_area;
          for (const double gs : gauss_nodes)
            for (const double gt : gauss_nodes)
              {
                map(sa + gs * (sb - sa), ta + gt * (tb - ta), x, density);
                sub_normal_area += 0.25 * (sb - sa) * (tb - ta) * density;
              }
          map(0.5 * (sa + sb), 0.5 * (ta + tb), x, density);
          if (!(density.norm() > 0.) || !on_boundary(x, density / density.norm()))
            continue;
          const double w = sub_normal_area.norm();
          normal_area += sub_normal_area;
          weight += w;
          s_mean += w * 0.5 * (sa + sb);
          t_mean += w * 0.5 * (ta + tb);
          kept.push_back(x);
        }
    if (kept.empty() || !(normal_area.norm() > 0.))
      return;
    // The point of the patch at the mean parameter of what is kept; if a cut leaves that outside
    // the boundary, the kept sub-patch centre nearest to it.
    dealii::Point<dim> centre;
    map(s_mean / weight, t_mean / weight, centre, density);
    if (k > 1 && !on_boundary(centre, density / density.norm()))
      centre = *std::min_element(kept.begin(), kept.end(), [&](const auto &a, const auto &b) {
        return a.distance(centre) < b.distance(centre);
      });
    elements.push_back(this->element(centre, normal_area));
  }


  template <int dim>
  std::vector<typename BoxBody<dim>::SurfaceElement>
  BoxBody<dim>::surface_elements_3d(const double spacing) const
  {
    std::vector<SurfaceElement> elements;
    const auto                  pieces = [&](const double a, const double b) {
      return std::max(1u, static_cast<unsigned int>(std::ceil((b - a) / spacing - 1e-9)));
    };

    // Box faces, cut along the edges of the other boxes' faces so that each rectangle lies
    // either wholly on the boundary or wholly off it (holes aside).
    for (unsigned int box = 0; box < boxes.size(); ++box)
      for (unsigned int a = 0; a < dim; ++a)
        for (const int side : {-1, 1})
          {
            const auto &[lower, upper]           = boxes[box];
            const unsigned int                 b = (a + 1) % dim, c = (a + 2) % dim;
            const double                       plane = side > 0 ? upper[a] : lower[a];
            std::array<std::vector<double>, 2> breaks;
            for (unsigned int q = 0; q < 2; ++q)
              {
                const unsigned int axis = q == 0 ? b : c;
                breaks[q]               = {lower[axis], upper[axis]};
                for (const auto &[other_lower, other_upper] : boxes)
                  for (const double x : {other_lower[axis], other_upper[axis]})
                    if (x > lower[axis] && x < upper[axis])
                      breaks[q].push_back(x);
                std::sort(breaks[q].begin(), breaks[q].end());
                breaks[q].erase(std::unique(breaks[q].begin(), breaks[q].end()), breaks[q].end());
              }
            for (unsigned int ib = 0; ib + 1 < breaks[0].size(); ++ib)
              for (unsigned int ic = 0; ic + 1 < breaks[1].size(); ++ic)
                {
                  const double                 b0 = breaks[0][ib], b1 = breaks[0][ib + 1];
                  const double                 c0 = breaks[1][ic], c1 = breaks[1][ic + 1];
                  const unsigned int           mb = pieces(b0, b1), mc = pieces(c0, c1);
                  const double                 db = (b1 - b0) / mb, dc = (c1 - c0) / mc;
                  const dealii::Tensor<1, dim> normal =
                    double(side) * dealii::Point<dim>::unit_vector(a);
                  const typename BoxBody<dim>::PatchMap map = [&](const double            s,
                                                                  const double            t,
                                                                  dealii::Point<dim>     &x,
                                                                  dealii::Tensor<1, dim> &density) {
                    x[a]    = plane;
                    x[b]    = s;
                    x[c]    = t;
                    density = normal;
                  };
                  dealii::Point<dim> mid;
                  mid[a] = plane;
                  mid[b] = 0.5 * (b0 + b1);
                  mid[c] = 0.5 * (c0 + c1);
                  if (on_earlier_box_face(box, mid, normal))
                    continue;
                  for (unsigned int i = 0; i < mb; ++i)
                    for (unsigned int j = 0; j < mc; ++j)
                      add_patch(elements,
                                map,
                                {{b0 + i * db, b0 + (i + 1) * db, c0 + j * dc, c0 + (j + 1) * dc}},
                                -1,
                                false);
                }
          }

    // Ball holes: the six faces of a cube projected onto the sphere (equal angles), the body's
    // outward normal pointing into the hole.
    for (unsigned int h = 0; h < holes.size(); ++h)
      {
        const auto &[centre, radius] = holes[h];
        const unsigned int n         = pieces(0., 0.5 * M_PI * radius);
        for (unsigned int a = 0; a < dim; ++a)
          for (const int side : {-1, 1})
            {
              const unsigned int                    b = (a + 1) % dim, c = (a + 2) % dim;
              const typename BoxBody<dim>::PatchMap map = [&](const double            alpha,
                                                              const double            beta,
                                                              dealii::Point<dim>     &x,
                                                              dealii::Tensor<1, dim> &density) {
                const double           u = std::tan(alpha), v = std::tan(beta);
                dealii::Tensor<1, dim> w = double(side) * dealii::Point<dim>::unit_vector(a);
                w[b]                     = u;
                w[c]                     = v;
                const double r2          = 1. + u * u + v * v;
                x                        = centre + (radius / std::sqrt(r2)) * w;
                // d(area) = R^2 (1 + u^2)(1 + v^2) / (1 + u^2 + v^2)^(3/2) d(alpha) d(beta).
                density = -(radius * radius * (1. + u * u) * (1. + v * v) / (r2 * r2)) * w;
              };
              const double d = 0.5 * M_PI / n;
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  add_patch(elements,
                            map,
                            {{-0.25 * M_PI + i * d,
                              -0.25 * M_PI + (i + 1) * d,
                              -0.25 * M_PI + j * d,
                              -0.25 * M_PI + (j + 1) * d}},
                            h,
                            true);
            }
      }

    // Cylinder holes, over the stretch of their axis that the boxes span.
    for (unsigned int h = 0; h < cylinders.size(); ++h)
      {
        const Cylinder &cylinder = cylinders[h];
        double          s_min = std::numeric_limits<double>::max(), s_max = -s_min;
        for (const auto &[lower, upper] : boxes)
          for (unsigned int corner = 0; corner < (1u << dim); ++corner)
            {
              dealii::Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = (corner >> d) & 1 ? upper[d] : lower[d];
              const double s = (x - cylinder.centre) * cylinder.axis;
              s_min          = std::min(s_min, s);
              s_max          = std::max(s_max, s);
            }
        const auto [e1, e2]                       = cylinder.frame();
        const typename BoxBody<dim>::PatchMap map = [&](const double            theta,
                                                        const double            s,
                                                        dealii::Point<dim>     &x,
                                                        dealii::Tensor<1, dim> &density) {
          const dealii::Tensor<1, dim> radial = std::cos(theta) * e1 + std::sin(theta) * e2;
          x       = cylinder.centre + s * cylinder.axis + cylinder.radius * radial;
          density = -cylinder.radius * radial;
        };
        const unsigned int n_theta = pieces(0., 2. * M_PI * cylinder.radius);
        const unsigned int n_s     = pieces(s_min, s_max);
        const double       ds = (s_max - s_min) / n_s, dtheta = 2. * M_PI / n_theta;
        for (unsigned int i = 0; i < n_theta; ++i)
          for (unsigned int j = 0; j < n_s; ++j)
            add_patch(elements,
                      map,
                      {{i * dtheta, (i + 1) * dtheta, s_min + j * ds, s_min + (j + 1) * ds}},
                      holes.size() + h,
                      true);
      }
    return elements;
  }


  // The members of this file; the class is instantiated in box_body.cc.
#define GELMPM_INSTANTIATE(dim)                                                                \
  template bool BoxBody<dim>::near_cut(const dealii::Point<dim> &, double, int, bool) const;   \
  template void BoxBody<dim>::add_patch(std::vector<SurfaceElement> &,                         \
                                        const PatchMap &,                                      \
                                        const std::array<double, 4> &,                         \
                                        int,                                                   \
                                        bool) const;                                           \
  template std::vector<BoxBody<dim>::SurfaceElement> BoxBody<dim>::surface_elements_3d(double) \
    const;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

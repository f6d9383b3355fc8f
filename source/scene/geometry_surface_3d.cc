// The boundary of a 3D body cut into surface elements: box faces, ball and cylinder holes, and
// the zero surface of a level set. (The 2D boundary and the mesh faces are in geometry.cc.)

#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/geometry.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    // The two-point Gauss rule on [0, 1].
    const double gauss_nodes[2] = {0.5 - 0.5 / std::sqrt(3.), 0.5 + 0.5 / std::sqrt(3.)};

    template <int dim>
    dealii::Tensor<1, dim>
    unit_vector(const unsigned int d)
    {
      dealii::Tensor<1, dim> e;
      e[d] = 1.;
      return e;
    }

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

    template <int dim>
    std::string
    text(const dealii::Point<dim> &p)
    {
      std::ostringstream out;
      out << "(" << p << ")";
      return out.str();
    }
  } // namespace


  template <int dim>
  bool
  Geometry<dim>::near_cut(const dealii::Point<dim> &p,
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
  Geometry<dim>::add_patch(std::vector<SurfaceElement> &elements,
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
    elements.push_back({centre, normal_area, dealii::numbers::invalid_boundary_id, {}});
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::box_surface_elements_3d(const double spacing) const
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
                  const dealii::Tensor<1, dim> normal = double(side) * unit_vector<dim>(a);
                  const typename Geometry<dim>::PatchMap map =
                    [&](const double            s,
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
              const unsigned int                     b = (a + 1) % dim, c = (a + 2) % dim;
              const typename Geometry<dim>::PatchMap map = [&](const double            alpha,
                                                               const double            beta,
                                                               dealii::Point<dim>     &x,
                                                               dealii::Tensor<1, dim> &density) {
                const double           u = std::tan(alpha), v = std::tan(beta);
                dealii::Tensor<1, dim> w = double(side) * unit_vector<dim>(a);
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
        const auto [e1, e2]                        = cylinder.frame();
        const typename Geometry<dim>::PatchMap map = [&](const double            theta,
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


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::level_set_surface_elements_3d(const double              spacing,
                                               const dealii::Point<dim> &lower,
                                               const dealii::Point<dim> &upper) const
  {
    // Sampling cubes of edge at most the spacing. The zero surface inside a cube C carries
    // int N dA = -sum over the faces f of C of n_f |f inside the body| (the divergence theorem on
    // the part of C inside the body), so each element gets the exact integral of the normal over
    // its piece of the surface as far as the inside areas of the faces are exact, and a face
    // shared by two cubes enters both with opposite signs: the sum over a closed surface
    // vanishes to round-off whatever the accuracy of the face areas.
    std::array<unsigned int, dim> n;
    std::array<double, dim>       step;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[d] = std::max(2u, static_cast<unsigned int>(std::ceil((upper[d] - lower[d]) / spacing)));
        step[d] = (upper[d] - lower[d]) / n[d];
      }
    using Index       = std::array<unsigned int, dim>;
    const auto sample = [&](const Index &i) {
      dealii::Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = lower[d] + i[d] * step[d];
      return x;
    };
    const auto flat = [&](const Index &i) {
      std::size_t k = 0;
      for (int d = dim - 1; d >= 0; --d)
        k = k * (n[d] + 1) + i[d];
      return k;
    };
    std::size_t n_samples = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_samples *= n[d] + 1;
    std::vector<double> values(n_samples);
    for (std::size_t k = 0; k < n_samples; ++k)
      {
        Index       i;
        std::size_t rest = k;
        bool        edge = false;
        for (unsigned int d = 0; d < dim; ++d)
          {
            i[d] = rest % (n[d] + 1);
            rest /= n[d] + 1;
            edge |= i[d] == 0 || i[d] == n[d];
          }
        values[k] = level_set(sample(i));
        require(!(values[k] < 0.) || !edge,
                "Geometry/Level set",
                "is negative on the edge of the background grid, e.g. at " + text(sample(i)) +
                  ": the body reaches outside the grid",
                "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the body");
      }

    // The area of the face of the sampling grid at sample i normal to axis a where phi < 0:
    // strips along the second in-plane axis, on each the inside length from the sign changes
    // of phi (bisection).
    const auto inside_area = [&](const Index &i, const unsigned int a) {
      const unsigned int       b = (a + 1) % dim, c = (a + 2) % dim;
      const unsigned int       strips = 8, samples = 8;
      const dealii::Point<dim> origin = sample(i);
      double                   area   = 0.;
      for (unsigned int q = 0; q < strips; ++q)
        {
          dealii::Point<dim> x = origin;
          x[c] += (q + 0.5) * step[c] / strips;
          const auto at = [&](const double s) {
            dealii::Point<dim> y = x;
            y[b] += s * step[b];
            return y;
          };
          double length = 0., s_prev = 0., v_prev = level_set(at(0.));
          for (unsigned int r = 1; r <= samples; ++r)
            {
              const double s = double(r) / samples, v = level_set(at(s));
              const bool   in_prev = v_prev < 0., in = v < 0.;
              if (in_prev && in)
                length += s - s_prev;
              else if (in_prev != in)
                {
                  double lo = s_prev, hi = s; // in_prev at lo
                  for (unsigned int it = 0; it < 40; ++it)
                    {
                      const double m                                 = 0.5 * (lo + hi);
                      ((level_set(at(m)) < 0.) == in_prev ? lo : hi) = m;
                    }
                  length += in_prev ? 0.5 * (lo + hi) - s_prev : s - 0.5 * (lo + hi);
                }
              s_prev = s;
              v_prev = v;
            }
          area += length * step[b] * step[c] / strips;
        }
      return area;
    };

    std::vector<SurfaceElement> elements;
    const double                max_shift = 2. * *std::max_element(step.begin(), step.end());
    Index                       cube;
    std::size_t                 n_cubes = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_cubes *= n[d];
    for (std::size_t k = 0; k < n_cubes; ++k)
      {
        std::size_t rest = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            cube[d] = rest % n[d];
            rest /= n[d];
          }
        // Corner values, corner v at cube + bits of v.
        std::array<double, 1u << dim> v;
        unsigned int                  n_in = 0;
        for (unsigned int corner = 0; corner < v.size(); ++corner)
          {
            Index i = cube;
            for (unsigned int d = 0; d < dim; ++d)
              i[d] += (corner >> d) & 1;
            v[corner] = values[flat(i)];
            n_in += v[corner] < 0.;
          }
        if (n_in == 0 || n_in == v.size())
          continue;

        dealii::Tensor<1, dim> normal_area;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int side = 0; side < 2; ++side)
            {
              unsigned int face_in = 0;
              for (unsigned int corner = 0; corner < v.size(); ++corner)
                face_in += ((corner >> a) & 1) == side && v[corner] < 0.;
              Index i = cube;
              i[a] += side;
              double face_area = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                if (d != a)
                  face_area *= step[d];
              const double area = face_in == 0 ? 0. : face_in == 4 ? face_area : inside_area(i, a);
              normal_area -= (side ? area : -area) * unit_vector<dim>(a);
            }
        if (!(normal_area.norm() > 0.))
          continue;

        // Where the surface crosses the cube's edges (linear interpolation), averaged, then
        // moved onto the zero set.
        dealii::Point<dim>              mean;
        unsigned int                    n_crossings = 0;
        std::vector<dealii::Point<dim>> crossings;
        for (unsigned int corner = 0; corner < v.size(); ++corner)
          for (unsigned int d = 0; d < dim; ++d)
            if (!((corner >> d) & 1))
              {
                const unsigned int other = corner | (1u << d);
                if ((v[corner] < 0.) == (v[other] < 0.))
                  continue;
                Index i = cube;
                for (unsigned int e = 0; e < dim; ++e)
                  i[e] += (corner >> e) & 1;
                dealii::Point<dim> x = sample(i);
                x[d] += v[corner] / (v[corner] - v[other]) * step[d];
                mean += x;
                crossings.push_back(x);
                ++n_crossings;
              }
        mean /= n_crossings;
        if (!split_at_edge(crossings, normal_area, max_shift, elements))
          elements.push_back({project_onto_zero_set(mean, max_shift),
                              normal_area,
                              dealii::numbers::invalid_boundary_id,
                              {}});
      }
    return elements;
  }


  template <int dim>
  bool
  Geometry<dim>::split_at_edge(const std::vector<dealii::Point<dim>> &crossings,
                               const dealii::Tensor<1, dim>          &normal_area,
                               const double                           max_shift,
                               std::vector<SurfaceElement>           &elements) const
  {
    // A cube through which an edge of the body runs (where two smooth pieces of the zero set
    // meet, e.g. a plane of symmetry and a sphere) holds surface of two or three faces; one
    // element with their summed normal would have a normal of neither, and a selector such as
    // 'nx < -0.99' would miss it. Group the crossings by the normal of the zero set there; with
    // two or three groups, split the cube's integral of the normal among their normals (least
    // squares, exact when each face is plane within the cube) and give each face its element.
    const double                        cos_same = std::cos(20. * M_PI / 180.);
    const double                        delta    = 1e-4 * max_shift;
    std::vector<dealii::Tensor<1, dim>> group_normal;
    std::vector<dealii::Point<dim>>     group_mean;
    std::vector<unsigned int>           group_size;
    for (const auto &x : crossings)
      {
        dealii::Tensor<1, dim> g = level_set_gradient(x, delta);
        if (!(g.norm() > 0.))
          return false;
        g /= g.norm();
        unsigned int k = 0;
        while (k < group_normal.size() && g * group_normal[k] / group_normal[k].norm() < cos_same)
          ++k;
        if (k == group_normal.size())
          {
            group_normal.emplace_back();
            group_mean.emplace_back();
            group_size.push_back(0);
          }
        group_normal[k] += g;
        group_mean[k] += x;
        ++group_size[k];
      }
    if (group_normal.size() < 2 || group_normal.size() > dim)
      return false;
    // How far each group's normals spread (0 for a plane face): 1 - |mean of the unit normals|
    // at its crossings and at its point on the zero set (two samples at least, so that a curved
    // face with one crossing in the cube shows its curvature too).
    std::vector<double>             spread(group_normal.size());
    std::vector<dealii::Point<dim>> group_point(group_normal.size());
    for (unsigned int k = 0; k < group_normal.size(); ++k)
      {
        group_mean[k] /= group_size[k];
        group_point[k]             = project_onto_zero_set(group_mean[k], max_shift);
        dealii::Tensor<1, dim> g_c = level_set_gradient(group_point[k], delta);
        dealii::Tensor<1, dim> sum = group_normal[k];
        if (g_c.norm() > 0.)
          sum += g_c / g_c.norm();
        spread[k] = 1. - sum.norm() / (group_size[k] + 1);
        group_normal[k] /= group_normal[k].norm();
        // The normal at the group's own point on the zero set: exact for a plane face even when
        // a crossing near the edge mixed the other face's gradient into the group's mean.
        if (g_c.norm() > 0. && g_c * group_normal[k] / g_c.norm() >= cos_same)
          group_normal[k] = g_c / g_c.norm();
      }
    // The groups to split among: all, or, if that fails (a crossing on the edge itself can form
    // a group of its own with a normal of neither face), the two largest.
    std::vector<unsigned int> order(group_normal.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return group_size[a] > group_size[b];
    });
    for (unsigned int n = order.size(); n >= 2; --n)
      {
        // normal_area = sum_k a_k n_k in the least-squares sense: (N^T N) a = N^T normal_area.
        dealii::FullMatrix<double> NtN(n, n), inverse(n, n);
        dealii::Vector<double>     rhs(n), a(n);
        for (unsigned int k = 0; k < n; ++k)
          {
            rhs(k) = group_normal[order[k]] * normal_area;
            for (unsigned int l = 0; l < n; ++l)
              NtN(k, l) = group_normal[order[k]] * group_normal[order[l]];
          }
        try
          {
            inverse.invert(NtN);
          }
        catch (...)
          {
            continue;
          }
        inverse.vmult(a, rhs);
        dealii::Tensor<1, dim> rest     = normal_area;
        bool                   positive = true;
        for (unsigned int k = 0; k < n; ++k)
          {
            positive &= a(k) > 0.;
            rest -= a(k) * group_normal[order[k]];
          }
        // The rest (mostly the curvature of a curved face within the cube: its normal turns
        // across the cube) goes to the group whose normals spread most, so that plane faces keep
        // their exact normals and the sum over a closed surface stays zero to round-off; it must
        // be a correction of that group's element, not most of it.
        unsigned int curved = 0;
        for (unsigned int k = 1; k < n; ++k)
          if (spread[order[k]] > spread[order[curved]])
            curved = k;
        if (!positive || rest.norm() > 0.5 * a(curved))
          continue;
        for (unsigned int k = 0; k < n; ++k)
          elements.push_back({group_point[order[k]],
                              a(k) * group_normal[order[k]] + (k == curved ? rest : 0. * rest),
                              dealii::numbers::invalid_boundary_id,
                              {}});
        return true;
      }
    return false;
  }


  // The members of this file; the class is instantiated in geometry.cc.
#define GELMPM_INSTANTIATE(dim)                                                                 \
  template bool Geometry<dim>::near_cut(const dealii::Point<dim> &, double, int, bool) const;   \
  template void Geometry<dim>::add_patch(std::vector<SurfaceElement> &,                         \
                                         const PatchMap &,                                      \
                                         const std::array<double, 4> &,                         \
                                         int,                                                   \
                                         bool) const;                                           \
  template std::vector<Geometry<dim>::SurfaceElement> Geometry<dim>::box_surface_elements_3d(   \
    double) const;                                                                              \
  template std::vector<Geometry<dim>::SurfaceElement>                                           \
                Geometry<dim>::level_set_surface_elements_3d(double,                            \
                                               const dealii::Point<dim> &,        \
                                               const dealii::Point<dim> &) const; \
  template bool Geometry<dim>::split_at_edge(const std::vector<dealii::Point<dim>> &,           \
                                             const dealii::Tensor<1, dim> &,                    \
                                             double,                                            \
                                             std::vector<SurfaceElement> &) const;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

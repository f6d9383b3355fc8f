// The zero surface of a 3D level-set body cut into surface elements. (The 2D contour is in
// level_set_body.cc.)

#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/level_set_body.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace GelMPM
{
  template <int dim>
  std::vector<typename LevelSetBody<dim>::SurfaceElement>
  LevelSetBody<dim>::surface_elements_3d(const double              spacing,
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
                "is negative on the edge of the background grid, e.g. at " +
                  format_point(sample(i)) + ": the body reaches outside the grid",
                "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the body");
      }

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
              const double area = face_in == 0   ? 0.
                                  : face_in == 4 ? face_area
                                                 : face_inside_area(sample(i), a, step);
              normal_area -= (side ? area : -area) * dealii::Point<dim>::unit_vector(a);
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
          elements.push_back(this->element(project_onto_zero_set(mean, max_shift), normal_area));
      }
    return elements;
  }


  template <int dim>
  double
  LevelSetBody<dim>::face_inside_area(const dealii::Point<dim>      &origin,
                                      const unsigned int             a,
                                      const std::array<double, dim> &step) const
  {
    // Strips along the second in-plane axis, on each the inside length from the sign changes of
    // phi (bisection).
    const unsigned int b = (a + 1) % dim, c = (a + 2) % dim;
    const unsigned int strips = 8, samples = 8;
    double             area = 0.;
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
  }


  template <int dim>
  bool
  LevelSetBody<dim>::split_at_edge(const std::vector<dealii::Point<dim>> &crossings,
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
        dealii::Tensor<1, dim> g = gradient(x, delta);
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
        dealii::Tensor<1, dim> g_c = gradient(group_point[k], delta);
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
          elements.push_back(
            this->element(group_point[order[k]],
                          a(k) * group_normal[order[k]] + (k == curved ? rest : 0. * rest)));
        return true;
      }
    return false;
  }


  // The members of this file; the class is instantiated in level_set_body.cc.
#define GELMPM_INSTANTIATE(dim)                                                                   \
  template std::vector<LevelSetBody<dim>::SurfaceElement> LevelSetBody<dim>::surface_elements_3d( \
    double,                                                                                       \
    const dealii::Point<dim> &,                                                                   \
    const dealii::Point<dim> &) const;                                                            \
  template double LevelSetBody<dim>::face_inside_area(const dealii::Point<dim> &,                 \
                                                      unsigned int,                               \
                                                      const std::array<double, dim> &) const;     \
  template bool   LevelSetBody<dim>::split_at_edge(const std::vector<dealii::Point<dim>> &,       \
                                                 const dealii::Tensor<1, dim> &,                \
                                                 double,                                        \
                                                 std::vector<SurfaceElement> &) const;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

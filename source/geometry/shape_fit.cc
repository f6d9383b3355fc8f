#include <gelmpm/geometry/shape_fit.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace GelMPM
{
  namespace ShapeFit
  {
    namespace
    {
      template <int n>
      using Matrix = std::array<std::array<double, n>, n>;

      /**
       * The eigenvector of the symmetric @p m of its smallest eigenvalue, by cyclic Jacobi
       * rotations (a few sweeps for these 3 x 3 and 4 x 4 matrices; no LAPACK kernel, so the
       * result does not depend on the BLAS).
       */
      template <int n>
      std::array<double, n>
      smallest_eigenvector(Matrix<n> m)
      {
        Matrix<n> v{};
        for (unsigned int i = 0; i < n; ++i)
          v[i][i] = 1.;
        for (unsigned int sweep = 0; sweep < 50; ++sweep)
          {
            double off = 0., scale = 0.;
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                (i == j ? scale : off) += m[i][j] * m[i][j];
            if (off <= 1e-30 * scale)
              break;
            for (unsigned int p = 0; p < n; ++p)
              for (unsigned int q = p + 1; q < n; ++q)
                {
                  if (m[p][q] == 0.)
                    continue;
                  const double theta = (m[q][q] - m[p][p]) / (2. * m[p][q]);
                  const double t =
                    (theta >= 0. ? 1. : -1.) / (std::abs(theta) + std::sqrt(theta * theta + 1.));
                  const double cs = 1. / std::sqrt(t * t + 1.), sn = t * cs;
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double mkp = m[k][p], mkq = m[k][q];
                      m[k][p] = cs * mkp - sn * mkq;
                      m[k][q] = sn * mkp + cs * mkq;
                    }
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double mpk = m[p][k], mqk = m[q][k];
                      m[p][k] = cs * mpk - sn * mqk;
                      m[q][k] = sn * mpk + cs * mqk;
                    }
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double vkp = v[k][p], vkq = v[k][q];
                      v[k][p] = cs * vkp - sn * vkq;
                      v[k][q] = sn * vkp + cs * vkq;
                    }
                }
          }
        unsigned int smallest = 0;
        for (unsigned int i = 1; i < n; ++i)
          if (m[i][i] < m[smallest][smallest])
            smallest = i;
        std::array<double, n> vector;
        for (unsigned int k = 0; k < n; ++k)
          vector[k] = v[k][smallest];
        return vector;
      }


      template <int dim>
      dealii::Point<dim>
      mean_of(const std::vector<dealii::Point<dim>> &points)
      {
        dealii::Tensor<1, dim> sum;
        for (const auto &x : points)
          sum += x;
        return dealii::Point<dim>(sum /
                                  static_cast<double>(std::max<std::size_t>(points.size(), 1)));
      }


      /** The arc lengths of @p curve's points from its first, and its length (closed: back to
       * the first point). */
      std::pair<std::vector<double>, double>
      arc_lengths(const std::vector<dealii::Point<2>> &curve, const bool closed)
      {
        std::vector<double> s(curve.size(), 0.);
        for (unsigned int i = 1; i < curve.size(); ++i)
          s[i] = s[i - 1] + curve[i].distance(curve[i - 1]);
        const double length =
          s.empty() ? 0. : s.back() + (closed ? curve.back().distance(curve.front()) : 0.);
        return {s, length};
      }


      /** @p values at @p s (increasing, from 0) linearly interpolated at n places equally spaced
       * over the length @p length: j L/n for a closed curve (periodic), j L/(n - 1) for an open
       * one. */
      std::vector<double>
      resampled(const std::vector<double> &s,
                const std::vector<double> &values,
                const double               length,
                const bool                 closed)
      {
        const unsigned int  n = s.size();
        std::vector<double> out(n);
        const double        step = length / (closed ? n : n - 1);
        unsigned int        i    = 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            const double place = std::min(j * step, length);
            while (i + 1 < n && s[i + 1] <= place)
              ++i;
            // Between point i and the next one, or the first one again across the closing segment.
            const double s_next = i + 1 < n ? s[i + 1] : length;
            const double v_next = i + 1 < n ? values[i + 1] : (closed ? values[0] : values[i]);
            const double w      = s_next > s[i] ? (place - s[i]) / (s_next - s[i]) : 0.;
            out[j]              = (1. - w) * values[i] + w * v_next;
          }
        return out;
      }


      /** The dominant wavelength of @p samples over the period @p period (see undulation()). */
      double
      dominant_wavelength(std::vector<double> samples, const double period, const bool closed)
      {
        const unsigned int n    = samples.size();
        double             mean = 0.;
        for (const double v : samples)
          mean += v / n;
        for (unsigned int j = 0; j < n; ++j)
          samples[j] =
            (samples[j] - mean) * (closed ? 1. : std::pow(std::sin(M_PI * j / (n - 1.)), 2));
        // A direct transform (n is a piece's point count, some hundreds), its roots of unity
        // tabulated once.
        std::vector<std::complex<double>> roots(n);
        for (unsigned int m = 0; m < n; ++m)
          roots[m] = std::polar(1., -2. * M_PI * m / n);
        std::vector<double> magnitude(n / 2 + 1, 0.);
        for (unsigned int k = 1; k < magnitude.size(); ++k)
          {
            std::complex<double> sum = 0.;
            for (std::size_t j = 0; j < n; ++j)
              sum += samples[j] * roots[(k * j) % n];
            magnitude[k] = std::abs(sum);
          }
        const unsigned int first = closed ? 1 : 2;
        if (magnitude.size() <= first + 1)
          return 0.;
        unsigned int peak = first;
        for (unsigned int k = first; k + 1 < magnitude.size(); ++k)
          if (magnitude[k] > magnitude[peak])
            peak = k;
        if (magnitude[peak] == 0.)
          return 0.;
        const double below = magnitude[peak - 1], at = magnitude[peak], above = magnitude[peak + 1];
        const double curvature = below - 2. * at + above;
        const double shift =
          curvature < 0. ? std::clamp(0.5 * (below - above) / curvature, -0.5, 0.5) : 0.;
        return period / (peak + shift);
      }


      double
      cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }
    } // namespace


    template <int dim>
    double
    Hypersphere<dim>::distance(const dealii::Point<dim> &x) const
    {
      const dealii::Tensor<1, dim> r = x - origin;
      const double                 P = a * r.norm_square() + b * r + c;
      return 2. * P / (1. + std::sqrt(std::max(1. + 4. * a * P, 0.)));
    }


    template <int dim>
    dealii::Tensor<1, dim>
    Hypersphere<dim>::gradient(const dealii::Point<dim> &x) const
    {
      return 2. * a * (x - origin) + b;
    }


    template <int dim>
    void
    Hypersphere<dim>::orient(const std::vector<dealii::Point<dim>>     &points,
                             const std::vector<dealii::Tensor<1, dim>> &normals)
    {
      double along = 0.;
      for (unsigned int i = 0; i < points.size(); ++i)
        along += normals[i] * gradient(points[i]);
      if (along < 0.)
        {
          a = -a;
          b = -b;
          c = -c;
        }
    }


    template <int dim>
    Hypersphere<dim>
    fit_sphere(const std::vector<dealii::Point<dim>> &points)
    {
      AssertThrow(points.size() >= dim + 1,
                  dealii::ExcMessage("fit_sphere() needs at least dim + 1 points"));
      // Centred on the mean and scaled by the RMS radius about it, so that the matrix is of
      // order one whatever the scene's length unit and position.
      Hypersphere<dim> shape;
      shape.origin   = mean_of(points);
      double radius2 = 0.;
      for (const auto &x : points)
        radius2 += (x - shape.origin).norm_square() / points.size();
      AssertThrow(radius2 > 0., dealii::ExcMessage("fit_sphere(): the points coincide"));
      const double scale = std::sqrt(radius2);

      // With z = |X|^2 (X scaled and centred, mean z = 1), c = -a mean z eliminates c; the rows
      // (z - 1, X) scaled by the constraint's diag(4 mean z, 1, ..., 1)^(-1/2).
      constexpr int         n = dim + 1;
      Matrix<n>             m{};
      std::array<double, n> weight;
      weight[0] = 0.5;
      for (unsigned int d = 0; d < dim; ++d)
        weight[d + 1] = 1.;
      for (const auto &x : points)
        {
          const dealii::Tensor<1, dim> X = (x - shape.origin) / scale;
          std::array<double, n>        row;
          row[0] = weight[0] * (X.norm_square() - 1.);
          for (unsigned int d = 0; d < dim; ++d)
            row[d + 1] = X[d];
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              m[i][j] += row[i] * row[j] / points.size();
        }
      const auto v = smallest_eigenvector<n>(m);
      // Back to the unscaled P(x) = P(X) scale: a = a' / scale, b = b', c = c' scale.
      const double a_scaled = weight[0] * v[0];
      double       norm2    = 4. * a_scaled * a_scaled; // |b'|^2 - 4 a' c' with c' = -a'
      for (unsigned int d = 0; d < dim; ++d)
        norm2 += v[d + 1] * v[d + 1];
      const double norm = std::sqrt(norm2);
      shape.a           = a_scaled / norm / scale;
      for (unsigned int d = 0; d < dim; ++d)
        shape.b[d] = v[d + 1] / norm;
      shape.c = -a_scaled / norm * scale;
      return shape;
    }


    template <int dim>
    Hypersphere<dim>
    fit_plane(const std::vector<dealii::Point<dim>> &points)
    {
      AssertThrow(points.size() >= dim, dealii::ExcMessage("fit_plane() needs dim points"));
      Hypersphere<dim> shape;
      shape.origin = mean_of(points);
      Matrix<dim> m{};
      for (const auto &x : points)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            m[i][j] += (x - shape.origin)[i] * (x - shape.origin)[j];
      const auto v = smallest_eigenvector<dim>(m);
      for (unsigned int d = 0; d < dim; ++d)
        shape.b[d] = v[d];
      shape.b /= shape.b.norm();
      return shape;
    }


    template <int dim>
    double
    rms_distance(const Hypersphere<dim> &shape, const std::vector<dealii::Point<dim>> &points)
    {
      double sum = 0.;
      for (const auto &x : points)
        sum += std::pow(shape.distance(x), 2);
      return points.empty() ? 0. : std::sqrt(sum / points.size());
    }


    template <int dim>
    Hypersphere<dim>
    smooth_shape(const std::vector<dealii::Point<dim>> &points)
    {
      const auto sphere = fit_sphere(points);
      const auto plane  = fit_plane(points);
      return rms_distance(sphere, points) <= 0.5 * rms_distance(plane, points) ? sphere : plane;
    }


    double
    skewness(const std::vector<double> &values)
    {
      const unsigned int n    = values.size();
      double             mean = 0.;
      for (const double v : values)
        mean += v / n;
      double second = 0., third = 0.;
      for (const double v : values)
        {
          second += std::pow(v - mean, 2) / n;
          third += std::pow(v - mean, 3) / n;
        }
      return second > 0. ? third / std::pow(second, 1.5) : 0.;
    }


    Undulation
    undulation(const std::vector<dealii::Point<2>> &curve,
               const std::vector<double>           &deviations,
               const bool                           closed)
    {
      Undulation         result;
      const unsigned int n = deviations.size();
      AssertThrow(curve.size() == n,
                  dealii::ExcMessage("undulation(): one deviation per point of the curve"));
      if (n == 0)
        return result;
      const auto [lowest, highest] = std::minmax_element(deviations.begin(), deviations.end());
      result.amplitude             = 0.5 * (*highest - *lowest);
      double square                = 0.;
      for (const double d : deviations)
        square += d * d / n;
      result.rms      = std::sqrt(square);
      result.skewness = skewness(deviations);
      if (n < 8)
        return result;
      const auto [s, length] = arc_lengths(curve, closed);
      const double period    = closed ? length : length * n / (n - 1.);
      result.wavelength =
        dominant_wavelength(resampled(s, deviations, length, closed), period, closed);
      return result;
    }


    double
    dip_crest_curvature_ratio(const std::vector<dealii::Point<2>> &curve,
                              const bool                           closed,
                              const double                         shape_curvature)
    {
      const unsigned int n   = curve.size();
      double             dip = 0., crest = 0.;
      for (unsigned int i = closed ? 0 : 1; i < (closed ? n : n - 1) && n >= 3; ++i)
        {
          const auto &before = curve[(i + n - 1) % n], &here = curve[i],
                     &after = curve[(i + 1) % n];
          const auto   a = here - before, b = after - here, c = after - before;
          const double lengths = a.norm() * b.norm() * c.norm();
          if (lengths == 0.)
            continue;
          // Turning to the right, about the body on the right, is convex.
          const double k = -2. * cross(a, b) / lengths - shape_curvature;
          dip            = std::max(dip, -k);
          crest          = std::max(crest, k);
        }
      if (dip == 0.)
        return 0.;
      return crest > 0. ? dip / crest : 1e6;
    }


    template struct Hypersphere<2>;
    template struct Hypersphere<3>;
    template Hypersphere<2>
    fit_sphere(const std::vector<dealii::Point<2>> &);
    template Hypersphere<3>
    fit_sphere(const std::vector<dealii::Point<3>> &);
    template Hypersphere<2>
    fit_plane(const std::vector<dealii::Point<2>> &);
    template Hypersphere<3>
    fit_plane(const std::vector<dealii::Point<3>> &);
    template double
    rms_distance(const Hypersphere<2> &, const std::vector<dealii::Point<2>> &);
    template double
    rms_distance(const Hypersphere<3> &, const std::vector<dealii::Point<3>> &);
    template Hypersphere<2>
    smooth_shape(const std::vector<dealii::Point<2>> &);
    template Hypersphere<3>
    smooth_shape(const std::vector<dealii::Point<3>> &);
  } // namespace ShapeFit
} // namespace GelMPM

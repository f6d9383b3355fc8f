#include <gelmpm/bspline/bspline_basis_1d.h>
#include <gelmpm/core/round_off.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  BSplineBasis1D::BSplineBasis1D(const unsigned int degree,
                                 const double       x_min,
                                 const double       x_max,
                                 const unsigned int n_cells)
    : degree_(degree)
    , x_min_(x_min)
    , x_max_(x_max)
    , n_cells_(n_cells)
    , h((x_max - x_min) / n_cells)
  {
    if (degree < 1 || degree > max_degree)
      throw std::invalid_argument("B-spline degree must lie in 1..." + std::to_string(max_degree));
    if (!(x_max > x_min) || n_cells < 1)
      throw std::invalid_argument("B-spline basis needs x_max > x_min and at least one cell");

    // c_k = N^(k)(midpoint) h^k / k!, the Taylor coefficients in t = (x - midpoint)/h.
    const unsigned int  n = degree + 1;
    std::vector<double> derivatives(n * n);
    coefficients.resize(n_cells * n * n);
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      {
        evaluate_by_recursion(x_min + (cell + 0.5) * h, cell, degree, derivatives.data());
        double scale = 1.;
        for (unsigned int k = 0; k < n; ++k)
          {
            for (unsigned int a = 0; a < n; ++a)
              coefficients[(cell * n + a) * n + k] = derivatives[k * n + a] * scale;
            scale *= h / (k + 1);
          }
      }
  }


  unsigned int
  BSplineBasis1D::degree() const
  {
    return degree_;
  }
  unsigned int
  BSplineBasis1D::n_cells() const
  {
    return n_cells_;
  }
  unsigned int
  BSplineBasis1D::n_functions() const
  {
    return n_cells_ + degree_;
  }
  double
  BSplineBasis1D::cell_size() const
  {
    return h;
  }
  double
  BSplineBasis1D::x_min() const
  {
    return x_min_;
  }
  double
  BSplineBasis1D::x_max() const
  {
    return x_max_;
  }


  unsigned int
  BSplineBasis1D::cell_of(const double x) const
  {
    const double tolerance = relative_position_tolerance * (x_max_ - x_min_);
    if (!(x >= x_min_ - tolerance && x <= x_max_ + tolerance))
      throw std::out_of_range("point outside the B-spline interval");
    const double s = std::floor((x - x_min_) / h);
    return static_cast<unsigned int>(std::clamp(s, 0., n_cells_ - 1.));
  }


  unsigned int
  BSplineBasis1D::first_function(const unsigned int cell) const
  {
    return cell;
  }


  double
  BSplineBasis1D::greville(const unsigned int j) const
  {
    double sum = 0.;
    for (unsigned int k = 1; k <= degree(); ++k)
      sum += knot(j + k);
    return sum / degree();
  }


  double
  BSplineBasis1D::knot(const int i) const
  {
    const int k = std::clamp(i - static_cast<int>(degree_), 0, static_cast<int>(n_cells_));
    return (k == static_cast<int>(n_cells_)) ? x_max_ : x_min_ + k * h;
  }


  void
  BSplineBasis1D::evaluate(const double       x,
                           const unsigned int cell,
                           const unsigned int n_derivatives,
                           double            *values) const
  {
    Assert(n_derivatives <= 2, dealii::ExcIndexRange(n_derivatives, 0, 3));
    const unsigned int n     = degree_ + 1;
    const double       t     = (x - x_min_) / h - (cell + 0.5);
    const double      *c     = coefficients.data() + cell * n * n;
    const double       scale = 1. / h;
    for (unsigned int a = 0; a < n; ++a, c += n)
      {
        // Horner's rule for p(t), p'(t) and p''(t)/2 at once.
        double value = c[degree_], first = 0., second = 0.;
        for (int k = static_cast<int>(degree_) - 1; k >= 0; --k)
          {
            second = second * t + first;
            first  = first * t + value;
            value  = value * t + c[k];
          }
        values[a] = value;
        if (n_derivatives >= 1)
          values[n + a] = first * scale;
        if (n_derivatives >= 2)
          values[2 * n + a] = 2. * second * scale * scale;
      }
  }


  void
  BSplineBasis1D::evaluate_by_recursion(const double       x,
                                        const unsigned int cell,
                                        const unsigned int n_derivatives,
                                        double            *values) const
  {
    constexpr unsigned int M    = max_degree + 1;
    const unsigned int     p    = degree_;
    const int              span = cell + p; // xi_span <= x < xi_span+1
    double                 left[M], right[M], ndu[M][M], a[2][M];

    ndu[0][0] = 1.;
    for (unsigned int j = 1; j <= p; ++j)
      {
        left[j]      = x - knot(span + 1 - j);
        right[j]     = knot(span + j) - x;
        double saved = 0.;
        for (unsigned int r = 0; r < j; ++r)
          {
            ndu[j][r]         = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j]         = saved + right[r + 1] * temp;
            saved             = left[j - r] * temp;
          }
        ndu[j][j] = saved;
      }
    for (unsigned int j = 0; j <= p; ++j)
      values[j] = ndu[j][p];

    const unsigned int n = std::min(n_derivatives, p);
    for (unsigned int r = 0; r <= p; ++r)
      {
        unsigned int s1 = 0, s2 = 1;
        a[0][0] = 1.;
        for (unsigned int k = 1; k <= n; ++k)
          {
            double    d  = 0.;
            const int rk = static_cast<int>(r) - static_cast<int>(k);
            const int pk = static_cast<int>(p) - static_cast<int>(k);
            if (rk >= 0)
              {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d        = a[s2][0] * ndu[rk][pk];
              }
            const int j1 = (rk >= -1) ? 1 : -rk;
            const int j2 = (static_cast<int>(r) - 1 <= pk) ? static_cast<int>(k) - 1 : p - r;
            for (int j = j1; j <= j2; ++j)
              {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
              }
            if (static_cast<int>(r) <= pk)
              {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
              }
            values[k * (p + 1) + r] = d;
            std::swap(s1, s2);
          }
      }
    // Multiply by p!/(p-k)!.
    double factor = p;
    for (unsigned int k = 1; k <= n; ++k)
      {
        for (unsigned int j = 0; j <= p; ++j)
          values[k * (p + 1) + j] *= factor;
        factor *= (p - k);
      }
    for (unsigned int k = n + 1; k <= n_derivatives; ++k)
      for (unsigned int j = 0; j <= p; ++j)
        values[k * (p + 1) + j] = 0.;
  }


  std::vector<double>
  refinement_mask(const unsigned int degree)
  {
    std::vector<double> mask(degree + 2);
    double              binomial = 1.;
    for (unsigned int k = 0; k <= degree + 1; ++k)
      {
        mask[k] = binomial / std::pow(2., degree);
        binomial *= static_cast<double>(degree + 1 - k) / (k + 1);
      }
    return mask;
  }


  dealii::FullMatrix<double>
  refinement_operator_1d(const BSplineBasis1D &coarse, const BSplineBasis1D &fine)
  {
    if (fine.n_cells() != 2 * coarse.n_cells() || fine.degree() != coarse.degree())
      throw std::invalid_argument("refinement_operator_1d needs the dyadically refined basis");
    // Collocation: coarse(x) = sum_j S_ij fine_j(x) at n_fine distinct points.
    const unsigned int               n_f = fine.n_functions(), n_c = coarse.n_functions();
    const unsigned int               q = fine.degree();
    dealii::LAPACKFullMatrix<double> collocation(n_f, n_f);
    dealii::FullMatrix<double>       rhs(n_f, n_c);
    std::vector<double>              v((q + 1) * 3);
    for (unsigned int i = 0; i < n_f; ++i)
      {
        // Greville abscissae: unisolvent by the Schoenberg-Whitney theorem.
        double x = 0.;
        for (unsigned int j = i + 1; j <= i + q; ++j)
          x += fine.x_min() +
               std::clamp<int>(static_cast<int>(j) - static_cast<int>(q), 0, fine.n_cells()) *
                 fine.cell_size();
        x /= q;
        unsigned int cell = fine.cell_of(x);
        fine.evaluate(x, cell, 0, v.data());
        for (unsigned int a = 0; a <= q; ++a)
          collocation(i, fine.first_function(cell) + a) = v[a];
        cell = coarse.cell_of(x);
        coarse.evaluate(x, cell, 0, v.data());
        for (unsigned int a = 0; a <= q; ++a)
          rhs(i, coarse.first_function(cell) + a) = v[a];
      }
    collocation.compute_lu_factorization();
    dealii::FullMatrix<double> S(n_c, n_f);
    for (unsigned int c = 0; c < n_c; ++c)
      {
        dealii::Vector<double> b(n_f);
        for (unsigned int i = 0; i < n_f; ++i)
          b(i) = rhs(i, c);
        collocation.solve(b);
        for (unsigned int j = 0; j < n_f; ++j)
          S(c, j) = std::abs(b(j)) < 1e-14 ? 0. : b(j);
      }
    return S;
  }
} // namespace GelMPM

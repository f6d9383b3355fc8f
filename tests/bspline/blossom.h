// The B-spline (Marsden) coefficients of monomials, for the tests of polynomial reproduction.
#ifndef gelmpm_tests_bspline_blossom_h
#define gelmpm_tests_bspline_blossom_h

#include <vector>

namespace blossom_coefficients
{
  /** Blossom of x^a (degree q = t.size()) at the knots t: e_a(t) / binom(q, a). */
  inline double
  blossom(const unsigned int a, const std::vector<double> &t)
  {
    // Elementary symmetric polynomials by the usual recursion.
    std::vector<double> e(t.size() + 1, 0.);
    e[0] = 1.;
    for (const double x : t)
      for (unsigned int k = t.size(); k >= 1; --k)
        e[k] += e[k - 1] * x;
    double binomial = 1.;
    for (unsigned int k = 0; k < a; ++k)
      binomial = binomial * (t.size() - k) / (k + 1);
    return e[a] / binomial;
  }
} // namespace blossom_coefficients

#endif

#ifndef gelmpm_bspline_bspline_basis_1d_h
#define gelmpm_bspline_bspline_basis_1d_h

#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace GelMPM
{
  /**
   * @brief Maximally smooth (C^{q-1}) B-splines of degree q on the open uniform knot vector over
   * [x_min, x_max] with n_cells equal cells (paper eq. (41)–(42)).
   *
   * There are n_cells + q functions; on cell c the nonzero ones are c, c+1, ..., c+q. On each
   * cell every function is a polynomial of degree q: the constructor expands it about the cell's
   * midpoint from its derivatives there (Cox–de Boor recursion in its triangular form, Piegl &
   * Tiller, A2.3), and evaluate() applies Horner's rule to these coefficients. The material
   * points are evaluated at every step, and Horner's rule on a local variable in [-1/2, 1/2]
   * costs a fraction of the recursion at the same round-off.
   */
  class BSplineBasis1D
  {
  public:
    static constexpr unsigned int max_degree = 6;

    BSplineBasis1D(const unsigned int degree,
                   const double       x_min,
                   const double       x_max,
                   const unsigned int n_cells);

    unsigned int
    degree() const;
    unsigned int
    n_cells() const;
    unsigned int
    n_functions() const;
    double
    cell_size() const;
    double
    x_min() const;
    double
    x_max() const;

    /** The cell holding x; x = x_max belongs to the last cell. Throws std::out_of_range outside. */
    unsigned int
    cell_of(const double x) const;

    /** Index of the first function nonzero on @p cell (= cell). */
    unsigned int
    first_function(const unsigned int cell) const;

    /**
     * values[r*(q+1) + a] = r-th derivative (r = 0..n_derivatives <= 2) of function
     * first_function(cell) + a at x (x in the closure of the cell).
     */
    void
    evaluate(const double       x,
             const unsigned int cell,
             const unsigned int n_derivatives,
             double            *values) const;

    /**
     * The Greville abscissa of function @p j, the mean of its interior knots: sum_j greville(j)
     * N_j(x) = x, so these are the coefficients of a linear field.
     */
    double
    greville(const unsigned int j) const;

  private:
    /** Knot i of the open knot vector (q+1 repeated end knots). */
    double
    knot(const int i) const;

    /**
     * The Cox–de Boor recursion: values[r*(q+1) + a] = r-th derivative (r = 0..n_derivatives,
     * any order) of function first_function(cell) + a at x.
     */
    void
    evaluate_by_recursion(const double       x,
                          const unsigned int cell,
                          const unsigned int n_derivatives,
                          double            *values) const;

    /**
     * coefficients[(cell*(q+1) + a)*(q+1) + k]: on @p cell, function first_function(cell) + a
     * is sum_k c_k t^k with t = (x - midpoint)/h.
     */
    std::vector<double> coefficients;

    unsigned int degree_;
    double       x_min_, x_max_;
    unsigned int n_cells_;
    double       h;
  };


  /** The degree-q refinement mask a_k = 2^-q binom(q+1, k), k = 0..q+1 (eq. (46), (49)). */
  std::vector<double>
  refinement_mask(const unsigned int degree);

  /**
   * The univariate refinement operator S (eq. (48)): rows are the functions of @p coarse, columns
   * those of @p fine (which must have twice the cells over the same interval), with
   * N_coarse = S N_fine. Computed by collocation, so that it also holds next to the open ends of
   * the knot vector, where the uniform mask of eq. (46) does not apply.
   */
  dealii::FullMatrix<double>
  refinement_operator_1d(const BSplineBasis1D &coarse, const BSplineBasis1D &fine);
} // namespace GelMPM

#endif

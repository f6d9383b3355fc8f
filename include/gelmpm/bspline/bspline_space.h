#ifndef gelmpm_bspline_bspline_space_h
#define gelmpm_bspline_bspline_space_h

#include <gelmpm/bspline/bspline_basis_1d.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Tensor-product B-splines (paper eq. (43)–(45)) of one degree on a structured grid
   * [lower, upper] with n_cells[d] cells in direction d; the geometry map is the identity.
   *
   * Cells and functions (control points) are numbered lexicographically with x running fastest.
   * The cell numbering agrees with active_cell_index() of the triangulation made by
   * dealii::GridGenerator::subdivided_hyper_rectangle with the same arguments. The
   * chemical-potential space of the subdivision pairs (§3.4) is simply a BSplineSpace with half
   * the cells per direction over the same box.
   */
  template <int dim>
  class BSplineSpace
  {
  public:
    BSplineSpace(const unsigned int                   degree,
                 const dealii::Point<dim>            &lower,
                 const dealii::Point<dim>            &upper,
                 const std::array<unsigned int, dim> &n_cells);

    unsigned int
    degree() const;
    /** Total number of cells. */
    unsigned int
    n_cells() const;
    /** Total number of functions (control points). */
    unsigned int
    n_functions() const;
    /** (q+1)^dim, the functions nonzero on a cell. */
    unsigned int
    functions_per_cell() const;
    const std::array<unsigned int, dim> &
    n_cells_per_direction() const;
    const BSplineBasis1D &
    basis_1d(const unsigned int d) const;
    double
    cell_size(const unsigned int d) const;

    /** The cell holding @p p (flat index). Throws std::out_of_range outside the grid. */
    unsigned int
    cell_containing(const dealii::Point<dim> &p) const;
    std::array<unsigned int, dim>
    cell_multi_index(const unsigned int cell) const;
    unsigned int
    cell_index(const std::array<unsigned int, dim> &multi_index) const;
    unsigned int
    function_index(const std::array<unsigned int, dim> &multi_index) const;
    std::array<unsigned int, dim>
    function_multi_index(const unsigned int i) const;

    /** Global indices of the functions nonzero on @p cell, local order lexicographic. */
    void
    cell_functions(const unsigned int cell, std::vector<unsigned int> &indices) const;

    /**
     * Values and gradients of the functions_per_cell() local functions of @p cell at @p p
     * (in the closure of the cell); the vectors must have that size. No allocation.
     */
    void
    evaluate(const dealii::Point<dim>            &p,
             const unsigned int                   cell,
             std::vector<double>                 &values,
             std::vector<dealii::Tensor<1, dim>> &gradients) const;

  private:
    unsigned int                  degree_;
    std::array<unsigned int, dim> n_cells_;
    std::vector<BSplineBasis1D>   bases;
  };
} // namespace GelMPM

#endif

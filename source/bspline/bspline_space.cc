#include <gelmpm/bspline/bspline_space.h>

namespace GelMPM
{
  template <int dim>
  BSplineSpace<dim>::BSplineSpace(const unsigned int                   degree,
                                  const dealii::Point<dim>            &lower,
                                  const dealii::Point<dim>            &upper,
                                  const std::array<unsigned int, dim> &n_cells)
    : degree_(degree)
    , n_cells_(n_cells)
  {
    for (unsigned int d = 0; d < dim; ++d)
      bases.emplace_back(degree, lower[d], upper[d], n_cells[d]);
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::degree() const
  {
    return degree_;
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::n_cells() const
  {
    unsigned int n = 1;
    for (const auto c : n_cells_)
      n *= c;
    return n;
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::n_functions() const
  {
    unsigned int n = 1;
    for (const auto &b : bases)
      n *= b.n_functions();
    return n;
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::functions_per_cell() const
  {
    unsigned int n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= degree_ + 1;
    return n;
  }


  template <int dim>
  const std::array<unsigned int, dim> &
  BSplineSpace<dim>::n_cells_per_direction() const
  {
    return n_cells_;
  }


  template <int dim>
  const BSplineBasis1D &
  BSplineSpace<dim>::basis_1d(const unsigned int d) const
  {
    return bases[d];
  }


  template <int dim>
  double
  BSplineSpace<dim>::cell_size(const unsigned int d) const
  {
    return bases[d].cell_size();
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::cell_containing(const dealii::Point<dim> &p) const
  {
    std::array<unsigned int, dim> index;
    for (unsigned int d = 0; d < dim; ++d)
      index[d] = bases[d].cell_of(p[d]);
    return cell_index(index);
  }


  template <int dim>
  std::array<unsigned int, dim>
  BSplineSpace<dim>::cell_multi_index(const unsigned int cell) const
  {
    std::array<unsigned int, dim> index;
    unsigned int                  rest = cell;
    for (unsigned int d = 0; d < dim; ++d)
      {
        index[d] = rest % n_cells_[d];
        rest /= n_cells_[d];
      }
    return index;
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::cell_index(const std::array<unsigned int, dim> &multi_index) const
  {
    unsigned int flat = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        flat += multi_index[d] * stride;
        stride *= n_cells_[d];
      }
    return flat;
  }


  template <int dim>
  unsigned int
  BSplineSpace<dim>::function_index(const std::array<unsigned int, dim> &multi_index) const
  {
    unsigned int flat = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        flat += multi_index[d] * stride;
        stride *= bases[d].n_functions();
      }
    return flat;
  }


  template <int dim>
  std::array<unsigned int, dim>
  BSplineSpace<dim>::function_multi_index(const unsigned int i) const
  {
    std::array<unsigned int, dim> index;
    unsigned int                  rest = i;
    for (unsigned int d = 0; d < dim; ++d)
      {
        index[d] = rest % bases[d].n_functions();
        rest /= bases[d].n_functions();
      }
    return index;
  }


  template <int dim>
  void
  BSplineSpace<dim>::cell_functions(const unsigned int         cell,
                                    std::vector<unsigned int> &indices) const
  {
    const auto         c = cell_multi_index(cell);
    const unsigned int n = degree_ + 1;
    indices.resize(functions_per_cell());
    for (unsigned int local = 0; local < indices.size(); ++local)
      {
        std::array<unsigned int, dim> f;
        unsigned int                  rest = local;
        for (unsigned int d = 0; d < dim; ++d)
          {
            f[d] = bases[d].first_function(c[d]) + rest % n;
            rest /= n;
          }
        indices[local] = function_index(f);
      }
  }


  template <int dim>
  void
  BSplineSpace<dim>::evaluate(const dealii::Point<dim>            &p,
                              const unsigned int                   cell,
                              std::vector<double>                 &values,
                              std::vector<dealii::Tensor<1, dim>> &gradients) const
  {
    constexpr unsigned int M = 2 * (BSplineBasis1D::max_degree + 1);
    const unsigned int     n = degree_ + 1;
    double                 v[dim][M];
    const auto             c = cell_multi_index(cell);
    for (unsigned int d = 0; d < dim; ++d)
      bases[d].evaluate(p[d], c[d], 1, v[d]);
    for (unsigned int local = 0; local < values.size(); ++local)
      {
        unsigned int a[dim];
        unsigned int rest = local;
        for (unsigned int d = 0; d < dim; ++d)
          {
            a[d] = rest % n;
            rest /= n;
          }
        double value = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          value *= v[d][a[d]];
        values[local] = value;
        for (unsigned int g = 0; g < dim; ++g)
          {
            double derivative = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              derivative *= (d == g) ? v[d][n + a[d]] : v[d][a[d]];
            gradients[local][g] = derivative;
          }
      }
  }


  template class BSplineSpace<1>;
  template class BSplineSpace<2>;
  template class BSplineSpace<3>;
} // namespace GelMPM

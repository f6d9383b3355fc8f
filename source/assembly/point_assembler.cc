#include <gelmpm/assembly/point_assembler.h>

namespace GelMPM
{
  template <int dim>
  void
  AssemblyScratch<dim>::gather_block_coefficients(const PointBlock             &block,
                                                  const PointCache<dim>        &cache,
                                                  const DiscreteSpaces<dim>    &spaces,
                                                  const dealii::Vector<double> &solution)
  {
    const auto        &u_dofs     = cache.u_dofs(block);
    const auto        &mu_dofs    = spaces.mu().cell_dofs(block.mu_cell, block.mu_piece);
    const unsigned int n_u_global = spaces.n_u_dofs();
    n_u                           = u_dofs.size();
    n_mu                          = mu_dofs.size();
    du.resize(n_u);
    mu.resize(n_mu);
    for (unsigned int a = 0; a < n_u; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        du[a][c] = solution(dim * u_dofs[a] + c);
    for (unsigned int b = 0; b < n_mu; ++b)
      mu[b] = solution(n_u_global + mu_dofs[b]);
  }


  template <int dim>
  void
  AssemblyScratch<dim>::evaluate_point_fields(const PointRecord<dim> &point,
                                              const PointCache<dim>  &cache)
  {
    N  = cache.u_values_at(point);
    G  = cache.u_gradients_at(point);
    M  = cache.mu_values_at(point);
    GM = cache.mu_gradients_at(point);

    delta_F     = dealii::unit_symmetric_tensor<dim>();
    du_at_point = 0;
    for (unsigned int a = 0; a < n_u; ++a)
      {
        delta_F += outer(du[a], G[a]);
        du_at_point += N[a] * du[a];
      }
    mu_at_point = 0.;
    grad_mu     = 0;
    for (unsigned int b = 0; b < n_mu; ++b)
      {
        mu_at_point += M[b] * mu[b];
        grad_mu += mu[b] * GM[b];
      }
  }


  template struct AssemblyScratch<2>;
  template struct AssemblyScratch<3>;
} // namespace GelMPM

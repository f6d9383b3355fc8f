#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>

namespace GelMPM
{
  using dealii::Tensor;


  template <int dim>
  void
  add_displacement_nitsche(const PointRecord<dim> &point,
                           const Tensor<2, dim>   &Pi,
                           const Tensor<1, dim>   &g,
                           const double            beta,
                           const double            symmetry,
                           const bool              with_matrix,
                           AssemblyScratch<dim>   &s,
                           AssemblyCopy           &copy)
  {
    if constexpr (dim == 2)
      if (point.axisymmetric())
        return add_axisymmetric_displacement_nitsche(point,
                                                     Pi,
                                                     g,
                                                     beta,
                                                     symmetry,
                                                     with_matrix,
                                                     s,
                                                     copy);
    const double         area  = point.measure;
    const auto          &N     = point.normal;
    const double         sym   = symmetry;
    const unsigned int   mu0   = dim * s.n_u;
    auto                &K     = copy.matrix;
    auto                &r     = copy.residual;
    const auto           state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p);
    const Tensor<2, dim> W     = outer(g, N);
    const Tensor<1, dim> Pi_PN = Pi * (state.P_n * N);
    Tensor<2, dim>       WA; // [k][L] = W_iJ A_iJkL
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int L = 0; L < dim; ++L)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            WA[k][L] += W[i][J] * state.A_n[i][J][k][L];
    const double W_dPdmu = dealii::scalar_product(W, state.dP_n_dmu);

    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> WAG = WA * s.G[a];
        for (unsigned int k = 0; k < dim; ++k)
          r(dim * a + k) += area * (beta * g[k] * s.N[a] - Pi_PN[k] * s.N[a] - sym * WAG[k]);
      }
    for (unsigned int b = 0; b < s.n_mu; ++b)
      r(mu0 + b) -= sym * area * W_dPdmu * s.M[b];

    if (with_matrix)
      {
        // C[k][m][L] = Pi_ki A_iJmL N_J: the consistency term's derivative.
        Tensor<3, dim> C;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int m = 0; m < dim; ++m)
            for (unsigned int L = 0; L < dim; ++L)
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int J = 0; J < dim; ++J)
                  C[k][m][L] += Pi[k][i] * state.A_n[i][J][m][L] * N[J];

        // Third derivative of the energy contracted with W, by a central difference of
        // the analytic tangent along W (second-order accurate, step 1e-5 relative).
        dealii::Tensor<4, dim> H;
        dealii::Tensor<2, dim> DW; // d(W : dP_n/dmu)/d(dF)
        const double           W_norm = W.norm();
        if (W_norm > 0.)
          {
            const double eps = 1e-5 / W_norm;
            const auto plus = point.gel->incremental(s.delta_F + eps * W, s.mu_at_point, point.F_p);
            const auto minus =
              point.gel->incremental(s.delta_F - eps * W, s.mu_at_point, point.F_p);
            H = (plus.A_n - minus.A_n) / (2. * eps);
            // The exact H has the major symmetry; the difference has it only to round-off
            // divided by eps, which would make the symmetric Nitsche tangent unsymmetric at
            // 1e-11.
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                for (unsigned int m = 0; m < dim; ++m)
                  for (unsigned int Q = 0; Q < dim; ++Q)
                    if (dim * m + Q > dim * k + L)
                      H[k][L][m][Q] = H[m][Q][k][L] = 0.5 * (H[k][L][m][Q] + H[m][Q][k][L]);
            // P_n is affine in mu, so this difference is exact.
            const auto mu_plus = point.gel->incremental(s.delta_F, s.mu_at_point + 1., point.F_p);
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int J = 0; J < dim; ++J)
                    DW[k][L] += W[i][J] * (mu_plus.A_n[i][J][k][L] - state.A_n[i][J][k][L]);
          }
        const Tensor<1, dim> Pi_dPdmu_N = Pi * (state.dP_n_dmu * N);

        for (unsigned int a = 0; a < s.n_u; ++a)
          for (unsigned int c = 0; c < s.n_u; ++c)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int m = 0; m < dim; ++m)
                {
                  double value = beta * Pi[k][m] * s.N[a] * s.N[c];
                  value -= s.N[a] * (C[k][m] * s.G[c]);
                  value -= sym * s.N[c] * (C[m][k] * s.G[a]);
                  if (W_norm > 0.)
                    for (unsigned int L = 0; L < dim; ++L)
                      for (unsigned int Q = 0; Q < dim; ++Q)
                        value -= sym * s.G[a][L] * H[k][L][m][Q] * s.G[c][Q];
                  K(dim * a + k, dim * c + m) += area * value;
                }
        for (unsigned int a = 0; a < s.n_u; ++a)
          {
            const Tensor<1, dim> DWG = DW * s.G[a];
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int b = 0; b < s.n_mu; ++b)
                {
                  K(dim * a + k, mu0 + b) -=
                    area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + sym * DWG[k]);
                  K(mu0 + b, dim * a + k) -=
                    sym * area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + DWG[k]);
                }
          }
      }
  }


  template <int dim>
  void
  DisplacementNitscheAssembler<dim>::assemble(const PointRecord<dim> &point,
                                              const double /*dt*/,
                                              const bool            with_matrix,
                                              AssemblyScratch<dim> &s,
                                              AssemblyCopy         &copy) const
  {
    if (!this->piece(point).displacement_prescribed())
      return;
    add_displacement_nitsche(point,
                             point.projector,
                             point.projector * (point.u_n + s.du_at_point - point.u_bar),
                             this->nitsche.displacement_penalty * point.gel->shear_modulus() /
                               this->spaces.h_u(),
                             this->nitsche.symmetry,
                             with_matrix,
                             s,
                             copy);
    const unsigned int mu0 = dim * s.n_u;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) += this->nitsche.symmetry * point.adjoint_solvent_n * s.M[b];
  }


#define GELMPM_INSTANTIATE(dim)                                    \
  template void add_displacement_nitsche(const PointRecord<dim> &, \
                                         const Tensor<2, dim> &,   \
                                         const Tensor<1, dim> &,   \
                                         double,                   \
                                         double,                   \
                                         bool,                     \
                                         AssemblyScratch<dim> &,   \
                                         AssemblyCopy &);          \
  template class DisplacementNitscheAssembler<dim>;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

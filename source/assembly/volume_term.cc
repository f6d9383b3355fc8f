#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/volume_term.h>

namespace GelMPM
{
  using dealii::Tensor;


  template <int dim>
  void
  VolumeTermAssembler<dim>::assemble(const PointRecord<dim> &point,
                                     const double            dt,
                                     const bool              with_matrix,
                                     AssemblyScratch<dim>   &s,
                                     AssemblyCopy           &copy) const
  {
    if constexpr (dim == 2)
      if (point.axisymmetric())
        return assemble_axisymmetric_volume_term(point, dt, with_matrix, s, copy);
    const auto   state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p, with_matrix);
    const double V     = point.measure;
    const double kTnu  = point.gel->kT_over_nu();
    const double m     = point.mobility;
    const unsigned int mu0 = dim * s.n_u;

    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> PG = state.P_n * s.G[a];
        for (unsigned int i = 0; i < dim; ++i)
          copy.residual(dim * a + i) += V * PG[i];
      }
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) +=
        V * (-kTnu * (state.delta_J - 1.) * s.M[b] - dt * m * (s.grad_mu * s.GM[b]));

    if (!with_matrix)
      return;

    // A volume point's tangent is symmetric (A has the major symmetry A_iJkL = A_kLiJ, and
    // K_mu,u = K_u,mu^T): only its lower triangle is summed here, and MixedSystem::assemble_block()
    // mirrors the block's sum once.
    auto &L = s.volume_lower;
    for (unsigned int c = 0; c < s.n_u; ++c)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int J = 0; J < dim; ++J)
          for (unsigned int k = 0; k < dim; ++k)
            s.A_dot_G[c][i][J][k] = state.A_n[i][J][k] * s.G[c];
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double *row = &L(dim * a + i, 0);
          for (unsigned int c = 0; c <= a; ++c)
            for (unsigned int k = 0; k < (c == a ? i + 1 : dim); ++k)
              {
                double value = 0.;
                for (unsigned int J = 0; J < dim; ++J)
                  value += s.G[a][J] * s.A_dot_G[c][i][J][k];
                row[dim * c + k] += V * value;
              }
        }
    for (unsigned int a = 0; a < s.n_u; ++a)
      {
        const Tensor<1, dim> Vq = V * (state.dP_n_dmu * s.G[a]);
        for (unsigned int b = 0; b < s.n_mu; ++b)
          {
            double *row = &L(mu0 + b, dim * a);
            for (unsigned int i = 0; i < dim; ++i)
              row[i] += Vq[i] * s.M[b];
          }
      }
    const double Vdtm = V * dt * m;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      {
        double *row = &L(mu0 + b, mu0);
        for (unsigned int d = 0; d <= b; ++d)
          row[d] -= Vdtm * (s.GM[b] * s.GM[d]);
      }
  }


  template class VolumeTermAssembler<2>;
  template class VolumeTermAssembler<3>;
} // namespace GelMPM

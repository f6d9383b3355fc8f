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
    if (generic_tangent)
      add_generic_tangent(point, state, dt, s);
    else
      add_structured_tangent(point, state, dt, s);
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::add_structured_tangent(
    const PointRecord<dim>                          &point,
    const typename FloryRehnerGel<dim>::Incremental &state,
    const double                                     dt,
    AssemblyScratch<dim>                            &s) const
  {
    // K(a,i; c,k) = V [delta_ik s_ac + a h_a[k] h_c[i] + b h_a[i] h_c[k]] with h_a = dF^{-T} G_a
    // and s_ac = G_a . S G_c (the structure of A_n, FloryRehnerGel::Incremental): two products
    // per entry of the lower triangle instead of dim (and the dim^3 n_u of A_n . G_c).
    const double       V   = point.measure;
    const unsigned int n_u = s.n_u, mu0 = dim * n_u;
    if (s.h.size() < mu0)
      {
        s.h.resize(mu0);
        s.SG.resize(mu0);
        s.s_row.resize(n_u);
      }
    double *const       h  = s.h.data();
    double *const       SG = s.SG.data();
    const double *const G  = &s.G[0][0];
    for (unsigned int c = 0; c < n_u; ++c)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double hv = 0., sv = 0.;
          for (unsigned int L = 0; L < dim; ++L)
            {
              hv += state.dFit[i][L] * G[dim * c + L];
              sv += state.S[i][L] * G[dim * c + L];
            }
          h[dim * c + i]  = hv;
          SG[dim * c + i] = V * sv;
        }

    auto        &Lw = s.volume_lower;
    const double Va = V * state.a, Vb = V * state.b;
    for (unsigned int a = 0; a < n_u; ++a)
      {
        double *const s_row = s.s_row.data();
        for (unsigned int c = 0; c <= a; ++c)
          {
            double value = 0.;
            for (unsigned int J = 0; J < dim; ++J)
              value += G[dim * a + J] * SG[dim * c + J];
            s_row[c] = value;
          }
        double ah[dim];
        for (unsigned int k = 0; k < dim; ++k)
          ah[k] = Va * h[dim * a + k];
        for (unsigned int i = 0; i < dim; ++i)
          {
            double *const row  = &Lw(dim * a + i, 0);
            const double  beta = Vb * h[dim * a + i];
            for (unsigned int c = 0; c < a; ++c)
              {
                const double hci = h[dim * c + i];
                for (unsigned int k = 0; k < dim; ++k)
                  row[dim * c + k] += beta * h[dim * c + k] + ah[k] * hci;
                row[dim * c + i] += s_row[c];
              }
            const double hai = h[dim * a + i];
            for (unsigned int k = 0; k <= i; ++k)
              row[dim * a + k] += beta * h[dim * a + k] + ah[k] * hai;
            row[dim * a + i] += s_row[a];
          }
      }

    // K_mu,u: (dP_n/dmu G_a)_i M_b with dP_n/dmu = -(k_BT/nu) dJ dF^{-T}, i.e. -(k_BT/nu) dJ h_a.
    const double q = -V * point.gel->kT_over_nu() * state.delta_J;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      {
        double *const row = &Lw(mu0 + b, 0);
        const double  qM  = q * s.M[b];
        for (unsigned int j = 0; j < mu0; ++j)
          row[j] += qM * h[j];
      }
    const double Vdtm = V * dt * point.mobility;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      {
        double *const row = &Lw(mu0 + b, mu0);
        for (unsigned int d = 0; d <= b; ++d)
          row[d] -= Vdtm * (s.GM[b] * s.GM[d]);
      }
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::add_generic_tangent(
    const PointRecord<dim>                          &point,
    const typename FloryRehnerGel<dim>::Incremental &state,
    const double                                     dt,
    AssemblyScratch<dim>                            &s) const
  {
    const double       V   = point.measure;
    const double       m   = point.mobility;
    const unsigned int mu0 = dim * s.n_u;
    if (s.A_dot_G.size() < s.n_u)
      s.A_dot_G.resize(s.n_u);
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

#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/volume_term.h>

#include <deal.II/lac/lapack_templates.h>

#include <algorithm>

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
    // K_mu,u = K_u,mu^T): only its lower triangle is summed here, and finish_block() mirrors the
    // block's sum once.
    if (tangent.generic_volume)
      add_generic_tangent(point, state, dt, s);
    else if (batched())
      gather_tangent(point, state, dt, s);
    else
      add_structured_tangent(point, state, dt, s);
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::start_block(AssemblyScratch<dim> &s,
                                        const unsigned int    n_points,
                                        const bool            with_matrix) const
  {
    if (!with_matrix)
      return;
    auto &B    = s.batch;
    B.n_points = 0;
    if (!batched())
      {
        s.volume_lower.reinit(s.mu0() + s.n_mu, s.mu0() + s.n_mu);
        return;
      }
    B.capacity             = std::max(B.capacity, n_points);
    const unsigned int n_u = s.n_u, n_mu = s.n_mu;
    const auto         grow = [](std::vector<double> &v, const std::size_t size) {
      if (v.size() < size)
        v.resize(size);
    };
    for (auto *v : {&B.h, &B.ah, &B.bh, &B.G, &B.SG})
      grow(*v, std::size_t(B.capacity) * dim * n_u);
    grow(B.qM, std::size_t(B.capacity) * n_mu);
    grow(B.GM, std::size_t(B.capacity) * dim * n_mu);
    grow(B.wGM, std::size_t(B.capacity) * dim * n_mu);
    grow(B.hbh, std::size_t(dim * n_u) * dim * n_u);
    grow(B.hah, std::size_t(dim * n_u) * dim * n_u);
    grow(B.s, std::size_t(n_u) * n_u);
    grow(B.mu_u, std::size_t(n_mu) * dim * n_u);
    grow(B.mu_mu, std::size_t(n_mu) * n_mu);
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::gather_tangent(const PointRecord<dim>                          &point,
                                           const typename FloryRehnerGel<dim>::Incremental &state,
                                           const double                                     dt,
                                           AssemblyScratch<dim>                            &s) const
  {
    auto              &B   = s.batch;
    const unsigned int p   = B.n_points++;
    const unsigned int cap = B.capacity, n_u = s.n_u, n_mu = s.n_mu;
    Assert(p < cap, dealii::ExcInternalError());
    const double        V = point.measure, Va = V * state.a, Vb = V * state.b;
    const double *const G = &s.G[0][0];
    for (unsigned int i = 0; i < dim; ++i)
      {
        double *const h  = &B.h[p + cap * (n_u * i)];
        double *const ah = &B.ah[p + cap * (n_u * i)];
        double *const bh = &B.bh[p + cap * (n_u * i)];
        double *const Gi = &B.G[n_u * (dim * p + i)];
        double *const SG = &B.SG[n_u * (dim * p + i)];
        for (unsigned int a = 0; a < n_u; ++a)
          {
            double hv = 0., sv = 0.;
            for (unsigned int L = 0; L < dim; ++L)
              {
                hv += state.dFit[i][L] * G[dim * a + L];
                sv += state.S[i][L] * G[dim * a + L];
              }
            h[cap * a]  = hv;
            ah[cap * a] = Va * hv;
            bh[cap * a] = Vb * hv;
            Gi[a]       = G[dim * a + i];
            SG[a]       = V * sv;
          }
      }
    const double q    = -V * point.gel->kT_over_nu() * state.delta_J;
    const double Vdtm = V * dt * point.mobility;
    for (unsigned int b = 0; b < n_mu; ++b)
      B.qM[p + cap * b] = q * s.M[b];
    for (unsigned int J = 0; J < dim; ++J)
      for (unsigned int b = 0; b < n_mu; ++b)
        {
          B.GM[b + n_mu * (dim * p + J)]  = s.GM[b][J];
          B.wGM[b + n_mu * (dim * p + J)] = -Vdtm * s.GM[b][J];
        }
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::finish_block(AssemblyScratch<dim> &s,
                                         AssemblyCopy         &copy,
                                         const bool            with_matrix) const
  {
    if (!with_matrix)
      return;
    if (batched())
      {
        add_block_tangent(s, copy);
        return;
      }
    const unsigned int n = s.mu0() + s.n_mu;
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = 0; c <= r; ++c)
        {
          const double value = s.volume_lower(r, c);
          copy.matrix(r, c) += value;
          if (c != r)
            copy.matrix(c, r) += value;
        }
  }


  template <int dim>
  void
  VolumeTermAssembler<dim>::add_block_tangent(AssemblyScratch<dim> &s, AssemblyCopy &copy) const
  {
    auto &B = s.batch;
    if (!batched() || B.n_points == 0)
      return;
    using dealii::types::blas_int;
    const unsigned int n_u = s.n_u, n_mu = s.n_mu, mu0 = dim * n_u;
    const blas_int     P = B.n_points, ld = B.capacity, nu = n_u, nm = n_mu, nU = dim * n_u,
                   Pd = dim * B.n_points;
    const double one = 1., zero = 0.;
    // C = op(A) op(B), column-major (BLAS dgemm).
    const auto product = [&](const char                *op_a,
                             const char                *op_b,
                             const blas_int             m,
                             const blas_int             n,
                             const blas_int             k,
                             const std::vector<double> &A,
                             const blas_int             lda,
                             const std::vector<double> &B_,
                             const blas_int             ldb,
                             std::vector<double>       &C) {
      dealii::gemm(op_a,
                   op_b,
                   &m,
                   &n,
                   &k,
                   &one,
                   A.data(),
                   &lda,
                   B_.data(),
                   &ldb,
                   &zero,
                   C.data(),
                   &m);
    };
    // hbh[(i a), (k c)] = sum_p V b_p h_p,a[i] h_p,c[k]; hah[(k a), (i c)] = sum_p V a_p h_p,a[k]
    // h_p,c[i]; s[a, c] = sum_p G_p,a . V S_p G_p,c; mu_u[(k c), b] = sum_p q_p M_p,b h_p,c[k];
    // mu_mu[b, d] = -sum_p V dt m GM_p,b . GM_p,d.
    product("T", "N", nU, nU, P, B.h, ld, B.bh, ld, B.hbh);
    product("T", "N", nU, nU, P, B.h, ld, B.ah, ld, B.hah);
    product("N", "T", nu, nu, Pd, B.G, nu, B.SG, nu, B.s);
    product("T", "N", nU, nm, P, B.h, ld, B.qM, ld, B.mu_u);
    product("N", "T", nm, nm, Pd, B.GM, nm, B.wGM, nm, B.mu_mu);

    // hbh, hah and s are symmetric (sums of w_p x_p x_p^T): each row of the block reads them
    // along their columns, which are contiguous.
    for (unsigned int a = 0; a < n_u; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double *const       row = &copy.matrix(dim * a + i, 0);
          const double *const s_a = &B.s[std::size_t(n_u) * a];
          for (unsigned int k = 0; k < dim; ++k)
            {
              // hbh[(k c), (i a)] = b-term of ((a, i), (c, k)); hah[(i c), (k a)] its a-term.
              const double *const hb = &B.hbh[n_u * k + std::size_t(nU) * (n_u * i + a)];
              const double *const ha = &B.hah[n_u * i + std::size_t(nU) * (n_u * k + a)];
              for (unsigned int c = 0; c < n_u; ++c)
                row[dim * c + k] += hb[c] + ha[c];
            }
          for (unsigned int c = 0; c < n_u; ++c)
            row[dim * c + i] += s_a[c];
        }
    for (unsigned int b = 0; b < n_mu; ++b)
      {
        double *const       row  = &copy.matrix(mu0 + b, 0);
        const double *const u_mu = &B.mu_u[std::size_t(nU) * b];
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int c = 0; c < n_u; ++c)
            {
              const double v = u_mu[n_u * k + c];
              row[dim * c + k] += v;
              copy.matrix(dim * c + k, mu0 + b) += v;
            }
        const double *const mm = &B.mu_mu[std::size_t(n_mu) * b];
        for (unsigned int d = 0; d < n_mu; ++d)
          row[mu0 + d] += mm[d];
      }
    B.n_points = 0;
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

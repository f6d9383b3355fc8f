#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>

namespace GelMPM
{
  using dealii::Tensor;


  namespace
  {
    /** The residual of add_displacement_nitsche() at the gel state @p state; returns g (x) N. */
    template <int dim>
    Tensor<2, dim>
    add_residual(const PointRecord<dim>                          &point,
                 const typename FloryRehnerGel<dim>::Incremental &state,
                 const Tensor<2, dim>                            &Pi,
                 const Tensor<1, dim>                            &g,
                 const double                                     beta,
                 const double                                     symmetry,
                 const AssemblyScratch<dim>                      &s,
                 AssemblyCopy                                    &copy)
    {
      const double         area  = point.measure;
      const auto          &N     = point.normal;
      const double         sym   = symmetry;
      const unsigned int   mu0   = dim * s.n_u;
      auto                &r     = copy.residual;
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

      return W;
    }

    /** The tangent of add_displacement_nitsche() at the gel state @p state, in closed form. */
    template <int dim>
    void
    add_closed_form_tangent(const PointRecord<dim>                          &point,
                            const typename FloryRehnerGel<dim>::Incremental &state,
                            const Tensor<2, dim>                            &Pi,
                            const Tensor<1, dim>                            &g,
                            const double                                     beta,
                            const double                                     symmetry,
                            AssemblyScratch<dim>                            &s,
                            AssemblyCopy                                    &copy)
    {
      // With D = dF^{-T}, h_a = D G_a, n = D N, p_a = g . h_a, w = g . n (= D : W) and the
      // structure A_n,iJkL = delta_ik S_JL + a D_iL D_kJ + b D_iJ D_kL
      // (FloryRehnerGel::Incremental):
      //  - consistency, CG_a[k][m] = sum_iJL Pi_ki A_n,iJmL N_J G_a[L]
      //      = Pi_km (S N . G_a) + a (Pi h_a)_k n[m] + b (Pi n)_k h_a[m];
      //  - the third derivative along W (dD = -D W^T D, so dh_a = -p_a n; da = -b w, db = c w),
      //    X(a,k; c,m) = sum_LQ G_a[L] (dA_n,kLmQ/d(dF) : W) G_c[Q]
      //      = h_a[m] u_c[k] + v_a[k] h_c[m] + n[m] z_ac[k],
      //    u_c = -b w h_c - a p_c n, v_a = c w h_a - b p_a n, z_ac = -a p_a h_c - b p_c h_a,
      //    which has the major symmetry X(a,k; c,m) = X(c,m; a,k) exactly;
      //  - d(W : dP_n/dmu)/d(dF) G_a = (k_BT/nu) dJ (p_a n - w h_a) (dP_n/dmu = -(k_BT/nu) dJ D).
      // The pairs c <= a are computed and their mirror written with the same X, so that the
      // symmetric variant's tangent is symmetric bit for bit.
      const double          area = point.measure;
      const auto           &N    = point.normal;
      const double          sym  = symmetry;
      const unsigned int    n_u = s.n_u, mu0 = dim * n_u;
      auto                 &K    = copy.matrix;
      const Tensor<2, dim> &D    = state.dFit;
      const Tensor<1, dim>  n    = D * N;
      const Tensor<1, dim>  SN   = state.S * N;
      const Tensor<1, dim>  Pi_n = Pi * n;
      const double          w    = g * n;
      // X and the consistency term scaled by the area (and X by the symmetry) once per point.
      const double as  = area * sym * state.a;
      const double bs  = area * sym * state.b;
      const double cs  = area * sym * state.c;
      const double aA  = area * state.a;
      const double bA  = area * state.b;
      const double kdJ = point.gel->kT_over_nu() * state.delta_J;

      // Per function: h[dim], u[dim], v[dim], p, CG[dim * dim] (area included), DWG[dim].
      constexpr unsigned int stride = 4 * dim + 1 + dim * dim;
      constexpr unsigned int u_ = dim, v_ = 2 * dim, p_ = 3 * dim, CG_ = 3 * dim + 1,
                             DW_ = 3 * dim + 1 + dim * dim;
      if (s.nitsche_work.size() < stride * n_u)
        s.nitsche_work.resize(stride * n_u);
      double *const work = s.nitsche_work.data();
      for (unsigned int a = 0; a < n_u; ++a)
        {
          double *const         f  = work + stride * a;
          const Tensor<1, dim> &Ga = s.G[a];
          double                p = 0., sg = 0.;
          for (unsigned int i = 0; i < dim; ++i)
            {
              double hi = 0.;
              for (unsigned int L = 0; L < dim; ++L)
                hi += D[i][L] * Ga[L];
              f[i] = hi;
              p += g[i] * hi;
              sg += SN[i] * Ga[i];
            }
          f[p_] = p;
          for (unsigned int k = 0; k < dim; ++k)
            {
              f[u_ + k]  = -bs * w * f[k] - as * p * n[k];
              f[v_ + k]  = cs * w * f[k] - bs * p * n[k];
              f[DW_ + k] = kdJ * (p * n[k] - w * f[k]);
            }
          for (unsigned int k = 0; k < dim; ++k)
            {
              double Pi_h = 0.;
              for (unsigned int i = 0; i < dim; ++i)
                Pi_h += Pi[k][i] * f[i];
              for (unsigned int m = 0; m < dim; ++m)
                f[CG_ + dim * k + m] =
                  area * Pi[k][m] * sg + aA * Pi_h * n[m] + bA * Pi_n[k] * f[m];
            }
        }

      const double beta_area = area * beta;
      for (unsigned int a = 0; a < n_u; ++a)
        {
          const double *const fa  = work + stride * a;
          const double        Na  = s.N[a];
          const double        apa = as * fa[p_];
          for (unsigned int c = 0; c <= a; ++c)
            {
              const double *const fc  = work + stride * c;
              const double        Nc  = s.N[c];
              const double        bNN = beta_area * Na * Nc;
              const double        bpc = bs * fc[p_];
              double              z[dim];
              for (unsigned int k = 0; k < dim; ++k)
                z[k] = -apa * fc[k] - bpc * fa[k];
              for (unsigned int k = 0; k < dim; ++k)
                {
                  double *const row = &K(dim * a + k, dim * c);
                  for (unsigned int m = 0; m < (c == a ? k + 1 : dim); ++m)
                    {
                      const double X  = fa[m] * fc[u_ + k] + fa[v_ + k] * fc[m] + n[m] * z[k];
                      const double t1 = Na * fc[CG_ + dim * k + m];
                      const double t2 = Nc * fa[CG_ + dim * m + k];
                      row[m] += bNN * Pi[k][m] - X - (t1 + sym * t2);
                      if (c != a || m != k)
                        K(dim * c + m, dim * a + k) += bNN * Pi[m][k] - X - (t2 + sym * t1);
                    }
                }
            }
        }

      const Tensor<1, dim> Pi_dPdmu_N = Pi * (state.dP_n_dmu * N);
      for (unsigned int a = 0; a < n_u; ++a)
        {
          const double *const fa = work + stride * a;
          for (unsigned int k = 0; k < dim; ++k)
            {
              const double x = s.N[a] * Pi_dPdmu_N[k];
              const double y = fa[DW_ + k];
              for (unsigned int b = 0; b < s.n_mu; ++b)
                {
                  K(dim * a + k, mu0 + b) -= area * s.M[b] * (x + sym * y);
                  K(mu0 + b, dim * a + k) -= sym * area * s.M[b] * (x + y);
                }
            }
        }
    }
  } // namespace


  template <int dim>
  void
  add_displacement_nitsche(const PointRecord<dim> &point,
                           const Tensor<2, dim>   &Pi,
                           const Tensor<1, dim>   &g,
                           const double            beta,
                           const double            symmetry,
                           const bool              with_matrix,
                           AssemblyScratch<dim>   &s,
                           AssemblyCopy           &copy,
                           const bool              reference_tangent)
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
    if (reference_tangent)
      return add_displacement_nitsche_reference(point, Pi, g, beta, symmetry, with_matrix, s, copy);
    const auto state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p);
    add_residual(point, state, Pi, g, beta, symmetry, s, copy);
    if (!with_matrix)
      return;

    add_closed_form_tangent(point, state, Pi, g, beta, symmetry, s, copy);
  }


  template <int dim>
  void
  add_displacement_nitsche_reference(const PointRecord<dim> &point,
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
    const auto           state = point.gel->incremental(s.delta_F, s.mu_at_point, point.F_p);
    const Tensor<2, dim> W     = add_residual(point, state, Pi, g, beta, symmetry, s, copy);

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
                             copy,
                             this->reference_nitsche_tangent);
    const unsigned int mu0 = dim * s.n_u;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) += this->nitsche.symmetry * point.adjoint_solvent_n * s.M[b];
  }


#define GELMPM_INSTANTIATE(dim)                                              \
  template void add_displacement_nitsche(const PointRecord<dim> &,           \
                                         const Tensor<2, dim> &,             \
                                         const Tensor<1, dim> &,             \
                                         double,                             \
                                         double,                             \
                                         bool,                               \
                                         AssemblyScratch<dim> &,             \
                                         AssemblyCopy &,                     \
                                         bool);                              \
  template void add_displacement_nitsche_reference(const PointRecord<dim> &, \
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

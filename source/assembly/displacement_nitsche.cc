#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>

#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <utility>

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

    /**
     * The factors of one surface point's displacement-displacement tangent
     * (gather_block_factors()): the "straight" ones, indexed (a, k) on both sides, and the
     * "crossed" ones, indexed (a, m) as rows and (c, k) as columns.
     */
    template <int dim>
    struct NitscheFactors
    {
      enum Straight : unsigned int
      {
        H  = 0,
        PN = 1,
        NP = 2,
        NE = 3,
        SE = 3 + dim,
      };
      enum Crossed : unsigned int
      {
        xH   = 0,
        xPN  = 1,
        xNN  = 2,
        xPiH = 3
      };
      static constexpr unsigned int n_straight = 3 + 2 * dim, n_crossed = 4;

      // C[x][y]: the coefficient of (row factor x) (column factor y).
      double straight[n_straight][n_straight] = {};
      double crossed[n_crossed][n_crossed]    = {};
    };


    /**
     * The coefficients C and C' of the factors, from the pair loop of add_closed_form_tangent():
     * K = beta A N N Pi - X - (t1 + s t2).
     */
    template <int dim>
    NitscheFactors<dim>
    factor_coefficients(const PointRecord<dim>                          &point,
                        const typename FloryRehnerGel<dim>::Incremental &state,
                        const Tensor<2, dim>                            &Pi,
                        const double                                     w,
                        const double                                     beta,
                        const double                                     sym)
    {
      using F = NitscheFactors<dim>;
      F            f;
      auto        &C = f.straight, &Cx = f.crossed;
      const double A  = point.measure;
      const double as = A * sym * state.a, bs = A * sym * state.b, cs = A * sym * state.c;
      const double aA = A * state.a, bA = A * state.b;
      C[F::H][F::H]  = -cs * w;
      C[F::PN][F::H] = bs;
      C[F::H][F::PN] = bs;
      C[F::NP][F::H] = -bA;
      C[F::H][F::NP] = -sym * bA;
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int l = 0; l < dim; ++l)
          {
            C[F::NE + j][F::NE + l] = beta * A * Pi[j][l];
            C[F::NE + j][F::SE + l] = -A * Pi[j][l];
            C[F::SE + j][F::NE + l] = -sym * A * Pi[l][j];
          }
      Cx[F::xH][F::xH]    = bs * w;
      Cx[F::xH][F::xPN]   = as;
      Cx[F::xPN][F::xH]   = as;
      Cx[F::xNN][F::xPiH] = -aA;
      Cx[F::xPiH][F::xNN] = -sym * aA;
      return f;
    }


    /** Z[:, y] = sum_x Y[:, x] C[x][y] (@p r factors of length @p U): the columns' partners. */
    template <unsigned int r>
    void
    combine_factors(const double *Y, double *Z, const double (&C)[r][r], const unsigned int U)
    {
      for (unsigned int y = 0; y < r; ++y)
        {
          double *const z = Z + U * y;
          std::fill(z, z + U, 0.);
          for (unsigned int x = 0; x < r; ++x)
            if (C[x][y] != 0.)
              for (unsigned int I = 0; I < U; ++I)
                z[I] += C[x][y] * Y[I + U * x];
        }
    }


    /**
     * Room in the batch for one more point's factors: the first straight and crossed column of
     * the point.
     */
    template <int dim>
    std::pair<std::size_t, std::size_t>
    append_factor_columns(typename AssemblyScratch<dim>::NitscheTangentBatch &B,
                          const unsigned int                                  U)
    {
      using F = NitscheFactors<dim>;
      const std::pair<std::size_t, std::size_t> first(B.n_straight, B.n_crossed);
      B.n_straight += F::n_straight;
      B.n_crossed += F::n_crossed;
      for (auto *v : {&B.Y, &B.Z})
        if (v->size() < std::size_t(U) * B.n_straight)
          v->resize(std::size_t(U) * 2 * B.n_straight);
      for (auto *v : {&B.Yx, &B.Zx})
        if (v->size() < std::size_t(U) * B.n_crossed)
          v->resize(std::size_t(U) * 2 * B.n_crossed);
      return first;
    }


    /**
     * The displacement-displacement part of the closed-form tangent (add_closed_form_tangent())
     * as factors into the block's batch: with I = (a, k), J = (c, m), and the vectors
     * H_I = h_a[k], PN_I = p_a n[k], NPn_I = N_a (Pi n)_k, NE^j_I = N_a delta_jk,
     * SE^j_I = (S N . G_a) delta_jk, NN_I = N_a n[k], PiH_I = (Pi h_a)_k,
     *   K_IJ += sum x_I C_xy y_J        over x, y in (H, PN, NPn, NE^j, SE^j)   (straight)
     *   K_(a,k),(c,m) += sum x_(a,m) C'_xy y_(c,k)  over x, y in (H, PN, NN, PiH)  (crossed),
     * the same terms as the pair loop, each a product of a row factor and a column factor.
     */
    template <int dim>
    void
    gather_block_factors(const PointRecord<dim>                          &point,
                         const typename FloryRehnerGel<dim>::Incremental &state,
                         const Tensor<2, dim>                            &Pi,
                         const Tensor<1, dim>                            &g,
                         const double                                     beta,
                         const double                                     sym,
                         AssemblyScratch<dim>                            &s)
    {
      using F                = NitscheFactors<dim>;
      auto              &B   = s.nitsche_batch;
      const unsigned int n_u = s.n_u, U = dim * n_u;
      const auto [first_s, first_x] = append_factor_columns<dim>(B, U);
      B.symmetric                   = B.symmetric && sym == 1. && Pi == dealii::transpose(Pi);

      double *const Y  = &B.Y[U * first_s];
      double *const Yx = &B.Yx[U * first_x];
      std::fill(Y, Y + U * F::n_straight, 0.);
      const auto          &D    = state.dFit;
      const Tensor<1, dim> n    = D * point.normal;
      const Tensor<1, dim> SN   = state.S * point.normal;
      const Tensor<1, dim> Pi_n = Pi * n;
      for (unsigned int a = 0; a < n_u; ++a)
        {
          const Tensor<1, dim> h    = D * s.G[a];
          const Tensor<1, dim> Pi_h = Pi * h;
          const double         p    = g * h;
          const double         Na   = s.N[a];
          for (unsigned int k = 0; k < dim; ++k)
            {
              const unsigned int I   = dim * a + k;
              Y[I + U * F::H]        = h[k];
              Y[I + U * F::PN]       = p * n[k];
              Y[I + U * F::NP]       = Na * Pi_n[k];
              Y[I + U * (F::NE + k)] = Na;
              Y[I + U * (F::SE + k)] = SN * s.G[a];
              Yx[I + U * F::xH]      = h[k];
              Yx[I + U * F::xPN]     = p * n[k];
              Yx[I + U * F::xNN]     = Na * n[k];
              Yx[I + U * F::xPiH]    = Pi_h[k];
            }
        }

      const F f = factor_coefficients(point, state, Pi, g * n, beta, sym);
      combine_factors(Y, &B.Z[U * first_s], f.straight, U);
      combine_factors(Yx, &B.Zx[U * first_x], f.crossed, U);
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
      if (s.nitsche_batch.open)
        gather_block_factors(point, state, Pi, g, beta, symmetry, s);
      else
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
  start_displacement_nitsche_block(AssemblyScratch<dim> &s, const bool batched)
  {
    auto &B      = s.nitsche_batch;
    B.open       = batched;
    B.symmetric  = true;
    B.n_straight = 0;
    B.n_crossed  = 0;
  }


  template <int dim>
  void
  add_displacement_nitsche_block(AssemblyScratch<dim> &s, AssemblyCopy &copy)
  {
    auto &B = s.nitsche_batch;
    // Once per block, whichever of the terms that gather into the batch closes it first.
    if (!B.open)
      return;
    B.open = false;
    if (B.n_straight == 0)
      return;
    using dealii::types::blas_int;
    const unsigned int n_u = s.n_u, U = dim * n_u;
    const blas_int     m = U, k_s = B.n_straight, k_x = B.n_crossed;
    const double       one = 1., zero = 0.;
    for (auto *v : {&B.straight, &B.crossed})
      if (v->size() < std::size_t(U) * U)
        v->resize(std::size_t(U) * U);
    // straight[J + U I] = sum_x,y Y[I, x] C_xy Y[J, y] = sum_r Y[J, r] Z[I, r]: row I is
    // contiguous; likewise crossed[(c, k) + U (a, m)].
    const auto product = [&](const blas_int             k,
                             const std::vector<double> &Y,
                             const std::vector<double> &Z,
                             std::vector<double>       &out) {
      dealii::gemm("N", "T", &m, &m, &k, &one, Y.data(), &m, Z.data(), &m, &zero, out.data(), &m);
    };
    product(k_s, B.Y, B.Z, B.straight);
    product(k_x, B.Yx, B.Zx, B.crossed);
    const auto entry = [&](const unsigned int I, const unsigned int J) {
      const unsigned int a = I / dim, k = I % dim, c = J / dim, m_ = J % dim;
      return B.straight[J + std::size_t(U) * I] +
             B.crossed[dim * c + k + std::size_t(U) * (dim * a + m_)];
    };
    if (B.symmetric)
      // Every point's tangent is symmetric, the products only to round-off: their mean keeps
      // the symmetric variant's tangent as symmetric as the volume points leave it.
      for (unsigned int I = 0; I < U; ++I)
        for (unsigned int J = 0; J <= I; ++J)
          {
            const double value = (I == J ? entry(I, I) : 0.5 * (entry(I, J) + entry(J, I)));
            copy.matrix(I, J) += value;
            if (J != I)
              copy.matrix(J, I) += value;
          }
    else
      for (unsigned int I = 0; I < U; ++I)
        {
          double *const row = &copy.matrix(I, 0);
          for (unsigned int J = 0; J < U; ++J)
            row[J] += entry(I, J);
        }
    B.n_straight = 0;
    B.n_crossed  = 0;
  }


  template <int dim>
  void
  DisplacementNitscheAssembler<dim>::start_block(AssemblyScratch<dim> &s,
                                                 const unsigned int /*n_points*/,
                                                 const bool with_matrix) const
  {
    if (with_matrix)
      start_displacement_nitsche_block(s, this->tangent.template batched<dim>());
  }


  template <int dim>
  void
  DisplacementNitscheAssembler<dim>::finish_block(AssemblyScratch<dim> &s,
                                                  AssemblyCopy         &copy,
                                                  const bool            with_matrix) const
  {
    if (with_matrix)
      add_displacement_nitsche_block(s, copy);
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
                               this->spaces.h_u(point.level),
                             this->nitsche.symmetry,
                             with_matrix,
                             s,
                             copy,
                             this->tangent.reference_nitsche);
    const unsigned int mu0 = dim * s.n_u;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) += this->nitsche.symmetry * point.adjoint_solvent_n * s.M[b];
  }


#define GELMPM_INSTANTIATE(dim)                                                         \
  template void add_displacement_nitsche(const PointRecord<dim> &,                      \
                                         const Tensor<2, dim> &,                        \
                                         const Tensor<1, dim> &,                        \
                                         double,                                        \
                                         double,                                        \
                                         bool,                                          \
                                         AssemblyScratch<dim> &,                        \
                                         AssemblyCopy &,                                \
                                         bool);                                         \
  template void add_displacement_nitsche_reference(const PointRecord<dim> &,            \
                                                   const Tensor<2, dim> &,              \
                                                   const Tensor<1, dim> &,              \
                                                   double,                              \
                                                   double,                              \
                                                   bool,                                \
                                                   AssemblyScratch<dim> &,              \
                                                   AssemblyCopy &);                     \
  template void start_displacement_nitsche_block(AssemblyScratch<dim> &, bool);         \
  template void add_displacement_nitsche_block(AssemblyScratch<dim> &, AssemblyCopy &); \
  template class DisplacementNitscheAssembler<dim>;
  GELMPM_INSTANTIATE(2)
  GELMPM_INSTANTIATE(3)
#undef GELMPM_INSTANTIATE
} // namespace GelMPM

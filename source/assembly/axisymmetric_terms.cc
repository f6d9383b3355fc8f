#include <gelmpm/assembly/axisymmetric_terms.h>

#include <vector>

namespace GelMPM
{
  using dealii::Tensor;

  namespace
  {
    /**
     * The virtual deformation B(a, k) of the test function N_a e_k of an axisymmetric point at
     * radius r: row k holds grad N_a, and the radial function adds the hoop entry N_a / r. These
     * contract it with a 3x3 tensor and a fourth-order tensor.
     */
    struct VirtualDeformation
    {
      const double       *N;
      const Tensor<1, 2> *G;
      double              inverse_radius;

      /** T : B(a, k). */
      double
      contract(const Tensor<2, 3> &T, const unsigned int a, const unsigned int k) const
      {
        double value = T[k][0] * G[a][0] + T[k][1] * G[a][1];
        if (k == 0)
          value += T[2][2] * N[a] * inverse_radius;
        return value;
      }

      /** (A : B(a, k))_pq = A_pqmL B(a, k)_mL. */
      Tensor<2, 3>
      apply(const Tensor<4, 3> &A, const unsigned int a, const unsigned int k) const
      {
        Tensor<2, 3> T;
        for (unsigned int p = 0; p < 3; ++p)
          for (unsigned int q = 0; q < 3; ++q)
            {
              T[p][q] = A[p][q][k][0] * G[a][0] + A[p][q][k][1] * G[a][1];
              if (k == 0)
                T[p][q] += A[p][q][2][2] * N[a] * inverse_radius;
            }
        return T;
      }
    };
  } // namespace


  Tensor<2, 3>
  with_hoop(const Tensor<2, 2> &F, const double hoop)
  {
    Tensor<2, 3> result;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        result[i][j] = F[i][j];
    result[2][2] = hoop;
    return result;
  }


  FloryRehnerGel<3>
  revolved_gel(const FloryRehnerGel<2> &gel)
  {
    return FloryRehnerGel<3>(gel.shear_modulus(),
                             gel.chi(),
                             gel.N_nu(),
                             gel.diffusivity(),
                             gel.lambda_0());
  }


  FloryRehnerGel<3>::Incremental
  axisymmetric_state(const PointRecord<2> &point,
                     const Tensor<2, 2>   &delta_F,
                     const double          du_r,
                     const double          mu,
                     const bool            with_tangent)
  {
    const double delta_hoop = 1. + du_r / point.radius;
    return revolved_gel(*point.gel)
      .incremental(with_hoop(delta_F, delta_hoop),
                   mu,
                   with_hoop(point.F_p, point.hoop),
                   with_tangent);
  }


  template <int dim>
  typename FloryRehnerGel<dim>::Incremental
  point_state(const PointRecord<dim> &point,
              const Tensor<2, dim>   &delta_F,
              const Tensor<1, dim>   &du,
              const double            mu,
              const bool              with_tangent)
  {
    if constexpr (dim == 2)
      if (point.axisymmetric())
        {
          const auto state = axisymmetric_state(point, delta_F, du[0], mu, with_tangent);
          typename FloryRehnerGel<2>::Incremental result;
          result.delta_J = state.delta_J;
          result.J       = state.J;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              {
                result.P_n[i][j]      = state.P_n[i][j];
                result.dP_n_dmu[i][j] = state.dP_n_dmu[i][j];
                for (unsigned int k = 0; k < 2; ++k)
                  for (unsigned int l = 0; l < 2; ++l)
                    result.A_n[i][j][k][l] = state.A_n[i][j][k][l];
              }
          return result;
        }
    return point.gel->incremental(delta_F, mu, point.F_p, with_tangent);
  }


  void
  assemble_axisymmetric_volume_term(const PointRecord<2> &point,
                                    const double          dt,
                                    const bool            with_matrix,
                                    AssemblyScratch<2>   &s,
                                    AssemblyCopy         &copy)
  {
    const auto state =
      axisymmetric_state(point, s.delta_F, s.du_at_point[0], s.mu_at_point, with_matrix);
    const double             V    = point.measure;
    const double             kTnu = point.gel->kT_over_nu();
    const double             m    = point.mobility;
    const unsigned int       mu0  = s.mu0();
    const VirtualDeformation B{s.N, s.G, 1. / point.radius};

    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int i = 0; i < 2; ++i)
        copy.residual(2 * a + i) += V * B.contract(state.P_n, a, i);
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) +=
        V * (-kTnu * (state.delta_J - 1.) * s.M[b] - dt * m * (s.grad_mu * s.GM[b]));
    if (!with_matrix)
      return;

    auto &L  = s.volume_lower;
    auto &AB = s.hoop_products;
    AB.resize(2 * s.n_u);
    for (unsigned int c = 0; c < s.n_u; ++c)
      for (unsigned int k = 0; k < 2; ++k)
        AB[2 * c + k] = B.apply(state.A_n, c, k);
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int col = 0; col <= 2 * a + i; ++col)
          L(2 * a + i, col) += V * B.contract(AB[col], a, i);
    for (unsigned int b = 0; b < s.n_mu; ++b)
      for (unsigned int a = 0; a < s.n_u; ++a)
        for (unsigned int i = 0; i < 2; ++i)
          L(mu0 + b, 2 * a + i) += V * B.contract(state.dP_n_dmu, a, i) * s.M[b];
    const double Vdtm = V * dt * m;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      for (unsigned int d = 0; d <= b; ++d)
        L(mu0 + b, mu0 + d) -= Vdtm * (s.GM[b] * s.GM[d]);
  }


  void
  add_axisymmetric_displacement_nitsche(const PointRecord<2> &point,
                                        const Tensor<2, 2>   &Pi,
                                        const Tensor<1, 2>   &g,
                                        const double          beta,
                                        const double          sym,
                                        const bool            with_matrix,
                                        AssemblyScratch<2>   &s,
                                        AssemblyCopy         &copy)
  {
    const double             area = point.measure;
    const auto              &N    = point.normal;
    const unsigned int       mu0  = s.mu0();
    const double             du_r = s.du_at_point[0];
    const VirtualDeformation B{s.N, s.G, 1. / point.radius};
    const auto               gel   = revolved_gel(*point.gel);
    const Tensor<2, 3>       F_p   = with_hoop(point.F_p, point.hoop);
    const Tensor<2, 3>       dF    = with_hoop(s.delta_F, 1. + du_r / point.radius);
    const auto               state = gel.incremental(dF, s.mu_at_point, F_p);
    const Tensor<2, 3>       W     = with_hoop(outer(g, N), 0.);

    Tensor<1, 2> PN, dPdmu_N;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int J = 0; J < 2; ++J)
        {
          PN[k] += state.P_n[k][J] * N[J];
          dPdmu_N[k] += state.dP_n_dmu[k][J] * N[J];
        }
    const Tensor<1, 2> Pi_PN      = Pi * PN;
    const Tensor<1, 2> Pi_dPdmu_N = Pi * dPdmu_N;
    Tensor<2, 3>       WA; // [k][L] = W_iJ A_iJkL
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int J = 0; J < 2; ++J)
            WA[k][L] += W[i][J] * state.A_n[i][J][k][L];
    const double W_dPdmu = dealii::scalar_product(W, state.dP_n_dmu);

    auto &K = copy.matrix;
    auto &r = copy.residual;
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int k = 0; k < 2; ++k)
        r(2 * a + k) +=
          area * (beta * g[k] * s.N[a] - Pi_PN[k] * s.N[a] - sym * B.contract(WA, a, k));
    for (unsigned int b = 0; b < s.n_mu; ++b)
      r(mu0 + b) -= sym * area * W_dPdmu * s.M[b];
    if (!with_matrix)
      return;

    // C_k[m][L] = Pi_ki A_iJmL N_J: the consistency term's derivative, one 3x3 tensor per k.
    Tensor<2, 3> C[2];
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int L = 0; L < 3; ++L)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int J = 0; J < 2; ++J)
              C[k][m][L] += Pi[k][i] * state.A_n[i][J][m][L] * N[J];

    // The third derivative of the energy contracted with W, by a central difference of the
    // tangent along W, symmetrised (as add_displacement_nitsche_reference()).
    Tensor<4, 3> H;
    Tensor<2, 3> DW; // d(W : dP_n/dmu)/d(dF)
    const double W_norm = W.norm();
    if (W_norm > 0.)
      {
        const double eps   = 1e-5 / W_norm;
        const auto   plus  = gel.incremental(dF + eps * W, s.mu_at_point, F_p);
        const auto   minus = gel.incremental(dF - eps * W, s.mu_at_point, F_p);
        H                  = (plus.A_n - minus.A_n) / (2. * eps);
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            for (unsigned int m = 0; m < 3; ++m)
              for (unsigned int Q = 0; Q < 3; ++Q)
                if (3 * m + Q > 3 * k + L)
                  H[k][L][m][Q] = H[m][Q][k][L] = 0.5 * (H[k][L][m][Q] + H[m][Q][k][L]);
        const auto mu_plus = gel.incremental(dF, s.mu_at_point + 1., F_p);
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int J = 0; J < 2; ++J)
                DW[k][L] += W[i][J] * (mu_plus.A_n[i][J][k][L] - state.A_n[i][J][k][L]);
      }

    auto &HB = s.hoop_products;
    HB.resize(2 * s.n_u);
    if (W_norm > 0.)
      for (unsigned int c = 0; c < s.n_u; ++c)
        for (unsigned int m = 0; m < 2; ++m)
          HB[2 * c + m] = B.apply(H, c, m);
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int c = 0; c < s.n_u; ++c)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int m = 0; m < 2; ++m)
            {
              double value = beta * Pi[k][m] * s.N[a] * s.N[c];
              value -= s.N[a] * B.contract(C[k], c, m);
              value -= sym * s.N[c] * B.contract(C[m], a, k);
              if (W_norm > 0.)
                value -= sym * B.contract(HB[2 * c + m], a, k);
              K(2 * a + k, 2 * c + m) += area * value;
            }
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int k = 0; k < 2; ++k)
        {
          const double DWB = B.contract(DW, a, k);
          for (unsigned int b = 0; b < s.n_mu; ++b)
            {
              K(2 * a + k, mu0 + b) -= area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + sym * DWB);
              K(mu0 + b, 2 * a + k) -= sym * area * s.M[b] * (s.N[a] * Pi_dPdmu_N[k] + DWB);
            }
        }
  }


  template typename FloryRehnerGel<2>::Incremental
  point_state(const PointRecord<2> &, const Tensor<2, 2> &, const Tensor<1, 2> &, double, bool);
  template typename FloryRehnerGel<3>::Incremental
  point_state(const PointRecord<3> &, const Tensor<2, 3> &, const Tensor<1, 3> &, double, bool);
} // namespace GelMPM

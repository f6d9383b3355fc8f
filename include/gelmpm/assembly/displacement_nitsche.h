#ifndef gelmpm_assembly_displacement_nitsche_h
#define gelmpm_assembly_displacement_nitsche_h

#include <gelmpm/assembly/point_assembler.h>

namespace GelMPM
{
  /**
   * The symmetric Nitsche terms of a displacement condition Pi (u - ubar) = 0 at a surface
   * point, with the violation @p g = Pi (u - ubar), penalty @p beta and symmetry @p symmetry (s):
   * the u-lines of the paper's eq. (32) (penalty, symmetry term) with the consistency term
   * -Pi (P_n N) . w of the boundary integral of eq. (26), and the mu-line's symmetry term
   * -s (g (x) N) : dP_n/dmu q:
   *   R_u[w]  += A_s [ beta g . w - Pi(P_n N) . w - s W : A_n : grad_n w ],  W = g (x) N,
   *   R_mu[q] -= s A_s (W : dP_n/dmu) q.
   * The exact tangent includes the third derivative of the energy contracted with W, so that it
   * is the Jacobian of the residual. It is taken in closed form from the structure of A_n
   * (FloryRehnerGel::Incremental: A_n,iJkL = delta_ik S_JL + a D_iL D_kJ + b D_iJ D_kL,
   * D = dF^{-T}): along W, dD = -D W^T D, d ln dJ = D : W = w, da = -b w, db = c w, so that with
   * h_a = D G_a, n = D N, p_a = g . h_a
   *   sum_LQ G_a[L] H_kLmQ G_c[Q] = -b w h_c[k] h_a[m] + c w h_a[k] h_c[m]
   *        - a (p_c n[k] h_a[m] + p_a h_c[k] n[m]) - b (p_a n[k] h_c[m] + p_c h_a[k] n[m])
   * for H = dA_n/d(dF) : W (H_kLmQ = sum_iJ dA_n,kLmQ/d(dF)_iJ W_iJ),
   * a few products per entry, and d(W : dP_n/dmu)/d(dF) G_a = (k_BT/nu) dJ (p_a n - w h_a).
   * With @p reference_tangent it is add_displacement_nitsche_reference() instead. Shared by the
   * prescribed displacements (DisplacementNitscheAssembler) and the Nitsche variant of plane
   * contact (ContactAssembler: a roller on the obstacle while active). Axisymmetric points go to
   * add_axisymmetric_displacement_nitsche().
   */
  template <int dim>
  void
  add_displacement_nitsche(const PointRecord<dim>       &point,
                           const dealii::Tensor<2, dim> &Pi,
                           const dealii::Tensor<1, dim> &g,
                           const double                  beta,
                           const double                  symmetry,
                           const bool                    with_matrix,
                           AssemblyScratch<dim>         &scratch,
                           AssemblyCopy                 &copy,
                           const bool                    reference_tangent = false);


  /**
   * Starts a block whose displacement Nitsche tangents add_displacement_nitsche() gathers as
   * factors (with @p batched; otherwise each point adds its tangent at once), to be added by
   * add_displacement_nitsche_block().
   */
  template <int dim>
  void
  start_displacement_nitsche_block(AssemblyScratch<dim> &scratch, const bool batched);
  /**
   * Adds the displacement-displacement part of the gathered Nitsche tangents of the block to
   * @p copy (both triangles, as VolumeTermAssembler::add_block_tangent() does) and closes the
   * block (nothing if it is closed, so that each term that gathers into it may call this): two
   * dgemm, of which the inner dimension is 3 + 2 dim resp. 4 per point, instead of the closed
   * form's loop over the pairs of functions of every point.
   */
  template <int dim>
  void
  add_displacement_nitsche_block(AssemblyScratch<dim> &scratch, AssemblyCopy &copy);
  /**
   * add_displacement_nitsche() with the third-derivative term of the tangent by a central
   * difference of A_n along W (two more evaluations of the gel, step 1e-5 / |W|, symmetrised;
   * about 1e-9 accurate) and d(W : dP_n/dmu)/d(dF) by a difference in mu (exact, P_n is affine
   * in mu), contracted with the dim^4 entries: the former assembly, kept as the reference the
   * closed form is tested against (tests/assembly/nitsche_tangent). The same residual.
   */
  template <int dim>
  void
  add_displacement_nitsche_reference(const PointRecord<dim>       &point,
                                     const dealii::Tensor<2, dim> &Pi,
                                     const dealii::Tensor<1, dim> &g,
                                     const double                  beta,
                                     const double                  symmetry,
                                     const bool                    with_matrix,
                                     AssemblyScratch<dim>         &scratch,
                                     AssemblyCopy                 &copy);


  /**
   * @brief The Nitsche terms of a prescribed displacement (paper eq. (32), u-lines, and the
   * mu-line's u symmetry term) at the surface points of a piece whose displacement is given
   * (fixed, normal or tangential: Pi = I, N_0 (x) N_0 or I - N_0 (x) N_0, PointRecord::projector).
   *
   * add_displacement_nitsche() with g = Pi (u_n + du - ubar) and beta_u = gamma_u G / h_u, and
   * the solvent of the u symmetry term at the start of the step subtracted,
   *   R_mu[q] += s A_s ((g_n (x) N) : dP_n/dmu)|_(t_n) q   (PointRecord::adjoint_solvent_n),
   * as the volume points subtract J_n: otherwise the violation g left by every step would add
   * solvent again at the next (doc/method.md).
   */
  template <int dim>
  class DisplacementNitscheAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    /** With the tangent: start_displacement_nitsche_block(). */
    void
    start_block(AssemblyScratch<dim> &scratch,
                const unsigned int    n_points,
                const bool            with_matrix) const override;

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;

    /** With the tangent: add_displacement_nitsche_block(). */
    void
    finish_block(AssemblyScratch<dim> &scratch,
                 AssemblyCopy         &copy,
                 const bool            with_matrix) const override;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_assembly_volume_term_h
#define gelmpm_assembly_volume_term_h

#include <gelmpm/assembly/point_assembler.h>

namespace GelMPM
{
  /**
   * @brief The volume integrals of the weak form at a volume point: the Flory–Rehner stress and
   * the solvent balance with its diffusive flux.
   *
   * The paper's eq. (26) (first term) and eq. (31) (volume term), integrated with the volume
   * points as quadrature (eq. (33)) in the previously-converged configuration (eq. (25), (28)–
   * (30)), the mu equation multiplied by k_BT:
   *   R_u[w]  += V_p P_n : grad_n w,
   *   R_mu[q] += V_p [ -(k_BT/nu)(Delta J - 1) q - dt m_p grad_n mu . grad_n q ],
   * with P_n, Delta J and A_n = dP_n/dDelta F from FloryRehnerGel::incremental() (eq. (19)) and
   * the mobility m_p of eq. (21) frozen over the step (PointRecord::mobility).
   *
   * The tangent of a volume point is symmetric (A has the major symmetry and K_mu,u = K_u,mu^T):
   * only its lower triangle is summed, into AssemblyScratch::volume_lower, which finish_block()
   * mirrors once per block.
   *
   * The displacement block of the tangent is contracted with the structure of A_n
   * (FloryRehnerGel::Incremental::S, dFit, a, b) rather than with its dim^4 entries:
   *   K(a,i; c,k) = V_p [delta_ik G_a . S G_c + a h_a[k] h_c[i] + b h_a[i] h_c[k]],
   * h_a = dF^{-T} G_a, two products per entry instead of dim (doc/performance.md, "Assembly at its
   * flop limit"). The contraction with A_n (the former assembly) is kept as the reference this is
   * tested against (tests/assembly/volume_tangent), selected by TangentOptions::generic_volume.
   *
   * In 3D the points of a block (one background cell) share their functions, and the sums over
   * the points are matrix products: the factors h_p, G_p, S_p G_p, M_p and grad M_p of the
   * block's volume points are gathered (gather_tangent()) and contracted once per block by
   * dgemm (add_block_tangent()), whose kernels use the machine's vector instructions.
   */
  template <int dim>
  class VolumeTermAssembler final : public PointAssembler<dim>
  {
  public:
    /** With the tangent formed as @p tangent says (TangentOptions::generic_volume: contracted
     * with the entries of A_n; pointwise_volume: summed point by point; batched()). */
    explicit VolumeTermAssembler(const TangentOptions &tangent)
      : tangent(tangent)
    {}

    bool
    at_volume_points() const override
    {
      return true;
    }

    /**
     * Before the points of a block of at most @p n_points points, with the tangent: an empty
     * batch (batched()), or else an empty lower triangle AssemblyScratch::volume_lower.
     */
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

    /**
     * After the points of a block, with the tangent: add_block_tangent() (batched()), or else the
     * lower triangle summed point by point, mirrored, into @p copy's matrix.
     */
    void
    finish_block(AssemblyScratch<dim> &scratch,
                 AssemblyCopy         &copy,
                 const bool            with_matrix) const override;

    /**
     * After the points of a block: the tangent of its volume points from the batch, by five
     * matrix products (BLAS dgemm) over the points instead of one sum per point and entry,
     * added to @p copy's matrix whole (both triangles).
     */
    void
    add_block_tangent(AssemblyScratch<dim> &scratch, AssemblyCopy &copy) const;

    /**
     * Whether this assembler batches the tangent of the block's volume points (in 3D, unless
     * TangentOptions says otherwise); the displacement Nitsche terms batch theirs likewise
     * (start_displacement_nitsche_block()).
     */
    bool
    batched() const
    {
      return tangent.batched<dim>();
    }

  private:
    /** The point's factors of the tangent into the block's batch (see add_block_tangent()). */
    void
    gather_tangent(const PointRecord<dim>                          &point,
                   const typename FloryRehnerGel<dim>::Incremental &state,
                   const double                                     dt,
                   AssemblyScratch<dim>                            &scratch) const;

    /** The lower triangle of the point's tangent from the structure of A_n. */
    void
    add_structured_tangent(const PointRecord<dim>                          &point,
                           const typename FloryRehnerGel<dim>::Incremental &state,
                           const double                                     dt,
                           AssemblyScratch<dim>                            &scratch) const;

    /** The lower triangle of the point's tangent from the entries of A_n (the reference). */
    void
    add_generic_tangent(const PointRecord<dim>                          &point,
                        const typename FloryRehnerGel<dim>::Incremental &state,
                        const double                                     dt,
                        AssemblyScratch<dim>                            &scratch) const;

    const TangentOptions &tangent;
  };
} // namespace GelMPM

#endif

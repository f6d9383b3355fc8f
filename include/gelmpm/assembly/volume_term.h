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
   * only its lower triangle is summed, into AssemblyScratch::volume_lower, which the caller
   * mirrors once per block (MixedSystem::assemble_block()).
   */
  template <int dim>
  class VolumeTermAssembler final : public PointAssembler<dim>
  {
  public:
    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;
  };
} // namespace GelMPM

#endif

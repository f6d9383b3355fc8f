#ifndef gelmpm_assembly_chemical_potential_nitsche_h
#define gelmpm_assembly_chemical_potential_nitsche_h

#include <gelmpm/assembly/contact.h>
#include <gelmpm/assembly/point_assembler.h>

namespace GelMPM
{
  /**
   * @brief The Nitsche terms of a prescribed chemical potential at the surface points of a
   * piece whose mu is given: the mu-line of the paper's eq. (32) (penalty and symmetry terms)
   * with the consistency term, the boundary integral of eq. (31) with i_n = -j_n . N_n, all
   * multiplied by k_BT as the volume term:
   *   R_mu[q] += dt A_s [ m (grad_n mu . N) q + s m (grad_n q . N)(mu - mubar)
   *                       - beta_mu (mu - mubar) q ],   beta_mu = gamma_mu m / h_mu,
   * with the point's frozen mobility m (PointRecord::mobility). Linear in mu: its tangent is
   * exact.
   *
   * The sign of the symmetry term is the one that makes the tangent symmetric for s = 1; with
   * the sign printed in eq. (32) the mu block would be skew.
   *
   * Where an impermeable obstacle touches the point (ContactAssembler::seals(), in the Newton
   * iterate's active set) the condition is off: the contact seals the surface (zero flux).
   */
  template <int dim>
  class ChemicalPotentialNitscheAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    /** Take the obstacles that may seal the surface from @p contact (which must outlive this). */
    void
    set_contact(const ContactAssembler<dim> &contact);

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;

  private:
    const ContactAssembler<dim> *contact = nullptr;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_assembly_neumann_terms_h
#define gelmpm_assembly_neumann_terms_h

#include <gelmpm/assembly/point_assembler.h>

namespace GelMPM
{
  /**
   * @brief The prescribed traction at the surface points of a piece: the boundary integral of
   * the paper's eq. (26) (T_n = P_n N_n, eq. (15), (28)) on the displacement components the piece
   * leaves free,
   *   R_u[w] -= A_s ((I - Pi) T) . w,
   * Pi the projector of the constrained components (PointRecord::projector); nothing on a fixed
   * piece. T is the piece's "Traction" at the end of the step (PointRecord::traction).
   */
  template <int dim>
  class TractionAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;
  };


  /**
   * @brief The prescribed solvent flux at the surface points of a piece whose chemical potential
   * is not given: the boundary integral of the paper's eq. (31), multiplied by k_BT,
   *   R_mu[q] += dt A_s (k_BT/nu) (nu i) q,
   * with nu i the piece's "Flux" (solvent volume per area and time, PointRecord::flux).
   */
  template <int dim>
  class SolventFluxAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;
  };
} // namespace GelMPM

#endif

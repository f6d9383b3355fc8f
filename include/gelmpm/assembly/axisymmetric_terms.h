#ifndef gelmpm_assembly_axisymmetric_terms_h
#define gelmpm_assembly_axisymmetric_terms_h

#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/tensor.h>

namespace GelMPM
{
  /**
   * @name Axisymmetric kinematics (doc/axisymmetric.md)
   *
   * In an axisymmetric scene the 2D grid is the meridian plane (x = R, y = z) of a body of
   * revolution. A point's deformation gradient is the 3D tensor with the in-plane block F and the
   * hoop stretch F_33 = r/R (times lambda_0 from the dry state); a displacement increment du adds
   * Delta F_33 = 1 + du_r / r_n. The gel is the three-dimensional Flory–Rehner gel of the same
   * constants, evaluated on these tensors; volumes and areas are those of the revolved body
   * (PointRecord::measure includes 2 pi r_n). The weak form's virtual deformation of the radial
   * test function N_a e_r has the extra hoop entry N_a / r_n.
   */
  /** @{ */

  /** The 3D tensor with the in-plane block @p F and the hoop entry @p hoop at [2][2]. */
  dealii::Tensor<2, 3>
  with_hoop(const dealii::Tensor<2, 2> &F, const double hoop);

  /** The three-dimensional gel of the constants of @p gel. */
  FloryRehnerGel<3>
  revolved_gel(const FloryRehnerGel<2> &gel);

  /**
   * The incremental state (FloryRehnerGel<3>::incremental()) at an axisymmetric point at the
   * in-plane increment @p delta_F and the radial displacement @p du_r.
   */
  FloryRehnerGel<3>::Incremental
  axisymmetric_state(const PointRecord<2>       &point,
                     const dealii::Tensor<2, 2> &delta_F,
                     const double                du_r,
                     const double                mu,
                     const bool                  with_tangent = true);

  /**
   * The incremental state at @p point as the in-plane quantities of the weak form's boundary
   * terms (P_n, its tangent and its mu derivative restricted to the plane; Delta J and J of the
   * whole deformation): FloryRehnerGel::incremental() in a Cartesian scene, the restriction of
   * axisymmetric_state() in an axisymmetric one.
   */
  template <int dim>
  typename FloryRehnerGel<dim>::Incremental
  point_state(const PointRecord<dim>       &point,
              const dealii::Tensor<2, dim> &delta_F,
              const dealii::Tensor<1, dim> &du,
              const double                  mu,
              const bool                    with_tangent = true);

  /**
   * The volume term of VolumeTermAssembler at an axisymmetric point:
   *   R_u[w] += V (P_n : grad_n w + P_n,33 w_r / r_n),  V = 2 pi r_n A_n,
   * the mu line with Delta J of the 3D increment, and the exact (symmetric) tangent, summed into
   * the lower triangle AssemblyScratch::volume_lower as the Cartesian term does.
   */
  void
  assemble_axisymmetric_volume_term(const PointRecord<2> &point,
                                    const double          dt,
                                    const bool            with_matrix,
                                    AssemblyScratch<2>   &scratch,
                                    AssemblyCopy         &copy);

  /**
   * add_displacement_nitsche() at an axisymmetric point: the same terms with the 3D stress and
   * tangent and the hoop entry of the test functions' virtual deformation.
   */
  void
  add_axisymmetric_displacement_nitsche(const PointRecord<2>       &point,
                                        const dealii::Tensor<2, 2> &Pi,
                                        const dealii::Tensor<1, 2> &g,
                                        const double                beta,
                                        const double                symmetry,
                                        const bool                  with_matrix,
                                        AssemblyScratch<2>         &scratch,
                                        AssemblyCopy               &copy);
  /** @} */
} // namespace GelMPM

#endif

#ifndef gelmpm_assembly_plane_contact_h
#define gelmpm_assembly_plane_contact_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/point_assembler.h>

#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The contact of free surfaces with the planes of symmetry of the "Contact" section
   * (ContactSettings) at the surface points of a piece whose displacement is free. Not a term of
   * the paper: the unilateral condition g = (x - x_plane) . n <= 0 of a pore that closes onto its
   * mirror image (doc/method.md), imposed
   * - by a penalty: R_u[w] += A_s beta_c max(g, 0) n . w, beta_c = gamma_c G / h_u;
   * - or by Nitsche's method: the terms of a roller on the plane (add_displacement_nitsche()
   *   with Pi = n (x) n, g n and beta_c) where beta_c g - n . (P_n N) > 0, Nitsche's active set.
   * The active set is that of the Newton iterate (semi-smooth Newton). Off (nothing added) until
   * set_settings() enables it.
   */
  template <int dim>
  class PlaneContactAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    /** Use @p settings, with the planes on the sides of the background grid they name. */
    void
    set_settings(const ContactSettings &settings);

    /** Whether contact is imposed at all. */
    bool
    enabled() const;

    /** Whether the grid side of direction @p axis, lower (@p sign -1) or upper (+1), is a
     * contact plane. */
    bool
    on_contact_plane(const unsigned int axis, const double sign) const;

    /**
     * Whether the contact condition is active at the surface point @p point of a free piece
     * with the fields @p du, @p delta_F and @p mu at it, and its largest penetration max(g)
     * over the planes (which may be negative: the distance to the nearest plane).
     */
    std::pair<bool, double>
    state(const PointRecord<dim>       &point,
          const dealii::Tensor<1, dim> &du,
          const dealii::Tensor<2, dim> &delta_F,
          const double                  mu) const;

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;

  private:
    ContactSettings                     contact;
    std::vector<ContactSettings::Plane> planes;
  };
} // namespace GelMPM

#endif

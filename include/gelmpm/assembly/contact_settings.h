#ifndef gelmpm_assembly_contact_settings_h
#define gelmpm_assembly_contact_settings_h

#include <gelmpm/assembly/self_contact_settings.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Contact" section: keeps free surfaces from crossing planes of symmetry.
   *
   * A scene that models one cell of a periodic or mirror-symmetric structure (§4.4: one cell of
   * a lattice of holes) has the cell's edges as planes of reflection. Material that reaches such
   * a plane meets its mirror image there: the two sides of a closing pore touch. The condition is
   * unilateral, g = (x - x_plane).n <= 0 with n the plane's outward normal, imposed on every
   * surface point of a piece whose displacement is free:
   * - penalty: beta_c max(g, 0) n on the points that penetrate (beta_c = gamma_c G / h_u); the
   *   penetration of a loaded contact is of order (normal stress)/beta_c;
   * - nitsche: the symmetric Nitsche terms of a roller on the points where f beta_c g - sigma_n >
   *   0 (sigma_n = n.(P_n N) the normal traction, negative in compression; f = 'Active set
   *   factor', 1 for the augmented active set of Nitsche's method for contact); consistent, so
   *   the penetration vanishes with the mesh.
   * Either way the active set is that of the current Newton iterate (semi-smooth Newton).
   *
   * The same terms keep the free surfaces out of the rigid obstacles named in 'Obstacles'
   * (Obstacle: planes, spheres, flat punches with a prescribed motion), each with a subsection
   * of its own; the grid sides are fixed plane obstacles (ContactAssembler).
   */
  struct ContactSettings
  {
    enum class Method
    {
      none,
      penalty,
      nitsche
    };

    /** One contact plane: x[axis] = value, outward normal sign * e_axis. */
    struct Plane
    {
      unsigned int axis;
      double       value;
      double       sign;
    };

    Method method = Method::none;
    /** gamma_c: beta_c = gamma_c G / h_u. */
    double penalty = 1000.;
    /** f of Nitsche's active set f beta_c g - sigma_n > 0 ('Active set factor'; 1: the augmented
     * active set). */
    double active_set_factor = 1.;
    /** The sides of the background grid that are contact planes (left, right, bottom, top,
     * front, back). */
    std::vector<std::string> sides;

    bool
    enabled() const
    {
      return method != Method::none;
    }

    /** The contact planes on the grid [@p lower, @p upper]. */
    template <int dim>
    std::vector<Plane>
    planes(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The subsection 'Self contact': the gel's boundary against itself (off by default,
     * independent of 'Method'). */
    SelfContactSettings self_contact;

    /** The names of the rigid obstacles ('Contact/Obstacles', read by SceneStructure). */
    std::vector<std::string> obstacles;

    /** Read the section; @p dim rejects sides a 2D grid does not have; @p obstacles are the
     * names of the rigid obstacles. */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const unsigned int              dim,
                     const std::vector<std::string> &obstacles = {});
  };
} // namespace GelMPM

#endif

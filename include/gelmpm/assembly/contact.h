#ifndef gelmpm_assembly_contact_h
#define gelmpm_assembly_contact_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/scene/obstacle.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The frictionless contact of free surfaces with the obstacles of the "Contact" section
   * (ContactSettings): the planes of symmetry on the grid's sides ('Grid sides', fixed plane
   * obstacles) and the rigid obstacles with a prescribed motion ('Obstacles'), at the surface
   * points of a piece whose displacement is free. Not a term of the paper: the unilateral
   * condition g <= 0 on the gap g (the penetration, Obstacle::gap(), along the direction m into
   * the obstacle; doc/method.md), imposed
   * - by a penalty: R_u[w] += A_s beta_c max(g, 0) m . w, beta_c = gamma_c G / h_u, with its
   *   exact tangent (including the curvature of a sphere);
   * - or by Nitsche's method: the terms of a roller on the obstacle's surface
   *   (add_displacement_nitsche() with Pi = m (x) m, g m and beta_c) where f beta_c g -
   *   m . (P_n N) > 0, Nitsche's active set (f = 'Active set factor', 1: the augmented one).
   * The active set is that of the Newton iterate (semi-smooth Newton); under Nitsche's method,
   * for the rigid obstacles, that of an earlier iterate where Newton holds it
   * (PointRecord::contact_held, active_rigid(), MixedSystem::freeze_switches()): at a rounded
   * edge points slide into and out of contact from one iterate to the next, and the residual
   * jumps with them. The obstacles are summed
   * in their order, the grid sides first. The grid sides are the term's own; the rigid obstacles
   * are the scene's (Scene::obstacles), which the term reads where they are and does not copy:
   * their owner moves them (MixedSystem::set_boundary_values()). Off (nothing added) until
   * set_settings() enables it.
   */
  template <int dim>
  class ContactAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    /** Use @p settings, with the planes on the sides of the background grid they name, and the
     * rigid @p obstacles after them (none if nullptr; they must outlive the term). */
    void
    set_settings(const ContactSettings &settings, const std::vector<Obstacle<dim>> *obstacles);

    /** With the tangent, Nitsche's method: start_displacement_nitsche_block(). */
    void
    start_block(AssemblyScratch<dim> &scratch,
                const unsigned int    n_points,
                const bool            with_matrix) const override;

    /** With the tangent, Nitsche's method: add_displacement_nitsche_block(). */
    void
    finish_block(AssemblyScratch<dim> &scratch,
                 AssemblyCopy         &copy,
                 const bool            with_matrix) const override;

    /** Whether contact is imposed at all. */
    bool
    enabled() const;

    /** Whether the grid side of direction @p axis, lower (@p sign -1) or upper (+1), is a
     * contact plane. */
    bool
    on_contact_plane(const unsigned int axis, const double sign) const;

    /** The number of rigid obstacles (those of 'Contact/Obstacles', not the grid sides). */
    unsigned int
    n_rigid_obstacles() const;

    /** The rigid obstacle @p k (0 for the first of 'Contact/Obstacles'). */
    const Obstacle<dim> &
    rigid_obstacle(const unsigned int k) const;

    /**
     * Whether the contact condition with the obstacle @p k (all obstacles, the grid sides first)
     * is active at the surface point @p point of a free piece with the fields @p du, @p delta_F
     * and @p mu at it, and its penetration g (-infinity where it cannot touch).
     */
    std::pair<bool, double>
    state(const unsigned int            k,
          const PointRecord<dim>       &point,
          const dealii::Tensor<1, dim> &du,
          const dealii::Tensor<2, dim> &delta_F,
          const double                  mu) const;

    /**
     * Whether the contact condition is active at the surface point @p point of a free piece for
     * any obstacle, and its largest penetration max(g) over them (which may be negative: the
     * distance to the nearest).
     */
    std::pair<bool, double>
    state(const PointRecord<dim>       &point,
          const dealii::Tensor<1, dim> &du,
          const dealii::Tensor<2, dim> &delta_F,
          const double                  mu) const;

    /**
     * Whether an impermeable obstacle (Obstacle::permeable false) is in active contact with the
     * surface point @p point with the fields @p du, @p delta_F and @p mu at it (the Newton
     * iterate's active set).
     */
    bool
    touches_impermeable(const PointRecord<dim>       &point,
                        const dealii::Tensor<1, dim> &du,
                        const dealii::Tensor<2, dim> &delta_F,
                        const double                  mu) const;

    /**
     * The rigid obstacles in active contact with @p point for the fields @p du, @p delta_F and
     * @p mu at it, bit k for the rigid obstacle k (the iterate's active set; at most 63).
     */
    std::int64_t
    active_rigid(const PointRecord<dim>       &point,
                 const dealii::Tensor<1, dim> &du,
                 const dealii::Tensor<2, dim> &delta_F,
                 const double                  mu) const;

    /** Whether Newton holds the rigid obstacles' active set (Nitsche's method, rigid obstacles). */
    bool
    holds_active_set() const
    {
      return contact.method == ContactSettings::Method::nitsche && n_rigid_obstacles() > 0;
    }

    /** Whether some rigid obstacle is impermeable (seals the points it touches). */
    bool
    seals_anywhere() const
    {
      return any_impermeable;
    }

    /**
     * Whether the chemical-potential condition at @p point is off: the seal held for Newton's
     * iterations (PointRecord::seal), or else touches_impermeable().
     */
    bool
    seals(const PointRecord<dim>       &point,
          const dealii::Tensor<1, dim> &du,
          const dealii::Tensor<2, dim> &delta_F,
          const double                  mu) const;

    /** Whether the term applies at @p point at all (contact on, a free piece). */
    bool
    applies(const PointRecord<dim> &point) const;

    /** The terms of the obstacle @p k (all obstacles, the grid sides first) at @p point. */
    void
    assemble_obstacle(const unsigned int      k,
                      const PointRecord<dim> &point,
                      const bool              with_matrix,
                      AssemblyScratch<dim>   &scratch,
                      AssemblyCopy           &copy) const;

    /** The index among all obstacles of the rigid obstacle @p k. */
    unsigned int
    index_of_rigid(const unsigned int k) const;

    void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const override;

  private:
    /** The traction P_n N at @p point for Nitsche's method (zero for the penalty, which needs
     * none). */
    dealii::Tensor<1, dim>
    nitsche_traction(const PointRecord<dim> &point, const AssemblyScratch<dim> &scratch) const;

    /**
     * The terms of @p obstacle at @p point, with the point's traction P_n N (Nitsche); @p held:
     * whether it is active as held for Newton's iterations (1, 0), or -1 as the iterate says.
     */
    void
    add_obstacle(const Obstacle<dim>          &obstacle,
                 const PointRecord<dim>       &point,
                 const dealii::Tensor<1, dim> &traction,
                 const bool                    with_matrix,
                 AssemblyScratch<dim>         &scratch,
                 AssemblyCopy                 &copy,
                 const int                     held = -1) const;

    /** For add_obstacle(): the held state of the rigid obstacle @p k at @p point, or -1. */
    static int
    held_state(const PointRecord<dim> &point, const unsigned int k)
    {
      return point.contact_held < 0 ? -1 : static_cast<int>((point.contact_held >> k) & 1);
    }

    /** The contact penalty beta_c at @p point. */
    double
    penalty(const PointRecord<dim> &point) const;

    /** The current position x_n + du of @p point. */
    static dealii::Point<dim>
    position(const PointRecord<dim> &point, const dealii::Tensor<1, dim> &du);

    /** The obstacle @p k: the grid sides, then the rigid obstacles. */
    const Obstacle<dim> &
    obstacle(const unsigned int k) const;

    /** The number of obstacles, grid sides and rigid ones. */
    unsigned int
    n_obstacles() const;

    ContactSettings contact;
    /** The planes of symmetry on the grid's sides, fixed plane obstacles. */
    std::vector<Obstacle<dim>> sides;
    /** The scene's rigid obstacles (nullptr: none). */
    const std::vector<Obstacle<dim>> *rigid = nullptr;
    /** Whether any obstacle is impermeable. */
    bool any_impermeable = false;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_scene_obstacle_h
#define gelmpm_scene_obstacle_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A rigid obstacle of the "Contact" section: a plane, a sphere (a circle in 2D) or a
   * flat-ended punch, moved by a prescribed displacement of its reference point. The sides of the
   * background grid that are planes of symmetry ('Contact/Grid sides') are fixed plane obstacles
   * (grid_side()), so that one contact term (ContactAssembler) serves both.
   *
   * One object per obstacle of 'Contact/Obstacles', owned by the scene (Scene::obstacles): it
   * knows its motion and where it is at the time of its last set_time(). The contact term refers
   * to it without a copy, the mixed system moves it to the end of each step
   * (MixedSystem::set_boundary_values()), the step control asks it how far it travels in a step
   * (travel()) and the scene's checks move it over the run's times and back to t = 0.
   *
   * Geometry, with c(t) = 'Center' + 'Motion'(t) the reference point at time t (in tau_d) and nu
   * the unit 'Normal' (the outward normal of the obstacle's face: from the obstacle towards the
   * gel):
   * - plane: the obstacle fills (x - c).nu < 0; gap g = -(x - c).nu;
   * - sphere: the ball |x - c| < R; g = R - |x - c|;
   * - flat punch: the half-space behind its face, (x - c).nu < 0, within the distance R of the
   *   axis through c along nu (a strip of half-width R in 2D, a disk of radius R in 3D); g =
   *   -(x - c).nu there. Beyond the face's edge (r > R, r the distance from the axis) the edge is
   *   rounded by a quarter circle of radius rho ('Edge radius'; a quarter torus in 3D) whose
   *   centre q = c + R e_r - rho nu lies at depth rho behind the edge (e_r the radial
   *   direction): g = rho - |x - q| and m = (q - x)/|x - q| there, as long as x lies in front of
   *   the centre, (x - c).nu >= -rho; no contact elsewhere beyond the edge (the punch's side is
   *   not modelled). g and m are continuous across r = R; rho = 0 is a sharp edge (no contact
   *   beyond r = R, g and m jump there).
   * The gap g is the penetration (positive inside) and m = -nu (plane, punch face) or
   * (c - x)/|x - c| (sphere) the direction of penetration, the obstacle's inward normal at the
   * closest point of its surface: the force on the gel at a penetrating point is along -m.
   */
  template <int dim>
  class Obstacle
  {
  public:
    enum class Shape
    {
      plane,
      sphere,
      flat_punch
    };

    /** The contact geometry of a point against the obstacle. */
    struct Gap
    {
      /** Whether the point can touch the obstacle at all (false beyond a punch's edge). */
      bool possible = false;
      /** The penetration g (positive inside). */
      double g = 0.;
      /** The unit direction m of penetration. */
      dealii::Tensor<1, dim> m;
      /** The derivative of m with respect to the point's position: -(I - m (x) m)/|x - c| for
       * a sphere, -(I - m (x) m)/|x - q| + R (I - nu (x) nu - e_r (x) e_r)/(r |x - q|) on a
       * punch's rounded edge (the second term the turn of e_r in 3D), zero on flat faces. */
      dealii::Tensor<2, dim> dm_dx;
    };

    /** The fixed plane x[@p axis] = @p value whose outward normal (out of the grid) is @p sign
     * e_axis, named @p name: a side of the background grid. */
    static Obstacle
    grid_side(const std::string &name,
              const unsigned int axis,
              const double       value,
              const double       sign);

    /** Declare the subsection 'Contact/<name>' of the obstacle @p name (in "Contact"). */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::string &name);

    /** Read and check the subsection of the obstacle @p name (in "Contact"); throws
     * InputError. */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &name);

    /** Move the obstacle to time @p t (in tau_d): c(t) = center + motion(t). */
    void
    set_time(const double t);

    /** The reference point c(t) at the time of the last set_time(). */
    const dealii::Point<dim> &
    reference_point() const;

    /**
     * How far the obstacle travels in the step [@p t_begin, @p t_end]: the largest distance of
     * its reference point from where it is at @p t_begin, sampled at 8 times within the step
     * (its end included), so that a motion that goes and comes back within the step counts.
     */
    double
    travel(const double t_begin, const double t_end) const;

    /**
     * The largest travel() of an obstacle in one step, in cells of the displacement grid (the
     * step control shortens the steps to it, MaterialPointModel::bound_step()). Contact is
     * found at the end of a step only: an obstacle that travels farther than the body is thick
     * in one step passes through it unseen (a sphere moving 0.8 per step crossed a post 0.5
     * wide without a contact force). Half a cell keeps every feature the grid resolves (a cell
     * or more) from being jumped over, and bounds the penetration that one step's Newton
     * iteration must push back to half a cell (the rigid flat punch's ramp moves it 0.36 cells
     * per step, prm/flat_punch_rigid.prm).
     */
    static constexpr double largest_travel_in_cells = 0.5;

    /** The gap of the current position @p x. */
    Gap
    gap(const dealii::Point<dim> &x) const;

    /** The distance of @p x from the obstacle's axis, the line through c(t) along the normal
     * (the contact radius of the points in contact). */
    double
    distance_from_axis(const dealii::Point<dim> &x) const;

    /** Throw InputError unless the obstacle reaches into the grid [@p lower, @p upper] at t =
     * 0: its reference point (plane) or its extent (sphere, punch). */
    void
    check_inside_grid(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper);

    /** Throw InputError if the motion is not finite at one of @p times. Leaves the obstacle at
     * t = 0. */
    void
    check_motion(const std::vector<double> &times);

    /** The obstacle's name (its subsection, the prefix of its statistics columns). */
    std::string name;
    Shape       shape = Shape::plane;
    /** The reference point at t = 0 ('Center'). */
    dealii::Point<dim> center;
    /** Radius of a sphere, of a punch's face (half-width in 2D). */
    double radius = 1.;
    /** The radius rho of the rounded edge of a flat punch ('Edge radius'); 0: a sharp edge. */
    double edge_radius = 0.;
    /** The default 'Edge radius' of a flat punch, as a fraction of its 'Radius'. */
    static constexpr double default_edge_fraction = 0.05;
    /** The unit outward normal nu of the face (plane, punch), the axis of a sphere. */
    dealii::Tensor<1, dim> normal;
    /** Whether solvent passes through the obstacle where it touches the gel ('Permeable'):
     * false seals the surface points in active contact (no chemical-potential condition there,
     * hence no flux). */
    bool permeable = true;

  private:
    /** The displacement of the reference point over time; none for a grid side. */
    std::shared_ptr<dealii::Functions::ParsedFunction<dim>> motion;
    dealii::Point<dim>                                      current_center;

    /** The motion's value at @p t. */
    dealii::Tensor<1, dim>
    displacement(const double t) const;
  };


  /**
   * Declare the subsections of the obstacles @p names in "Contact" (Obstacle::declare_parameters).
   */
  template <int dim>
  void
  declare_obstacles(dealii::ParameterHandler &prm, const std::vector<std::string> &names);

  /** Read the obstacles @p names of "Contact"; throws InputError. */
  template <int dim>
  std::vector<Obstacle<dim>>
  parse_obstacles(dealii::ParameterHandler &prm, const std::vector<std::string> &names);
} // namespace GelMPM

#endif

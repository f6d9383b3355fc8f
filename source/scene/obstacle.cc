#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/scene/expression.h>
#include <gelmpm/scene/obstacle.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    const char *shape_names = "plane | sphere | flat punch";

    std::string
    number(const double x)
    {
      if (std::isnan(x))
        return "NaN"; // not "-nan" or "nan" as the sign bit happens to be
      std::ostringstream text;
      text << x;
      return text.str();
    }


    /** The gap of a point at @p e from the centre of a ball of radius @p R into @p result (not
     * possible at the centre): g = R - |e|, m = -e/|e|, dm/dx = -(I - m (x) m)/|e|. */
    template <typename Gap, int dim>
    void
    ball_gap(const dealii::Tensor<1, dim> &e, const double R, Gap &result)
    {
      const double d = e.norm();
      if (d == 0.)
        return;
      result.possible = true;
      result.g        = R - d;
      result.m        = -e / d;
      result.dm_dx =
        -(dealii::unit_symmetric_tensor<dim>() - dealii::outer_product(result.m, result.m)) / d;
    }
  } // namespace


  template <int dim>
  Obstacle<dim>
  Obstacle<dim>::grid_side(const std::string &name,
                           const unsigned int axis,
                           const double       value,
                           const double       sign)
  {
    Obstacle<dim> side;
    side.name         = name;
    side.shape        = Shape::plane;
    side.center[axis] = value;
    // Into the grid: the outward normal of the obstacle beyond the side.
    side.normal[axis]   = -sign;
    side.current_center = side.center;
    return side;
  }


  template <int dim>
  void
  Obstacle<dim>::declare_parameters(dealii::ParameterHandler &prm, const std::string &name)
  {
    using namespace dealii;
    prm.enter_subsection(name);
    prm.declare_entry("Shape",
                      "plane",
                      Patterns::Anything(),
                      std::string("The obstacle's shape: ") + shape_names +
                        ". plane: the half-space behind the plane through 'Center' with the "
                        "outward normal 'Normal'; sphere: the ball (a disk in 2D) of 'Radius' "
                        "about 'Center'; flat punch: a rigid punch whose flat face, centred at "
                        "'Center' with the outward normal 'Normal', has the radius 'Radius' (a "
                        "half-width in 2D), its edge rounded by a quarter circle of 'Edge "
                        "radius' beyond it. Frictionless, imposed as 'Method' says "
                        "(doc/method.md, \"Contact\").");
    prm.declare_entry("Center",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "The obstacle's reference point at t = 0, one coordinate per direction: a "
                      "point of the plane, the centre of the sphere, the centre of the punch's "
                      "face. The contact radius of the statistics is measured from the axis "
                      "through it along 'Normal'.");
    prm.declare_entry("Radius",
                      "1",
                      Patterns::Anything(),
                      "Sphere: its radius; flat punch: the radius of its face (in 2D its "
                      "half-width). Not used by a plane.");
    prm.declare_entry("Edge radius",
                      "",
                      Patterns::Anything(),
                      "Flat punch: the radius of its rounded edge, a quarter circle (3D: a quarter "
                      "torus) beyond the face's edge that meets the face tangentially, so that the "
                      "gap and the contact direction of a point sliding off the face are "
                      "continuous. The face stays flat out to 'Radius'. Empty: " +
                        number(100. * default_edge_fraction) +
                        " % of 'Radius'; 0: a sharp edge (no contact beyond 'Radius', the contact "
                        "force jumps there and Newton can cycle: doc/flat_punch.md, \"A rigid "
                        "punch\"). Not used by a plane or a sphere.");
    prm.declare_entry("Normal",
                      dim == 2 ? "0, -1" : "0, 0, -1",
                      Patterns::Anything(),
                      "The outward normal of the obstacle's face, pointing from the obstacle "
                      "towards the gel (need not be of unit length): a plane or a punch pressing "
                      "down onto a gel below has '0, -1' (3D: '0, 0, -1'). For a sphere only the "
                      "axis of the contact radius.");
    prm.declare_entry("Permeable",
                      "true",
                      Patterns::Bool(),
                      "Whether solvent passes through the obstacle's surface where it touches the "
                      "gel. true: a surface point in contact keeps its piece's chemical-potential "
                      "condition (a porous tool, or a bath that reaches the contact). false: the "
                      "contact seals the surface, no solvent flows through it where the contact "
                      "is active (a glass or steel indenter), whatever the piece prescribes; the "
                      "laboratory's indentation test and its published relaxation functions "
                      "assume this (doc/indentation.md).");
    prm.enter_subsection("Motion");
    Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
    prm.leave_subsection();
    prm.leave_subsection();
  }


  template <int dim>
  void
  Obstacle<dim>::parse_parameters(dealii::ParameterHandler &prm, const std::string &obstacle_name)
  {
    name                    = obstacle_name;
    const std::string where = "Contact/" + name;
    prm.enter_subsection(name);
    try
      {
        const std::string shape_text = prm.get("Shape");
        require(shape_text == "plane" || shape_text == "sphere" || shape_text == "flat punch",
                where + "/Shape",
                "is '" + shape_text + "', which is not a shape of an obstacle",
                std::string("give one of ") + shape_names);
        shape        = shape_text == "plane"    ? Shape::plane
                       : shape_text == "sphere" ? Shape::sphere
                                                : Shape::flat_punch;
        const auto c = get_double_list(prm, "Center", where + "/Center", dim);
        const auto n = get_double_list(prm, "Normal", where + "/Normal", dim);
        const auto r = get_double_list(prm, "Radius", where + "/Radius", 1);
        for (unsigned int d = 0; d < dim; ++d)
          {
            require(std::isfinite(c[d]) && std::isfinite(n[d]),
                    where + (std::isfinite(c[d]) ? "/Normal" : "/Center"),
                    "has a coordinate that is not finite",
                    "give finite numbers");
            center[d] = c[d];
            normal[d] = n[d];
          }
        require(normal.norm() > 0.,
                where + "/Normal",
                "is the zero vector, which has no direction",
                "give the outward normal of the obstacle's face, e.g. '" +
                  std::string(dim == 2 ? "0, -1" : "0, 0, -1") + "' for one that presses down");
        normal /= normal.norm();
        radius = r[0];
        require(shape == Shape::plane || (std::isfinite(radius) && radius > 0.),
                where + "/Radius",
                "is " + number(radius) + ", but a " + prm.get("Shape") + " needs a positive radius",
                "give the radius (half-width in 2D) of the obstacle, e.g. 0.5");
        edge_radius = 0.;
        if (shape == Shape::flat_punch)
          {
            if (dealii::Utilities::trim(prm.get("Edge radius")).empty())
              edge_radius = default_edge_fraction * radius;
            else
              edge_radius = get_double_list(prm, "Edge radius", where + "/Edge radius", 1)[0];
            require(std::isfinite(edge_radius) && edge_radius >= 0.,
                    where + "/Edge radius",
                    "is " + number(edge_radius) +
                      ", but the radius of a punch's rounded edge cannot be negative",
                    "give 0 for a sharp edge, a small positive length for a rounded one, or "
                    "leave it empty (" +
                      number(100. * default_edge_fraction) + " % of 'Radius')");
          }

        permeable = prm.get_bool("Permeable");

        prm.enter_subsection("Motion");
        motion = std::make_shared<dealii::Functions::ParsedFunction<dim>>(dim);
        try
          {
            const QuietCerr quiet;
            motion->parse_parameters(prm);
            dealii::Vector<double> values(dim);
            motion->vector_value(center, values);
          }
        catch (const dealii::ExceptionBase &e)
          {
            prm.leave_subsection();
            throw InputError(where + "/Motion",
                             "cannot be parsed: " + describe(e),
                             "give " + std::to_string(dim) +
                               " expressions of t (the displacement of 'Center' along x, y" +
                               (dim == 3 ? ", z" : "") +
                               ") separated by ';' in 'Function expression'");
          }
        prm.leave_subsection();
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
    set_time(0.);
  }


  template <int dim>
  dealii::Tensor<1, dim>
  Obstacle<dim>::displacement(const double t) const
  {
    dealii::Tensor<1, dim> u;
    if (!motion)
      return u;
    motion->set_time(t);
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = motion->value(center, d);
    return u;
  }


  template <int dim>
  double
  Obstacle<dim>::travel(const double t_begin, const double t_end) const
  {
    if (!motion)
      return 0.;
    constexpr unsigned int       n_samples = 8;
    const dealii::Tensor<1, dim> start     = displacement(t_begin);
    double                       farthest  = 0.;
    for (unsigned int k = 1; k <= n_samples; ++k)
      {
        const double t = k == n_samples ? t_end : t_begin + (t_end - t_begin) * k / n_samples;
        farthest       = std::max(farthest, (displacement(t) - start).norm());
      }
    return farthest;
  }


  template <int dim>
  void
  Obstacle<dim>::set_time(const double t)
  {
    if (motion)
      current_center = center + displacement(t);
    else
      current_center = center;
  }


  template <int dim>
  const dealii::Point<dim> &
  Obstacle<dim>::reference_point() const
  {
    return current_center;
  }


  template <int dim>
  typename Obstacle<dim>::Gap
  Obstacle<dim>::gap(const dealii::Point<dim> &x) const
  {
    Gap result;
    if (shape == Shape::sphere)
      {
        ball_gap(dealii::Tensor<1, dim>(x - current_center), radius, result);
        return result;
      }
    // A plane or a punch's face: m = -nu. For a grid side nu = -sign e_axis, so that m and g are
    // the side's sign e_axis and sign (x - value)[axis] exactly.
    for (unsigned int d = 0; d < dim; ++d)
      result.m[d] = 0. - normal[d]; // not -0 where normal[d] = 0
    result.g = (x - current_center) * result.m;
    if (shape == Shape::plane)
      {
        result.possible = true;
        return result;
      }
    const dealii::Tensor<1, dim> e      = x - current_center;
    const dealii::Tensor<1, dim> radial = e - (e * normal) * normal;
    const double                 r      = radial.norm();
    if (r <= radius * (1. + 1e-12))
      {
        result.possible = true;
        return result;
      }
    // Beyond the face's edge: the quarter circle of radius rho about q = c + R e_r - rho nu, on
    // the side of the gel of its centre, (x - c).nu >= -rho.
    if (edge_radius == 0. || e * normal < -edge_radius)
      return result;
    const dealii::Tensor<1, dim> e_r = radial / r;
    const dealii::Tensor<1, dim> v   = e - radius * e_r + edge_radius * normal;
    ball_gap(v, edge_radius, result);
    // In 3D the centre q turns with e_r: dq/dx = R (I - nu (x) nu - e_r (x) e_r)/r.
    const double d = v.norm();
    if (dim == 3 && result.possible)
      result.dm_dx += radius / (r * d) *
                      (dealii::Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()) -
                       dealii::outer_product(normal, normal) - dealii::outer_product(e_r, e_r));
    return result;
  }


  template <int dim>
  double
  Obstacle<dim>::distance_from_axis(const dealii::Point<dim> &x) const
  {
    const dealii::Tensor<1, dim> e = x - current_center;
    return (e - (e * normal) * normal).norm();
  }


  template <int dim>
  void
  Obstacle<dim>::check_inside_grid(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper)
  {
    // A motion that is not finite at t = 0 puts the obstacle nowhere: that is the motion's fault,
    // not the centre's.
    check_motion({0.});
    set_time(0.);
    const double reach  = shape == Shape::plane ? 0. : radius + edge_radius;
    bool         inside = true;
    for (unsigned int d = 0; d < dim; ++d)
      inside =
        inside && current_center[d] + reach >= lower[d] && current_center[d] - reach <= upper[d];
    require(inside,
            "Contact/" + name + "/Center",
            "puts the obstacle at t = 0 (" +
              std::string(shape == Shape::plane ? "its point " : "its extent about ") +
              format_point(current_center) + ") entirely outside the background grid " +
              format_point(lower) + " to " + format_point(upper) +
              ", where no material point can ever touch it",
            "give a 'Center' (and 'Motion' at t = 0) inside 'Background grid', or remove the "
            "obstacle from 'Contact/Obstacles'");
  }


  template <int dim>
  void
  Obstacle<dim>::check_motion(const std::vector<double> &times)
  {
    for (const double t : times)
      {
        const auto u = displacement(t);
        for (unsigned int d = 0; d < dim; ++d)
          require(std::isfinite(u[d]),
                  "Contact/" + name + "/Motion",
                  "is not finite (" + number(u[d]) + ") in component " + std::to_string(d) +
                    " at t = " + number(t),
                  "give an expression that is finite for 0 <= t <= 'Time stepping/End time' "
                  "(guard divisions and logarithms)");
      }
    set_time(0.);
  }


  template <int dim>
  void
  declare_obstacles(dealii::ParameterHandler &prm, const std::vector<std::string> &names)
  {
    // After ContactSettings: an obstacle called like one of its entries would merge with it.
    require_new_subsection_names(prm, "Contact", names, "Contact/Obstacles", "obstacle");
    prm.enter_subsection("Contact");
    for (const auto &name : names)
      Obstacle<dim>::declare_parameters(prm, name);
    prm.leave_subsection();
  }


  template <int dim>
  std::vector<Obstacle<dim>>
  parse_obstacles(dealii::ParameterHandler &prm, const std::vector<std::string> &names)
  {
    std::vector<Obstacle<dim>> obstacles(names.size());
    prm.enter_subsection("Contact");
    try
      {
        for (unsigned int i = 0; i < names.size(); ++i)
          obstacles[i].parse_parameters(prm, names[i]);
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
    return obstacles;
  }


  template class Obstacle<2>;
  template class Obstacle<3>;
  template void
  declare_obstacles<2>(dealii::ParameterHandler &, const std::vector<std::string> &);
  template void
  declare_obstacles<3>(dealii::ParameterHandler &, const std::vector<std::string> &);
  template std::vector<Obstacle<2>>
  parse_obstacles<2>(dealii::ParameterHandler &, const std::vector<std::string> &);
  template std::vector<Obstacle<3>>
  parse_obstacles<3>(dealii::ParameterHandler &, const std::vector<std::string> &);
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/box_body.h>
#include <gelmpm/scene/geometry.h>
#include <gelmpm/scene/level_set_body.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    std::vector<double>
    parse_numbers(const std::string &text,
                  const unsigned int n,
                  const std::string &entry,
                  const std::string &item)
    {
      const auto parts = dealii::Utilities::split_string_list(text, ',');
      require(parts.size() == n,
              entry,
              "has the item '" + item + "' with " + std::to_string(parts.size()) +
                " numbers where " + std::to_string(n) + " are expected",
              "give " + std::to_string(n) + " comma-separated number(s) there, e.g. '" +
                std::string(n == 1 ? "0.2" : (n == 2 ? "0.5, 0.5" : "0.5, 0.5, 0.5")) + "'");
      std::vector<double> values;
      for (const auto &p : parts)
        try
          {
            values.push_back(dealii::Utilities::string_to_double(p));
          }
        catch (...)
          {
            throw InputError(entry,
                             "has the non-number '" + p + "' in '" + item + "'",
                             "give numbers");
          }
      for (const double v : values)
        require(std::isfinite(v),
                entry,
                "has a number that is not finite in '" + item + "'",
                "give finite numbers");
      return values;
    }


    // The default of "Geometry/Boxes": with a level set or a mesh file, Boxes must keep it.
    template <int dim>
    std::string
    default_boxes()
    {
      return dim == 2 ? "0, 0 : 1, 1" : "0, 0, 0 : 1, 1, 1";
    }
  } // namespace


  template <int dim>
  Geometry<dim>::Geometry()
    : body_(std::make_shared<BoxBody<dim>>())
  {}


  template <int dim>
  void
  Geometry<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Boxes",
                      default_boxes<dim>(),
                      dealii::Patterns::Anything(),
                      "The body in its initial configuration is the union of these boxes, each "
                      "'lower corner : upper corner' (coordinates separated by commas), boxes "
                      "separated by ';'. Example: '0, 0 : 0.2, 1'. Keep the default when the body "
                      "is given by 'Level set' or 'Mesh file'.");
    prm.declare_entry("Holes",
                      "",
                      dealii::Patterns::Anything(),
                      "Balls (disks in 2D) removed from the boxes, each 'centre : radius', "
                      "separated by ';'; in 3D also cylinders, 'point on the axis : radius : "
                      "axis direction', e.g. '0.5, 0.5, 0 : 0.2 : 0, 0, 1'. Example (§4.4, "
                      "quarter holes at the corners of a cell of size a): "
                      "'0, 0 : R; a, 0 : R; 0, a : R; a, a : R'. Empty: no holes. Boxes only.");
    prm.declare_entry("Level set",
                      "",
                      dealii::Patterns::Anything(),
                      "Instead of boxes: the body is where this expression in x, y (2D) or x, y, "
                      "z (3D) is negative, e.g. '(x-1)^2/0.5^2 + (y-1)^2/0.3^2 - 1' for an "
                      "ellipse. It must be non-negative on the edge of the background grid. "
                      "Volume points at the sub-cell centres where it is negative; surface points "
                      "on its zero contour (2D) or surface (3D), normals from its gradient. "
                      "Empty: not used.");
    prm.declare_entry("Level set constants",
                      "",
                      dealii::Patterns::Anything(),
                      "Constants for the level set, e.g. 'a=0.5, b=0.3'.");
    prm.declare_entry(
      "Mesh file",
      "",
      dealii::Patterns::Anything(),
      "Instead of boxes: the body is this Gmsh mesh (.msh, ASCII format 2.2 or "
      "4.1, all quadrilaterals or all triangles in 2D, all hexahedra or all "
      "tetrahedra in 3D; relative to the directory of the scene file). Volume points at the Gauss points of its cells (V_0 = JxW), "
      "surface points at the Gauss points of its boundary faces (N_0 A_0 = "
      "normal x JxW); a boundary piece may select the faces of its physical "
      "groups: 'Selector = boundary id 3'. Empty: not used.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  Geometry<dim>::parse_parameters(dealii::ParameterHandler &prm, const std::string &scene_directory)
  {
    prm.enter_subsection("Geometry");
    const std::string box_text             = prm.get("Boxes");
    const std::string hole_text            = prm.get("Holes");
    const std::string level_text           = dealii::Utilities::trim(prm.get("Level set"));
    const std::string level_constants_text = prm.get("Level set constants");
    const std::string mesh_text            = dealii::Utilities::trim(prm.get("Mesh file"));
    prm.leave_subsection();


    // One way of giving the body: the entries of the others must be left alone, since a box or a
    // hole beside a level set or a mesh would be silently ignored.
    if (!level_text.empty() || !mesh_text.empty())
      {
        const std::string given = level_text.empty() ? "Geometry/Mesh file" : "Geometry/Level set";
        require(level_text.empty() || mesh_text.empty(),
                "Geometry/Mesh file",
                "is given together with 'Geometry/Level set', but a body is given by one of them",
                "remove one of the two entries");
        require(dealii::Utilities::trim(box_text) == default_boxes<dim>(),
                "Geometry/Boxes",
                "is given together with '" + given + "', which gives the whole body",
                "remove the 'Boxes' entry (or '" + given + "')");
        require(dealii::Utilities::trim(hole_text).empty(),
                "Geometry/Holes",
                "is given together with '" + given + "', but holes are cut from boxes only",
                level_text.empty()
                  ? "remove the holes and mesh them instead"
                  : "remove the holes and write them into the level set, e.g. "
                    "'max(phi, r - sqrt((x-a)^2 + (y-b)^2))' for a hole of radius r at (a, b)");
        if (!level_text.empty())
          body_ = std::make_shared<LevelSetBody<dim>>(level_text, level_constants_text);
        else
          {
            const std::filesystem::path path(mesh_text);
            read_mesh(path.is_relative() && !scene_directory.empty()
                        ? (std::filesystem::path(scene_directory) / path).string()
                        : mesh_text);
          }
        return;
      }
    require(dealii::Utilities::trim(level_constants_text).empty(),
            "Geometry/Level set constants",
            "is given without a 'Geometry/Level set'",
            "give the level set, or remove the constants");

    auto body = std::make_shared<BoxBody<dim>>();
    for (const auto &item : dealii::Utilities::split_string_list(box_text, ';'))
      {
        const auto corners = dealii::Utilities::split_string_list(item, ':');
        require(corners.size() == 2,
                "Geometry/Boxes",
                "has the item '" + item + "' that is not 'lower corner : upper corner'",
                "write e.g. '0, 0 : 0.2, 1'");
        const auto         lo = parse_numbers(corners[0], dim, "Geometry/Boxes", item);
        const auto         hi = parse_numbers(corners[1], dim, "Geometry/Boxes", item);
        dealii::Point<dim> lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = lo[d];
            upper[d] = hi[d];
            require(upper[d] > lower[d],
                    "Geometry/Boxes",
                    "has the box '" + item + "' whose upper corner is not above its lower corner",
                    "list the lower corner first");
          }
        body->add_box(lower, upper);
      }
    require(!body->empty(), "Geometry/Boxes", "is empty", "give at least one box");
    for (const auto &item : dealii::Utilities::split_string_list(hole_text, ';'))
      {
        const auto parts = dealii::Utilities::split_string_list(item, ':');
        require(parts.size() == 2 || (dim == 3 && parts.size() == 3),
                "Geometry/Holes",
                "has the item '" + item + "' that is not 'centre : radius'" +
                  (dim == 3 ? " or 'centre : radius : axis'" : ""),
                dim == 3
                  ? "write e.g. '0.5, 0.5, 0.5 : 0.2' (a ball) or '0.5, 0.5, 0 : 0.2 : 0, 0, "
                    "1' (a cylinder along z)"
                  : "write e.g. '0.5, 0.5 : 0.2'");
        const auto c = parse_numbers(parts[0], dim, "Geometry/Holes", item);
        const auto r = parse_numbers(parts[1], 1, "Geometry/Holes", item);
        require(r[0] > 0.,
                "Geometry/Holes",
                "has a non-positive radius in '" + item + "'",
                "give radius > 0");
        dealii::Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = c[d];
        if (parts.size() == 2)
          {
            body->add_hole(centre, r[0]);
            continue;
          }
        const auto             a = parse_numbers(parts[2], dim, "Geometry/Holes", item);
        dealii::Tensor<1, dim> axis;
        for (unsigned int d = 0; d < dim; ++d)
          axis[d] = a[d];
        require(axis.norm() > 0.,
                "Geometry/Holes",
                "has the cylinder '" + item + "' with a zero axis",
                "give the direction of the axis, e.g. '0, 0, 1'");
        body->add_cylinder(centre, r[0], axis);
      }
    body_ = body;
  }


  template <int dim>
  void
  Geometry<dim>::read_mesh(const std::string &file_name)
  {
    body_ = std::make_shared<MeshBody<dim>>(file_name);
  }


  template <int dim>
  const Body<dim> &
  Geometry<dim>::body() const
  {
    return *body_;
  }


  template <int dim>
  typename Geometry<dim>::Source
  Geometry<dim>::source() const
  {
    return body_->source();
  }


  template <int dim>
  std::string
  Geometry<dim>::entry() const
  {
    return body_->entry();
  }


  template <int dim>
  bool
  Geometry<dim>::inside(const dealii::Point<dim> &p) const
  {
    return body_->inside(p);
  }


  template <int dim>
  double
  Geometry<dim>::level_set(const dealii::Point<dim> &p) const
  {
    const auto *level_set = dynamic_cast<const LevelSetBody<dim> *>(body_.get());
    if (level_set == nullptr)
      throw std::logic_error("Geometry::level_set() of a body that is not a level set");
    return level_set->level_set(p);
  }


  template <int dim>
  const MeshBody<dim> &
  Geometry<dim>::mesh_body() const
  {
    const auto *mesh = dynamic_cast<const MeshBody<dim> *>(body_.get());
    if (mesh == nullptr)
      throw std::logic_error("Geometry: a mesh function for a body that is not a mesh");
    return *mesh;
  }


  template <int dim>
  std::vector<typename Geometry<dim>::VolumeElement>
  Geometry<dim>::mesh_volume_elements(const unsigned int points_per_direction,
                                      const double       spacing) const
  {
    return mesh_body().volume_elements(points_per_direction, spacing);
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::mesh_surface_elements(const double spacing) const
  {
    return mesh_body().surface_elements(spacing, dealii::Point<dim>(), dealii::Point<dim>());
  }


  template <int dim>
  std::set<dealii::types::boundary_id>
  Geometry<dim>::mesh_boundary_ids() const
  {
    return mesh_body().boundary_ids();
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  Geometry<dim>::mesh_group_names() const
  {
    return mesh_body().group_names();
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  Geometry<dim>::mesh_volume_group_names() const
  {
    return mesh_body().volume_group_names();
  }


  template <int dim>
  const dealii::Triangulation<dim> &
  Geometry<dim>::mesh() const
  {
    return mesh_body().mesh();
  }


  template class Geometry<2>;
  template class Geometry<3>;
} // namespace GelMPM

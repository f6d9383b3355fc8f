#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/scene/expression.h>
#include <gelmpm/scene/geometry.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_in.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
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
  } // namespace


  namespace
  {
    // The default of "Geometry/Boxes": with a level set or a mesh file, Boxes must keep it.
    template <int dim>
    std::string
    default_boxes()
    {
      return dim == 2 ? "0, 0 : 1, 1" : "0, 0, 0 : 1, 1, 1";
    }

    std::string
    variable_names(const int dim)
    {
      return dim == 2 ? "x,y" : "x,y,z";
    }

    template <int dim>
    std::string
    text(const dealii::Point<dim> &p)
    {
      std::ostringstream out;
      out << "(" << p << ")";
      return out.str();
    }

    /** The physical groups of dimension @p dim in the $PhysicalNames section of a Gmsh file. */
    std::map<dealii::types::boundary_id, std::string>
    read_physical_names(std::istream &in, const int dim)
    {
      std::map<dealii::types::boundary_id, std::string> names;
      std::string                                       line;
      while (std::getline(in, line))
        if (dealii::Utilities::trim(line) == "$PhysicalNames")
          break;
      if (!in)
        return names;
      unsigned int n = 0;
      if (!std::getline(in, line))
        return names;
      std::istringstream(line) >> n;
      for (unsigned int k = 0; k < n && std::getline(in, line); ++k)
        {
          std::istringstream item(line);
          int                group_dim = -1;
          long               tag       = -1;
          item >> group_dim >> tag;
          std::string name;
          std::getline(item, name);
          name = dealii::Utilities::trim(name);
          if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
            name = name.substr(1, name.size() - 2);
          if (group_dim == dim && tag >= 0 && !name.empty())
            names[static_cast<dealii::types::boundary_id>(tag)] = name;
        }
      return names;
    }

    /**
     * The fewest Gauss points per direction (at least @p at_least) for which no point of an
     * edge of length @p length stands for more than @p spacing of it: the largest weight of the
     * Gauss rule (near the middle, about pi/(2q)) exceeds the mean 1/q, so that the plain count
     * length/spacing would give elements up to 1.6 times too long.
     */
    unsigned int
    gauss_points_for(const double length, const double spacing, const unsigned int at_least)
    {
      unsigned int q =
        std::max(at_least, static_cast<unsigned int>(std::ceil(length / spacing - 1e-9)));
      for (;; ++q)
        {
          const dealii::QGauss<1> rule(q);
          const double            largest =
            *std::max_element(rule.get_weights().begin(), rule.get_weights().end());
          if (largest * length <= spacing * (1. + 1e-12))
            return q;
        }
    }

    /**
     * Throw InputError naming @p entry unless @p file_name looks like an ASCII Gmsh file whose
     * node and element sections hold only numbers, and no more of them are announced than they
     * hold. deal.II's reader trusts the counts it reads: a garbled count (or a word where a
     * count belongs, which leaves the stream failed and the count uninitialised) makes it
     * allocate without bound instead of failing.
     */
    void
    check_gmsh_file(const std::string &file_name, const std::string &entry)
    {
      std::ifstream in(file_name);
      std::string   line;
      while (std::getline(in, line) && dealii::Utilities::trim(line).empty())
        ;
      const std::string head = dealii::Utilities::trim(line);
      const std::string fix  = "give a Gmsh .msh file in ASCII (format 2 or 4)";
      require(head == "$MeshFormat" || head == "$NOD",
              entry,
              "'" + file_name + "' is not a Gmsh mesh (it does not start with $MeshFormat)",
              fix);
      double version = 1.;
      if (head == "$MeshFormat")
        {
          std::getline(in, line);
          std::istringstream format(line);
          int                file_type = -1;
          format >> version >> file_type;
          require(static_cast<bool>(format) && (version == 2.2 || version == 4.1) && file_type == 0,
                  entry,
                  "'" + file_name + "' has the Gmsh format '" + dealii::Utilities::trim(line) +
                    "', but only ASCII formats 2.2 and 4.1 ('2.2 0 8', '4.1 0 8') are read",
                  "write it with 'gmsh -format msh41' (or msh22), not in binary");
        }
      // The sections whose counts deal.II allocates by.
      const std::map<std::string, std::string> sections = {{"$Nodes", "$EndNodes"},
                                                           {"$Elements", "$EndElements"},
                                                           {"$Entities", "$EndEntities"},
                                                           {"$NOD", "$ENDNOD"},
                                                           {"$ELM", "$ENDELM"}};
      in.clear();
      in.seekg(0);
      while (std::getline(in, line))
        {
          const auto section = sections.find(dealii::Utilities::trim(line));
          if (section == sections.end())
            continue;
          std::vector<double> numbers;
          bool                ended = false;
          while (std::getline(in, line))
            {
              if (dealii::Utilities::trim(line) == section->second)
                {
                  ended = true;
                  break;
                }
              std::istringstream words(line);
              for (std::string word; words >> word;)
                {
                  char        *end   = nullptr;
                  const double value = std::strtod(word.c_str(), &end);
                  require(end != word.c_str() && *end == '\0' && std::isfinite(value),
                          entry,
                          "'" + file_name + "' has '" + word + "' in its " + section->first +
                            " section, where only numbers belong",
                          fix);
                  numbers.push_back(value);
                }
            }
          require(ended,
                  entry,
                  "'" + file_name + "' ends inside its " + section->first + " section",
                  fix);
          // The counts that open the section: format 4 gives the number of blocks and the
          // total ($Nodes, $Elements) or four numbers of entities ($Entities), formats 1 and 2
          // the total.
          const unsigned int n_counts = section->first == "$Entities" ? 4 : version > 3. ? 2 : 1;
          for (unsigned int k = 0; k < n_counts; ++k)
            require(k < numbers.size() && numbers[k] >= 0. &&
                      numbers[k] <= static_cast<double>(numbers.size()),
                    entry,
                    "'" + file_name + "' announces more items in its " + section->first +
                      " section than it holds",
                    fix);
        }
    }

    /**
     * The linear element and mapping of a mesh whose cells are all quadrilaterals/hexahedra or,
     * with @p simplex, all triangles/tetrahedra: what FEValues needs to give the points and JxW.
     */
    template <int dim>
    std::pair<std::unique_ptr<dealii::FiniteElement<dim>>, std::unique_ptr<dealii::Mapping<dim>>>
    linear_element(const bool simplex)
    {
      if (simplex)
        return {std::make_unique<dealii::FE_SimplexP<dim>>(1),
                std::make_unique<dealii::MappingFE<dim>>(dealii::FE_SimplexP<dim>(1))};
      return {std::make_unique<dealii::FE_Q<dim>>(1), std::make_unique<dealii::MappingQ1<dim>>()};
    }

    /**
     * @p q Gauss points per direction of a quadrilateral/hexahedron; for a simplex (and
     * @p simplex), the centroids of its k^dim equal sub-simplices with k the smallest power of two
     * (deal.II's QIteratedSimplex subdivides by halving the edges) at least @p q: points spread
     * evenly over it as the Gauss points over a quadrilateral, each with the same weight.
     */
    template <int dim>
    dealii::Quadrature<dim>
    point_rule(const bool simplex, const unsigned int q)
    {
      if (!simplex || dim == 1)
        return dealii::QGauss<dim>(q);
      unsigned int k = 1;
      while (k < q)
        k *= 2;
      return dealii::QIteratedSimplex<dim>(dealii::QGaussSimplex<dim>(1), k);
    }
  } // namespace


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

    boxes.clear();
    holes.clear();
    phi.reset();
    mesh_.reset();
    source_ = Source::boxes;

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
          set_level_set(level_text, level_constants_text);
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
        add_box(lower, upper);
      }
    require(!boxes.empty(), "Geometry/Boxes", "is empty", "give at least one box");
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
            add_hole(centre, r[0]);
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
        add_cylinder(centre, r[0], axis);
      }
  }


  template <int dim>
  void
  Geometry<dim>::add_box(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper)
  {
    boxes.emplace_back(lower, upper);
  }


  template <int dim>
  void
  Geometry<dim>::add_hole(const dealii::Point<dim> &centre, const double radius)
  {
    holes.emplace_back(centre, radius);
  }


  template <int dim>
  void
  Geometry<dim>::add_cylinder(const dealii::Point<dim>     &centre,
                              const double                  radius,
                              const dealii::Tensor<1, dim> &axis)
  {
    cylinders.push_back({centre, radius, axis / axis.norm()});
  }


  template <int dim>
  void
  Geometry<dim>::set_level_set(const std::string &expression, const std::string &constants)
  {
    const auto values =
      parse_expression_constants(constants, variable_names(dim), "Geometry/Level set constants");
    auto parser = std::make_shared<dealii::FunctionParser<dim>>(1);
    try
      {
        const QuietCerr quiet;
        parser->initialize(variable_names(dim), expression, values);
        // The parser compiles lazily: evaluate once to surface syntax errors here.
        (void)parser->value(dealii::Point<dim>());
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("Geometry/Level set",
                         "'" + expression + "' cannot be parsed: " + describe(e),
                         "write an expression in " + variable_names(dim) +
                           " (and the 'Level set constants'), negative inside the body");
      }
    phi            = parser;
    level_set_text = expression;
    source_        = Source::level_set;
  }


  template <int dim>
  void
  Geometry<dim>::read_mesh(const std::string &file_name)
  {
    const std::string entry = "Geometry/Mesh file";
    const std::string fix   = "give a Gmsh .msh file (relative paths are taken from the directory "
                              "of the scene file)";
    {
      std::ifstream probe(file_name);
      require(static_cast<bool>(probe) && !std::filesystem::is_directory(file_name),
              entry,
              "'" + file_name + "' cannot be opened",
              fix);
    }
    check_gmsh_file(file_name, entry);
    auto                mesh = std::make_shared<dealii::Triangulation<dim>>();
    dealii::GridIn<dim> grid_in;
    grid_in.attach_triangulation(*mesh);
    try
      {
        const QuietCerr quiet;
        std::ifstream   in(file_name);
        grid_in.read_msh(in);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError(entry,
                         "'" + file_name + "' cannot be read as a " + std::to_string(dim) +
                           "D Gmsh mesh: " + describe(e),
                         "check that it is a Gmsh .msh file (format 2 or 4) of a " +
                           std::to_string(dim) + "D body, e.g. written by 'gmsh -" +
                           std::to_string(dim) + " body.geo'");
      }
    catch (const std::exception &e)
      {
        throw InputError(entry,
                         "'" + file_name + "' cannot be read as a Gmsh mesh: " + e.what(),
                         "check that it is a Gmsh .msh file (format 2 or 4)");
      }
    require(mesh->n_active_cells() > 0,
            entry,
            "'" + file_name + "' holds no " + std::to_string(dim) + "D cells",
            "mesh the body in " + std::to_string(dim) + "D, or set 'Dimension' to the mesh's");
    // One kind of cell, so that one element and mapping serve every cell.
    require(mesh->all_reference_cells_are_hyper_cube() || mesh->all_reference_cells_are_simplex(),
            entry,
            "'" + file_name + "' mixes " +
              (dim == 2 ? "triangles and quadrilaterals" : "kinds of cells") +
              ", but GelMPM reads meshes of one kind of cell",
            "mesh the body with " +
              std::string(dim == 2
                            ? "quadrilaterals or triangles only (Gmsh: Mesh.RecombineAll = 1; "
                              "Mesh.SubdivisionAlgorithm = 1 for quadrilaterals only)"
                            : "hexahedra or tetrahedra only"));
    // An inverted or self-intersecting cell gives its points negative volumes (while the total
    // may still match): the Jacobian must be positive at every corner (for a bilinear
    // quadrilateral that is where it is smallest; a simplex's is constant).
    {
      const bool simplex       = mesh->all_reference_cells_are_simplex();
      const auto [fe, mapping] = linear_element<dim>(simplex);
      dealii::FEValues<dim> corners(*mapping,
                                    *fe,
                                    simplex ? dealii::Quadrature<dim>(dealii::QGaussSimplex<dim>(1))
                                            : dealii::Quadrature<dim>(dealii::QTrapezoid<dim>()),
                                    dealii::update_JxW_values);
      for (const auto &cell : mesh->active_cell_iterators())
        {
          corners.reinit(cell);
          for (const unsigned int k : corners.quadrature_point_indices())
            if (!(corners.JxW(k) > 0.))
              {
                std::ostringstream vertices;
                for (const unsigned int v : cell->vertex_indices())
                  vertices << (v > 0 ? ", " : "") << text(cell->vertex(v));
                throw InputError(entry,
                                 "'" + file_name +
                                   "' has a flat, inverted or crossed cell with the vertices " +
                                   vertices.str() +
                                   ": material points in it would get volumes of zero or below",
                                 "remesh the body so that every cell is convex and none is "
                                 "flat (Gmsh: Tools > Statistics shows the cells' quality)");
              }
        }
    }
    std::ifstream in(file_name);
    group_names = read_physical_names(in, dim - 1);
    std::ifstream again(file_name);
    volume_group_names = read_physical_names(again, dim);
    mesh_              = mesh;
    mesh_file          = file_name;
    source_            = Source::mesh;
  }


  template <int dim>
  typename Geometry<dim>::Source
  Geometry<dim>::source() const
  {
    return source_;
  }


  template <int dim>
  std::string
  Geometry<dim>::entry() const
  {
    switch (source_)
      {
        case Source::level_set:
          return "Geometry/Level set";
        case Source::mesh:
          return "Geometry/Mesh file";
        default:
          return "Geometry/Boxes";
      }
  }


  template <int dim>
  double
  Geometry<dim>::level_set(const dealii::Point<dim> &p) const
  {
    Assert(phi, dealii::ExcInternalError());
    const double value = phi->value(p);
    if (!std::isfinite(value))
      throw InputError("Geometry/Level set",
                       "'" + level_set_text + "' is not a number at " + text(p),
                       "write an expression that is finite in the whole background grid");
    return value;
  }


  template <int dim>
  bool
  Geometry<dim>::inside(const dealii::Point<dim> &p) const
  {
    if (source_ == Source::level_set)
      return level_set(p) < 0.;
    if (source_ == Source::mesh)
      {
        for (const auto &cell : mesh_->active_cell_iterators())
          if (cell->point_inside(p))
            return true;
        return false;
      }
    for (const auto &[centre, radius] : holes)
      if (p.distance(centre) < radius)
        return false;
    for (const auto &cylinder : cylinders)
      if (cylinder.distance_to_axis(p) < cylinder.radius)
        return false;
    return inside_boxes(p);
  }


  template <int dim>
  bool
  Geometry<dim>::inside_boxes(const dealii::Point<dim> &p) const
  {
    if (source_ != Source::boxes)
      return inside(p);
    for (const auto &[lower, upper] : boxes)
      {
        bool in = true;
        for (unsigned int d = 0; d < dim; ++d)
          in &= (p[d] >= lower[d] && p[d] <= upper[d]);
        if (in)
          return true;
      }
    return false;
  }


  template <int dim>
  bool
  Geometry<dim>::on_boundary(const dealii::Point<dim>     &p,
                             const dealii::Tensor<1, dim> &normal) const
  {
    double size = 0.;
    for (const auto &[lower, upper] : boxes)
      size = std::max(size, lower.distance(upper));
    const double eps = 1e-9 * size;
    return inside(p - eps * normal) && !inside(p + eps * normal);
  }


  template <int dim>
  bool
  Geometry<dim>::on_earlier_box_face(const unsigned int            box,
                                     const dealii::Point<dim>     &p,
                                     const dealii::Tensor<1, dim> &normal) const
  {
    unsigned int a = 0;
    for (unsigned int d = 1; d < dim; ++d)
      if (std::abs(normal[d]) > std::abs(normal[a]))
        a = d;
    double size = 0.;
    for (const auto &[lower, upper] : boxes)
      size = std::max(size, lower.distance(upper));
    const double eps = 1e-9 * size;
    for (unsigned int j = 0; j < box; ++j)
      {
        const auto &[lower, upper] = boxes[j];
        const double plane         = normal[a] > 0. ? upper[a] : lower[a];
        bool         on            = std::abs(p[a] - plane) <= eps;
        for (unsigned int d = 0; d < dim && on; ++d)
          on = d == a || (p[d] >= lower[d] - eps && p[d] <= upper[d] + eps);
        if (on)
          return true;
      }
    return false;
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::surface_elements(const double              spacing,
                                  const dealii::Point<dim> &lower,
                                  const dealii::Point<dim> &upper) const
  {
    switch (source_)
      {
        case Source::level_set:
          return dim == 3 ? level_set_surface_elements_3d(spacing, lower, upper)
                          : level_set_surface_elements(spacing, lower, upper);
        case Source::mesh:
          return mesh_surface_elements(spacing);
        default:
          return dim == 3 ? box_surface_elements_3d(spacing) : box_surface_elements(spacing);
      }
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::box_surface_elements(const double spacing) const
  {
    if (dim != 2)
      throw std::logic_error("box_surface_elements is the 2D version");
    std::vector<SurfaceElement> elements;
    using P = dealii::Point<dim>;
    using T = dealii::Tensor<1, dim>;

    // Box edges, split where hole circles cross them.
    for (unsigned int box = 0; box < boxes.size(); ++box)
      {
        const auto &[lower, upper] = boxes[box];
        const P corners[4]         = {P(lower[0], lower[1]),
                                      P(upper[0], lower[1]),
                                      P(upper[0], upper[1]),
                                      P(lower[0], upper[1])};
        for (unsigned int e = 0; e < 4; ++e)
          {
            const P             a = corners[e], b = corners[(e + 1) % 4];
            const T             t = (b - a) / a.distance(b);
            const T             n({t[1], -t[0]}); // outward for counter-clockwise corners
            const double        L      = a.distance(b);
            std::vector<double> breaks = {0., L};
            for (const auto &[centre, radius] : holes)
              {
                // |a + s t - c|^2 = r^2
                const T      ac   = a - centre;
                const double bq   = ac * t;
                const double disc = bq * bq - (ac * ac - radius * radius);
                if (disc > 0.)
                  for (const double s : {-bq - std::sqrt(disc), -bq + std::sqrt(disc)})
                    if (s > 0. && s < L)
                      breaks.push_back(s);
              }
            std::sort(breaks.begin(), breaks.end());
            for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
              {
                const double length = breaks[k + 1] - breaks[k];
                if (length <= relative_position_tolerance * L)
                  continue;
                const unsigned int m =
                  std::max(1u, static_cast<unsigned int>(std::ceil(length / spacing - 1e-9)));
                for (unsigned int j = 0; j < m; ++j)
                  {
                    const P c = a + (breaks[k] + (j + 0.5) * length / m) * t;
                    if (on_boundary(c, n) && !on_earlier_box_face(box, c, n))
                      elements.push_back(
                        {c, (length / m) * n, dealii::numbers::invalid_boundary_id, {}});
                  }
              }
          }
      }

    // Hole arcs, split where box edges cross them; the body's outward normal points into the hole.
    for (const auto &[centre, radius] : holes)
      {
        std::vector<double> breaks = {0., 2. * M_PI};
        for (const auto &[lower, upper] : boxes)
          for (unsigned int d = 0; d < dim; ++d)
            for (const double line : {lower[d], upper[d]})
              {
                const double offset = (line - centre[d]) / radius;
                if (std::abs(offset) >= 1.)
                  continue;
                for (const double sign : {-1., 1.})
                  {
                    // Point on the circle with coordinate d equal to line.
                    const double other = sign * std::sqrt(1. - offset * offset);
                    double angle = (d == 0) ? std::atan2(other, offset) : std::atan2(offset, other);
                    if (angle < 0.)
                      angle += 2. * M_PI;
                    breaks.push_back(angle);
                  }
              }
        std::sort(breaks.begin(), breaks.end());
        for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
          {
            const double span = breaks[k + 1] - breaks[k];
            if (span <= relative_position_tolerance) // radians
              continue;
            const unsigned int m =
              std::max(1u, static_cast<unsigned int>(std::ceil(span * radius / spacing - 1e-9)));
            for (unsigned int j = 0; j < m; ++j)
              {
                const double t0 = breaks[k] + j * span / m, t1 = t0 + span / m,
                             tm = 0.5 * (t0 + t1);
                const P c       = centre + radius * T({std::cos(tm), std::sin(tm)});
                const T n({-std::cos(tm), -std::sin(tm)});
                // Exact integral of the (inward-radial) normal over the arc.
                const T normal_area({-radius * (std::sin(t1) - std::sin(t0)),
                                     radius * (std::cos(t1) - std::cos(t0))});
                if (on_boundary(c, n))
                  elements.push_back({c, normal_area, dealii::numbers::invalid_boundary_id, {}});
              }
          }
      }
    return elements;
  }


  template <int dim>
  dealii::Tensor<1, dim>
  Geometry<dim>::level_set_gradient(const dealii::Point<dim> &p, const double delta) const
  {
    dealii::Tensor<1, dim> gradient;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dealii::Point<dim> plus = p, minus = p;
        plus[d] += delta;
        minus[d] -= delta;
        gradient[d] = (level_set(plus) - level_set(minus)) / (2. * delta);
      }
    return gradient;
  }


  template <int dim>
  dealii::Point<dim>
  Geometry<dim>::project_onto_zero_set(const dealii::Point<dim> &p, const double max_shift) const
  {
    // Newton's method for phi(p + s grad phi / |grad phi|) = 0, the gradient re-evaluated at
    // each iterate: quadratic convergence from the marching-squares estimate, which lies within
    // a sampling cell of the contour. The finite-difference step only affects the rate.
    const double       delta = 1e-4 * max_shift;
    dealii::Point<dim> x     = p;
    for (unsigned int k = 0; k < 30; ++k)
      {
        const double                 value    = level_set(x);
        const dealii::Tensor<1, dim> gradient = level_set_gradient(x, delta);
        const double                 g2       = gradient.norm_square();
        if (!(g2 > 0.))
          return p;
        const dealii::Tensor<1, dim> step = (value / g2) * gradient;
        x -= step;
        if (x.distance(p) > max_shift)
          return p;
        if (step.norm() <= 1e-14 * max_shift)
          break;
      }
    return x;
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::level_set_surface_elements(const double              spacing,
                                            const dealii::Point<dim> &lower,
                                            const dealii::Point<dim> &upper) const
  {
    if constexpr (dim != 2)
      {
        (void)spacing;
        (void)lower;
        (void)upper;
        throw std::logic_error("level_set_surface_elements is the 2D version");
      }
    else
      {
        using P = dealii::Point<2>;
        using T = dealii::Tensor<1, 2>;

        // Sample phi on a grid twice as fine as the elements: the contour between samples is
        // only a first guess, which the projection below moves onto the zero set.
        std::array<unsigned int, 2> n;
        std::array<double, 2>       step;
        for (unsigned int d = 0; d < 2; ++d)
          {
            n[d]    = std::max(2u,
                            static_cast<unsigned int>(
                              std::ceil((upper[d] - lower[d]) / (0.5 * spacing))));
            step[d] = (upper[d] - lower[d]) / n[d];
          }
        const auto sample = [&](const unsigned int i, const unsigned int j) {
          return P(lower[0] + i * step[0], lower[1] + j * step[1]);
        };
        std::vector<double> values((n[0] + 1) * (n[1] + 1));
        const auto          value_at = [&](const unsigned int i, const unsigned int j) -> double          &{
          return values[j * (n[0] + 1) + i];
        };
        for (unsigned int j = 0; j <= n[1]; ++j)
          for (unsigned int i = 0; i <= n[0]; ++i)
            {
              const double v = level_set(sample(i, j));
              // A contour crossing the grid's edge would be open there: the body would be cut
              // off by the grid.
              require(!(v < 0.) || (i > 0 && j > 0 && i < n[0] && j < n[1]),
                      "Geometry/Level set",
                      "is negative on the edge of the background grid, e.g. at " +
                        text(sample(i, j)) + ": the body reaches outside the grid",
                      "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the "
                      "body");
              value_at(i, j) = v;
            }

        // Marching squares. Edges are numbered: horizontal (i, j)-(i+1, j) first, then vertical
        // (i, j)-(i, j+1). A sampling cell's crossings, walked counter-clockwise, alternate
        // between leaving the body (in -> out) and entering it; each contour segment runs from
        // a leaving to an entering crossing, so that the body lies on its left and the contours
        // run counter-clockwise around the body (clockwise around holes).
        const auto horizontal = [&](const unsigned int i, const unsigned int j) {
          return static_cast<std::size_t>(j) * n[0] + i;
        };
        const auto vertical = [&](const unsigned int i, const unsigned int j) {
          return static_cast<std::size_t>(n[0]) * (n[1] + 1) +
                 static_cast<std::size_t>(j) * (n[0] + 1) + i;
        };
        std::map<std::size_t, std::size_t> next;
        std::map<std::size_t, P>           crossing;
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i)
            {
              const std::array<std::pair<unsigned int, unsigned int>, 4> corner = {
                {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
              const std::array<std::size_t, 4> edge = {
                {horizontal(i, j), vertical(i + 1, j), horizontal(i, j + 1), vertical(i, j)}};
              std::array<bool, 4> in;
              for (unsigned int k = 0; k < 4; ++k)
                in[k] = value_at(corner[k].first, corner[k].second) < 0.;
              // Crossings in counter-clockwise order, with whether they leave the body.
              std::vector<std::pair<std::size_t, bool>> cuts;
              for (unsigned int k = 0; k < 4; ++k)
                {
                  const unsigned int l = (k + 1) % 4;
                  if (in[k] == in[l])
                    continue;
                  const double va   = value_at(corner[k].first, corner[k].second),
                               vb   = value_at(corner[l].first, corner[l].second);
                  const P a         = sample(corner[k].first, corner[k].second),
                          b         = sample(corner[l].first, corner[l].second);
                  crossing[edge[k]] = a + (va / (va - vb)) * (b - a);
                  cuts.emplace_back(edge[k], in[k]);
                }
              if (cuts.size() == 2)
                next[cuts[0].second ? cuts[0].first : cuts[1].first] =
                  cuts[0].second ? cuts[1].first : cuts[0].first;
              else if (cuts.size() == 4)
                {
                  // A saddle: the value at the centre decides whether the two inside corners
                  // are connected (the segments cut off the outside corners) or not.
                  const bool centre_in = level_set(sample(i, j) + 0.5 * T({step[0], step[1]})) < 0.;
                  for (unsigned int k = 0; k < 4; ++k)
                    if (cuts[k].second)
                      next[cuts[k].first] = cuts[(k + (centre_in ? 1 : 3)) % 4].first;
                }
            }

        // Each closed contour, its crossings projected onto the zero set, divided into elements
        // of equal length along the polyline through them.
        std::vector<SurfaceElement> elements;
        const double                max_shift = 2. * std::max(step[0], step[1]);
        std::set<std::size_t>       done;
        for (const auto &[start, ignored] : next)
          {
            (void)ignored;
            if (done.count(start))
              continue;
            std::vector<P> loop;
            for (std::size_t e = start;;)
              {
                done.insert(e);
                loop.push_back(project_onto_zero_set(crossing.at(e), max_shift));
                const auto found = next.find(e);
                if (found == next.end())
                  throw std::logic_error("level set: a contour is not closed");
                e = found->second;
                if (e == start)
                  break;
              }
            // Kinks (a level set like max(phi_1, phi_2) has corners): where the normals of
            // neighbouring points differ by more than 30 degrees, the corner is where their
            // tangent lines meet. Elements end at corners, so that none straddles one with a
            // chord that cuts it short. (A smooth contour turns by 30 degrees between two
            // samples only where its radius of curvature is below the element length, which
            // the elements cannot resolve anyway.)
            const double   delta = 1e-4 * max_shift;
            std::vector<T> normal(loop.size());
            for (std::size_t k = 0; k < loop.size(); ++k)
              {
                const T g = level_set_gradient(loop[k], delta);
                normal[k] = g.norm() > 0. ? g / g.norm() : T();
              }
            std::vector<P>    points;
            std::vector<bool> is_corner;
            const auto        add = [&](const P &x, const bool corner) {
              if (!points.empty() && points.back().distance(x) <= 1e-9 * max_shift)
                is_corner.back() = is_corner.back() || corner;
              else
                {
                  points.push_back(x);
                  is_corner.push_back(corner);
                }
            };
            for (std::size_t k = 0; k < loop.size(); ++k)
              {
                add(loop[k], false);
                const std::size_t l = (k + 1) % loop.size();
                if (normal[k] * normal[l] >= std::cos(M_PI / 6.))
                  continue;
                // (x - loop[k]).normal[k] = 0 and (x - loop[l]).normal[l] = 0.
                const double det = normal[k][0] * normal[l][1] - normal[k][1] * normal[l][0];
                if (std::abs(det) < 1e-3)
                  continue;
                const double bk = normal[k] * loop[k], bl = normal[l] * loop[l];
                const P      corner((bk * normal[l][1] - bl * normal[k][1]) / det,
                               (normal[k][0] * bl - normal[l][0] * bk) / det);
                if (corner.distance(loop[k]) > max_shift || corner.distance(loop[l]) > max_shift)
                  continue;
                // The tangent lines at the samples miss the corner of curved branches by
                // (sample distance)^2 x curvature: redo them at points of each branch close
                // to the estimate (close, but not so close that the difference quotients of
                // the gradient straddle the corner).
                P estimate = corner;
                for (unsigned int refinement = 0; refinement < 3; ++refinement)
                  {
                    std::array<P, 2> q;
                    std::array<T, 2> n;
                    bool             refined = true;
                    for (unsigned int side = 0; side < 2; ++side)
                      {
                        const P     &sample = side == 0 ? loop[k] : loop[l];
                        const double away   = sample.distance(estimate);
                        if (away <= 1e-2 * max_shift)
                          {
                            refined = false;
                            break;
                          }
                        q[side]   = project_onto_zero_set(estimate + (1e-2 * max_shift / away) *
                                                                     (sample - estimate),
                                                        max_shift);
                        const T g = level_set_gradient(q[side], delta);
                        n[side]   = g / g.norm();
                      }
                    const double d = refined ? n[0][0] * n[1][1] - n[0][1] * n[1][0] : 0.;
                    if (std::abs(d) < 1e-3)
                      break;
                    const double b0 = n[0] * q[0], b1 = n[1] * q[1];
                    const P      better((b0 * n[1][1] - b1 * n[0][1]) / d,
                                   (n[0][0] * b1 - n[1][0] * b0) / d);
                    if (better.distance(corner) > max_shift)
                      break;
                    estimate = better;
                  }
                add(estimate, true);
              }
            if (points.size() > 1 && points.front().distance(points.back()) <= 1e-9 * max_shift)
              {
                is_corner.front() = is_corner.front() || is_corner.back();
                points.pop_back();
                is_corner.pop_back();
              }

            // Start at a corner if there is one; then cut the contour at its corners into
            // pieces, each divided into elements of equal length along the polyline.
            const std::size_t first =
              std::find(is_corner.begin(), is_corner.end(), true) - is_corner.begin();
            const bool closed = first == is_corner.size();
            std::rotate(points.begin(), points.begin() + (closed ? 0 : first), points.end());
            std::rotate(is_corner.begin(),
                        is_corner.begin() + (closed ? 0 : first),
                        is_corner.end());
            points.push_back(points.front());
            is_corner.push_back(!closed);

            for (std::size_t begin = 0; begin + 1 < points.size();)
              {
                std::size_t end = begin + 1;
                while (end + 1 < points.size() && !is_corner[end])
                  ++end;
                std::vector<double> arc(end - begin + 1, 0.);
                for (std::size_t k = begin; k < end; ++k)
                  arc[k - begin + 1] = arc[k - begin] + points[k].distance(points[k + 1]);
                const double length = arc.back();
                // The polyline is a little shorter than the contour (by the relative amount
                // (step * curvature)^2 / 24): 1 % more elements keep each below the spacing.
                const unsigned int m =
                  std::max(closed ? 3u : 1u,
                           static_cast<unsigned int>(std::ceil(1.01 * length / spacing - 1e-9)));
                const auto at = [&](const double s) {
                  const std::size_t k =
                    std::min<std::size_t>(std::upper_bound(arc.begin(), arc.end(), s) -
                                            arc.begin() - 1,
                                          end - begin - 1);
                  const double piece = arc[k + 1] - arc[k];
                  const double w     = piece > 0. ? (s - arc[k]) / piece : 0.;
                  return project_onto_zero_set(points[begin + k] +
                                                 w * (points[begin + k + 1] - points[begin + k]),
                                               max_shift);
                };
                // The ends of a piece are its corners, where the projection is not defined.
                std::vector<P> ends(m + 1);
                ends[0] = closed ? at(0.) : points[begin];
                ends[m] = closed ? ends[0] : points[end];
                for (unsigned int k = 1; k < m; ++k)
                  ends[k] = at(k * length / m);
                for (unsigned int k = 0; k < m; ++k)
                  {
                    const T chord = ends[k + 1] - ends[k];
                    // The integral of the outward normal over the contour between two points is
                    // the chord rotated clockwise, whatever the contour's shape between them.
                    elements.push_back({at((k + 0.5) * length / m),
                                        T({chord[1], -chord[0]}),
                                        dealii::numbers::invalid_boundary_id,
                                        {}});
                  }
                begin = end;
              }
          }
        return elements;
      }
  }


  template <int dim>
  std::vector<typename Geometry<dim>::VolumeElement>
  Geometry<dim>::mesh_volume_elements(const unsigned int points_per_direction,
                                      const double       spacing) const
  {
    const bool simplex       = mesh_->all_reference_cells_are_simplex();
    const auto [fe, mapping] = linear_element<dim>(simplex);
    std::map<unsigned int, std::unique_ptr<dealii::FEValues<dim>>> values;
    std::vector<VolumeElement>                                     elements;
    for (const auto &cell : mesh_->active_cell_iterators())
      {
        double longest = 0.;
        for (unsigned int l = 0; l < cell->n_lines(); ++l)
          longest = std::max(longest, cell->line(l)->diameter());
        // As many points per direction as sub-cells of the background grid would fit along the
        // longest edge: the density of a box body's points. (Unlike surface elements, no single
        // volume point's extent is prescribed.) A simplex is divided into k^dim equal ones with
        // k a power of two: as many as make each no larger than a sub-cell, and at least the
        // share of a simplex (1/dim!) of the n^dim points of a quadrilateral/hexahedron.
        unsigned int q = std::max(points_per_direction,
                                  static_cast<unsigned int>(std::ceil(longest / spacing - 1e-9)));
        if (simplex)
          {
            const double target =
              std::max(std::pow(points_per_direction, dim) / (dim == 2 ? 2. : 6.),
                       cell->measure() / std::pow(spacing, dim));
            for (q = 1; std::pow(q, dim) < target; q *= 2)
              ;
          }
        auto &fe_values = values[q];
        if (!fe_values)
          fe_values = std::make_unique<dealii::FEValues<dim>>(*mapping,
                                                              *fe,
                                                              point_rule<dim>(simplex, q),
                                                              dealii::update_quadrature_points |
                                                                dealii::update_JxW_values);
        fe_values->reinit(cell);
        const auto  named = volume_group_names.find(cell->material_id());
        const auto &group = named == volume_group_names.end() ? std::string() : named->second;
        for (const unsigned int k : fe_values->quadrature_point_indices())
          elements.push_back({fe_values->quadrature_point(k), fe_values->JxW(k), group});
      }
    return elements;
  }


  template <int dim>
  std::vector<typename Geometry<dim>::SurfaceElement>
  Geometry<dim>::mesh_surface_elements(const double spacing) const
  {
    const bool simplex       = mesh_->all_reference_cells_are_simplex();
    const auto [fe, mapping] = linear_element<dim>(simplex);
    std::map<unsigned int, std::unique_ptr<dealii::FEFaceValues<dim>>> values;
    std::vector<SurfaceElement>                                        elements;
    for (const auto &cell : mesh_->active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (!face->at_boundary())
            continue;
          double longest = 0.;
          if constexpr (dim == 2)
            longest = face->diameter();
          else
            for (unsigned int l = 0; l < face->n_lines(); ++l)
              longest = std::max(longest, face->line(l)->diameter());
          const unsigned int q         = gauss_points_for(longest, spacing, 1);
          auto              &fe_values = values[q];
          if (!fe_values)
            fe_values =
              std::make_unique<dealii::FEFaceValues<dim>>(*mapping,
                                                          *fe,
                                                          point_rule<dim - 1>(simplex, q),
                                                          dealii::update_quadrature_points |
                                                            dealii::update_JxW_values |
                                                            dealii::update_normal_vectors);
          fe_values->reinit(cell, f);
          const auto  id     = face->boundary_id();
          const auto  named  = group_names.find(id);
          const auto &name   = named == group_names.end() ? std::string() : named->second;
          const auto  volume = volume_group_names.find(cell->material_id());
          const auto &group  = volume == volume_group_names.end() ? std::string() : volume->second;
          for (const unsigned int k : fe_values->quadrature_point_indices())
            elements.push_back({fe_values->quadrature_point(k),
                                fe_values->JxW(k) * fe_values->normal_vector(k),
                                id,
                                name,
                                group});
        }
    return elements;
  }


  template <int dim>
  std::set<dealii::types::boundary_id>
  Geometry<dim>::mesh_boundary_ids() const
  {
    std::set<dealii::types::boundary_id> ids;
    for (const auto &face : mesh_->active_face_iterators())
      if (face->at_boundary())
        ids.insert(face->boundary_id());
    return ids;
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  Geometry<dim>::mesh_group_names() const
  {
    return group_names;
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  Geometry<dim>::mesh_volume_group_names() const
  {
    return volume_group_names;
  }


  template <int dim>
  const dealii::Triangulation<dim> &
  Geometry<dim>::mesh() const
  {
    Assert(mesh_, dealii::ExcInternalError());
    return *mesh_;
  }


  template class Geometry<2>;
  template class Geometry<3>;
} // namespace GelMPM

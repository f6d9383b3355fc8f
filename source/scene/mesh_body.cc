#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/input_file.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/scene/expression.h>
#include <gelmpm/scene/mesh_body.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_in.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace GelMPM
{
  namespace
  {
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
  MeshBody<dim>::MeshBody(const std::string &file_name)
  {
    const std::string entry = "Geometry/Mesh file";
    const std::string fix   = "give a Gmsh .msh file (relative paths are taken from the directory "
                              "of the scene file)";
    // Every read below runs to the end of the file (and opening a pipe waits for a writer).
    require_bounded_file(file_name, entry, "a Gmsh mesh", largest_mesh_file_bytes, fix);
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
                  vertices << (v > 0 ? ", " : "") << format_point(cell->vertex(v));
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
    group_names_ = read_physical_names(in, dim - 1);
    std::ifstream again(file_name);
    volume_group_names_ = read_physical_names(again, dim);
    mesh_               = mesh;
  }


  template <int dim>
  BodySource
  MeshBody<dim>::source() const
  {
    return BodySource::mesh;
  }


  template <int dim>
  std::string
  MeshBody<dim>::entry() const
  {
    return "Geometry/Mesh file";
  }


  template <int dim>
  bool
  MeshBody<dim>::inside(const dealii::Point<dim> &p) const
  {
    for (const auto &cell : mesh_->active_cell_iterators())
      if (cell->point_inside(p))
        return true;
    return false;
  }


  template <int dim>
  bool
  MeshBody<dim>::has_own_volume_points() const
  {
    return true;
  }


  template <int dim>
  std::vector<typename MeshBody<dim>::VolumeElement>
  MeshBody<dim>::volume_elements(const unsigned int points_per_direction,
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
        const auto  named = volume_group_names_.find(cell->material_id());
        const auto &group = named == volume_group_names_.end() ? std::string() : named->second;
        for (const unsigned int k : fe_values->quadrature_point_indices())
          elements.push_back({fe_values->quadrature_point(k), fe_values->JxW(k), group});
      }
    return elements;
  }


  template <int dim>
  std::vector<typename MeshBody<dim>::SurfaceElement>
  MeshBody<dim>::surface_elements(const double spacing,
                                  const dealii::Point<dim> &,
                                  const dealii::Point<dim> &) const
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
          const auto  named  = group_names_.find(id);
          const auto &name   = named == group_names_.end() ? std::string() : named->second;
          const auto  volume = volume_group_names_.find(cell->material_id());
          const auto &group  = volume == volume_group_names_.end() ? std::string() : volume->second;
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
  MeshBody<dim>::boundary_ids() const
  {
    std::set<dealii::types::boundary_id> ids;
    for (const auto &face : mesh_->active_face_iterators())
      if (face->at_boundary())
        ids.insert(face->boundary_id());
    return ids;
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  MeshBody<dim>::group_names() const
  {
    return group_names_;
  }


  template <int dim>
  const std::map<dealii::types::boundary_id, std::string> &
  MeshBody<dim>::volume_group_names() const
  {
    return volume_group_names_;
  }


  template <int dim>
  const dealii::Triangulation<dim> &
  MeshBody<dim>::mesh() const
  {
    return *mesh_;
  }


  template class MeshBody<2>;
  template class MeshBody<3>;
} // namespace GelMPM

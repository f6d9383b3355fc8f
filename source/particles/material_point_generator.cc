#include <gelmpm/core/available_memory.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/particles/material_point_generator.h>
#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/point_location.h>
#include <gelmpm/particles/point_refinement.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <cmath>
#include <sstream>
#include <unistd.h>

namespace GelMPM
{
  namespace
  {
    /**
     * A volume point of the uniform grid's sub-cell at @p x (volume @p volume) in a cell refined
     * @p level times: 2^level children per direction at the centres of the sub-cell's parts,
     * each with volume / 2^(dim level), so that the points per cell are the scene's at every
     * level. The division by a power of two is exact: the children's volumes sum to the
     * parent's bit for bit. At creation a point's history is its initial state, which each
     * child takes as the parent would.
     */
    template <int dim, typename Insert>
    void
    split_volume_point(const dealii::Point<dim>  &x,
                       const double               volume,
                       const unsigned int         level,
                       const BackgroundGrid<dim> &grid,
                       const unsigned int         points_per_cell,
                       const Insert              &insert)
    {
      std::array<double, dim> sides;
      for (unsigned int d = 0; d < dim; ++d)
        sides[d] = grid.cell_size(d) / points_per_cell;
      const auto   offsets      = volume_point_offsets<dim>(sides, 1u << level);
      const double child_volume = volume / offsets.size();
      for (const auto &offset : offsets)
        insert(x + offset, child_volume, "");
    }


    /**
     * The children of the surface element @p e in a cell refined into @p parts per direction,
     * appended to @p split, each with the parent's normal and N_0 A_0 divided by parts^(dim-1),
     * at surface_element_offsets(). The division by a power of two is exact, so the children's
     * N_0 A_0 sum to the parent's to round-off (bit for bit for two children). On a curved
     * boundary they lie in the parent's chord or tangent plane, within s^2 kappa / 8 of the
     * surface (s the parent's side, kappa the curvature).
     */
    template <int dim, typename Element>
    void
    split_surface_element(const Element &e, const unsigned int parts, std::vector<Element> &split)
    {
      const auto offsets = surface_element_offsets<dim>(e.normal_area, parts);
      for (const auto &offset : offsets)
        {
          Element child     = e;
          child.normal_area = e.normal_area / static_cast<double>(offsets.size());
          child.centre += offset;
          split.push_back(child);
        }
    }


    /**
     * The surface elements @p elements of the uniform grid's spacing, those in a cell refined
     * l times split into 2^l per direction of the boundary (split_surface_element()), so that
     * the surface points per cell edge are the scene's at every level, as the volume points
     * are. @p levels receives each element's level l.
     */
    template <int dim, typename Element>
    std::vector<Element>
    split_surface_elements(const std::vector<Element> &elements,
                           const BackgroundGrid<dim>  &grid,
                           std::vector<unsigned int>  &levels)
    {
      levels.clear();
      if (!grid.refined())
        {
          levels.assign(elements.size(), 0);
          return elements;
        }
      std::vector<Element> split;
      split.reserve(elements.size());
      for (const auto &e : elements)
        {
          const unsigned int level = grid.refinement_level(e.centre);
          if (level == 0)
            split.push_back(e);
          else
            split_surface_element<dim>(e, 1u << level, split);
          levels.resize(split.size(), level);
        }
      return split;
    }
  } // namespace


  template <int dim>
  void
  MaterialPointGenerator<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material points");
    prm.declare_entry("Points per cell",
                      "3",
                      dealii::Patterns::Integer(1, 20),
                      "n: volume points per background cell and direction (n^dim per cell, at "
                      "sub-cell centres inside the body); at least 3. Paper: "
                      "6 (§4.1), 5 (§4.2), 8 (§4.3).");
    prm.declare_entry("Surface points per cell edge",
                      "0",
                      dealii::Patterns::Integer(0, 40),
                      "n_s: surface points per background cell length along the boundary "
                      "(0: the same as 'Points per cell').");
    prm.leave_subsection();
  }


  template <int dim>
  void
  MaterialPointGenerator<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material points");
    points_per_cell         = prm.get_integer("Points per cell");
    surface_points_per_edge = prm.get_integer("Surface points per cell edge");
    prm.leave_subsection();
    if (surface_points_per_edge == 0)
      surface_points_per_edge = points_per_cell;
  }


  namespace
  {
    /**
     * Throw InputError if piece @p i selects surface points that an earlier piece takes: a point
     * belongs to the first piece that selects it, so the later one is left without points. The
     * elements for which @p no_boundary holds (the axis of an axisymmetric scene) are no surface
     * points of any piece.
     */
    template <int dim, typename Elements, typename NoBoundary>
    void
    check_not_overlapped(const Elements                &elements,
                         const BoundaryConditions<dim> &boundary_conditions,
                         const unsigned int             i,
                         const NoBoundary              &no_boundary)
    {
      const auto &piece = boundary_conditions.piece(i);
      for (const auto &e : elements)
        {
          if (no_boundary(e))
            continue;
          const dealii::Tensor<1, dim> normal = e.normal_area / e.normal_area.norm();
          if (!piece.selects(e.centre, normal, e.boundary_id, e.group_name))
            continue;
          const auto &first = boundary_conditions.piece(
            boundary_conditions.piece_of(e.centre, normal, e.boundary_id, e.group_name));
          throw InputError("Boundary conditions/" + piece.name + "/Selector",
                           "overlaps the selector of the earlier piece '" + first.name +
                             "', which takes all its points, e.g. the one at " +
                             format_point(e.centre) +
                             " (a point belongs to the first piece that selects it)",
                           "make the selectors of '" + first.name + "' and '" + piece.name +
                             "' disjoint");
        }
    }

    /**
     * Throw InputError naming @p entry if @p body is inside somewhere on the line x = @p lower[0]
     * beyond the axis of an axisymmetric scene, at the points where a level set's contour is
     * sampled there (LevelSetBody): such a body crosses the axis. The sampling would otherwise
     * find it reaching beyond the grid and ask for a lower 'Lower corner', which an axisymmetric
     * scene must keep at x = 0.
     */
    template <int dim>
    void
    check_not_across_axis(const Body<dim>          &body,
                          const std::string        &entry,
                          const dealii::Point<dim> &lower,
                          const dealii::Point<dim> &upper,
                          const double              spacing)
    {
      const unsigned int n =
        std::max(2u, static_cast<unsigned int>(std::ceil((upper[1] - lower[1]) / (0.5 * spacing))));
      for (unsigned int j = 0; j <= n; ++j)
        {
          dealii::Point<dim> p = lower;
          p[1] += j * (upper[1] - lower[1]) / n;
          require(!body.inside(p),
                  entry,
                  "puts material at R = x < 0 in an axisymmetric scene, e.g. at " +
                    format_point(p) +
                    ": the body crosses the axis, and the meridian plane has "
                    "nothing there",
                  std::string("cut the body at the axis so that it lies at x >= 0") +
                    (body.source() == BodySource::level_set ? " (for a level set phi: "
                                                              "'max(phi, -x)')"
                                                            : ""));
        }
    }

    /**
     * Throw InputError if a piece selects by the physical groups of a mesh ('boundary id') but
     * the body is not a mesh, or names a group that is not on the mesh's boundary.
     */
    template <int dim>
    void
    check_boundary_groups(const Geometry<dim> &geometry, const BoundaryConditions<dim> &bcs)
    {
      for (unsigned int i = 0; i < bcs.n_pieces(); ++i)
        {
          const auto &piece = bcs.piece(i);
          if (piece.boundary_groups().empty())
            continue;
          const std::string entry = "Boundary conditions/" + piece.name + "/Selector";
          require(geometry.source() == Geometry<dim>::Source::mesh,
                  entry,
                  "selects by 'boundary id', but the body is not a mesh ('" + geometry.entry() +
                    "' gives it)",
                  "select by position and normal, e.g. 'ny > 0.5', or give the body as "
                  "'Geometry/Mesh file'");
          const auto  ids   = geometry.mesh_boundary_ids();
          const auto &names = geometry.mesh_group_names();
          std::string known;
          for (const auto id : ids)
            {
              known += (known.empty() ? "" : ", ") + std::to_string(id);
              if (const auto n = names.find(id); n != names.end())
                known += " (" + n->second + ")";
            }
          for (const auto &group : piece.boundary_groups())
            {
              bool found = false;
              for (const auto id : ids)
                {
                  const auto n = names.find(id);
                  found |= group == std::to_string(id) || (n != names.end() && n->second == group);
                }
              require(found,
                      entry,
                      "names the physical group '" + group +
                        "', which is not on the boundary of the mesh (its boundary groups: " +
                        known + ")",
                      "name one of these groups by its number or name");
            }
        }
    }
  } // namespace


  template <int dim>
  void
  MaterialPointGenerator<dim>::generate(const Geometry<dim>              &geometry,
                                        const BackgroundGrid<dim>        &grid,
                                        const dealii::Triangulation<dim> &tria,
                                        const BoundaryConditions<dim>    &boundary_conditions,
                                        const MaterialRegions<dim>       &regions,
                                        dealii::Particles::ParticleHandler<dim> &particles) const
  {
    // Every region's points start at one chemical potential, each at its own stretch.
    generate_at(geometry, grid, tria, boundary_conditions, regions, regions[0].mu_0(), particles);
  }


  template <int dim>
  void
  MaterialPointGenerator<dim>::generate(const Geometry<dim>              &geometry,
                                        const BackgroundGrid<dim>        &grid,
                                        const dealii::Triangulation<dim> &tria,
                                        const BoundaryConditions<dim>    &boundary_conditions,
                                        const double                      lambda_0,
                                        const double                      mu_0,
                                        dealii::Particles::ParticleHandler<dim> &particles) const
  {
    const MaterialRegions<dim> one(FloryRehnerGel<dim>(1., 0.1, 7.299e-3, 1., lambda_0));
    generate_at(geometry, grid, tria, boundary_conditions, one, mu_0, particles);
  }


  template <int dim>
  void
  MaterialPointGenerator<dim>::check_point_memory(const Geometry<dim>       &geometry,
                                                  const BackgroundGrid<dim> &grid) const
  {
    // About as many points as the cells whose centre lies in the body hold: beyond the
    // machine's memory their allocation fails late (std::bad_alloc), naming no entry. A lower
    // bound of what a point costs: its properties and its shape values in the step's cache.
    const double  bytes_per_point = dim == 2 ? 512. : 2048.;
    unsigned long n_cells = 1, cells_inside = 0;
    for (unsigned int d = 0; d < dim; ++d)
      n_cells *= grid.n_cells[d];
    for (unsigned long c = 0; c < n_cells; ++c)
      {
        dealii::Point<dim> centre;
        unsigned long      rest = c;
        for (unsigned int d = 0; d < dim; ++d)
          {
            centre[d] = grid.lower[d] + (rest % grid.n_cells[d] + 0.5) * grid.cell_size(d);
            rest /= grid.n_cells[d];
          }
        cells_inside += geometry.inside(centre) ? 1 : 0;
      }
    const double points    = cells_inside * std::pow(static_cast<double>(points_per_cell), dim);
    const double available = available_memory();
    if (!(available > 0.))
      return;
    if (points * bytes_per_point > available)
      {
        std::ostringstream problem;
        problem.precision(3);
        problem << "is " << points_per_cell << ": the body's " << cells_inside
                << " cells would hold about " << points << " volume points, which need at least "
                << points * bytes_per_point / 1e9 << " GB of memory, more than the "
                << available / 1e9 << " GB this machine has available";
        throw InputError("Material points/Points per cell",
                         problem.str(),
                         "give fewer points per cell, or fewer cells ('Background grid/Cells')");
      }
    // The whole run: the grid's cells, and per cell of the body its points, its rows of the
    // tangent and their share of the factorisation. Measured peaks (Q2-Q2SD, 3 points per
    // cell): 255-290 kB per body cell in 3D (the free-swelling cube with 216 to 2744 body cells;
    // the factorisation's fill grows faster than the cells), 26 kB in 2D (2500 to 10000), and
    // 0.8 kB per empty cell of a 3D grid. The share of the available memory leaves a margin for
    // that growth and for the rest of the machine.
    const double bytes_per_body_cell =
      (dim == 2 ? 21e3 : 200e3) +
      std::pow(static_cast<double>(points_per_cell), dim) * bytes_per_point;
    const double bytes_per_cell = dim == 2 ? 300. : 800.;
    const double estimate       = cells_inside * bytes_per_body_cell + n_cells * bytes_per_cell;
    const double usable         = 0.8 * available;
    if (estimate <= usable)
      return;
    std::ostringstream problem;
    problem.precision(3);
    problem << "gives the body about " << cells_inside << " of the grid's " << double(n_cells)
            << " cells, whose points, unknowns and factorised tangent need about " << estimate / 1e9
            << " GB (about " << bytes_per_body_cell / 1e3
            << " kB a cell of the body), more than 80 % of the " << available / 1e9
            << " GB this machine has available";
    throw InputError("Background grid/Cells",
                     problem.str(),
                     "give fewer cells per direction, a smaller body or grid ('Geometry', "
                     "'Background grid/Lower corner', 'Upper corner'), or fewer 'Material "
                     "points/Points per cell'");
  }


  template <int dim>
  void
  MaterialPointGenerator<dim>::generate_at(const Geometry<dim>              &geometry,
                                           const BackgroundGrid<dim>        &grid,
                                           const dealii::Triangulation<dim> &tria,
                                           const BoundaryConditions<dim>    &boundary_conditions,
                                           const MaterialRegions<dim>       &regions,
                                           const double                      mu_0,
                                           dealii::Particles::ParticleHandler<dim> &particles) const
  {
    using Layout = PropertyLayout<dim>;

    const GridCellLocator<dim> locator(grid, tria);
    if (regions.uses_mesh_groups())
      {
        require(geometry.source() == Geometry<dim>::Source::mesh,
                "Material/Regions",
                "has a region chosen by 'Mesh group', but the body is not a mesh",
                "give the body by 'Geometry/Mesh file' or choose the region by 'Selector'");
        std::vector<std::string> volume_groups, boundary_groups;
        for (const auto &[id, name] : geometry.mesh_volume_group_names())
          volume_groups.push_back(name);
        for (const auto &[id, name] : geometry.mesh_group_names())
          boundary_groups.push_back(name);
        regions.check_mesh_groups(volume_groups, boundary_groups);
      }
    std::vector<unsigned long>    volume_points_of_region(regions.size(), 0);
    std::vector<double>           properties(Layout::n_properties, 0.);
    dealii::types::particle_index next_id = 0;
    const auto insert = [&](const dealii::Point<dim> &x, const unsigned int region) {
      for (unsigned int d = 0; d < dim; ++d)
        properties[Layout::position_0 + d] = x[d];
      properties[Layout::region] = region;
      // The initial stretch of the point's own constants (its material state).
      const double lambda_0 = material_state_of(regions, properties).gel->lambda_0();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          properties[Layout::F + i * dim + j] = (i == j) ? lambda_0 : 0.;
      properties[Layout::mu] = mu_0;
      if constexpr (dim == 2)
        properties[Layout::out_of_plane] = lambda_0;
      // Every rank walks all points, so that ids and checks are the same on all; each keeps
      // the points of the cells it owns.
      const auto [cell, reference] = locator.locate(x);
      if (cell->is_locally_owned())
        particles.insert_particle(x, reference, next_id, cell, dealii::make_array_view(properties));
      ++next_id;
    };

    const double h_min = grid.smallest_cell_size();

    // In an axisymmetric scene every measure is that of the revolved body: 2 pi R times the
    // meridian plane's. Surface points closer to the axis than on_axis_tolerance h lie on it
    // (a level set's contour is projected onto x = 0 to about round-off).
    constexpr double on_axis_tolerance = 1e-8;
    const auto       revolution        = [&](const dealii::Point<dim> &x) {
      return grid.axisymmetric ? 2. * dealii::numbers::PI * x[0] : 1.;
    };
    // A point of the uniform grid's spacing at level 0 until split (a mesh element's: never).
    int        spacing_level = 0;
    const auto insert_volume_point =
      [&](const dealii::Point<dim> &x, const double volume, const std::string &group) {
        std::fill(properties.begin(), properties.end(), 0.);
        properties[Layout::kind]          = static_cast<double>(PointKind::volume);
        properties[Layout::piece]         = -1;
        properties[Layout::spacing_level] = spacing_level;
        properties[Layout::measure_0] = properties[Layout::measure_n] = revolution(x) * volume;
        const unsigned int region = regions.size() > 1 ? regions.region_of(x, group) : 0;
        ++volume_points_of_region[region];
        insert(x, region);
      };

    const Body<dim> &body = geometry.body();
    if (body.has_own_volume_points())
      // At the body's own points (the Gauss points of mesh cells), as densely as the sub-cells
      // of a box body.
      for (const auto &e : body.volume_elements(points_per_cell, h_min / points_per_cell))
        {
          spacing_level = -1;
          require(grid.contains(e.centre),
                  geometry.entry(),
                  "puts the body outside the background grid, e.g. at " + format_point(e.centre),
                  "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the body");
          insert_volume_point(e.centre, e.volume, e.group_name);
        }
    else
      {
        // At sub-cell centres.
        const unsigned int n          = points_per_cell;
        double             sub_volume = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          sub_volume *= grid.cell_size(d) / n;
        unsigned int n_sub = 1, n_cells = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n_sub *= n;
            n_cells *= grid.n_cells[d];
          }
        bool in_boxes = false;
        for (unsigned int c = 0; c < n_cells; ++c)
          for (unsigned int s = 0; s < n_sub; ++s)
            {
              dealii::Point<dim> x;
              unsigned int       rest_c = c, rest_s = s;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const unsigned int ic = rest_c % grid.n_cells[d], is = rest_s % n;
                  rest_c /= grid.n_cells[d];
                  rest_s /= n;
                  x[d] = grid.lower[d] + (ic + (is + 0.5) / n) * grid.cell_size(d);
                }
              in_boxes |= body.inside_boxes(x);
              if (!body.inside(x))
                continue;
              const unsigned int level = grid.refinement_level(x);
              spacing_level            = level;
              if (level == 0)
                insert_volume_point(x, sub_volume, "");
              else
                split_volume_point<dim>(x,
                                        sub_volume,
                                        level,
                                        grid,
                                        points_per_cell,
                                        insert_volume_point);
            }
        body.check_volume_points(next_id, in_boxes, n_cells * n_sub);
      }

    regions.check_populated(volume_points_of_region);

    // The body must lie in the grid: check the boundary (it bounds the body).
    check_boundary_groups(geometry, boundary_conditions);
    {
      // The axis of an axisymmetric scene is the grid's lower x edge, where the body may end:
      // a level set is sampled beyond it, so that its contour closes along the axis.
      dealii::Point<dim> sample_lower = grid.lower;
      if (grid.axisymmetric)
        {
          sample_lower[0] -= h_min;
          check_not_across_axis(body,
                                geometry.entry(),
                                sample_lower,
                                grid.upper,
                                h_min / surface_points_per_edge);
        }
      const auto elements =
        body.surface_elements(h_min / surface_points_per_edge, sample_lower, grid.upper);
      // The axis of an axisymmetric scene is no boundary of the revolved body (its area
      // 2 pi R ds vanishes): u_r = 0 holds there by the axis unknowns (MixedSystem).
      const auto on_axis = [&](const auto &e) {
        return grid.axisymmetric && e.centre[0] <= on_axis_tolerance * h_min;
      };
      std::vector<unsigned int> count(boundary_conditions.n_pieces(), 0);
      std::vector<unsigned int> levels;
      const auto                split = split_surface_elements(elements, grid, levels);
      for (unsigned int k = 0; k < split.size(); ++k)
        {
          const auto &e = split[k];
          require(!grid.axisymmetric || e.centre[0] >= -relative_position_tolerance * h_min,
                  geometry.entry(),
                  "puts material at R = x < 0 in an axisymmetric scene, e.g. at " +
                    format_point(e.centre) + ", where the meridian plane has none",
                  "move or cut the body so that it lies at x >= 0 (the axis is x = 0)");
          require(grid.contains(e.centre),
                  geometry.entry(),
                  "puts the body outside the background grid, e.g. at " + format_point(e.centre),
                  "enlarge 'Background grid/Lower corner' and 'Upper corner' or move the body");
          if (on_axis(e))
            continue;
          const double                 area   = e.normal_area.norm();
          const dealii::Tensor<1, dim> normal = e.normal_area / area;
          const int                    piece =
            boundary_conditions.piece_of(e.centre, normal, e.boundary_id, e.group_name);
          std::fill(properties.begin(), properties.end(), 0.);
          if (piece >= 0)
            {
              const auto &p = boundary_conditions.piece(piece);
              ++count[piece];
              properties[Layout::kind] = static_cast<double>(
                surface_point_kind(p.displacement_prescribed(), p.chemical_potential_prescribed()));
            }
          else
            properties[Layout::kind] = static_cast<double>(PointKind::neumann_neumann);
          properties[Layout::piece]         = piece;
          properties[Layout::spacing_level] = levels[k];
          const double revolved_area        = revolution(e.centre) * area;
          properties[Layout::measure_0] = properties[Layout::measure_n] = revolved_area;
          for (unsigned int d = 0; d < dim; ++d)
            properties[Layout::normal_area_0 + d] = properties[Layout::normal_area_n + d] =
              revolution(e.centre) * e.normal_area[d];
          // A surface point takes the region of the body just inside it: on an interface that
          // meets the boundary, the side its normal points away from.
          unsigned int region = 0;
          if (regions.size() > 1)
            region = regions.region_of(e.centre - (0.01 * h_min) * normal, e.volume_group);
          insert(e.centre, region);
        }
      for (unsigned int i = 0; i < boundary_conditions.n_pieces(); ++i)
        if (count[i] == 0)
          check_not_overlapped(elements, boundary_conditions, i, on_axis);
      for (unsigned int i = 0; i < boundary_conditions.n_pieces(); ++i)
        require(count[i] > 0,
                "Boundary conditions/" + boundary_conditions.piece(i).name + "/Selector",
                "selects no point of the body's boundary",
                boundary_conditions.piece(i).boundary_groups().empty()
                  ? "check the expression against the geometry (variables " +
                      PointNormalExpression::variable_names(dim) + ")" +
                      (grid.axisymmetric ? "; in an axisymmetric scene the axis x = 0 is no "
                                           "boundary and needs no piece (u_r = 0 holds there)"
                                         : "")
                  : "check the groups against the mesh's physical groups");
    }
    particles.update_cached_numbers();
  }


  template class MaterialPointGenerator<2>;
  template class MaterialPointGenerator<3>;
} // namespace GelMPM

#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/core/collective.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/io/grid_output.h>
#include <gelmpm/particles/point_refinement.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/rigid_motion.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/simulator/symmetry_planes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  void
  Scene<dim>::declare_parameters(dealii::ParameterHandler       &prm,
                                 const std::vector<std::string> &boundary_pieces,
                                 const std::vector<std::string> &material_regions,
                                 const std::vector<std::string> &obstacle_names)
  {
    FloryRehnerGel<dim>::declare_parameters(prm);
    MaterialRegions<dim>::declare_parameters(prm, material_regions);
    BackgroundGrid<dim>::declare_parameters(prm);
    Geometry<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm, boundary_pieces);
    MaterialPointGenerator<dim>::declare_parameters(prm);
    DiscretisationSettings::declare_parameters(prm);
    NitscheSettings::declare_parameters(prm);
    ContactSettings::declare_parameters(prm);
    declare_obstacles<dim>(prm, obstacle_names);
  }


  template <int dim>
  Scene<dim>::Scene(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &boundary_pieces,
                    const std::string              &scene_directory,
                    const MPI_Comm                  communicator,
                    const std::vector<std::string> &material_regions,
                    const std::vector<std::string> &obstacle_names)
    : communicator(communicator)
  {
    material.parse_parameters(prm);
    regions.parse_parameters(prm, material_regions, material);
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm, scene_directory);
    boundary_conditions.parse_parameters(prm, boundary_pieces);
    generator.parse_parameters(prm);
    discretisation.parse_parameters(prm);
    grid.set_grading_reach(discretisation.support_reach_in_pair_cells());
    nitsche.parse_parameters(prm);
    contact.parse_parameters(prm, dim, obstacle_names);
    // Both name statistics columns <name>_force_x, ...: the piece's force would be lost.
    for (const auto &name : obstacle_names)
      require(std::find(boundary_pieces.begin(), boundary_pieces.end(), name) ==
                boundary_pieces.end(),
              "Contact/Obstacles",
              "names the obstacle '" + name +
                "', and 'Boundary conditions/Pieces' names a piece '" + name +
                "': both would write the statistics columns " + name +
                "_force_x, ..., and the piece's force would be lost",
              "give the obstacle a name of its own, e.g. '" + name + "_obstacle'");
    require(!contact.self_contact.enabled() || !contact.self_contact.separate_faces ||
              dealii::Utilities::MPI::n_mpi_processes(communicator) == 1,
            "Contact/Self contact/Separate faces",
            "is true in a run on several MPI ranks, but the faces' copies of the grid's functions "
            "are found on one rank only for now (the pairs of points and segments work on "
            "several)",
            "run on one rank, or set 'Separate faces = false' (faces that share cells then stay "
            "tied)");
    require(!contact.self_contact.enabled() || dim == 2 || contact.self_contact.tangent_planes,
            "Contact/Self contact/Other face",
            "is 'segments' in a 3D scene, whose surface points form no polylines (in 3D a point "
            "always touches the tangent planes of the nearest facing points)",
            "remove the entry, or set it to 'tangent planes'");
    if (contact.self_contact.enabled())
      self_contact_pieces(contact.self_contact, boundary_conditions);
    obstacles = parse_obstacles<dim>(prm, obstacle_names);
    for (auto &obstacle : obstacles)
      obstacle.check_inside_grid(grid.lower, grid.upper);
    check_points_per_cell();
    band_pieces    = band_piece_indices();
    band_obstacles = band_obstacle_indices();
  }


  template <int dim>
  std::vector<int>
  Scene<dim>::band_piece_indices() const
  {
    std::vector<int> indices;
    for (const auto &name : grid.band_piece_names)
      {
        int index = -1;
        for (unsigned int i = 0; i < boundary_conditions.n_pieces(); ++i)
          if (boundary_conditions.piece(i).name == name)
            index = i;
        require(index >= 0,
                "Background grid/Refinement band pieces",
                "names '" + name + "', which is no piece of 'Boundary conditions/Pieces'",
                "name pieces listed in 'Boundary conditions/Pieces'");
        indices.push_back(index);
      }
    return indices;
  }


  template <int dim>
  std::vector<unsigned int>
  Scene<dim>::band_obstacle_indices() const
  {
    std::vector<unsigned int> indices;
    if (!(grid.obstacle_band > 0.))
      return indices;
    require(!obstacles.empty(),
            "Background grid/Refinement obstacle band",
            "is set, but the scene has no rigid obstacle ('Contact/Obstacles' is empty)",
            "name the obstacles in 'Contact/Obstacles', or set the band to 0");
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      if (grid.band_obstacle_names.empty())
        indices.push_back(k);
    for (const auto &name : grid.band_obstacle_names)
      {
        unsigned int k = 0;
        while (k < obstacles.size() && obstacles[k].name != name)
          ++k;
        require(k < obstacles.size(),
                "Background grid/Refinement obstacles",
                "names '" + name + "', which is no obstacle of 'Contact/Obstacles'",
                "name obstacles listed in 'Contact/Obstacles', or leave it empty (every one)");
        indices.push_back(k);
      }
    return indices;
  }


  template <int dim>
  void
  Scene<dim>::flag_obstacle_band(std::vector<std::vector<bool>> &flagged) const
  {
    // A cell is flagged where the obstacle's surface passes within the band of its centre's
    // distance, widened by half the cell's diagonal; |g| is that distance for planes, spheres
    // and a punch's face and rounded edge, and a cell where no contact is possible is not
    // flagged.
    for (unsigned int l = 0; l < flagged.size(); ++l)
      for (unsigned int c = 0; c < flagged[l].size(); ++c)
        {
          const auto [centre, half_diagonal] = grid.pair_cell_centre(l, c);
          for (const unsigned int k : band_obstacles)
            {
              const auto gap = obstacles[k].gap(centre);
              if (gap.possible && std::abs(gap.g) <= grid.obstacle_band + half_diagonal)
                flagged[l][c] = true;
            }
        }
  }


  namespace
  {
    /** The sums of the normal equations of a least-squares plane in dim coordinates. */
    template <int dim>
    struct PlaneSums
    {
      static constexpr unsigned int n_xx = dim * (dim + 1) / 2;
      /** 1, x (dim), x x^T (upper triangle), mu, x mu (dim). */
      static constexpr unsigned int size = 2 + 2 * dim + n_xx;

      /** Add the sample @p mu at @p x (relative to the cell's centre) to @p s. */
      static void
      add(double *s, const dealii::Tensor<1, dim> &x, const double mu)
      {
        s[0] += 1.;
        for (unsigned int d = 0, k = 0; d < dim; ++d)
          {
            s[1 + d] += x[d];
            s[2 + dim + n_xx + d] += x[d] * mu;
            for (unsigned int e = d; e < dim; ++e, ++k)
              s[1 + dim + k] += x[d] * x[e];
          }
        s[1 + dim + n_xx] += mu;
      }

      /**
       * The plane's gradient from the sums @p s of a cell of size about @p h into @p g; false
       * where the samples are too few or spread over less than a tenth of the cell in some
       * direction (a sliver of a cut cell), which gives no plane.
       */
      static bool
      gradient(const double *s, const double h, dealii::Tensor<1, dim> &g)
      {
        if (s[0] < dim + 1)
          return false;
        // The covariance of the positions, and of the positions and mu.
        dealii::Tensor<2, dim> C;
        dealii::Tensor<1, dim> b;
        for (unsigned int d = 0, k = 0; d < dim; ++d)
          {
            b[d] = (s[2 + dim + n_xx + d] - s[1 + d] * s[1 + dim + n_xx] / s[0]) / s[0];
            for (unsigned int e = d; e < dim; ++e, ++k)
              C[d][e] = C[e][d] = (s[1 + dim + k] - s[1 + d] * s[1 + e] / s[0]) / s[0];
          }
        if (dealii::determinant(C) <= std::pow(0.01 * h * h, dim))
          return false;
        g = dealii::invert(C) * b;
        return true;
      }
    };
  } // namespace


  template <int dim>
  bool
  Scene<dim>::prescribed_mu(const dealii::ArrayView<const double> &properties, double &mu) const
  {
    using Layout    = PropertyLayout<dim>;
    const int piece = std::lround(properties[Layout::piece]);
    if (kind_of(properties) == PointKind::volume || piece < 0 ||
        !boundary_conditions.piece(piece).chemical_potential_prescribed())
      return false;
    dealii::Point<dim> X_0;
    for (unsigned int d = 0; d < dim; ++d)
      X_0[d] = properties[Layout::position_0 + d];
    mu = boundary_conditions.piece(piece).chemical_potential_value().value(X_0);
    return true;
  }


  template <int dim>
  std::vector<std::vector<double>>
  Scene<dim>::mu_plane_sums() const
  {
    using Layout = PropertyLayout<dim>;
    using Sums   = PlaneSums<dim>;
    std::vector<std::vector<double>> sums(grid.refinement_levels);
    for (unsigned int l = 0; l < grid.refinement_levels; ++l)
      {
        unsigned int n = 1;
        for (const unsigned int n_d : grid.pair_cells(l))
          n *= n_d;
        sums[l].assign(Sums::size * n, 0.);
      }
    const auto add = [&](const dealii::Point<dim> &x, const double mu) {
      for (unsigned int l = 0; l < grid.refinement_levels; ++l)
        {
          const unsigned int c = grid.pair_cell_of(x, l);
          Sums::add(sums[l].data() + Sums::size * c, x - grid.pair_cell_centre(l, c).first, mu);
        }
    };
    for (const auto &particle : particles)
      {
        const auto properties = particle.get_properties();
        double     mu         = properties[Layout::mu];
        if (kind_of(properties) == PointKind::volume)
          add(particle.get_location(), mu);
        // As for the mu range: a bath's mu counts before the gel has taken it up, in the cell of
        // the material behind the point (a face on a grid line would put its points alone in
        // the empty cell beyond, where they make no plane).
        else if (prescribed_mu(properties, mu))
          {
            dealii::Tensor<1, dim> normal;
            for (unsigned int d = 0; d < dim; ++d)
              normal[d] = properties[Layout::normal_area_n + d];
            const double h = grid.smallest_cell_size() / (1u << grid.refinement_levels);
            add(particle.get_location() - 1e-3 * h * normal / normal.norm(), mu);
          }
      }
    if (Collective::is_parallel(communicator))
      for (auto &level : sums)
        dealii::Utilities::MPI::sum(level, communicator, level);
    return sums;
  }


  template <int dim>
  void
  Scene<dim>::flag_mu_gradient_jumps(std::vector<std::vector<bool>> &flagged) const
  {
    using Sums      = PlaneSums<dim>;
    const auto sums = mu_plane_sums();
    for (unsigned int l = 0; l < flagged.size(); ++l)
      {
        const auto                          n = grid.pair_cells(l);
        std::vector<dealii::Tensor<1, dim>> g(flagged[l].size());
        std::vector<bool>                   has(flagged[l].size());
        for (unsigned int c = 0; c < g.size(); ++c)
          has[c] = Sums::gradient(sums[l].data() + Sums::size * c,
                                  2. * grid.pair_cell_centre(l, c).second / std::sqrt(double(dim)),
                                  g[c]);
        // The slope's change from a cell to its face neighbour, over a cell: how far mu departs
        // from a plane across the two cells, which the degree-q pieces must follow.
        for (unsigned int c = 0; c < g.size(); ++c)
          for (unsigned int d = 0, stride = 1; d < dim; stride *= n[d], ++d)
            if (has[c] && (c / stride) % n[d] + 1 < n[d] && has[c + stride] &&
                (g[c + stride] - g[c]).norm() * (grid.upper[d] - grid.lower[d]) / n[d] >
                  grid.refinement_mu_gradient_jump)
              flagged[l][c] = flagged[l][c + stride] = true;
      }
  }


  template <int dim>
  std::vector<dealii::Point<dim>>
  Scene<dim>::band_surface_points() const
  {
    std::vector<dealii::Point<dim>> surface;
    if (!(grid.refinement_band > 0.))
      return surface;
    for (const auto &particle : particles)
      {
        const auto properties = particle.get_properties();
        if (kind_of(properties) == PointKind::volume)
          continue;
        const int piece = std::lround(properties[PropertyLayout<dim>::piece]);
        if (band_pieces.empty() ||
            std::find(band_pieces.begin(), band_pieces.end(), piece) != band_pieces.end())
          surface.push_back(position_of(particle.get_location(), properties));
      }
    if (Collective::is_parallel(communicator))
      {
        std::vector<dealii::Point<dim>> all;
        for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, surface))
          all.insert(all.end(), part.begin(), part.end());
        surface = std::move(all);
      }
    return surface;
  }


  template <int dim>
  std::vector<std::vector<bool>>
  Scene<dim>::flagged_cells(const double t)
  {
    std::vector<std::vector<bool>> flagged;
    const bool by_mu = grid.refinement_mu_range > 0., by_material = grid.material_region != nullptr;
    if (!by_mu && !by_material && band_obstacles.empty() && grid.moving_region == nullptr &&
        !(grid.refinement_mu_gradient_jump > 0.))
      return flagged;
    using Layout = PropertyLayout<dim>;
    std::vector<std::vector<double>> lowest(grid.refinement_levels),
      highest(grid.refinement_levels), material(grid.refinement_levels);
    for (unsigned int l = 0; l < grid.refinement_levels; ++l)
      {
        unsigned int n = 1;
        for (const unsigned int n_d : grid.pair_cells(l))
          n *= n_d;
        lowest[l].assign(n, std::numeric_limits<double>::max());
        highest[l].assign(n, std::numeric_limits<double>::lowest());
        material[l].assign(n, 0.);
      }
    const auto add = [&](const dealii::Point<dim> &x, const double mu) {
      for (unsigned int l = 0; l < grid.refinement_levels; ++l)
        {
          const unsigned int c = grid.pair_cell_of(x, l);
          lowest[l][c]         = std::min(lowest[l][c], mu);
          highest[l][c]        = std::max(highest[l][c], mu);
        }
    };
    // Nothing to gather for the other criteria.
    for (const auto &particle : particles)
      {
        if (!by_mu && !by_material)
          break;
        const auto         properties = particle.get_properties();
        const auto         x          = particle.get_location();
        dealii::Point<dim> X_0;
        for (unsigned int d = 0; d < dim; ++d)
          X_0[d] = properties[Layout::position_0 + d];
        if (by_material && grid.material_region->value(X_0) <= 0.)
          for (unsigned int l = 0; l < grid.refinement_levels; ++l)
            material[l][grid.pair_cell_of(x, l)] = 1.;
        if (!by_mu)
          continue;
        add(x, properties[Layout::mu]);
        // A bath's mu refines before the gel has taken it up (at t = 0 the points all hold
        // mu_0): the prescribed value at the start of the step.
        if (double mu; prescribed_mu(properties, mu))
          add(x, mu);
      }
    flagged.resize(grid.refinement_levels);
    for (unsigned int l = 0; l < grid.refinement_levels; ++l)
      {
        if (Collective::is_parallel(communicator))
          {
            dealii::Utilities::MPI::min(lowest[l], communicator, lowest[l]);
            dealii::Utilities::MPI::max(highest[l], communicator, highest[l]);
            dealii::Utilities::MPI::max(material[l], communicator, material[l]);
          }
        flagged[l].assign(lowest[l].size(), false);
        for (unsigned int c = 0; c < flagged[l].size(); ++c)
          flagged[l][c] = material[l][c] > 0. ||
                          (by_mu && highest[l][c] - lowest[l][c] > grid.refinement_mu_range);
      }
    if (grid.moving_region != nullptr)
      for (unsigned int l = 0; l < flagged.size(); ++l)
        {
          const auto inside = grid.moving_region_cells(l, t);
          for (unsigned int c = 0; c < flagged[l].size(); ++c)
            flagged[l][c] = flagged[l][c] || inside[c];
        }
    if (grid.refinement_mu_gradient_jump > 0.)
      flag_mu_gradient_jumps(flagged);
    if (!band_obstacles.empty())
      {
        // Where the obstacles are at the step's start, whatever the last attempt left them at:
        // a resumed run marks as the uninterrupted one.
        for (const unsigned int k : band_obstacles)
          obstacles[k].set_time(t);
        flag_obstacle_band(flagged);
      }
    return flagged;
  }


  template <int dim>
  bool
  Scene<dim>::keep_last_marking()
  {
    if (!grid.moves() || last_marking.empty() || last_marking == grid.moving_marked)
      return false;
    grid.set_moving_marks(last_marking);
    spaces->rebuild_hierarchies(grid);
    split_points_to_leaves(particles, grid, regions, generator.points_per_cell, *triangulation);
    return true;
  }


  template <int dim>
  bool
  Scene<dim>::coarsen_moving_refinement()
  {
    if (!grid.moves() || !grid.drop_finest_moving_level())
      return false;
    spaces->rebuild_hierarchies(grid);
    merge_points_to_leaves(particles, grid, regions, generator.points_per_cell, *triangulation);
    return true;
  }


  template <int dim>
  bool
  Scene<dim>::update_moving_refinement(const double t_begin)
  {
    if (!grid.moves())
      return false;
    // The prescribed mu at the step's start, whatever time the last attempt left the boundary
    // data at: a resumed run marks as the uninterrupted one.
    boundary_conditions.set_time(t_begin);
    last_marking = grid.moving_marked;
    // q + 2 cells of a level round a front: as deep as the shallowest box that the extension
    // accepts at a boundary (§4.1's, 4 cells of its level for q = 2).
    const bool changed = grid.mark_moving(band_surface_points(),
                                          flagged_cells(t_begin),
                                          discretisation.chemical_potential_degree + 2);
    if (changed)
      spaces->rebuild_hierarchies(grid);
    merge_points_to_leaves(particles, grid, regions, generator.points_per_cell, *triangulation);
    split_points_to_leaves(particles, grid, regions, generator.points_per_cell, *triangulation);
    return changed;
  }


  template <int dim>
  void
  Scene<dim>::check_points_per_cell() const
  {
    // With 2 x 2 points per cell the swollen cells at a cut boundary hold too few points to keep
    // the B-spline stiffness definite: §4.1 stops at 11.3 tau_d, every step size failing, while
    // 3 x 3 runs to the end with degree 2 and 3.
    require(generator.points_per_cell >= 3,
            "Material points/Points per cell",
            "is " + std::to_string(generator.points_per_cell) +
              ": with fewer than 3 points per cell and direction the cells at the body's boundary "
              "hold too few points to keep the stiffness definite once the gel swells",
            "use at least 3 (the paper: 5 to 8)");
  }


  namespace
  {
    /** The material points inside an obstacle, over all ranks. */
    template <int dim>
    struct Overlap
    {
      unsigned long long n_inside = 0;
      unsigned long long n_points = 0;
      /** The deepest penetration and the point that has it. */
      double             deepest = 0.;
      dealii::Point<dim> where;
    };


    /** The points of @p particles inside @p obstacle by more than @p tolerance. */
    template <int dim>
    Overlap<dim>
    overlap(const Obstacle<dim>                           &obstacle,
            const dealii::Particles::ParticleHandler<dim> &particles,
            const double                                   tolerance,
            const MPI_Comm                                 communicator)
    {
      Overlap<dim> local;
      for (const auto &p : particles)
        {
          const auto x   = position_of(p.get_location(), p.get_properties());
          const auto gap = obstacle.gap(x);
          ++local.n_points;
          if (!gap.possible || !(gap.g > tolerance))
            continue;
          ++local.n_inside;
          if (gap.g > local.deepest)
            {
              local.deepest = gap.g;
              local.where   = x;
            }
        }
      Overlap<dim> global;
      global.n_inside          = dealii::Utilities::MPI::sum(local.n_inside, communicator);
      global.n_points          = dealii::Utilities::MPI::sum(local.n_points, communicator);
      std::vector<double> mine = {local.deepest};
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(local.where[d]);
      // The deepest point of all ranks, the first rank's on a tie: the same on every rank.
      for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, mine))
        if (part[0] > global.deepest)
          {
            global.deepest = part[0];
            for (unsigned int d = 0; d < dim; ++d)
              global.where[d] = part[1 + d];
          }
      return global;
    }


    template <int dim>
    std::string
    shape_name(const Obstacle<dim> &obstacle)
    {
      using Shape = typename Obstacle<dim>::Shape;
      return obstacle.shape == Shape::plane    ? "plane"
             : obstacle.shape == Shape::sphere ? "sphere"
                                               : "flat punch";
    }


    std::string
    number(const double x)
    {
      std::ostringstream text;
      text << x;
      return text.str();
    }
  } // namespace


  template <int dim>
  void
  Scene<dim>::check_obstacles(const std::vector<double> &times)
  {
    // Far below any gap a scene means, far above the round-off of a point placed on the
    // obstacle's surface (an obstacle that starts touching the body, gap 0).
    const double tolerance = 1e-6 * grid.smallest_cell_size();
    for (auto &obstacle : obstacles)
      {
        obstacle.check_motion(times);
        check_obstacle_start(obstacle, tolerance);
        check_obstacle_path(obstacle, times, tolerance);
        obstacle.set_time(0.);
      }
  }


  template <int dim>
  void
  Scene<dim>::check_obstacle_start(Obstacle<dim> &obstacle, const double tolerance) const
  {
    using Shape = typename Obstacle<dim>::Shape;
    obstacle.set_time(0.);
    const auto inside = overlap(obstacle, particles, tolerance, communicator);
    if (inside.n_inside == 0)
      return;
    const std::string where = "Contact/" + obstacle.name;
    const std::string count =
      inside.n_inside == inside.n_points
        ? "all " + std::to_string(inside.n_points) + " material points of the body"
        : std::to_string(inside.n_inside) + " of the body's " + std::to_string(inside.n_points) +
            " material points";
    // A face turned the wrong way holds the body and leaves none outside; turned round it
    // holds none.
    if (obstacle.shape != Shape::sphere)
      {
        Obstacle<dim> reversed = obstacle;
        for (unsigned int d = 0; d < dim; ++d)
          reversed.normal[d] = 0. - obstacle.normal[d]; // not -0
        if (overlap(reversed, particles, tolerance, communicator).n_inside == 0)
          throw InputError(where + "/Normal",
                           "is " + format_point(obstacle.normal) + " (normalised), which puts " +
                             count + " behind the " + shape_name(obstacle) +
                             "'s face at t = 0, inside the obstacle; turned round it holds none",
                           "give the outward normal of the obstacle's face, pointing from the "
                           "obstacle towards the gel: " +
                             format_point(reversed.normal));
      }
    const std::string how =
      obstacle.shape == Shape::sphere
        ? "move 'Center' out of the body or reduce 'Radius'"
        : "move 'Center' by at least " + number(inside.deepest) + " along 'Normal'";
    throw InputError(where + "/Center",
                     "puts the " + shape_name(obstacle) + " around " + count +
                       " at t = 0 (the deepest " + number(inside.deepest) + " inside, at " +
                       format_point(inside.where) +
                       "): contact acts on the body's surface only, so an obstacle that starts "
                       "inside the body is never pushed out of it (the first step cannot "
                       "converge), and one wholly inside the gel never touches it",
                     "place the obstacle clear of the body at t = 0, touching its surface at "
                     "most: " +
                       how);
  }


  template <int dim>
  void
  Scene<dim>::check_obstacle_path(Obstacle<dim>             &obstacle,
                                  const std::vector<double> &times,
                                  const double               tolerance) const
  {
    for (const double t : times)
      {
        obstacle.set_time(t);
        const auto inside = overlap(obstacle, particles, tolerance, communicator);
        if (inside.n_points == 0 || inside.n_inside < inside.n_points)
          continue;
        const dealii::Tensor<1, dim> moved = obstacle.reference_point() - obstacle.center;
        throw InputError("Contact/" + obstacle.name + "/Motion",
                         "moves the " + shape_name(obstacle) + " by " + format_point(moved) +
                           " by t = " + number(t) +
                           ", where it would hold the whole body as it is at t = 0 (all " +
                           std::to_string(inside.n_points) +
                           " material points): the gel would have to be pressed to nothing, "
                           "and the run would stop where it cannot converge",
                         "give a motion that presses the obstacle into the body by less than "
                         "the body's size (a slower speed, a ramp that ends earlier), or a "
                         "shorter 'Time stepping/End time'");
      }
  }


  template <int dim>
  void
  Scene<dim>::create_material_points()
  {
    // The spaces first: an odd cell count with subdivision is reported before point generation,
    // which may take long on a large grid.
    spaces = std::make_unique<DiscreteSpaces<dim>>(grid, discretisation);
    // The run's memory from the grid and the body's cells, before any cell or point is made
    // (also under --check): a body of boxes or a level set, whose cells are known from the
    // grid alone.
    if (geometry.source() != Geometry<dim>::Source::mesh)
      generator.check_point_memory(geometry, grid);
    if (Collective::is_parallel(communicator))
      {
        auto distributed =
          std::make_unique<dealii::parallel::distributed::Triangulation<dim>>(communicator);
        distributed->signals.weight.connect(
          [this](const typename dealii::Triangulation<dim>::cell_iterator &cell,
                 const typename dealii::Triangulation<dim>::CellStatus) -> unsigned int {
            return added_weight(particles.n_particles_in_cell(cell));
          });
        triangulation = std::move(distributed);
      }
    else
      triangulation = std::make_unique<dealii::Triangulation<dim>>();
    grid.create_triangulation(*triangulation);
    particles.initialize(*triangulation, mapping, PropertyLayout<dim>::n_properties);
    generator.generate(geometry, grid, *triangulation, boundary_conditions, regions, particles);
    update_moving_refinement(0.);
    balance_partition();
  }


  template <int dim>
  void
  Scene<dim>::balance_partition()
  {
    auto *distributed =
      dynamic_cast<dealii::parallel::distributed::Triangulation<dim> *>(triangulation.get());
    if (distributed == nullptr)
      return;
    particles.prepare_for_coarsening_and_refinement();
    distributed->repartition();
    particles.unpack_after_coarsening_and_refinement();
  }


  template <int dim>
  double
  Scene<dim>::imbalance() const
  {
    if (!Collective::is_parallel(communicator))
      return 1.;
    double local = 0.;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        local += base_weight + added_weight(particles.n_particles_in_cell(cell));
    const double mean = dealii::Utilities::MPI::sum(local, communicator) /
                        dealii::Utilities::MPI::n_mpi_processes(communicator);
    return mean > 0. ? dealii::Utilities::MPI::max(local, communicator) / mean : 1.;
  }


  template <int dim>
  void
  Scene<dim>::create_system()
  {
    system = std::make_unique<MixedSystem<dim>>(regions,
                                                boundary_conditions,
                                                nitsche,
                                                *spaces,
                                                triangulation->get_communicator());
    if (contact.enabled() || contact.self_contact.enabled())
      system->set_contact(contact, obstacles);
  }


  template <int dim>
  std::vector<unsigned int>
  Scene<dim>::volume_points_per_cell() const
  {
    auto count = GridOutput<dim>::count_volume_points(particles, spaces->u_space());
    if (Collective::is_parallel(communicator))
      dealii::Utilities::MPI::sum(count, communicator, count);
    return count;
  }


  template <int dim>
  void
  Scene<dim>::check_grid_resolves_body()
  {
    const auto        volume_points = volume_points_per_cell();
    std::vector<bool> has_material(volume_points.size());
    for (unsigned int c = 0; c < has_material.size(); ++c)
      has_material[c] = volume_points[c] > 0;
    try
      {
        spaces->reinit(has_material);
        while (grid.refinement_budget > 0 && spaces->n_dofs() > grid.refinement_budget &&
               coarsen_moving_refinement())
          spaces->reinit(has_material);
      }
    catch (const InputError &)
      {
        // Already names its entry and fix (a refinement box too shallow for the extension).
        throw;
      }
    catch (const std::runtime_error &e)
      {
        throw_unresolved_body(e.what());
      }
    require(grid.refinement_budget == 0 || spaces->n_dofs() <= grid.refinement_budget,
            "Background grid/Refinement budget",
            "is " + std::to_string(grid.refinement_budget) +
              " unknowns, but the grid without its moving refinement gives " +
              std::to_string(spaces->n_dofs()) + " at the start",
            "raise the budget, or refine less by 'Refinement boxes' and 'Refinement region'");
  }


  template <int dim>
  void
  Scene<dim>::throw_unresolved_body(const std::string &reason) const
  {
    // The planes of symmetry first: there the extension's own advice (let the body end on the
    // grid's side, enlarge the grid) misleads, as the body already ends on the side, and the
    // fix is exact: the plane on a grid line with q + 1 cells beyond it.
    const unsigned int q = discretisation.displacement_degree;
    const auto         near =
      planes_near_grid_side(roller_planes(particles, boundary_conditions, communicator), grid, q);
    if (!near.empty())
      throw InputError("Background grid",
                       "cannot carry the body where it meets its plane(s) of symmetry " +
                         plane_list(near, grid) +
                         ": the cut cells where the body's surface meets a plane are extrapolated "
                         "from control points within " +
                         std::to_string(q) +
                         " cells of the grid's side, where the extended B-splines' "
                         "extrapolation is not exact",
                       "let the grid reach " + std::to_string(q + 1) +
                         " cells beyond each such plane, the plane on a grid line, with the same "
                         "cell size: " +
                         grid_entries_for_planes(near, grid, q + 1, discretisation.subdivision));
    throw InputError("Background grid/Cells",
                     "cannot carry the body's initial configuration: " + reason,
                     "refine the grid ('Background grid/Cells') or lower "
                     "'Discretisation/Displacement degree'; where the body ends at the "
                     "grid's side, place the grid so that it ends on a grid line there "
                     "('Lower corner', 'Upper corner')");
  }


  template <int dim>
  std::vector<std::vector<dealii::Point<dim>>>
  Scene<dim>::boundary_samples() const
  {
    std::vector<std::vector<dealii::Point<dim>>> points(boundary_conditions.n_pieces());
    // (piece, X_0) of the surface points of every rank, in the order of the ranks, so that
    // every rank checks the same samples and fails or passes with the others.
    std::vector<double> local;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        const int  piece = piece_of(props);
        if (piece < 0)
          continue;
        local.push_back(piece);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(props[PropertyLayout<dim>::position_0 + d]);
      }
    for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, local))
      for (std::size_t k = 0; k < part.size(); k += dim + 1)
        {
          dealii::Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = part[k + 1 + d];
          points[static_cast<unsigned int>(part[k])].push_back(x);
        }
    std::vector<std::vector<dealii::Point<dim>>> samples(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const std::size_t stride = points[i].size() / 64 + 1;
        for (std::size_t k = 0; k < points[i].size(); k += stride)
          samples[i].push_back(points[i][k]);
      }
    return samples;
  }


  template <int dim>
  std::string
  Scene<dim>::check_boundary_values(const double end_time)
  {
    // Samples of each piece and times over the run: enough to catch an expression that is not
    // finite (1/0, log(-1)) before the run cuts its steps without saying why.
    const auto          samples = boundary_samples();
    std::vector<double> times;
    for (unsigned int k = 0; k <= 8; ++k)
      times.push_back(end_time * k / 8.);
    const double largest_mu = regions.largest_swelling_chemical_potential(grid.axisymmetric);
    for (unsigned int i = 0; i < boundary_conditions.n_pieces(); ++i)
      boundary_conditions.piece(i).check_values(samples[i], times, largest_mu);
    check_obstacles(times);
    return boundary_jump(samples);
  }


  template <int dim>
  std::string
  Scene<dim>::boundary_jump(const std::vector<std::vector<dealii::Point<dim>>> &samples) const
  {
    // The functions are at t = 0 (check_values() leaves them there).
    const double mu_0    = regions[0].mu_0();
    double       largest = 0.1 * std::abs(mu_0);
    std::string  jump;
    for (unsigned int i = 0; i < boundary_conditions.n_pieces(); ++i)
      {
        const auto &piece = boundary_conditions.piece(i);
        if (!piece.chemical_potential_prescribed())
          continue;
        for (const auto &x : samples[i])
          if (const double mu = piece.chemical_potential_value().value(x);
              std::abs(mu - mu_0) > largest)
            {
              largest = std::abs(mu - mu_0);
              std::ostringstream words;
              words << "the chemical potential prescribed on '" << piece.name
                    << "' jumps at t = 0 from the gel's mu_0/(k_BT) = " << mu_0 << " to " << mu;
              jump = words.str();
            }
      }
    return jump;
  }


  template <int dim>
  void
  Scene<dim>::check_rigid_motions() const
  {
    const auto motions = unheld_rigid_motions(particles,
                                              boundary_conditions,
                                              contact,
                                              grid.lower,
                                              grid.upper,
                                              communicator,
                                              grid.axisymmetric);
    if (motions.empty())
      return;
    std::string list;
    for (unsigned int i = 0; i < motions.size(); ++i)
      list += (i == 0 ? "" : i + 1 == motions.size() ? " and " : ", ") + motions[i];
    // The tangent is singular along them: the solver gives the body an arbitrary amount of
    // them, made of round-off (a quarter square free on all sides ended its swelling 6 % of
    // its size off its symmetric position, without a word).
    throw InputError("Boundary conditions",
                     "leave the body free in " + list +
                       ": no piece prescribes the displacement along such a motion and no "
                       "contact plane lies across it, so the tangent is singular and the solves "
                       "move the body by an arbitrary amount of it made of round-off",
                     "give the pieces on the body's planes of symmetry 'Displacement = normal', "
                     "or hold a piece by 'Displacement = fixed'");
  }


  template class Scene<2>;
  template class Scene<3>;
} // namespace GelMPM

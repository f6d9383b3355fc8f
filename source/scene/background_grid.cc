#include <gelmpm/core/available_memory.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unistd.h>

namespace GelMPM
{
  namespace
  {
    /**
     * Call @p f(cell, index) for every cell of a grid of @p n cells per direction whose
     * multi-index lies between @p first and @p last (both included) in every direction.
     */
    template <int dim, typename F>
    void
    for_each_cell_between(const std::array<unsigned int, dim> &n,
                          const std::array<unsigned int, dim> &first,
                          const std::array<unsigned int, dim> &last,
                          const F                             &f)
    {
      std::array<unsigned int, dim> i = first;
      while (true)
        {
          unsigned int cell = 0, stride = 1;
          for (unsigned int d = 0; d < dim; ++d)
            {
              cell += i[d] * stride;
              stride *= n[d];
            }
          f(cell, i);
          unsigned int d = 0;
          for (; d < dim && i[d] == last[d]; ++d)
            i[d] = first[d];
          if (d == dim)
            return;
          ++i[d];
        }
    }


    /**
     * Call @p f(cell) for every cell of a grid of @p n cells per direction whose multi-index
     * differs from that of @p centre by at most @p distance in every direction.
     */
    template <int dim, typename F>
    void
    for_each_cell_near(const std::array<unsigned int, dim> &n,
                       const unsigned int                   centre,
                       const unsigned int                   distance,
                       const F                             &f)
    {
      std::array<unsigned int, dim> first, last;
      unsigned int                  rest = centre;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int index = rest % n[d];
          rest /= n[d];
          first[d] = index >= distance ? index - distance : 0;
          last[d]  = std::min(n[d] - 1, index + distance);
        }
      for_each_cell_between<dim>(n, first, last, [&](const unsigned int cell, const auto &) {
        f(cell);
      });
    }


    /** The cell of the next coarser grid of pairs that holds cell @p c of a grid of @p n. */
    template <int dim>
    unsigned int
    parent_cell(const std::array<unsigned int, dim> &n, const unsigned int c)
    {
      unsigned int rest = c, parent = 0, stride = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          parent += (rest % n[d]) / 2 * stride;
          rest /= n[d];
          stride *= n[d] / 2;
        }
      return parent;
    }


    /**
     * The level set @p text in x, y (, z) of the entry @p entry, or null if empty; InputError if
     * it cannot be parsed.
     */
    template <int dim>
    std::shared_ptr<dealii::FunctionParser<dim>>
    parse_level_set(const std::string &text,
                    const std::string &entry,
                    const bool         time_dependent = false)
    {
      if (text.empty())
        return nullptr;
      const std::string variables =
        std::string(dim == 2 ? "x,y" : "x,y,z") + (time_dependent ? ",t" : "");
      auto parser = std::make_shared<dealii::FunctionParser<dim>>(1);
      try
        {
          const QuietCerr quiet;
          parser->initialize(variables, text, {}, time_dependent);
          // The parser compiles lazily: evaluate once to surface syntax errors here.
          (void)parser->value(dealii::Point<dim>());
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(entry,
                           "'" + text + "' cannot be parsed: " + describe(e),
                           "write an expression in " + variables +
                             ", <= 0 where the grid is to be refined");
        }
      return parser;
    }
  } // namespace


  template <int dim>
  void
  BackgroundGrid<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Background grid");
    prm.declare_entry("Lower corner",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Lower corner of the fixed background grid, one coordinate per direction.");
    prm.declare_entry("Upper corner",
                      dim == 2 ? "1, 1" : "1, 1, 1",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Upper corner of the background grid. The body must stay inside the grid for "
                      "the whole run (it swells): a face that reaches the edge of the grid stops "
                      "the run unless a roller or a fixed condition holds it there.");
    prm.declare_entry("Cells",
                      dim == 2 ? "10, 10" : "10, 10, 10",
                      Patterns::List(Patterns::Integer(1), dim, dim),
                      "Number of cells per direction of the displacement grid (cell size h_u). "
                      "With mu on the coarse grid (subdivision) the counts must be even.");
    prm.declare_entry("Coordinate system",
                      "Cartesian",
                      Patterns::Selection("Cartesian|axisymmetric"),
                      "Cartesian: x, y (, z); in 2D the gel is in plane strain. axisymmetric (2D "
                      "only): the grid is the meridian plane of a body of revolution, x the "
                      "radius R and y the axis z; the hoop stretch r/R enters F, every volume "
                      "and area is that of the revolved body (2 pi R), and u_r = 0 on the axis. "
                      "The grid's 'Lower corner' must then have x = 0: its left edge is the axis "
                      "(doc/axisymmetric.md).");
    prm.declare_entry(
      "Refinement boxes",
      "",
      Patterns::Anything(),
      "Boxes where the background grid is refined, each 'lower corner : upper "
      "corner' (coordinates separated by commas), boxes separated by ';', e.g. "
      "'0, 0.75 : 0.2, 1.05'. Every cell pair (cell size 2h, the chemical "
      "potential's grid with subdivision) that overlaps a box is halved, "
      "'Refinement levels' times; the displacement grid is halved with it, so that "
      "mu stays one level coarser than u (truncated hierarchical B-splines, "
      "doc/architecture.md). Volume and surface points are as many per cell at "
      "every level, and the penalties take each leaf's h. 2D and 3D, any linear "
      "solver (Krylov with the algebraic multigrid), on one or several ranks. A box that "
      "meets the body's boundary must reach about 2(q+1) cells of its finest "
      "level into the body (the extension). Empty: the uniform grid.");
    prm.declare_entry("Refinement region",
                      "",
                      Patterns::Anything(),
                      "Where the background grid is refined, besides 'Refinement boxes': an "
                      "expression in x, y (2D) or x, y, z (3D) of the initial configuration "
                      "(the fixed grid's coordinates), e.g. 'abs(sqrt(x^2 + y^2 + z^2) - 0.5) - "
                      "0.1' for a band round a sphere of radius 0.5. A cell pair is refined at "
                      "a level when its parent is (or at the first level) and the expression is "
                      "<= 0 at one of 5 points per direction of the cell, corners included (a "
                      "region thinner than a quarter of a cell may be missed). The grid is "
                      "fixed for the run: a band must cover the room a moving surface sweeps. "
                      "Combined with the boxes: a cell is refined where either refines it. "
                      "Empty: none.");
    prm.declare_entry("Refinement band",
                      "0",
                      Patterns::Double(0.),
                      "Refine the grid within this distance of the body's current surface "
                      "(its surface points, or those of 'Refinement band pieces'), marked anew "
                      "at the start of every step, so that the refined cells follow a moving "
                      "surface. Points that enter a finer leaf are split into 2^dim children per "
                      "level (volume, solvent and N_0 A_0 conserved); points stay split where the "
                      "band has moved on (doc/architecture.md, \"A band that follows the "
                      "surface\"). The band must reach about 2(q+1) cells of its finest level "
                      "into the body (the extension). Combined with the boxes and the region. "
                      "A length in the scene's units; 0: none.");
    prm.declare_entry(
      "Refinement moving region",
      "",
      Patterns::Anything(),
      "Refine the grid where this expression in x, y (, z) and t is <= 0: a level set of "
      "the current configuration that moves in time (e.g. 'abs(x - 0.5 - 0.1 * t) - 0.1' for a "
      "strip that travels with a loading), evaluated at the start of every step at 5 points "
      "per direction of each cell pair, corners included, with q + 2 cells of each level round "
      "the marked ones. Points are split and merged as for 'Refinement band'. Combined with the "
      "other entries. Empty: none.");
    prm.declare_entry("Refinement obstacle band",
                      "0",
                      Patterns::Double(0.),
                      "Refine the grid within this distance of the current surfaces of the "
                      "rigid obstacles ('Contact/Obstacles', or those of 'Refinement "
                      "obstacles'), marked anew at the start of every step with q + 2 cells of "
                      "each level round the marked ones, so that the refined cells follow a "
                      "moving indenter, gripper or wall and hold the edge of its contact with "
                      "the gel. Points are split and merged as for 'Refinement band'. Combined "
                      "with the other entries. A length in the scene's units; 0: none.");
    prm.declare_entry("Refinement obstacles",
                      "",
                      Patterns::Anything(),
                      "The rigid obstacles ('Contact/Obstacles', comma-separated) that "
                      "'Refinement obstacle band' follows. Empty: every one.");
    prm.declare_entry("Refinement band pieces",
                      "",
                      Patterns::Anything(),
                      "The boundary pieces ('Boundary conditions/Pieces', comma-separated) "
                      "whose surface points 'Refinement band' follows, e.g. the bath side of a "
                      "layer or an indented face. Empty: every surface point.");
    prm.declare_entry(
      "Refinement grading",
      "false",
      Patterns::Bool(),
      "Whether the refined cells are graded: round every refined cell, the cells of its level "
      "within the reach of a function's support (the degree's cells of mu's grid) have refined "
      "parents, so that at most two levels of functions are nonzero on any leaf cell (admissible "
      "truncated hierarchical B-splines of class 2; ungraded, up to one more per level). Widens "
      "the refined domains by a few cells of each coarser level (2 of mu's for Q2-Q2SD), which "
      "must then meet the extension's rule at the body's boundary too; only with 'Refinement "
      "levels' >= 2. false: the criteria's cells as they are (doc/architecture.md, \"Grading\").");
    prm.declare_entry("Refinement levels",
                      "1",
                      Patterns::Integer(1, 4),
                      "How many times the cells in 'Refinement boxes', 'Refinement region' and "
                      "'Refinement band' are halved.");
    prm.declare_entry(
      "Refinement budget",
      "0",
      Patterns::Integer(0),
      "The most unknowns (displacement and chemical potential together) that the moving "
      "refinement ('Refinement band', 'Refinement mu range', 'Refinement material region') "
      "may give a step: where a step's marking gives more, its finest level of moving marks "
      "is dropped (the points there merged back), level by level, until the step is within "
      "the budget; the next step marks anew. The log's last lines count the steps it "
      "limited. A grid that exceeds it without moving refinement at the start is an error; "
      "one that the body outgrows later runs on without moving refinement (counted in the "
      "log). 0: no limit.");
    prm.declare_entry(
      "Refinement material region",
      "",
      Patterns::Anything(),
      "Refine the grid round the material that starts in this region: an "
      "expression in x, y (, z) of the initial configuration, <= 0 in the region "
      "(e.g. 'abs(x - 1.25) - 0.2' for a strip round a film's dip). At the start of "
      "every step the cell pairs, at every level, that hold a point whose initial "
      "position lies in the region are refined, with q + 2 cells round them, so "
      "that the refined cells follow that material as it moves and deforms. "
      "Points are split and merged as for 'Refinement band'. Combined with the "
      "other entries. Empty: none.");
    prm.declare_entry(
      "Refinement mu gradient jump",
      "0",
      Patterns::Double(0.),
      "Refine the grid where the slope of the chemical potential changes: the least-squares "
      "plane of mu/(k_B T) through the points of a cell pair (volume points, and surface points "
      "with their piece's prescribed mu) is compared with its face neighbours', at every level "
      "up to 'Refinement levels', and both are refined where the gradients differ by g with "
      "|g| h > this (h the cell pair's size), marked anew at the start of every step with q + 2 "
      "cells round them. Unlike 'Refinement mu range' it leaves a region where mu varies "
      "linearly unrefined and finds a front's foot, a kink or a corner: where the pieces of "
      "degree q have most to follow. Points are split and merged as for 'Refinement band'. "
      "Combined with the other entries. 0: none.");
    prm.declare_entry("Refinement mu range",
                      "0",
                      Patterns::Double(0.),
                      "Refine the grid where the chemical potential varies: a cell pair (at "
                      "every level, up to 'Refinement levels') is refined where the material "
                      "points in it, with the prescribed mu of its surface points, span more than "
                      "this range of mu/(k_B T), marked anew at the start of every step, so that "
                      "the refined cells follow a swelling front and leave it once it has spread. "
                      "Points are split as for 'Refinement band'. A cell whose points all have one "
                      "mu is not refined: at t = 0 only a bath that differs from the gel's mu "
                      "refines. Combined with the boxes, the region and the band. 0: none.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  BackgroundGrid<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Background grid");
    const auto lo = get_double_list(prm, "Lower corner", "Background grid/Lower corner", dim);
    const auto hi = get_double_list(prm, "Upper corner", "Background grid/Upper corner", dim);
    const auto n  = get_double_list(prm, "Cells", "Background grid/Cells", dim);
    axisymmetric  = prm.get("Coordinate system") == "axisymmetric";
    const std::string refinement_text = prm.get("Refinement boxes");
    const std::string region_text     = dealii::Utilities::trim(prm.get("Refinement region"));
    refinement_levels                 = prm.get_integer("Refinement levels");
    refinement_band                   = prm.get_double("Refinement band");
    refinement_mu_range               = prm.get_double("Refinement mu range");
    refinement_mu_gradient_jump       = prm.get_double("Refinement mu gradient jump");
    obstacle_band                     = prm.get_double("Refinement obstacle band");
    const std::string moving_text = dealii::Utilities::trim(prm.get("Refinement moving region"));
    band_obstacle_names = dealii::Utilities::split_string_list(prm.get("Refinement obstacles"));
    refinement_budget   = prm.get_integer("Refinement budget");
    refinement_grading  = prm.get_bool("Refinement grading");
    moving_levels       = refinement_levels;
    const std::string material_text =
      dealii::Utilities::trim(prm.get("Refinement material region"));
    band_piece_names = dealii::Utilities::split_string_list(prm.get("Refinement band pieces"));
    prm.leave_subsection();
    require(!axisymmetric || dim == 2,
            "Background grid/Coordinate system",
            "is axisymmetric in a 3D scene: a body of revolution is modelled in its meridian "
            "plane",
            "set 'Dimension = 2' for an axisymmetric scene, or 'Coordinate system = Cartesian'");
    std::ostringstream lower_x;
    lower_x << lo[0];
    require(!axisymmetric || lo[0] == 0.,
            "Background grid/Lower corner",
            "has x = " + lower_x.str() +
              " in an axisymmetric scene, whose grid starts on the axis R = 0",
            "give 'Lower corner = 0, <z_min>' and keep the body at R >= 0");
    check_memory(n);
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d]   = lo[d];
        upper[d]   = hi[d];
        n_cells[d] = static_cast<unsigned int>(n[d]);
        require(upper[d] > lower[d],
                "Background grid/Upper corner",
                "is not above 'Lower corner' in direction " + std::to_string(d),
                "give an upper corner larger than the lower corner in every coordinate");
      }
    parse_refinement_boxes(refinement_text);
    parse_refinement_region(region_text);
    material_region =
      parse_level_set<dim>(material_text, "Background grid/Refinement material region");
    moving_region =
      parse_level_set<dim>(moving_text, "Background grid/Refinement moving region", true);
    moving_marked.clear();
    graded_marked.clear();
    require(refinement_band > 0. || band_piece_names.empty(),
            "Background grid/Refinement band pieces",
            "names pieces but 'Refinement band' is 0",
            "give the band's width in 'Refinement band', or leave the pieces empty");
    require(obstacle_band > 0. || band_obstacle_names.empty(),
            "Background grid/Refinement obstacles",
            "names obstacles but 'Refinement obstacle band' is 0",
            "give the band's width in 'Refinement obstacle band', or leave the obstacles empty");
    if (refinement_boxes.empty() && refinement_region == nullptr && !moves())
      refinement_levels = 0;
    if (!refined())
      return;
    for (unsigned int d = 0; d < dim; ++d)
      require(n_cells[d] % 2 == 0,
              refinement_entry(),
              "needs an even number of cells in every direction ('Background grid/Cells'): "
              "cells are refined in pairs",
              "use an even number of cells in every direction");
    if (refinement_region != nullptr)
      mark_region();
  }


  template <int dim>
  void
  BackgroundGrid<dim>::parse_refinement_boxes(const std::string &text)
  {
    const std::string entry = "Background grid/Refinement boxes";
    refinement_boxes.clear();
    for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
      {
        const auto corners = dealii::Utilities::split_string_list(item, ':');
        require(corners.size() == 2,
                entry,
                "has the item '" + item + "' that is not 'lower corner : upper corner'",
                "write e.g. '0, 0.75 : 0.2, 1.05'");
        std::pair<dealii::Point<dim>, dealii::Point<dim>> box;
        for (unsigned int end = 0; end < 2; ++end)
          {
            const auto numbers = dealii::Utilities::split_string_list(corners[end], ',');
            require(numbers.size() == dim,
                    entry,
                    "has the corner '" + corners[end] + "' without " + std::to_string(dim) +
                      " coordinates",
                    "give one coordinate per direction, separated by commas");
            for (unsigned int d = 0; d < dim; ++d)
              {
                double value = 0.;
                try
                  {
                    value = dealii::Utilities::string_to_double(numbers[d]);
                  }
                catch (...)
                  {
                    throw InputError(entry,
                                     "has the coordinate '" + numbers[d] + "' that is not a number",
                                     "give numbers, e.g. '0, 0.75 : 0.2, 1.05'");
                  }
                (end == 0 ? box.first : box.second)[d] = value;
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          require(box.second[d] > box.first[d],
                  entry,
                  "has the box '" + item + "' whose upper corner is not above its lower corner",
                  "list the lower corner first");
        refinement_boxes.push_back(box);
      }
  }


  template <int dim>
  void
  BackgroundGrid<dim>::parse_refinement_region(const std::string &text)
  {
    region_marked.clear();
    refinement_region = parse_level_set<dim>(text, "Background grid/Refinement region");
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::pair_cell_in_box(const unsigned int l, const unsigned int c) const
  {
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = n_cells[d] / 2 * (1u << l);
    dealii::Point<dim> lo, hi;
    unsigned int       rest = c;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const unsigned int i = rest % n[d];
        rest /= n[d];
        const double h = (upper[d] - lower[d]) / n[d];
        lo[d]          = lower[d] + i * h;
        hi[d]          = lower[d] + (i + 1) * h;
      }
    for (const auto &[box_lo, box_hi] : refinement_boxes)
      {
        bool overlaps = true;
        for (unsigned int d = 0; d < dim; ++d)
          overlaps &= lo[d] < box_hi[d] && box_lo[d] < hi[d];
        if (overlaps)
          return true;
      }
    return false;
  }


  template <int dim>
  std::array<unsigned int, dim>
  BackgroundGrid<dim>::pair_cells(const unsigned int level) const
  {
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = n_cells[d] / 2 * (1u << level);
    return n;
  }


  template <int dim>
  void
  BackgroundGrid<dim>::mark_region()
  {
    region_marked.assign(refinement_levels, {});
    for (unsigned int l = 0; l < refinement_levels; ++l)
      {
        const auto   n       = pair_cells(l);
        unsigned int n_total = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_total *= n[d];
        region_marked[l].assign(n_total, false);
        for (unsigned int c = 0; c < n_total; ++c)
          {
            // Nested domains: only the children of a refined cell can be refined.
            const unsigned int parent = l > 0 ? parent_cell<dim>(n, c) : 0;
            if (l > 0 && !region_marked[l - 1][parent] && !pair_cell_in_box(l - 1, parent))
              continue;
            region_marked[l][c] =
              level_set_meets_cell(*refinement_region, l, c, "Background grid/Refinement region");
          }
      }
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::moves() const
  {
    return refinement_band > 0. || refinement_mu_range > 0. || material_region != nullptr ||
           obstacle_band > 0. || moving_region != nullptr || refinement_mu_gradient_jump > 0.;
  }


  template <int dim>
  std::vector<bool>
  BackgroundGrid<dim>::moving_region_cells(const unsigned int level, const double t) const
  {
    const auto   n       = pair_cells(level);
    unsigned int n_total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_total *= n[d];
    std::vector<bool> marked(n_total, false);
    moving_region->set_time(t);
    for (unsigned int c = 0; c < n_total; ++c)
      marked[c] = level_set_meets_cell(*moving_region,
                                       level,
                                       c,
                                       "Background grid/Refinement moving region",
                                       " at t = " + std::to_string(t));
    return marked;
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::level_set_meets_cell(const dealii::Function<dim> &level_set,
                                            const unsigned int           level,
                                            const unsigned int           c,
                                            const std::string           &entry,
                                            const std::string           &when) const
  {
    const auto   n         = pair_cells(level);
    unsigned int n_samples = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_samples *= region_samples;
    for (unsigned int s = 0; s < n_samples; ++s)
      {
        dealii::Point<dim> x;
        unsigned int       rest = c, rest_s = s;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double h = (upper[d] - lower[d]) / n[d];
            x[d] =
              lower[d] + (rest % n[d] + double(rest_s % region_samples) / (region_samples - 1)) * h;
            rest /= n[d];
            rest_s /= region_samples;
          }
        const double value = level_set.value(x);
        if (!std::isfinite(value))
          throw InputError(entry,
                           "is not a number at " + format_point(x) + when,
                           "write an expression that is finite in the whole background grid" +
                             std::string(when.empty() ? "" : " over the run"));
        if (value <= 0.)
          return true;
      }
    return false;
  }


  template <int dim>
  std::pair<dealii::Point<dim>, double>
  BackgroundGrid<dim>::pair_cell_centre(const unsigned int level, const unsigned int c) const
  {
    const auto         n    = pair_cells(level);
    unsigned int       rest = c;
    dealii::Point<dim> centre;
    double             half_diagonal = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double h = (upper[d] - lower[d]) / n[d];
        centre[d]      = lower[d] + (rest % n[d] + 0.5) * h;
        rest /= n[d];
        half_diagonal += 0.25 * h * h;
      }
    return {centre, std::sqrt(half_diagonal)};
  }


  template <int dim>
  unsigned int
  BackgroundGrid<dim>::pair_cell_of(const dealii::Point<dim> &x, const unsigned int level) const
  {
    const auto   n    = pair_cells(level);
    unsigned int cell = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double h = (upper[d] - lower[d]) / n[d];
        cell += stride *
                static_cast<unsigned int>(std::clamp((x[d] - lower[d]) / h, 0., double(n[d] - 1)));
        stride *= n[d];
      }
    return cell;
  }


  template <int dim>
  std::string
  BackgroundGrid<dim>::refinement_entry() const
  {
    if (!refinement_boxes.empty())
      return "Background grid/Refinement boxes";
    if (refinement_region != nullptr)
      return "Background grid/Refinement region";
    if (refinement_band > 0.)
      return "Background grid/Refinement band";
    if (obstacle_band > 0.)
      return "Background grid/Refinement obstacle band";
    if (moving_region != nullptr)
      return "Background grid/Refinement moving region";
    if (refinement_mu_gradient_jump > 0.)
      return "Background grid/Refinement mu gradient jump";
    return refinement_mu_range > 0. ? "Background grid/Refinement mu range"
                                    : "Background grid/Refinement material region";
  }


  template <int dim>
  std::vector<bool>
  BackgroundGrid<dim>::band_cells(const unsigned int                     level,
                                  const std::vector<dealii::Point<dim>> &surface) const
  {
    const auto              n = pair_cells(level);
    std::array<double, dim> h;
    unsigned int            n_total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        h[d] = (upper[d] - lower[d]) / n[d];
        n_total *= n[d];
      }
    std::vector<bool> marked(n_total, false);
    for (const auto &p : surface)
      {
        std::array<unsigned int, dim> first, last;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const auto index = [&](const double x) {
              return static_cast<unsigned int>(
                std::clamp((x - lower[d]) / h[d], 0., double(n[d] - 1)));
            };
            first[d] = index(p[d] - refinement_band);
            last[d]  = index(p[d] + refinement_band);
          }
        for_each_cell_between<dim>(n, first, last, [&](const unsigned int cell, const auto &i) {
          double distance_squared = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double lo = lower[d] + i[d] * h[d], hi = lo + h[d];
              const double gap = std::max({lo - p[d], p[d] - hi, 0.});
              distance_squared += gap * gap;
            }
          if (distance_squared <= refinement_band * refinement_band)
            marked[cell] = true;
        });
      }
    return marked;
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::mark_moving(const std::vector<dealii::Point<dim>> &surface,
                                   const std::vector<std::vector<bool>>  &flagged,
                                   const unsigned int                     buffer)
  {
    // A cell is marked when its box lies within the band's width of a surface point. Its
    // parent's box contains it, so the parent is marked too: the domains nest.
    std::vector<std::vector<bool>> marked(refinement_levels);
    for (unsigned int l = 0; l < refinement_levels; ++l)
      marked[l] = band_cells(l, l < moving_levels ? surface : std::vector<dealii::Point<dim>>());
    // A cell's points include its children's: the spread of a parent is at least theirs. The
    // cells within 'buffer' cells of a marked one are marked too, at every level: the parent of
    // such a cell lies within 'buffer' cells of the marked cell's parent, so the domains nest.
    for (unsigned int l = 0; l < flagged.size() && l < moving_levels; ++l)
      {
        const auto n = pair_cells(l);
        for (unsigned int c = 0; c < flagged[l].size(); ++c)
          if (flagged[l][c])
            for_each_cell_near<dim>(n, c, buffer, [&](const unsigned int near) {
              marked[l][near] = true;
            });
      }
    // The domains must nest. The criteria above mark a cell's parent with it (a parent holds
    // its children's points and box), but a level set sampled per cell can mark a cell whose
    // parent's samples miss the region, and an obstacle's gap need not be a distance
    // everywhere: such a parent is marked too.
    for (unsigned int l = refinement_levels; l-- > 1;)
      {
        const auto n = pair_cells(l);
        for (unsigned int c = 0; c < marked[l].size(); ++c)
          if (marked[l][c])
            marked[l - 1][parent_cell<dim>(n, c)] = true;
      }
    const bool changed = marked != moving_marked;
    moving_marked      = std::move(marked);
    if (changed)
      grade();
    return changed;
  }


  template <int dim>
  void
  BackgroundGrid<dim>::set_moving_marks(const std::vector<std::vector<bool>> &marks)
  {
    moving_marked = marks;
    grade();
  }


  template <int dim>
  void
  BackgroundGrid<dim>::set_grading_reach(const unsigned int cells)
  {
    grading_reach = cells;
    grade();
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::marked_by_criteria(const unsigned int l, const unsigned int c) const
  {
    return pair_cell_in_box(l, c) || (!region_marked.empty() && region_marked[l][c]) ||
           (!moving_marked.empty() && moving_marked[l][c]);
  }


  template <int dim>
  void
  BackgroundGrid<dim>::grade()
  {
    graded_marked.clear();
    if (!refinement_grading || grading_reach == 0 || refinement_levels < 2)
      return;
    graded_marked.resize(refinement_levels);
    for (unsigned int l = 0; l < refinement_levels; ++l)
      {
        const auto   n       = pair_cells(l);
        unsigned int n_total = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_total *= n[d];
        graded_marked[l].resize(n_total);
        for (unsigned int c = 0; c < n_total; ++c)
          graded_marked[l][c] = marked_by_criteria(l, c);
      }
    // A leaf of level l + 1 lies in a refined cell Q of level l. The functions of level l that
    // are nonzero on Q reach grading_reach cells beyond it; where one of them is not active (its
    // support leaves Omega^l, the refined cells of level l - 1), a function of level l - 1 is
    // nonzero on Q too, and three levels meet on the leaf. So the cells of level l near Q must
    // lie in Omega^l: their parents are refined.
    for (unsigned int l = refinement_levels; l-- > 1;)
      {
        const auto n = pair_cells(l);
        for (unsigned int c = 0; c < graded_marked[l].size(); ++c)
          if (graded_marked[l][c])
            for_each_cell_near<dim>(n, c, grading_reach, [&](const unsigned int near) {
              graded_marked[l - 1][parent_cell<dim>(n, near)] = true;
            });
      }
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::drop_finest_moving_level()
  {
    for (unsigned int l = moving_marked.size(); l-- > 0;)
      if (std::find(moving_marked[l].begin(), moving_marked[l].end(), true) !=
          moving_marked[l].end())
        {
          // The finer levels hold no marks: the domains still nest.
          std::fill(moving_marked[l].begin(), moving_marked[l].end(), false);
          moving_levels = std::min(moving_levels, l);
          grade();
          return true;
        }
    return false;
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::refined() const
  {
    return refinement_levels > 0;
  }


  template <int dim>
  std::vector<std::vector<unsigned int>>
  BackgroundGrid<dim>::refined_pair_cells() const
  {
    std::vector<std::vector<unsigned int>> refined(refinement_levels);
    for (unsigned int l = 0; l < refinement_levels; ++l)
      {
        const auto   n       = pair_cells(l);
        unsigned int n_total = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_total *= n[d];
        for (unsigned int c = 0; c < n_total; ++c)
          if (graded_marked.empty() ? marked_by_criteria(l, c) : graded_marked[l][c])
            refined[l].push_back(c);
      }
    return refined;
  }


  template <int dim>
  unsigned int
  BackgroundGrid<dim>::refinement_level(const dealii::Point<dim> &x) const
  {
    // A cell that overlaps a box has a parent that does: the first level whose cell at x does
    // not overlap one is the leaf's.
    for (unsigned int l = 0; l < refinement_levels; ++l)
      {
        bool         overlaps = false;
        unsigned int cell = 0, stride = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double       h = 2. * cell_size(d) / (1u << l);
            const unsigned int n = n_cells[d] / 2 * (1u << l);
            const unsigned int i =
              std::min(n - 1, static_cast<unsigned int>(std::max(0., (x[d] - lower[d]) / h)));
            cell += i * stride;
            stride *= n;
          }
        for (const auto &[box_lo, box_hi] : refinement_boxes)
          {
            bool inside = true;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double       h = 2. * cell_size(d) / (1u << l);
                const unsigned int n = n_cells[d] / 2 * (1u << l);
                const unsigned int i =
                  std::min(n - 1, static_cast<unsigned int>(std::max(0., (x[d] - lower[d]) / h)));
                inside &= lower[d] + i * h < box_hi[d] && box_lo[d] < lower[d] + (i + 1) * h;
              }
            overlaps |= inside;
          }
        overlaps |= !region_marked.empty() && region_marked[l][cell];
        overlaps |= !moving_marked.empty() && moving_marked[l][cell];
        overlaps |= !graded_marked.empty() && graded_marked[l][cell];
        if (!overlaps)
          return l;
      }
    return refinement_levels;
  }


  template <int dim>
  void
  BackgroundGrid<dim>::check_memory(const std::vector<double> &cells) const
  {
    // A lower bound: the cell of the triangulation, its points, its rows of the tangent. Above
    // the machine's memory the allocation fails late, with nothing that names the entry.
    const double bytes_per_cell = dim == 2 ? 1024. : 4096.;
    double       n              = 1.;
    for (const double c : cells)
      n *= c;
    const double available = available_memory();
    if (!(available > 0.) || n * bytes_per_cell <= available)
      return;
    std::ostringstream problem;
    problem.precision(3);
    problem << "asks for " << n << " cells, which need at least " << n * bytes_per_cell / 1e9
            << " GB of memory, more than the " << available / 1e9
            << " GB this machine has available";
    throw InputError("Background grid/Cells", problem.str(), "give fewer cells per direction");
  }


  template <int dim>
  double
  BackgroundGrid<dim>::cell_size(const unsigned int d) const
  {
    return (upper[d] - lower[d]) / n_cells[d];
  }


  template <int dim>
  double
  BackgroundGrid<dim>::smallest_cell_size() const
  {
    double h = cell_size(0);
    for (unsigned int d = 1; d < dim; ++d)
      h = std::min(h, cell_size(d));
    return h;
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::contains(const dealii::Point<dim> &p) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double tolerance = relative_position_tolerance * (upper[d] - lower[d]);
        if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
          return false;
      }
    return true;
  }


  template <int dim>
  void
  BackgroundGrid<dim>::create_triangulation(dealii::Triangulation<dim> &triangulation) const
  {
    std::vector<unsigned int> repetitions(n_cells.begin(), n_cells.end());
    dealii::GridGenerator::subdivided_hyper_rectangle(triangulation, repetitions, lower, upper);
  }


  template struct BackgroundGrid<2>;
  template struct BackgroundGrid<3>;
} // namespace GelMPM

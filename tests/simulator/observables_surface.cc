// 'Observables/Surface pieces' on material points placed by hand (grid spacing h = 0.1): the top
// piece of a film, 61 surface points h/2 apart, first flat, then folded into a hairpin 3 h deep
// whose flanks are 2 r = h/pi apart (so that the samples lie symmetrically about its bottom).
// Checked against closed forms:
// - the columns are top_relief, top_curvature, top_turning, top_folds (only top_relief in 3D);
//   the bottom piece and the volume points do not enter;
// - flat: relief, curvature, turning and folds 0, no event;
// - folded: relief D (10 significant digits), turning 90 degrees (the corners at the hairpin's
//   mouth and bottom), curvature times h that of the circle through the bottom corner's three
//   points, 2 h / sqrt(h^2/4 + 4 r^2), one fold, one event 'crease_top' (pore 0), and none when
//   asked again;
// - surface_top-00000.csv and -00001.csv hold the points in order along the surface: s_0 = k h/2,
//   the current positions and mu;
// - a piece name not in 'Boundary conditions/Pieces', a piece named twice and 'Fold arc length'
//   not above 'Fold approach distance' are InputErrors naming the entry.
#include <gelmpm/core/input_error.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observables.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace GelMPM;

namespace
{
  const double       h = 0.1, D = 3. * h, r = 0.5 * h / M_PI, a = 1.;
  const unsigned int n = 61;

  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }

  /**
   * The folded position of the point k, initially at (k h/2, 1), and its outward normal: flat up
   * to k = 20 (x = a), down the left flank (normal +x) to the depth D at k = 26, up the right
   * flank (normal -x) from k = 27, flat again from k = 33 (the half circle of length pi r = h/2
   * between k = 26 and 27 holds no point).
   */
  std::pair<Point<2>, Tensor<1, 2>>
  folded(const unsigned int k)
  {
    const int j = static_cast<int>(k) - 20;
    if (j <= 0)
      return {Point<2>(0.5 * h * k, 1.), Tensor<1, 2>({0., 1.})};
    if (j <= 6)
      return {Point<2>(a, 1. - 0.5 * h * j), Tensor<1, 2>({1., 0.})};
    if (j <= 12)
      return {Point<2>(a + 2. * r, 1. - D + 0.5 * h * (j - 7)), Tensor<1, 2>({-1., 0.})};
    return {Point<2>(a + 2. * r + 0.5 * h * (j - 13), 1.), Tensor<1, 2>({0., 1.})};
  }


  /** Observables<dim> parsed with 'Surface pieces' = @p names and the fold entries. */
  template <int dim>
  Observables<dim>
  parse(const std::string &names,
        const std::string &approach   = "0.5",
        const std::string &arc_length = "3")
  {
    ParameterHandler prm;
    Observables<dim>::declare_parameters(prm);
    prm.enter_subsection("Observables");
    prm.set("Surface pieces", names);
    prm.set("Fold approach distance", approach);
    prm.set("Fold arc length", arc_length);
    prm.leave_subsection();
    Observables<dim> observables;
    observables.parse_parameters(prm, {"bottom", "top", "sides"});
    return observables;
  }

  /** Whether parse() fails with an InputError for @p entry whose problem contains @p text. */
  bool
  refused(const std::string &entry,
          const std::string &text,
          const std::string &names,
          const std::string &approach   = "0.5",
          const std::string &arc_length = "3")
  {
    try
      {
        parse<2>(names, approach, arc_length);
      }
    catch (const InputError &e)
      {
        return e.entry() == entry && e.problem().find(text) != std::string::npos;
      }
    return false;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  ok &= report("a piece not in 'Boundary conditions/Pieces' is refused",
               refused("Observables/Surface pieces", "'tops'", "top, tops"));
  ok &= report("a piece named twice is refused",
               refused("Observables/Surface pieces", "twice", "top, sides, top"));
  ok &= report("'Fold arc length' not above 'Fold approach distance' is refused",
               refused("Observables/Fold arc length", "not larger", "top", "0.5", "0.5"));
  ok &= report("in 3D only the relief",
               parse<3>("top").columns() == std::vector<std::string>{"top_relief"} &&
                 !parse<3>("top").writes_events());
  ok &= report("off when empty", parse<2>("").columns().empty() && !parse<2>("").writes_events());

  auto observables = parse<2>("top");
  observables.set_grid_spacing(h);
  const std::vector<std::string> columns = {"top_relief",
                                            "top_curvature",
                                            "top_turning",
                                            "top_folds"};
  ok &= report("the columns of the top piece", observables.columns() == columns);
  ok &= report("it writes events", observables.writes_events());

  // The top piece (index 1), a bottom piece (index 0) and volume points below.
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(tria, {5, 5}, Point<2>(-1, -1), Point<2>(5, 3));
  MappingQ1<2>                  mapping;
  Particles::ParticleHandler<2> particles(tria, mapping, PropertyLayout<2>::n_properties);
  using Layout     = PropertyLayout<2>;
  unsigned int id  = 0;
  const auto   add = [&](const Point<2> &X, const int piece, const Tensor<1, 2> &normal) {
    std::vector<double> props(Layout::n_properties, 0.);
    props[Layout::kind] =
      static_cast<double>(piece >= 0 ? PointKind::neumann_dirichlet : PointKind::volume);
    props[Layout::piece] = piece;
    props[Layout::mu]    = 0.01 * id;
    for (unsigned int d = 0; d < 2; ++d)
      {
        props[Layout::position_0 + d]    = X[d];
        props[Layout::normal_area_0 + d] = 0.5 * h * normal[d];
        props[Layout::normal_area_n + d] = 0.5 * h * normal[d];
      }
    const auto cell = GridTools::find_active_cell_around_point(tria, X);
    particles.insert_particle(X,
                              mapping.transform_real_to_unit_cell(cell, X),
                              id++,
                              cell,
                              make_array_view(props));
  };
  // In reverse order: the observables order the points themselves.
  for (unsigned int k = n; k-- > 0;)
    add(Point<2>(0.5 * h * k, 1.), 1, Tensor<1, 2>({0., 1.}));
  for (unsigned int k = 0; k < n; ++k)
    {
      add(Point<2>(0.5 * h * k, 0.), 0, Tensor<1, 2>({0., -1.}));
      add(Point<2>(0.5 * h * k, 0.5), -1, Tensor<1, 2>());
    }
  particles.update_cached_numbers();

  const MaterialRegions<2> gel;
  StatisticsFile           statistics;
  statistics.open("statistics.csv", columns);
  std::filesystem::create_directories("surfaces");

  observables.evaluate(particles, gel, {}, statistics);
  statistics.write_row();
  ok &= report("flat: no event", observables.new_events(particles).empty());
  observables.write_surfaces(particles, "surfaces");

  for (auto &particle : particles)
    {
      auto props = particle.get_properties();
      if (piece_of(props) != 1)
        continue;
      const auto [x, normal] = folded(std::lround(props[Layout::position_0] / (0.5 * h)));
      particle.set_location(x);
      for (unsigned int d = 0; d < 2; ++d)
        props[Layout::normal_area_n + d] = 0.5 * h * normal[d];
    }
  observables.evaluate(particles, gel, {}, statistics);
  statistics.write_row();
  const auto events = observables.new_events(particles);
  ok &= report("folded: one event 'crease_top' of no pore",
               events.size() == 1 && events[0].first == "crease_top" && events[0].second == 0);
  ok &= report("  none when asked again", observables.new_events(particles).empty());
  observables.write_surfaces(particles, "surfaces");

  const auto s = read_statistics("statistics.csv");
  ok &= report("flat: relief, curvature, turning and folds 0",
               s.at("top_relief")[0] == 0. && s.at("top_curvature")[0] == 0. &&
                 s.at("top_turning")[0] == 0. && s.at("top_folds")[0] == 0.);
  ok &= report("folded: relief D", std::abs(s.at("top_relief")[1] - D) < 1e-9 * D);
  ok &= report("  turning 90 degrees", std::abs(s.at("top_turning")[1] - 90.) < 1e-8);
  const double curvature = 2. * h / std::sqrt(0.25 * h * h + 4. * r * r);
  ok &= report("  curvature h / the radius of the circle through the bottom corner",
               std::abs(s.at("top_curvature")[1] - curvature) < 1e-9 * curvature);
  ok &= report("  one fold", s.at("top_folds")[1] == 1.);

  for (const unsigned int output : {0u, 1u})
    {
      std::ifstream in("surfaces/surface_top-0000" + std::to_string(output) + ".csv");
      std::string   line;
      std::getline(in, line);
      bool         in_order = line == "s_0,x,y,mu";
      unsigned int k        = 0;
      for (; std::getline(in, line); ++k)
        {
          std::istringstream row(line);
          double             s_0, x, y, mu;
          char               comma;
          row >> s_0 >> comma >> x >> comma >> y >> comma >> mu;
          const Point<2> expected = output == 0 ? Point<2>(0.5 * h * k, 1.) : folded(k).first;
          // The points were added from k = n - 1 down, with mu = 0.01 id.
          in_order = in_order && std::abs(s_0 - 0.5 * h * k) < 1e-9 &&
                     expected.distance(Point<2>(x, y)) < 1e-9 &&
                     std::abs(mu - 0.01 * (n - 1 - k)) < 1e-9;
        }
      ok &= report("surface_top-0000" + std::to_string(output) +
                     ".csv: the top points in order along the surface",
                   in_order && k == n);
    }

  std::cout << (ok ? "surface observables checks passed" : "SURFACE OBSERVABLES CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}

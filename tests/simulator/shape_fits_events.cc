// 'Observables/Shape pieces' and 'Instability threshold' on material points placed by hand: the
// top piece of a film, 121 surface points 0.05 apart on 0 <= x <= 6 (grid spacing h = 0.1), with
// volume points below that do not enter. Checked against closed forms:
// - the columns (seven per piece in 2D, four in 3D), none when empty; events only with a
//   threshold; a piece not in 'Boundary conditions/Pieces', a threshold in 3D and a threshold
//   without pieces are InputErrors naming the entry;
// - flat: fitted curvature 0, residual, amplitude and relative amplitude 0, no event;
// - a wrinkle y = 1 + a cos(2 pi x / lambda), lambda = 0.6 (ten wavelengths), a = 0.002: fitted
//   curvature about 0 (below 1e-4: the least-squares parabola through the points, symmetric about
//   x = 3, curves by 3.6e-5), amplitude a (1e-9), wavelength L/10
//   along the surface (0.5%), skewness 0 (0.05), relative amplitude 0.0033 below the threshold
//   0.005: no event; a = 0.006 (relative amplitude 0.01): one event 'instability_wrinkle_top', and
//   none when asked again;
// - the wrinkle turned into narrow cusped dips 0.02 deep every 0.6 (a crease's relief; skewness
//   -2.1, below -'Crease skewness' = -0.5): one more event 'instability_crease_top', then none;
//   the same dips on a piece seen first then: one event 'instability_crease_top'.
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
#include <functional>
#include <iostream>

using namespace dealii;
using namespace GelMPM;

namespace
{
  const double       h = 0.1, spacing = 0.05, lambda = 0.6;
  const unsigned int n = 121;

  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }

  /** Observables<dim> with 'Shape pieces' = @p names and 'Instability threshold' = @p threshold. */
  template <int dim>
  Observables<dim>
  parse(const std::string &names, const std::string &threshold)
  {
    ParameterHandler prm;
    Observables<dim>::declare_parameters(prm);
    prm.enter_subsection("Observables");
    prm.set("Shape pieces", names);
    prm.set("Instability threshold", threshold);
    prm.leave_subsection();
    Observables<dim> observables;
    observables.parse_parameters(prm, {"bottom", "top"});
    return observables;
  }

  /** Whether parse() fails with an InputError for @p entry whose problem contains @p text. */
  template <int dim>
  bool
  refused(const std::string &entry,
          const std::string &text,
          const std::string &names,
          const std::string &threshold)
  {
    try
      {
        parse<dim>(names, threshold);
      }
    catch (const InputError &e)
      {
        return e.entry() == entry && e.problem().find(text) != std::string::npos;
      }
    return false;
  }

  /** The film: the top piece's points at (k spacing, 1) and volume points below. */
  class Film
  {
  public:
    Film()
    {
      GridGenerator::subdivided_hyper_rectangle(tria, {8, 4}, Point<2>(-1, -1), Point<2>(7, 3));
      particles.initialize(tria, mapping, PropertyLayout<2>::n_properties);
      using Layout = PropertyLayout<2>;
      for (unsigned int k = 0; k < n; ++k)
        for (const int piece : {1, -1})
          {
            const Point<2>      X(spacing * k, piece == 1 ? 1. : 0.5);
            std::vector<double> props(Layout::n_properties, 0.);
            props[Layout::kind] =
              static_cast<double>(piece >= 0 ? PointKind::neumann_dirichlet : PointKind::volume);
            props[Layout::piece] = piece;
            for (unsigned int d = 0; d < 2; ++d)
              {
                props[Layout::position_0 + d]    = X[d];
                props[Layout::normal_area_0 + d] = piece == 1 && d == 1 ? spacing : 0.;
                props[Layout::normal_area_n + d] = piece == 1 && d == 1 ? spacing : 0.;
              }
            const auto cell = GridTools::find_active_cell_around_point(tria, X);
            particles.insert_particle(X,
                                      mapping.transform_real_to_unit_cell(cell, X),
                                      particles.n_locally_owned_particles(),
                                      cell,
                                      make_array_view(props));
          }
      particles.update_cached_numbers();
    }

    /** Move the top points to (x, 1 + @p height(x)); the normals stay +y (small slopes). */
    void
    shape(const std::function<double(double)> &height)
    {
      for (auto &particle : particles)
        if (piece_of(particle.get_properties()) == 1)
          {
            const double x = particle.get_location()[0];
            particle.set_location(Point<2>(x, 1. + height(x)));
          }
    }

    /** The length of the top's polyline. */
    double
    length() const
    {
      std::vector<Point<2>> top(n);
      for (const auto &particle : particles)
        if (piece_of(particle.get_properties()) == 1)
          top[std::lround(particle.get_location()[0] / spacing)] = particle.get_location();
      double length = 0.;
      for (unsigned int k = 1; k < n; ++k)
        length += top[k].distance(top[k - 1]);
      return length;
    }

    Triangulation<2>              tria;
    MappingQ1<2>                  mapping;
    Particles::ParticleHandler<2> particles;
  };

  /** The relief of narrow cusped dips 0.02 deep, one every lambda, at (j + 1/2) lambda. */
  double
  dips(const double x)
  {
    const double phase = std::fmod(x, lambda) - 0.5 * lambda;
    return -0.02 * std::exp(-std::abs(phase) / (lambda / 12.));
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  ok &= report("a piece not in 'Boundary conditions/Pieces' is refused",
               refused<2>("Observables/Shape pieces", "'tops'", "top, tops", "0"));
  ok &= report("a threshold in 3D is refused",
               refused<3>("Observables/Instability threshold", "3D", "top", "0.01"));
  ok &= report("a threshold without pieces is refused",
               refused<2>("Observables/Instability threshold", "no piece", "", "0.01"));
  ok &= report("off when empty", parse<2>("", "0").columns().empty());
  ok &= report("in 3D four columns",
               parse<3>("top", "0").columns() == std::vector<std::string>{"top_fit_curvature",
                                                                          "top_fit_residual",
                                                                          "top_amplitude",
                                                                          "top_skewness"});
  ok &= report("no events without a threshold", !parse<2>("top", "0").writes_events());

  const std::vector<std::string> columns   = {"top_fit_curvature",
                                              "top_fit_residual",
                                              "top_amplitude",
                                              "top_skewness",
                                              "top_wavelength",
                                              "top_relative_amplitude",
                                              "top_dip_crest_ratio"};
  auto                           wrinkling = parse<2>("top", "0.005");
  ok &= report("in 2D seven columns", wrinkling.columns() == columns);
  ok &= report("events with a threshold", wrinkling.writes_events());
  wrinkling.set_grid_spacing(h);

  Film                     film;
  const MaterialRegions<2> gel;
  StatisticsFile           statistics;
  statistics.open("statistics.csv", columns);
  const auto row = [&](Observables<2> &observables) {
    observables.evaluate(film.particles, gel, {}, statistics);
    statistics.write_row();
    return observables.new_events(film.particles);
  };

  ok &= report("flat: no event", row(wrinkling).empty());
  film.shape([](const double x) {
    return 0.002 * std::cos(2. * M_PI * x / lambda);
  });
  ok &= report("a = 0.002: no event", row(wrinkling).empty());
  const double length = film.length();
  film.shape([](const double x) {
    return 0.006 * std::cos(2. * M_PI * x / lambda);
  });
  const auto wrinkle = row(wrinkling);
  ok &= report("a = 0.006: one event 'instability_wrinkle_top'",
               wrinkle.size() == 1 && wrinkle[0].first == "instability_wrinkle_top" &&
                 wrinkle[0].second == 0);
  ok &= report("  none when asked again", wrinkling.new_events(film.particles).empty());

  film.shape(dips);
  const auto turned = row(wrinkling);
  ok &= report("the wrinkle turned into cusped dips: one event 'instability_crease_top'",
               turned.size() == 1 && turned[0].first == "instability_crease_top");
  ok &= report("  none when asked again", wrinkling.new_events(film.particles).empty());

  auto creasing = parse<2>("top", "0.005");
  creasing.set_grid_spacing(h);
  const auto crease = row(creasing);
  ok &= report("cusped dips at once: one event 'instability_crease_top'",
               crease.size() == 1 && crease[0].first == "instability_crease_top");

  const auto s = read_statistics("statistics.csv");
  ok &=
    report("flat: curvature, residual, amplitude and relative amplitude 0",
           std::abs(s.at("top_fit_curvature")[0]) < 1e-12 && s.at("top_fit_residual")[0] < 1e-12 &&
             s.at("top_amplitude")[0] < 1e-12 && s.at("top_relative_amplitude")[0] < 1e-9);
  ok &= report("wrinkle: fitted curvature about 0 (below 1e-4)",
               std::abs(s.at("top_fit_curvature")[1]) < 1e-4);
  ok &= report("  amplitude a", std::abs(s.at("top_amplitude")[1] - 0.002) < 1e-9);
  ok &= report("  wavelength L/10 along the surface",
               std::abs(s.at("top_wavelength")[1] - length / 10.) < 5e-3 * lambda);
  ok &= report("  skewness 0", std::abs(s.at("top_skewness")[1]) < 0.05);
  ok &=
    report("  relative amplitude a / wavelength, below 0.005",
           std::abs(s.at("top_relative_amplitude")[1] - 0.002 / s.at("top_wavelength")[1]) < 1e-9 &&
             s.at("top_relative_amplitude")[1] < 0.005);
  ok &= report("cusped dips: skewness below -1", s.at("top_skewness")[3] < -1.);
  ok &= report("  the same relief for both observers",
               s.at("top_skewness")[4] == s.at("top_skewness")[3]);

  std::cout << (ok ? "shape fits checks passed" : "SHAPE FITS CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

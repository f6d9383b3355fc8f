#include <gelmpm/core/input_error.h>
#include <gelmpm/geometry/pore_geometry.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/simulator/observable_surface_shapes.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace GelMPM
{
  template <int dim>
  void
  SurfaceShapes<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
      "Surface pieces",
      "",
      dealii::Patterns::Anything(),
      "Boundary piece names 'first, second, ...' (e.g. 'top', the free surface of a film): "
      "per piece the column <piece>_relief, the extent of its current surface points along "
      "their mean current normal (max minus min of (x - x_mean) . n_mean, n_mean along the sum "
      "of N_n A_n; 0 if |sum N_n A_n| <= 0.1 sum |N_n A_n|, e.g. a closed curve), in the "
      "scene's length unit. In 2D also <piece>_curvature, <piece>_turning and <piece>_folds of "
      "the polyline of its points in their order along the surface in the initial "
      "configuration (a nearest-neighbour walk along the initial tangents with the body on the "
      "right, a top surface from left to right; open or closed curves, no centre needed): the "
      "largest Menger curvature of three consecutive points times the grid spacing h_u (1 for "
      "a bend of radius h_u), the largest turning angle in degrees, and the number of folds "
      "(see 'Fold approach distance'); a new fold is the event 'crease_<piece>' in events.csv, "
      "and every output writes the polyline to surface_<piece>-NNNNN.csv (columns s_0, x, y, "
      "mu). A resolved crease turns by less than 'Crease angle' at every point, but folds. In "
      "3D only <piece>_relief. Empty: off.");
    prm.declare_entry(
      "Fold approach distance",
      "0.75",
      dealii::Patterns::Double(0.),
      "With 'Surface pieces' (2D): a piece folds where one of its points comes closer than "
      "this distance, in units of the grid spacing h_u, to a segment of its polyline whose ends "
      "are both more than 'Fold arc length' away along the current surface, or where its "
      "polyline crosses itself; folded stretches of surface that overlap or lie less than 'Fold "
      "arc length' apart (the nested pairs of the two flanks of one crease) make one fold. The "
      "flanks of a closed crease come to rest about h_u/2 apart (one cell's motion carries both), "
      "a groove that has not folded keeps them more than h_u apart: 0.75 lies between "
      "(doc/own_scenes.md, the creasing film).");
    prm.declare_entry("Fold arc length",
                      "3",
                      dealii::Patterns::Double(0.),
                      "With 'Surface pieces' (2D): the least distance along the current surface, "
                      "in units of h_u, between two places whose approach counts as a fold "
                      "(places closer along the surface are neighbours on a bend). More than "
                      "'Fold approach distance'.");
  }


  template <int dim>
  std::unique_ptr<SurfaceShapes<dim>>
  SurfaceShapes<dim>::parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces)
  {
    auto surfaces           = std::make_unique<SurfaceShapes>();
    surfaces->surface_names = dealii::Utilities::split_string_list(prm.get("Surface pieces"), ',');
    surfaces->fold_approach_distance = prm.get_double("Fold approach distance");
    surfaces->fold_arc_length        = prm.get_double("Fold arc length");
    // In 3D only the relief: the points of a surface form no polyline there.
    surfaces->surface_pieces =
      piece_indices(surfaces->surface_names, pieces, "Observables/Surface pieces");
    require(surfaces->fold_approach_distance > 0.,
            "Observables/Fold approach distance",
            "must be positive",
            "give a fraction of the grid spacing h_u, e.g. 0.5");
    require(surfaces->fold_arc_length > surfaces->fold_approach_distance,
            "Observables/Fold arc length",
            "is not larger than 'Fold approach distance': neighbouring points of a flat "
            "surface would count as a fold",
            "give a multiple of h_u larger than 'Fold approach distance', e.g. 3");
    if (surfaces->surface_names.empty())
      return nullptr;
    return surfaces;
  }


  template <int dim>
  std::vector<std::string>
  SurfaceShapes<dim>::columns() const
  {
    std::vector<std::string> c;
    for (const auto &name : surface_names)
      {
        c.push_back(name + "_relief");
        if (dim == 2)
          for (const char *measure : {"_curvature", "_turning", "_folds"})
            c.push_back(name + measure);
      }
    return c;
  }


  template <int dim>
  void
  SurfaceShapes<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    const auto pieces = shapes(state.particles);
    for (unsigned int k = 0; k < pieces.size(); ++k)
      {
        statistics.set(surface_names[k] + "_relief", pieces[k].relief);
        if (dim == 2)
          {
            statistics.set(surface_names[k] + "_curvature", pieces[k].curvature);
            statistics.set(surface_names[k] + "_turning", pieces[k].turning * 180. / M_PI);
            statistics.set(surface_names[k] + "_folds", pieces[k].folds);
          }
      }
  }


  template <int dim>
  void
  SurfaceShapes<dim>::set_grid_spacing(const double spacing)
  {
    h_u = spacing;
  }


  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  SurfaceShapes<dim>::new_events(const dealii::Particles::ParticleHandler<dim> &particles)
  {
    std::vector<std::pair<std::string, unsigned int>> events;
    if (dim != 2)
      return events;
    const auto pieces = shapes(particles);
    folds_seen.resize(pieces.size(), 0);
    for (unsigned int k = 0; k < pieces.size(); ++k)
      {
        for (unsigned int f = folds_seen[k]; f < pieces[k].folds; ++f)
          events.emplace_back("crease_" + surface_names[k], 0);
        folds_seen[k] = std::max(folds_seen[k], pieces[k].folds);
      }
    return events;
  }


  template <int dim>
  std::vector<typename SurfaceShapes<dim>::Shape>
  SurfaceShapes<dim>::shapes(const dealii::Particles::ParticleHandler<dim> &particles,
                             std::vector<SurfaceGeometry::Polyline>        *polylines) const
  {
    AssertThrow(dim == 3 || h_u > 0.,
                dealii::ExcMessage("Observables: set_grid_spacing() before the surface shapes"));
    // A piece's polyline needs all of its points: gathered from every rank.
    auto sample = ObservedPieces::surface_sample(particles, surface_pieces, this->communicator);
    const unsigned int n_pieces     = surface_pieces.size();
    const auto        &positions    = sample.positions;
    const auto        &normal_areas = sample.normal_areas;
    auto              &points       = sample.points;

    std::vector<Shape> shapes(n_pieces);
    if (polylines)
      polylines->assign(n_pieces, SurfaceGeometry::Polyline());
    for (unsigned int k = 0; k < n_pieces; ++k)
      {
        shapes[k].relief = SurfaceGeometry::relief(positions[k], normal_areas[k]);
        if (dim != 2)
          continue;
        // Surface points of a 2D piece are at most h apart (one per boundary element no longer
        // than h/n_s): a gap of 2 h_u separates curves.
        auto polyline = SurfaceGeometry::order_along_surface(std::move(points[k]), 2. * h_u);
        for (unsigned int c = 0; c < polyline.n_curves(); ++c)
          {
            const auto curve = polyline.current_curve(c);
            shapes[k].curvature =
              std::max(shapes[k].curvature, PoreGeometry::largest_curvature(curve) * h_u);
            shapes[k].turning = std::max(shapes[k].turning, PoreGeometry::largest_turning(curve));
          }
        shapes[k].folds = SurfaceGeometry::count_folds(polyline,
                                                       fold_approach_distance * h_u,
                                                       fold_arc_length * h_u);
        if (polylines)
          (*polylines)[k] = std::move(polyline);
      }
    return shapes;
  }


  template <int dim>
  void
  SurfaceShapes<dim>::write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                                     const std::string                             &directory)
  {
    if (dim != 2)
      return;
    std::vector<SurfaceGeometry::Polyline> polylines;
    shapes(particles, &polylines);
    std::ostringstream number;
    number << std::setw(5) << std::setfill('0') << surface_outputs;
    Collective::on_root(this->communicator, [&]() {
      for (unsigned int k = 0; k < polylines.size(); ++k)
        {
          const std::string path =
            directory + "/surface_" + surface_names[k] + "-" + number.str() + ".csv";
          std::ofstream out = open_partial(path + ".tmp", path);
          out << "s_0,x,y,mu\n" << std::setprecision(10);
          const auto &polyline = polylines[k];
          for (unsigned int i = 0; i < polyline.points.size(); ++i)
            out << polyline.s_0[i] << ',' << polyline.points[i].x[0] << ','
                << polyline.points[i].x[1] << ',' << polyline.points[i].mu << '\n';
          commit_file(out, path + ".tmp", path);
        }
    });
    ++surface_outputs;
  }


  template class SurfaceShapes<2>;
  template class SurfaceShapes<3>;
} // namespace GelMPM

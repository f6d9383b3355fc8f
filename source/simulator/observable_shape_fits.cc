#include <gelmpm/core/input_error.h>
#include <gelmpm/geometry/surface_geometry.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/simulator/observable_shape_fits.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  namespace
  {
    /**
     * The current positions of the curve of @p polyline with the most points (a piece is
     * usually one curve), and whether it is closed.
     */
    std::pair<std::vector<dealii::Point<2>>, bool>
    longest_curve_of(const SurfaceGeometry::Polyline &polyline)
    {
      unsigned int longest = 0;
      for (unsigned int c = 1; c < polyline.n_curves(); ++c)
        if (polyline.curve_begin[c + 1] - polyline.curve_begin[c] >
            polyline.curve_begin[longest + 1] - polyline.curve_begin[longest])
          longest = c;
      std::vector<dealii::Point<2>> curve;
      for (unsigned int i = polyline.curve_begin[longest]; i < polyline.curve_begin[longest + 1];
           ++i)
        curve.push_back(polyline.points[i].x);
      return {curve, polyline.n_curves() > 0 && polyline.closed[longest]};
    }
  } // namespace


  template <int dim>
  void
  ShapeFits<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
      "Shape pieces",
      "",
      dealii::Patterns::Anything(),
      "Boundary piece names 'first, second, ...' (e.g. 'bottom', the lower face of a bilayer): "
      "per piece the fitted shape of its current surface points and the relief on it. "
      "<piece>_fit_curvature: the signed curvature 1/R of the least-squares circle (2D, also "
      "an axisymmetric scene's meridian) or sphere (3D) through them (Taubin's fit; positive "
      "where the body lies on the centre's side, a convex piece; 0 for a straight or flat "
      "one); <piece>_fit_residual: their RMS distance from it. The relief is measured from the "
      "piece's smooth shape, that circle or sphere if its RMS distance is at most half that of "
      "the least-squares line or plane, the line or plane otherwise, as the points' distances "
      "from it along the outward normal: <piece>_amplitude (half their range) and "
      "<piece>_skewness (negative: narrow deep dips between broad crests). In 2D also, along "
      "the points in their order along the surface (as for 'Surface pieces'): "
      "<piece>_wavelength (the dominant wavelength of the relief over the current arc length, "
      "by a discrete Fourier transform), <piece>_relative_amplitude (amplitude over "
      "wavelength) and <piece>_dip_crest_ratio (the largest curvature of the relief's dips "
      "over that of its crests: 1 for a sinusoid). Lengths in the scene's unit. Empty: off.");
    prm.declare_entry(
      "Instability threshold",
      "0",
      dealii::Patterns::Double(0.),
      "With 'Shape pieces' (2D): when a piece's <piece>_relative_amplitude (its relief's "
      "amplitude over its wavelength) first reaches this value, the relief has left the smooth "
      "shape: a row 'instability_wrinkle_<piece>' or 'instability_crease_<piece>' in events.csv "
      "(see 'Crease skewness'); a wrinkle whose relief turns crease-like later, while above this "
      "value, adds a row 'instability_crease_<piece>'. At most these two rows per piece. The "
      "initial state counts: a row at t = 0 says the piece starts with more relief than this "
      "(a seed, a texture; row 0 of statistics.csv has its value), so give a larger one. "
      "Measured (doc/own_scenes.md, 'The shape of a piece'): 0.01 is reached as the first "
      "grooves of the core-shell disk and the spontaneous creases of the film appear, 0.001 as "
      "a stiff skin's wrinkles do (they reach 0.0125 before the run stops); the creasing film's "
      "seeded top starts at 0.011 and reaches 0.05 0.26 tau_d before its crease folds. 0: no "
      "such events.");
    prm.declare_entry(
      "Crease skewness",
      "0.5",
      dealii::Patterns::Double(0.),
      "With 'Instability threshold': a piece's relief is a crease when its <piece>_skewness is "
      "at or below minus this value (narrow dips into the body between broad crests), a wrinkle "
      "otherwise (a sinusoidal relief has skewness 0). Measured (doc/own_scenes.md, 'The shape "
      "of a piece'): a stiff skin's wrinkles -0.06 to +0.01 up to a relative amplitude of "
      "0.0125, the film's creases -0.74 at 0.024 and -1.2 at 0.08 (seeded: -2.4); just after "
      "leaving the smooth shape the creases' relief is still near symmetric (-0.08 at 0.017), "
      "hence the later crease row.");
  }


  template <int dim>
  std::unique_ptr<ShapeFits<dim>>
  ShapeFits<dim>::parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces)
  {
    auto fits    = std::make_unique<ShapeFits>();
    fits->names  = dealii::Utilities::split_string_list(prm.get("Shape pieces"), ',');
    fits->pieces = piece_indices(fits->names, pieces, "Observables/Shape pieces");
    fits->instability_threshold = prm.get_double("Instability threshold");
    fits->crease_skewness       = prm.get_double("Crease skewness");
    require(dim == 2 || fits->instability_threshold == 0.,
            "Observables/Instability threshold",
            "is not available in 3D: the relief's wavelength is measured along a 2D piece's "
            "polyline",
            "set it to 0 (the 3D columns of 'Shape pieces' remain)");
    require(fits->instability_threshold == 0. || !fits->names.empty(),
            "Observables/Instability threshold",
            "is set but 'Shape pieces' names no piece to watch",
            "name the pieces in 'Observables/Shape pieces', e.g. 'top'");
    if (fits->names.empty())
      return nullptr;
    return fits;
  }


  template <int dim>
  std::vector<std::string>
  ShapeFits<dim>::columns() const
  {
    std::vector<std::string> c;
    for (const auto &name : names)
      {
        for (const char *measure : {"_fit_curvature", "_fit_residual", "_amplitude", "_skewness"})
          c.push_back(name + measure);
        if (dim == 2)
          for (const char *measure : {"_wavelength", "_relative_amplitude", "_dip_crest_ratio"})
            c.push_back(name + measure);
      }
    return c;
  }


  template <int dim>
  void
  ShapeFits<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    const auto measured = shapes(state.particles);
    for (unsigned int k = 0; k < measured.size(); ++k)
      {
        const auto &shape = measured[k];
        statistics.set(names[k] + "_fit_curvature", shape.fit_curvature);
        statistics.set(names[k] + "_fit_residual", shape.fit_residual);
        statistics.set(names[k] + "_amplitude", shape.amplitude);
        statistics.set(names[k] + "_skewness", shape.skewness);
        if (dim == 2)
          {
            statistics.set(names[k] + "_wavelength", shape.wavelength);
            statistics.set(names[k] + "_relative_amplitude", shape.relative_amplitude);
            statistics.set(names[k] + "_dip_crest_ratio", shape.dip_crest_ratio);
          }
      }
  }


  template <int dim>
  void
  ShapeFits<dim>::set_grid_spacing(const double spacing)
  {
    h_u = spacing;
  }


  template <int dim>
  bool
  ShapeFits<dim>::writes_events() const
  {
    return dim == 2 && instability_threshold > 0.;
  }


  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  ShapeFits<dim>::new_events(const dealii::Particles::ParticleHandler<dim> &particles)
  {
    std::vector<std::pair<std::string, unsigned int>> events;
    if (!writes_events())
      return events;
    const auto measured = shapes(particles);
    instabilities_seen.resize(measured.size(), no_instability);
    for (unsigned int k = 0; k < measured.size(); ++k)
      {
        // Judged only while the relief is above the threshold: below it the skewness of a
        // relief the size of the points' scatter means nothing.
        if (instabilities_seen[k] == crease_seen ||
            measured[k].relative_amplitude < instability_threshold)
          continue;
        const unsigned int kind =
          measured[k].skewness <= -crease_skewness ? crease_seen : wrinkle_seen;
        if (kind > instabilities_seen[k])
          events.emplace_back(std::string("instability_") +
                                (kind == crease_seen ? "crease_" : "wrinkle_") + names[k],
                              0);
        instabilities_seen[k] = std::max(instabilities_seen[k], kind);
      }
    return events;
  }


  template <int dim>
  std::vector<typename ShapeFits<dim>::Shape>
  ShapeFits<dim>::shapes(const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    AssertThrow(dim == 3 || h_u > 0.,
                dealii::ExcMessage("Observables: set_grid_spacing() before the shape fits"));
    // A fit needs all of the piece: gathered from every rank.
    auto sample = ObservedPieces::surface_sample(particles, pieces, this->communicator);
    const unsigned int n_pieces  = pieces.size();
    const auto        &positions = sample.positions;
    const auto        &normals   = sample.normal_areas;
    auto              &points    = sample.points;

    std::vector<Shape> shapes(n_pieces);
    for (unsigned int k = 0; k < n_pieces; ++k)
      if (positions[k].size() >= dim + 1)
        shapes[k] = shape_of(positions[k], normals[k], points[k]);
    return shapes;
  }


  template <int dim>
  typename ShapeFits<dim>::Shape
  ShapeFits<dim>::shape_of(const std::vector<dealii::Point<dim>>            &positions,
                           const std::vector<dealii::Tensor<1, dim>>        &normals,
                           const std::vector<SurfaceGeometry::SurfacePoint> &points) const
  {
    Shape shape;
    auto  fit = ShapeFit::fit_sphere(positions);
    fit.orient(positions, normals);
    shape.fit_curvature = fit.curvature();
    shape.fit_residual  = ShapeFit::rms_distance(fit, positions);

    auto smooth = ShapeFit::smooth_shape(positions);
    smooth.orient(positions, normals);
    std::vector<double> deviations;
    for (const auto &x : positions)
      deviations.push_back(smooth.distance(x));
    const auto extent = std::minmax_element(deviations.begin(), deviations.end());
    shape.amplitude   = 0.5 * (*extent.second - *extent.first);
    shape.skewness    = ShapeFit::skewness(deviations);
    if constexpr (dim == 2)
      {
        const auto [curve, closed] =
          longest_curve_of(SurfaceGeometry::order_along_surface(points, 2. * h_u));
        std::vector<double> along;
        for (const auto &x : curve)
          along.push_back(smooth.distance(x));
        const auto relief = ShapeFit::undulation(curve, along, closed);
        shape.wavelength  = relief.wavelength;
        shape.relative_amplitude =
          relief.wavelength > 0. ? shape.amplitude / relief.wavelength : 0.;
        shape.dip_crest_ratio =
          ShapeFit::dip_crest_curvature_ratio(curve, closed, smooth.curvature());
      }
    return shape;
  }


  template class ShapeFits<2>;
  template class ShapeFits<3>;
} // namespace GelMPM

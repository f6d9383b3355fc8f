#include <gelmpm/core/input_error.h>
#include <gelmpm/geometry/pore_geometry.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable_pore_shapes.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <limits>

namespace GelMPM
{
  template <int dim>
  void
  PoreShapes<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Pore piece",
                      "",
                      dealii::Patterns::Anything(),
                      "A boundary piece name (e.g. 'holes') whose surface points outline the "
                      "pores listed in 'Pore centres': adds the columns pore_ratio_1 ... "
                      "pore_ratio_N, each pore's extent along x over its extent along y (1 for a "
                      "circle or a quarter circle, > 1 for a pore elongated along x), from the "
                      "current positions of the points assigned to it, and mu_boundary, the mean "
                      "mu/k_BT over the piece's points (paper §4.4: alternating ellipses). Empty: "
                      "off.");
    prm.declare_entry("Pore centres",
                      "",
                      dealii::Patterns::Anything(),
                      "With 'Pore piece': the pores' centres 'x1, y1; x2, y2; ...' in the initial "
                      "configuration (a pore cut by the grid's edge, e.g. a quarter hole, is given "
                      "by its full circle's centre). Each surface point of the piece belongs to "
                      "the pore whose centre is nearest its initial position.");
    prm.declare_entry(
      "Crease angle",
      "60",
      dealii::Patterns::Double(0., 180.),
      "With 'Pore piece': a pore creases (event 'crease' in events.csv) when the "
      "polyline of its surface points turns by more than this angle (degrees) at "
      "a new place (column pore_creases_k counts them), or crosses itself. Points d apart on a smooth surface of "
      "curvature radius r turn by d/r (a few degrees); a crease turns at once "
      "(column pore_turning_k).");
  }


  template <int dim>
  std::unique_ptr<PoreShapes<dim>>
  PoreShapes<dim>::parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces)
  {
    auto pores          = std::make_unique<PoreShapes>();
    pores->crease_angle = prm.get_double("Crease angle") * M_PI / 180.;
    for (const auto &text : dealii::Utilities::split_string_list(prm.get("Pore centres"), ';'))
      {
        const auto coordinates = dealii::Utilities::split_string_list(text, ',');
        require(coordinates.size() == dim,
                "Observables/Pore centres",
                "has the centre '" + text + "' with " + std::to_string(coordinates.size()) +
                  " coordinates",
                "give " + std::to_string(dim) +
                  " coordinates per centre, centres separated by ';'");
        dealii::Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = dealii::Utilities::string_to_double(coordinates[d]);
        pores->pore_centres.push_back(centre);
      }
    const std::string name = dealii::Utilities::trim(prm.get("Pore piece"));
    if (name.empty())
      return nullptr;
    // A pore's outline is a polyline ordered by angle about its centre: a curve in the plane.
    // In 3D the points of a pore's surface form no such curve.
    require(dim == 2,
            "Observables/Pore piece",
            "is set in a 3D scene, but pore outlines (ratios, turning, creases) are measured "
            "in 2D only",
            "leave 'Pore piece' empty in 3D");
    pores->pore_piece = ObservedPieces::index(name, pieces, "Observables/Pore piece");
    require(!pores->pore_centres.empty(),
            "Observables/Pore centres",
            "is empty, but 'Pore piece' is set",
            "list the pores' centres 'x1, y1; x2, y2; ...'");
    return pores;
  }


  template <int dim>
  std::vector<std::string>
  PoreShapes<dim>::columns() const
  {
    std::vector<std::string> c;
    for (unsigned int k = 0; k < pore_centres.size(); ++k)
      c.push_back("pore_ratio_" + std::to_string(k + 1));
    for (unsigned int k = 0; k < pore_centres.size(); ++k)
      c.push_back("pore_curvature_" + std::to_string(k + 1));
    for (unsigned int k = 0; k < pore_centres.size(); ++k)
      c.push_back("pore_turning_" + std::to_string(k + 1));
    for (unsigned int k = 0; k < pore_centres.size(); ++k)
      c.push_back("pore_creases_" + std::to_string(k + 1));
    if (!contact_planes.empty())
      for (unsigned int k = 0; k < pore_centres.size(); ++k)
        c.push_back("pore_contact_" + std::to_string(k + 1));
    c.push_back("mu_boundary");
    return c;
  }


  template <int dim>
  void
  PoreShapes<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    double     mu_mean = 0.;
    const auto pores   = shapes(state.particles, mu_mean);
    for (unsigned int k = 0; k < pores.size(); ++k)
      {
        const std::string number = std::to_string(k + 1);
        statistics.set("pore_ratio_" + number, pores[k].ratio);
        statistics.set("pore_curvature_" + number, pores[k].curvature);
        statistics.set("pore_turning_" + number, pores[k].turning * 180. / M_PI);
        statistics.set("pore_creases_" + number, pores[k].creases);
        if (!contact_planes.empty())
          statistics.set("pore_contact_" + number, pores[k].contact_points);
      }
    statistics.set("mu_boundary", mu_mean);
  }


  template <int dim>
  double
  PoreShapes<dim>::boundary_chemical_potential(
    const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    double mu_mean = 0.;
    shapes(particles, mu_mean);
    return mu_mean;
  }


  template <int dim>
  void
  PoreShapes<dim>::set_contact_planes(const std::vector<ContactSettings::Plane> &planes,
                                      const double                               tolerance)
  {
    contact_planes    = planes;
    contact_tolerance = tolerance;
  }


  template <int dim>
  unsigned int
  PoreShapes<dim>::pore_of(const dealii::Point<dim> &X0) const
  {
    if (pore_centres.empty())
      return 0;
    unsigned int nearest = 0;
    for (unsigned int k = 1; k < pore_centres.size(); ++k)
      if (X0.distance(pore_centres[k]) < X0.distance(pore_centres[nearest]))
        nearest = k;
    return nearest + 1;
  }


  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  PoreShapes<dim>::new_events(const dealii::Particles::ParticleHandler<dim> &particles)
  {
    std::vector<std::pair<std::string, unsigned int>> events;
    double                                            mu_mean = 0.;
    const auto                                        pores   = shapes(particles, mu_mean);
    contact_seen.resize(pores.size(), false);
    creases_seen.resize(pores.size(), 0);
    for (unsigned int k = 0; k < pores.size(); ++k)
      {
        if (pores[k].contact_points > 0 && !contact_seen[k])
          events.emplace_back("self_contact", k + 1);
        // A crease is new when the pore has more sharp corners than it ever had.
        for (unsigned int c = creases_seen[k]; c < pores[k].creases; ++c)
          events.emplace_back("crease", k + 1);
        contact_seen[k] = contact_seen[k] || pores[k].contact_points > 0;
        creases_seen[k] = std::max(creases_seen[k], pores[k].creases);
      }
    return events;
  }


  template <int dim>
  std::vector<typename PoreShapes<dim>::Shape>
  PoreShapes<dim>::shapes(const dealii::Particles::ParticleHandler<dim> &particles,
                          double                                        &mu_mean) const
  {
    using Layout                        = PropertyLayout<dim>;
    const unsigned int            n     = pore_centres.size();
    const double                  large = std::numeric_limits<double>::max();
    std::vector<dealii::Point<2>> lower(n, dealii::Point<2>(large, large)),
      upper(n, dealii::Point<2>(-large, -large));
    // Per pore: (angle of the initial position about the centre, current position); the
    // initial angle orders the points along the boundary whatever the pore's current shape.
    std::vector<std::vector<std::pair<double, dealii::Point<2>>>> ordered(n);
    std::vector<double>                                           radius(n, 0.);
    std::vector<Shape>                                            shapes(n);
    double                                                        mu_sum = 0.;
    unsigned int                                                  count  = 0;
    // The points of the pores' boundaries of every rank, in the order of the ranks: the shape
    // of a pore needs all of its boundary. Per point: X_0, x, mu.
    std::vector<double> local;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (piece_of(props) != pore_piece)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(props[Layout::position_0 + d]);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(position_of(particle.get_location(), props)[d]);
        local.push_back(props[Layout::mu]);
      }
    const std::vector<double> all = ObservedPieces::gathered(this->communicator, std::move(local));
    for (std::size_t first = 0; first < all.size(); first += 2 * dim + 1)
      {
        dealii::Point<dim> X_0, x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            X_0[d] = all[first + d];
            x[d]   = all[first + dim + d];
          }
        const double mu      = all[first + 2 * dim];
        unsigned int nearest = 0;
        for (unsigned int k = 1; k < n; ++k)
          if (X_0.distance(pore_centres[k]) < X_0.distance(pore_centres[nearest]))
            nearest = k;
        dealii::Point<2> x_2;
        for (unsigned int d = 0; d < 2; ++d)
          {
            x_2[d]            = x[d];
            lower[nearest][d] = std::min(lower[nearest][d], x[d]);
            upper[nearest][d] = std::max(upper[nearest][d], x[d]);
          }
        const auto offset = X_0 - pore_centres[nearest];
        ordered[nearest].emplace_back(std::atan2(offset[1], offset[0]), x_2);
        radius[nearest] += offset.norm();
        for (const auto &plane : contact_planes)
          if (plane.sign * (x[plane.axis] - plane.value) > -contact_tolerance)
            {
              ++shapes[nearest].contact_points;
              break;
            }
        mu_sum += mu;
        ++count;
      }
    mu_mean = count > 0 ? mu_sum / count : 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        if (upper[k][1] > lower[k][1])
          shapes[k].ratio = (upper[k][0] - lower[k][0]) / (upper[k][1] - lower[k][1]);
        if (ordered[k].empty())
          continue;
        std::sort(ordered[k].begin(), ordered[k].end(), [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        // A part of a pore cut by the grid's edge whose arc crosses the angle +-pi (a half pore
        // on the right edge) runs from -pi to -pi/2 and from pi/2 to pi: start it after its gap,
        // or the chord across the gap reads as a crease.
        std::size_t start = 0;
        for (std::size_t i = 0; i + 1 < ordered[k].size(); ++i)
          if (ordered[k][i + 1].first - ordered[k][i].first > 0.5 * M_PI)
            start = i + 1;
        std::rotate(ordered[k].begin(), ordered[k].begin() + start, ordered[k].end());
        std::vector<dealii::Point<2>> polyline;
        for (const auto &entry : ordered[k])
          polyline.push_back(entry.second);
        const double R      = radius[k] / ordered[k].size();
        shapes[k].curvature = PoreGeometry::largest_curvature(polyline) * R;
        shapes[k].turning   = PoreGeometry::largest_turning(polyline);
        shapes[k].creases   = std::max(PoreGeometry::sharp_corners(polyline, crease_angle),
                                     PoreGeometry::self_intersects(polyline) ? 1u : 0u);
      }
    return shapes;
  }


  template class PoreShapes<2>;
  template class PoreShapes<3>;
} // namespace GelMPM

#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/geometry/pore_geometry.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/simulator/observables.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace GelMPM
{
  template <int dim>
  void
  Observables<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Observables");
    prm.declare_entry("Thickness pieces",
                      "",
                      dealii::Patterns::Anything(),
                      "Two boundary piece names 'first, second': adds the column "
                      "delta_h_over_h0 = h/h_0 - 1, with h the distance between the mean "
                      "positions of the two pieces' surface points along 'Thickness direction' "
                      "(h_0 in the initial configuration). Empty: off.");
    prm.declare_entry("Thickness direction",
                      "1",
                      dealii::Patterns::Integer(0, 2),
                      "Coordinate direction of the thickness (0: x, 1: y, 2: z).");
    prm.declare_entry("Radius piece",
                      "",
                      dealii::Patterns::Anything(),
                      "A boundary piece name (e.g. 'sphere'): adds the column radius_over_R0, the "
                      "mean distance of the piece's surface points from 'Radius centre' over its "
                      "value in the initial configuration (r/R_0 of a swelling sphere, disk or "
                      "cylinder). Empty: off.");
    prm.declare_entry("Radius centre",
                      "0, 0, 0",
                      dealii::Patterns::List(dealii::Patterns::Double(), 2, 3),
                      "With 'Radius piece': the centre the distances are measured from (its first "
                      "'Dimension' coordinates are used).");
    prm.declare_entry("Centre offset pieces",
                      "",
                      dealii::Patterns::Anything(),
                      "Two boundary piece names 'first, second' (e.g. 'bottom, top' of a column): "
                      "adds the columns centre_offset_x, centre_offset_y (and centre_offset_z in "
                      "3D), the vector from the mean position of the first piece's surface points "
                      "to that of the second's minus its initial value, and centre_distance, its "
                      "length (paper Fig. 10a: the sideways separation of the ends of a buckling "
                      "column). Empty: off.");
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
    prm.declare_entry("Volume ratio range",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the columns J_min, J_mean and J_max: the smallest, mean (weighted "
                      "by the initial volumes V_0) and largest volume ratio J (dry state to "
                      "current) over the volume points. A homogeneous state has J_min = J_max.");
    prm.declare_entry("Boundary condition error",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the columns u_bc_error and mu_bc_error: after every converged step, "
                      "the largest violation of the weakly imposed (Nitsche) conditions over the "
                      "surface points, |Pi (u - ubar)| for prescribed displacements (in the "
                      "scene's length unit) and |mu - mubar|/k_BT for prescribed chemical "
                      "potentials. Empty in the initial row.");
    prm.declare_entry("Chemical potential oscillation",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the column mu_oscillation: along every row of volume points (points "
                      "with the same initial y, ordered by initial x), the sum of |second "
                      "differences| of mu; the mean over rows, divided by the range of mu over "
                      "all volume points. Spurious (inf-sup) pressure modes make it of order one; "
                      "a smooth field gives a small value that shrinks with the point spacing "
                      "(doc/flat_punch.md). 2D only.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  Observables<dim>::parse_parameters(dealii::ParameterHandler       &prm,
                                     const std::vector<std::string> &pieces)
  {
    prm.enter_subsection("Observables");
    const auto names = dealii::Utilities::split_string_list(prm.get("Thickness pieces"), ',');
    const auto offset_names =
      dealii::Utilities::split_string_list(prm.get("Centre offset pieces"), ',');
    thickness_direction           = prm.get_integer("Thickness direction");
    volume_ratio_range            = prm.get_bool("Volume ratio range");
    mu_oscillation                = prm.get_bool("Chemical potential oscillation");
    boundary_error                = prm.get_bool("Boundary condition error");
    const std::string pore_name   = dealii::Utilities::trim(prm.get("Pore piece"));
    const std::string radius_name = dealii::Utilities::trim(prm.get("Radius piece"));
    const auto centre_text = dealii::Utilities::split_string_list(prm.get("Radius centre"), ',');
    for (unsigned int d = 0; d < dim && d < centre_text.size(); ++d)
      radius_centre[d] = dealii::Utilities::string_to_double(centre_text[d]);
    crease_angle           = prm.get_double("Crease angle") * M_PI / 180.;
    surface_names          = dealii::Utilities::split_string_list(prm.get("Surface pieces"), ',');
    fold_approach_distance = prm.get_double("Fold approach distance");
    fold_arc_length        = prm.get_double("Fold arc length");
    pore_centres.clear();
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
        pore_centres.push_back(centre);
      }
    prm.leave_subsection();
    // Its rows are the points of equal initial y, ordered by x: lines in 2D, but in 3D planes
    // whose points in x order jump between lines of different z.
    require(!mu_oscillation || dim == 2,
            "Observables/Chemical potential oscillation",
            "is set in a 3D scene, but it is measured along rows of points of equal initial y, "
            "which are lines in 2D only",
            "set it to false in 3D");
    pore_piece = -1;
    if (!pore_name.empty())
      {
        // A pore's outline is a polyline ordered by angle about its centre: a curve in the
        // plane. In 3D the points of a pore's surface form no such curve.
        require(dim == 2,
                "Observables/Pore piece",
                "is set in a 3D scene, but pore outlines (ratios, turning, creases) are measured "
                "in 2D only",
                "leave 'Pore piece' empty in 3D");
        const auto it = std::find(pieces.begin(), pieces.end(), pore_name);
        require(it != pieces.end(),
                "Observables/Pore piece",
                "names the piece '" + pore_name + "' that is not in 'Boundary conditions/Pieces'",
                "use one of the declared pieces");
        require(!pore_centres.empty(),
                "Observables/Pore centres",
                "is empty, but 'Pore piece' is set",
                "list the pores' centres 'x1, y1; x2, y2; ...'");
        pore_piece = it - pieces.begin();
      }

    require(thickness_direction < dim,
            "Observables/Thickness direction",
            "exceeds the dimension",
            "give a direction below " + std::to_string(dim));
    thickness_pieces = piece_pair(names, pieces, "Observables/Thickness pieces", "top, bottom");

    // In 3D only the relief: the points of a surface form no polyline there.
    surface_pieces = piece_indices(surface_names, pieces, "Observables/Surface pieces");
    require(fold_approach_distance > 0.,
            "Observables/Fold approach distance",
            "must be positive",
            "give a fraction of the grid spacing h_u, e.g. 0.5");
    require(fold_arc_length > fold_approach_distance,
            "Observables/Fold arc length",
            "is not larger than 'Fold approach distance': neighbouring points of a flat "
            "surface would count as a fold",
            "give a multiple of h_u larger than 'Fold approach distance', e.g. 3");
    offset_pieces =
      piece_pair(offset_names, pieces, "Observables/Centre offset pieces", "bottom, top");
    radius_piece = -1;
    if (!radius_name.empty())
      {
        const auto it = std::find(pieces.begin(), pieces.end(), radius_name);
        require(it != pieces.end(),
                "Observables/Radius piece",
                "names the piece '" + radius_name + "' that is not in 'Boundary conditions/Pieces'",
                "use one of the declared pieces");
        radius_piece = it - pieces.begin();
      }
  }


  template <int dim>
  std::array<int, 2>
  Observables<dim>::piece_pair(const std::vector<std::string> &names,
                               const std::vector<std::string> &pieces,
                               const std::string              &entry,
                               const std::string              &example)
  {
    std::array<int, 2> pair = {{-1, -1}};
    if (names.empty())
      return pair;
    require(names.size() == 2, entry, "must name exactly two pieces", "write '" + example + "'");
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto it = std::find(pieces.begin(), pieces.end(), names[k]);
        require(it != pieces.end(),
                entry,
                "names the piece '" + names[k] + "' that is not in 'Boundary conditions/Pieces'",
                "use one of the declared pieces");
        pair[k] = it - pieces.begin();
      }
    return pair;
  }


  template <int dim>
  std::vector<std::string>
  Observables<dim>::columns() const
  {
    std::vector<std::string> c;
    if (thickness_pieces[0] >= 0)
      c.push_back("delta_h_over_h0");
    if (radius_piece >= 0)
      c.push_back("radius_over_R0");
    if (offset_pieces[0] >= 0)
      {
        for (unsigned int d = 0; d < dim; ++d)
          c.push_back(std::string("centre_offset_") + "xyz"[d]);
        c.push_back("centre_distance");
      }
    if (pore_piece >= 0)
      {
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
      }
    for (const auto &name : surface_names)
      {
        c.push_back(name + "_relief");
        if (dim == 2)
          for (const char *measure : {"_curvature", "_turning", "_folds"})
            c.push_back(name + measure);
      }
    if (volume_ratio_range)
      for (const char *name : {"J_min", "J_mean", "J_max"})
        c.push_back(name);
    if (mu_oscillation)
      c.push_back("mu_oscillation");
    if (boundary_error)
      for (const char *name : {"u_bc_error", "mu_bc_error"})
        c.push_back(name);
    return c;
  }


  template <int dim>
  void
  Observables<dim>::evaluate(const dealii::Particles::ParticleHandler<dim>    &particles,
                             const MaterialRegions<dim>                       &material,
                             const std::function<std::pair<double, double>()> &dirichlet_errors,
                             StatisticsFile                                   &statistics) const
  {
    if (thickness_pieces[0] >= 0)
      {
        const auto   means = piece_means(particles, thickness_pieces);
        const double h     = means[0][thickness_direction] - means[1][thickness_direction];
        const double h_0   = means[2][thickness_direction] - means[3][thickness_direction];
        statistics.set("delta_h_over_h0", h / h_0 - 1.);
      }
    if (radius_piece >= 0)
      {
        using Layout = PropertyLayout<dim>;
        // Sums of the current and the initial distances.
        std::vector<double> sums(2, 0.);
        for (const auto &particle : particles)
          {
            const auto props = particle.get_properties();
            if (kind_of(props) == PointKind::volume || piece_of(props) != radius_piece)
              continue;
            dealii::Point<dim> X0;
            for (unsigned int d = 0; d < dim; ++d)
              X0[d] = props[Layout::position_0 + d];
            sums[0] += position_of(particle.get_location(), props).distance(radius_centre);
            sums[1] += X0.distance(radius_centre);
          }
        dealii::Utilities::MPI::sum(sums, communicator, sums);
        statistics.set("radius_over_R0", sums[0] / sums[1]);
      }
    if (offset_pieces[0] >= 0)
      {
        const auto                   means  = piece_means(particles, offset_pieces);
        const dealii::Tensor<1, dim> offset = (means[1] - means[0]) - (means[3] - means[2]);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.set(std::string("centre_offset_") + "xyz"[d], offset[d]);
        statistics.set("centre_distance", offset.norm());
      }
    if (pore_piece >= 0)
      {
        double     mu_mean = 0.;
        const auto shapes  = pore_shapes(particles, mu_mean);
        for (unsigned int k = 0; k < shapes.size(); ++k)
          {
            const std::string number = std::to_string(k + 1);
            statistics.set("pore_ratio_" + number, shapes[k].ratio);
            statistics.set("pore_curvature_" + number, shapes[k].curvature);
            statistics.set("pore_turning_" + number, shapes[k].turning * 180. / M_PI);
            statistics.set("pore_creases_" + number, shapes[k].creases);
            if (!contact_planes.empty())
              statistics.set("pore_contact_" + number, shapes[k].contact_points);
          }
        statistics.set("mu_boundary", mu_mean);
      }
    if (!surface_pieces.empty())
      {
        const auto shapes = surface_shapes(particles);
        for (unsigned int k = 0; k < shapes.size(); ++k)
          {
            statistics.set(surface_names[k] + "_relief", shapes[k].relief);
            if (dim == 2)
              {
                statistics.set(surface_names[k] + "_curvature", shapes[k].curvature);
                statistics.set(surface_names[k] + "_turning", shapes[k].turning * 180. / M_PI);
                statistics.set(surface_names[k] + "_folds", shapes[k].folds);
              }
          }
      }
    if (volume_ratio_range)
      {
        const auto J = volume_ratio_statistics(particles, material);
        statistics.set("J_min", J[0]);
        statistics.set("J_mean", J[1]);
        statistics.set("J_max", J[2]);
      }
    if (mu_oscillation)
      statistics.set("mu_oscillation", chemical_potential_oscillation(particles));
    if (boundary_error && dirichlet_errors)
      {
        const auto [u_error, mu_error] = dirichlet_errors();
        statistics.set("u_bc_error", u_error);
        statistics.set("mu_bc_error", mu_error);
      }
  }


  template <int dim>
  std::array<dealii::Point<dim>, 4>
  Observables<dim>::piece_means(const dealii::Particles::ParticleHandler<dim> &particles,
                                const std::array<int, 2>                      &pair) const
  {
    using Layout = PropertyLayout<dim>;
    std::array<dealii::Point<dim>, 4> sum;
    std::array<unsigned int, 2>       count = {{0, 0}};
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        const int  piece = piece_of(props);
        for (unsigned int k = 0; k < 2; ++k)
          if (piece == pair[k])
            {
              for (unsigned int d = 0; d < dim; ++d)
                {
                  sum[k][d] += position_of(particle.get_location(), props)[d];
                  sum[2 + k][d] += props[Layout::position_0 + d];
                }
              ++count[k];
            }
      }
    std::vector<double> flat;
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        flat.push_back(sum[k][d]);
    flat.push_back(count[0]);
    flat.push_back(count[1]);
    Collective::sum_in_place(communicator, flat);
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        sum[k][d] = flat[k * dim + d] / flat[4 * dim + k % 2];
    return sum;
  }


  template <int dim>
  std::vector<typename Observables<dim>::PoreShape>
  Observables<dim>::pore_shapes(const dealii::Particles::ParticleHandler<dim> &particles,
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
    std::vector<PoreShape>                                        shapes(n);
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
    std::vector<double> all;
    if (Collective::is_parallel(communicator))
      for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, local))
        all.insert(all.end(), part.begin(), part.end());
    else
      all = std::move(local);
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


  template <int dim>
  std::vector<std::pair<std::string, unsigned int>>
  Observables<dim>::new_events(const dealii::Particles::ParticleHandler<dim> &particles)
  {
    std::vector<std::pair<std::string, unsigned int>> events;
    if (dim == 2 && !surface_pieces.empty())
      {
        const auto shapes = surface_shapes(particles);
        folds_seen.resize(shapes.size(), 0);
        for (unsigned int k = 0; k < shapes.size(); ++k)
          {
            for (unsigned int f = folds_seen[k]; f < shapes[k].folds; ++f)
              events.emplace_back("crease_" + surface_names[k], 0);
            folds_seen[k] = std::max(folds_seen[k], shapes[k].folds);
          }
      }
    if (pore_piece < 0)
      return events;
    double     mu_mean = 0.;
    const auto shapes  = pore_shapes(particles, mu_mean);
    contact_seen.resize(shapes.size(), false);
    creases_seen.resize(shapes.size(), 0);
    for (unsigned int k = 0; k < shapes.size(); ++k)
      {
        if (shapes[k].contact_points > 0 && !contact_seen[k])
          events.emplace_back("self_contact", k + 1);
        // A crease is new when the pore has more sharp corners than it ever had.
        for (unsigned int c = creases_seen[k]; c < shapes[k].creases; ++c)
          events.emplace_back("crease", k + 1);
        contact_seen[k] = contact_seen[k] || shapes[k].contact_points > 0;
        creases_seen[k] = std::max(creases_seen[k], shapes[k].creases);
      }
    return events;
  }


  template <int dim>
  bool
  Observables<dim>::writes_events() const
  {
    return pore_piece >= 0 || (dim == 2 && !surface_pieces.empty());
  }


  template <int dim>
  void
  Observables<dim>::set_grid_spacing(const double spacing)
  {
    h_u = spacing;
  }


  template <int dim>
  std::vector<typename Observables<dim>::SurfaceShape>
  Observables<dim>::surface_shapes(const dealii::Particles::ParticleHandler<dim> &particles,
                                   std::vector<SurfaceGeometry::Polyline>        *polylines) const
  {
    using Layout = PropertyLayout<dim>;
    AssertThrow(dim == 3 || h_u > 0.,
                dealii::ExcMessage("Observables: set_grid_spacing() before the surface shapes"));
    // Per point of a surface piece, gathered from every rank (a piece's polyline needs all of
    // it): the piece's place in 'Surface pieces', x, N_n A_n, and in 2D X_0, N_0 A_0 and mu.
    const unsigned int  n_values = dim == 2 ? 1 + 4 * dim + 1 : 1 + 2 * dim;
    std::vector<double> local;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        const auto it    = std::find(surface_pieces.begin(), surface_pieces.end(), piece_of(props));
        if (it == surface_pieces.end())
          continue;
        local.push_back(it - surface_pieces.begin());
        const auto x = position_of(particle.get_location(), props);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(x[d]);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(props[Layout::normal_area_n + d]);
        if (dim == 2)
          {
            for (unsigned int d = 0; d < dim; ++d)
              local.push_back(props[Layout::position_0 + d]);
            for (unsigned int d = 0; d < dim; ++d)
              local.push_back(props[Layout::normal_area_0 + d]);
            local.push_back(props[Layout::mu]);
          }
      }
    std::vector<double> all;
    if (Collective::is_parallel(communicator))
      for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, local))
        all.insert(all.end(), part.begin(), part.end());
    else
      all = std::move(local);

    const unsigned int                                      n_pieces = surface_pieces.size();
    std::vector<std::vector<dealii::Point<dim>>>            positions(n_pieces);
    std::vector<std::vector<dealii::Tensor<1, dim>>>        normal_areas(n_pieces);
    std::vector<std::vector<SurfaceGeometry::SurfacePoint>> points(n_pieces);
    for (std::size_t first = 0; first < all.size(); first += n_values)
      {
        const unsigned int     k = std::lround(all[first]);
        dealii::Point<dim>     x;
        dealii::Tensor<1, dim> normal_area;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d]           = all[first + 1 + d];
            normal_area[d] = all[first + 1 + dim + d];
          }
        positions[k].push_back(x);
        normal_areas[k].push_back(normal_area);
        if (dim == 2)
          {
            SurfaceGeometry::SurfacePoint point;
            for (unsigned int d = 0; d < 2; ++d)
              {
                point.x[d]        = x[d];
                point.X_0[d]      = all[first + 1 + 2 * dim + d];
                point.normal_0[d] = all[first + 1 + 3 * dim + d];
              }
            point.mu = all[first + 1 + 4 * dim];
            points[k].push_back(point);
          }
      }

    std::vector<SurfaceShape> shapes(n_pieces);
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
  Observables<dim>::write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                                   const std::string                             &directory)
  {
    if (dim != 2 || surface_pieces.empty())
      return;
    std::vector<SurfaceGeometry::Polyline> polylines;
    surface_shapes(particles, &polylines);
    std::ostringstream number;
    number << std::setw(5) << std::setfill('0') << surface_outputs;
    Collective::on_root(communicator, [&]() {
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


  template <int dim>
  void
  Observables<dim>::set_contact_planes(const std::vector<ContactSettings::Plane> &planes,
                                       const double                               tolerance)
  {
    contact_planes    = planes;
    contact_tolerance = tolerance;
  }


  template <int dim>
  std::optional<double>
  Observables<dim>::boundary_chemical_potential(
    const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    if (pore_piece < 0)
      return std::nullopt;
    double mu_mean = 0.;
    pore_shapes(particles, mu_mean);
    return mu_mean;
  }


  template <int dim>
  std::array<double, 3>
  Observables<dim>::volume_ratio_statistics(
    const dealii::Particles::ParticleHandler<dim> &particles,
    const MaterialRegions<dim>                    &material) const
  {
    using Layout = PropertyLayout<dim>;
    double J_min = std::numeric_limits<double>::max(), J_max = -J_min;
    double sum_JV = 0., sum_V = 0.;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (kind_of(props) != PointKind::volume)
          continue;
        dealii::Tensor<2, dim> F;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] = props[Layout::F + i * dim + j];
        const double J =
          material[region_of_point<dim>(props)].J(F, out_of_plane_stretch_of<dim>(props));
        J_min = std::min(J_min, J);
        J_max = std::max(J_max, J);
        sum_JV += J * props[Layout::measure_0];
        sum_V += props[Layout::measure_0];
      }
    return {{dealii::Utilities::MPI::min(J_min, communicator),
             dealii::Utilities::MPI::sum(sum_JV, communicator) /
               dealii::Utilities::MPI::sum(sum_V, communicator),
             dealii::Utilities::MPI::max(J_max, communicator)}};
  }


  template <int dim>
  double
  Observables<dim>::chemical_potential_oscillation(
    const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    using Layout = PropertyLayout<dim>;
    // (row coordinate, position along the row, mu) of every volume point. Points are generated at
    // sub-cell centres of the background grid, so rows of equal initial y exist for any body.
    std::vector<std::array<double, 3>> points;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (kind_of(props) == PointKind::volume)
          points.push_back(
            {{props[Layout::position_0 + dim - 1], props[Layout::position_0], props[Layout::mu]}});
      }
    if (Collective::is_parallel(communicator))
      {
        std::vector<std::array<double, 3>> all;
        for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, points))
          all.insert(all.end(), part.begin(), part.end());
        points = std::move(all);
      }
    if (points.size() < 3)
      return 0.;
    std::sort(points.begin(), points.end());
    double mu_min = points[0][2], mu_max = points[0][2];
    for (const auto &p : points)
      mu_min = std::min(mu_min, p[2]), mu_max = std::max(mu_max, p[2]);
    const double extent = std::abs(points.back()[0] - points.front()[0]) + 1.;

    double       sum    = 0.;
    unsigned int n_rows = 0;
    for (std::size_t first = 0; first < points.size();)
      {
        std::size_t end = first + 1;
        while (end < points.size() && points[end][0] - points[first][0] <= 1e-9 * extent)
          ++end;
        for (std::size_t i = first + 1; i + 1 < end; ++i)
          sum += std::abs(points[i + 1][2] - 2. * points[i][2] + points[i - 1][2]);
        ++n_rows;
        first = end;
      }
    return (mu_max > mu_min) ? sum / n_rows / (mu_max - mu_min) : 0.;
  }


  template <int dim>
  void
  Observables<dim>::set_communicator(const MPI_Comm comm)
  {
    communicator = comm;
  }


  template class Observables<2>;
  template class Observables<3>;
} // namespace GelMPM

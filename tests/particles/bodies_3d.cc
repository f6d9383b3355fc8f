// Material points of 3D bodies, generated as a scene generates them, against exact geometry. For
// a closed surface sum N_0 A_0 = 0 and sum x (x) N_0 A_0 = V I (divergence theorem), which checks
// the areas, the normals and the positions of the surface points together.
// - boxes (one, and two overlapping into an L): every sum exact to round-off, every normal a
//   coordinate direction, and the boundary pieces selected by nx, ny, nz with their exact areas;
// - a ball hole inside a box: the sphere's area and the sums within the bound of the two-point
//   Gauss rule on its patches;
// - a ball hole cutting a face and a cylinder through the box: the sums within the bound of the
//   8 x 8 sub-patches on the cut patches (a sub-patch counts whole or not at all);
// - a ball given by a level set: sum N_0 A_0 = 0 to round-off (the divergence theorem on each
//   sampling cube), sum A_0 and sum x (x) N_0 A_0 converging to the exact values at rate >= 1.8,
//   every surface point on the zero surface.
#include <gelmpm/particles/material_point_generator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

using namespace dealii;
using namespace GelMPM;

namespace
{
  bool all_ok = true;

  void
  report(const std::string &what, const bool ok)
  {
    all_ok &= ok;
    std::cout << "  " << what << ": " << (ok ? "PASS" : "FAIL") << std::endl;
  }

  struct Sums
  {
    double       volume = 0., area = 0., off_surface = 0.;
    Tensor<1, 3> normal_area;
    Tensor<2, 3> moment; // sum x (x) N_0 A_0
    unsigned int n_volume = 0, n_surface = 0;
    // Per piece (-1: none): the number of points and their area.
    std::map<int, std::pair<unsigned int, double>> pieces;
    bool                                           normals_follow_pieces = true;
    bool                                           axis_normals          = true;
  };

  /**
   * The points of @p geometry_entries on [0, 2]^3 with @p cells per direction, 2 x 2 x 2 points
   * per cell and 2 surface points per cell edge; pieces 'bottom' (nz < -0.9) and 'right'
   * (nx > 0.9) if @p with_pieces.
   */
  Sums
  generate(const std::string &geometry_entries, const unsigned int cells, const bool with_pieces)
  {
    ParameterHandler               prm;
    const std::vector<std::string> pieces =
      with_pieces ? std::vector<std::string>{"bottom", "right"} : std::vector<std::string>{};
    BackgroundGrid<3>::declare_parameters(prm);
    Geometry<3>::declare_parameters(prm);
    BoundaryConditions<3>::declare_parameters(prm, pieces);
    MaterialPointGenerator<3>::declare_parameters(prm);
    const std::string c = std::to_string(cells);
    prm.parse_input_from_string(
      "subsection Background grid\n set Upper corner = 2, 2, 2\n set Cells = " + c + ", " + c +
      ", " + c + "\nend\nsubsection Geometry\n" + geometry_entries +
      "\nend\nsubsection Material points\n set Points per cell = 2\n"
      " set Surface points per cell edge = 2\nend\nsubsection Boundary conditions\n" +
      (with_pieces ? " subsection bottom\n  set Selector = nz < -0.9\n  set Displacement = normal\n"
                     " end\n subsection right\n  set Selector = nx > 0.9\n"
                     "  set Chemical potential = prescribed\n end\n"
                   : "") +
      "end\n");
    BackgroundGrid<3>         grid;
    Geometry<3>               geometry;
    BoundaryConditions<3>     bcs;
    MaterialPointGenerator<3> generator;
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm);
    bcs.parse_parameters(prm, pieces);
    generator.parse_parameters(prm);
    Triangulation<3> tria;
    MappingQ1<3>     mapping;
    grid.create_triangulation(tria);
    Particles::ParticleHandler<3> particles(tria, mapping, PropertyLayout<3>::n_properties);
    generator.generate(geometry, grid, tria, bcs, 1.2801, -0.146, particles);

    Sums s;
    using Layout = PropertyLayout<3>;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) == PointKind::volume)
          {
            s.volume += props[Layout::measure_0];
            ++s.n_volume;
            continue;
          }
        Tensor<1, 3> na;
        for (unsigned int d = 0; d < 3; ++d)
          na[d] = props[Layout::normal_area_0 + d];
        const Point<3> x = p.get_location();
        s.area += na.norm();
        s.normal_area += na;
        s.moment += outer_product(x, na);
        ++s.n_surface;
        const Tensor<1, 3> normal = na / na.norm();
        unsigned int       n_axis = 0;
        for (unsigned int d = 0; d < 3; ++d)
          n_axis += std::abs(std::abs(normal[d]) - 1.) < 1e-12;
        s.axis_normals &= n_axis == 1;
        if (geometry.source() == Geometry<3>::Source::level_set)
          {
            // Distance from the surface to first order: |phi| / |grad phi|.
            const double delta = 1e-6;
            Tensor<1, 3> g;
            for (unsigned int d = 0; d < 3; ++d)
              {
                Tensor<1, 3> e;
                e[d] = delta;
                g[d] = (geometry.level_set(x + e) - geometry.level_set(x - e)) / 2. / delta;
              }
            s.off_surface = std::max(s.off_surface, std::abs(geometry.level_set(x)) / g.norm());
          }
        const int piece = piece_of(props);
        ++s.pieces[piece].first;
        s.pieces[piece].second += na.norm();
        if (piece == 0)
          s.normals_follow_pieces &= normal[2] < -0.9;
        if (piece == 1)
          s.normals_follow_pieces &=
            normal[0] > 0.9 && kind_of(props) == PointKind::neumann_dirichlet;
      }
    return s;
  }

  Tensor<2, 3>
  unit_matrix()
  {
    Tensor<2, 3> I;
    for (unsigned int d = 0; d < 3; ++d)
      I[d][d] = 1.;
    return I;
  }

  void
  print(const Sums &s, const double volume, const double area)
  {
    std::cout << "  " << s.n_volume << " volume points, " << s.n_surface
              << " surface points; sum V_0 error " << std::scientific
              << std::abs(s.volume - volume) / volume << ", sum A_0 error "
              << std::abs(s.area - area) / area << ", |sum N_0 A_0| / area "
              << s.normal_area.norm() / area << ", |sum x(x)N A - V I| / V "
              << (s.moment - volume * unit_matrix()).norm() / volume << std::defaultfloat
              << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(3);
  const Tensor<2, 3> I = unit_matrix();

  std::cout << "Box [0.2, 1.8] x [0.4, 1.6] x [0.6, 1.4] on 20^3 cells, pieces bottom (nz < -0.9) "
               "and right (nx > 0.9):"
            << std::endl;
  {
    const auto   s = generate(" set Boxes = 0.2, 0.4, 0.6 : 1.8, 1.6, 1.4", 20, true);
    const double V = 1.6 * 1.2 * 0.8, A = 2. * (1.6 * 1.2 + 1.6 * 0.8 + 1.2 * 0.8);
    print(s, V, A);
    report("sum V_0, sum A_0, sum N_0 A_0 = 0 and sum x (x) N_0 A_0 = V I to round-off",
           std::abs(s.volume - V) < 1e-12 && std::abs(s.area - A) < 1e-12 &&
             s.normal_area.norm() < 1e-12 && (s.moment - V * I).norm() < 1e-12);
    report("every normal along a coordinate axis", s.axis_normals);
    report("bottom: 32 x 24 points of area 1.6 x 1.2; right: 24 x 16 points of area 1.2 x 0.8, "
           "prescribed chemical potential",
           s.pieces.at(0).first == 768 && std::abs(s.pieces.at(0).second - 1.92) < 1e-12 &&
             s.pieces.at(1).first == 384 && std::abs(s.pieces.at(1).second - 0.96) < 1e-12 &&
             s.normals_follow_pieces);
  }

  std::cout << "L of two overlapping boxes on 20^3 cells:" << std::endl;
  {
    const auto s =
      generate(" set Boxes = 0.2, 0.2, 0.2 : 1.0, 1.8, 1.0; 0.2, 0.2, 0.2 : 1.8, 1.0, 1.0",
               20,
               false);
    const double V = 0.8 * 1.6 * 0.8 + 0.8 * 0.8 * 0.8;
    // A prism of height 0.8 over an L of area 1.92 and perimeter 6.4.
    const double A = 2. * 1.92 + 6.4 * 0.8;
    print(s, V, A);
    report("sums to round-off, normals along axes",
           std::abs(s.volume - V) < 1e-12 && std::abs(s.area - A) < 1e-12 &&
             s.normal_area.norm() < 1e-12 && (s.moment - V * I).norm() < 1e-12 && s.axis_normals);
  }

  // A sphere patch of angular size delta <= spacing / r (the projected cube's patches are largest
  // at the face centres) carries |int N dA| below its area by at most delta^2 / 8 relative, and
  // its point at the patch centre errs in int x (x) N dA by as much times r. The sub-cell volume
  // points err by at most the sphere's area times the sub-cell diagonal.
  std::cout << "Box [0.2, 1.8]^3 minus the ball of radius 0.5 at its centre, 20^3 cells:"
            << std::endl;
  {
    const auto s =
      generate(" set Boxes = 0.2, 0.2, 0.2 : 1.8, 1.8, 1.8\n set Holes = 1, 1, 1 : 0.5", 20, false);
    const double r = 0.5, V = std::pow(1.6, 3) - 4. / 3. * M_PI * std::pow(r, 3),
                 A = 6. * 1.6 * 1.6 + 4. * M_PI * r * r, spacing = 0.05;
    print(s, V, A);
    const double chord = 4. * M_PI * r * r * std::pow(spacing / r, 2) / 8.;
    report("sum V_0 within sphere area x sub-cell diagonal",
           std::abs(s.volume - V) < 4. * M_PI * r * r * std::sqrt(3.) * 0.05);
    report("sum A_0 and sum x (x) N_0 A_0 = V I within the chord bound, sum N_0 A_0 = 0 to "
           "round-off",
           s.area < A && A - s.area < chord && s.normal_area.norm() < 1e-12 &&
             (s.moment - V * I).norm() < r * chord);
  }

  // A patch cut by another part of the boundary keeps whole 1/8 x 1/8 sub-patches: the error is
  // at most (length of the cut) x (sub-patch diagonal) in area, per component of the sums.
  std::cout << "Box [0.2, 1.8]^3 minus a half ball (centre on the top face, radius 0.5), and minus "
               "a cylinder of radius 0.4 along z, 20^3 cells:"
            << std::endl;
  {
    const double spacing = 0.05, sub_diagonal = std::sqrt(2.) * spacing / 8.;
    {
      const auto s =
        generate(" set Boxes = 0.2, 0.2, 0.2 : 1.8, 1.8, 1.8\n set Holes = 1, 1, 1.8 : 0.5",
                 20,
                 false);
      const double r = 0.5, V = std::pow(1.6, 3) - 2. / 3. * M_PI * std::pow(r, 3),
                   A = 6. * 1.6 * 1.6 - M_PI * r * r + 2. * M_PI * r * r;
      print(s, V, A);
      const double bound = 2. * M_PI * r * sub_diagonal;
      report("half ball: sum A_0, sum N_0 A_0 and sum x (x) N_0 A_0 / 1.8 within cut length x "
             "sub-patch diagonal",
             std::abs(s.area - A) < 2. * bound && s.normal_area.norm() < 2. * bound &&
               (s.moment - V * I).norm() < 2. * 1.8 * bound * 3.);
    }
    {
      const auto s =
        generate(" set Boxes = 0.2, 0.2, 0.2 : 1.8, 1.8, 1.8\n set Holes = 1, 1, 0 : 0.4 : 0, 0, 1",
                 20,
                 false);
      const double r = 0.4, V = std::pow(1.6, 3) - M_PI * r * r * 1.6,
                   A = 6. * 1.6 * 1.6 - 2. * M_PI * r * r + 2. * M_PI * r * 1.6;
      print(s, V, A);
      const double bound = 2. * 2. * M_PI * r * sub_diagonal;
      report("cylinder: sum A_0, sum N_0 A_0 and sum x (x) N_0 A_0 / 1.8 within cut length x "
             "sub-patch diagonal",
             std::abs(s.area - A) < 2. * bound && s.normal_area.norm() < 2. * bound &&
               (s.moment - V * I).norm() < 2. * 1.8 * bound * 3.);
    }
  }

  std::cout << "Ball of radius 0.6 at (1, 1, 1) as a level set, 10^3 and 20^3 cells:" << std::endl;
  {
    const std::string ball = " set Level set = (x-1)^2 + (y-1)^2 + (z-1)^2 - 0.36";
    const double      r = 0.6, V = 4. / 3. * M_PI * std::pow(r, 3), A = 4. * M_PI * r * r;
    double            e_area[2], e_moment[2];
    bool              closed = true, on_surface = true;
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto s = generate(ball, 10u << k, false);
        print(s, V, A);
        e_area[k]   = std::abs(s.area - A);
        e_moment[k] = (s.moment - V * I).norm();
        closed &= s.normal_area.norm() < 1e-12 * A;
        on_surface &= s.off_surface < 1e-10;
      }
    const double rate_area   = std::log2(e_area[0] / e_area[1]),
                 rate_moment = std::log2(e_moment[0] / e_moment[1]);
    std::cout << "  rates: sum A_0 " << std::fixed << std::setprecision(2) << rate_area
              << ", sum x (x) N_0 A_0 " << rate_moment << std::defaultfloat << std::setprecision(3)
              << std::endl;
    report("sum N_0 A_0 = 0 to round-off", closed);
    report("every surface point on the zero surface (|phi|/|grad phi| < 1e-10)", on_surface);
    report("sum A_0 and sum x (x) N_0 A_0 within 1 % on 20^3 cells and converging at rate >= 1.8",
           e_area[1] < 0.01 * A && e_moment[1] < 0.01 * V && rate_area >= 1.8 &&
             rate_moment >= 1.8);
  }

  std::cout << (all_ok ? "OK" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}

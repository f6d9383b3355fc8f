// Material points of a body given by a level set ("Geometry/Level set", inside where negative),
// generated as a scene generates them, against exact geometry:
// - an ellipse (semi-axes 0.7, 0.4 at (1, 1)) at three resolutions: sum V_0 within the sub-cell
//   bound of the area, sum A_0 against the perimeter within the chord bound and converging with
//   rate >= 1.8, sum N_0 A_0 = 0 to round-off, sum x (x) N_0 A_0 = area I within the bound of the
//   midpoint rule, every surface point on the zero contour, no element longer than h/n_s;
// - a rectangle written as a level set with its edges on sub-cell lines: exactly the points of the
//   same rectangle given as a box (sum V_0, sum A_0 to round-off);
// - a quarter ellipse with two straight sides (the example scene prm/ellipse_swelling.prm): the
//   sums with elements that end at the kinks, and boundary pieces selected by normals.
#include <gelmpm/particles/material_point_generator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
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
    double                      volume = 0., area = 0., longest = 0., off_contour = 0.;
    Tensor<1, 2>                normal_area;
    Tensor<2, 2>                moment; // sum x (x) N_0 A_0
    unsigned int                n_volume = 0, n_surface = 0;
    std::map<int, unsigned int> points_of_piece;
    bool                        normals_follow_pieces = true;
  };

  /**
   * Generate the points of @p geometry_entries on [0, 2]^2 with @p cells per direction, n points
   * per cell and n_s surface points per cell length; pieces 'left' (nx < -0.9) and 'bottom'
   * (ny < -0.9), the rest unselected.
   */
  Sums
  generate(const std::string &geometry_entries,
           const unsigned int cells,
           const unsigned int n,
           const unsigned int n_s)
  {
    ParameterHandler               prm;
    const std::vector<std::string> pieces = {"left", "bottom"};
    BackgroundGrid<2>::declare_parameters(prm);
    Geometry<2>::declare_parameters(prm);
    BoundaryConditions<2>::declare_parameters(prm, pieces);
    MaterialPointGenerator<2>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Background grid\n set Upper corner = 2, 2\n set Cells = " +
      std::to_string(cells) + ", " + std::to_string(cells) + "\nend\nsubsection Geometry\n" +
      geometry_entries + "\nend\nsubsection Material points\n set Points per cell = " +
      std::to_string(n) + "\n set Surface points per cell edge = " + std::to_string(n_s) +
      "\nend\nsubsection Boundary conditions\n"
      " subsection left\n  set Selector = nx < -0.9\n  set Displacement = normal\n end\n"
      " subsection bottom\n  set Selector = ny < -0.9\n  set Displacement = normal\n end\n"
      "end\n");
    BackgroundGrid<2>         grid;
    Geometry<2>               geometry;
    BoundaryConditions<2>     bcs;
    MaterialPointGenerator<2> generator;
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm);
    bcs.parse_parameters(prm, pieces);
    generator.parse_parameters(prm);
    Triangulation<2> tria;
    MappingQ1<2>     mapping;
    grid.create_triangulation(tria);
    Particles::ParticleHandler<2> particles(tria, mapping, PropertyLayout<2>::n_properties);
    // Pieces that select nothing are an input error: the callers' bodies have no such sides
    // unless they ask for them, so give those bodies no pieces.
    generator.generate(geometry, grid, tria, bcs, 1.2801, -0.146, particles);

    Sums s;
    using Layout = PropertyLayout<2>;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) == PointKind::volume)
          {
            s.volume += props[Layout::measure_0];
            ++s.n_volume;
            continue;
          }
        Tensor<1, 2> na;
        for (unsigned int d = 0; d < 2; ++d)
          na[d] = props[Layout::normal_area_0 + d];
        const Point<2> x = p.get_location();
        s.area += na.norm();
        s.normal_area += na;
        s.moment += outer_product(x, na);
        s.longest = std::max(s.longest, na.norm());
        if (geometry.source() == Geometry<2>::Source::level_set)
          {
            // Distance from the contour to first order: |phi| / |grad phi|.
            const double       delta = 1e-6;
            const Tensor<1, 2> dx({delta, 0.}), dy({0., delta});
            const double gx = (geometry.level_set(x + dx) - geometry.level_set(x - dx)) / 2 / delta,
                         gy = (geometry.level_set(x + dy) - geometry.level_set(x - dy)) / 2 / delta;
            s.off_contour =
              std::max(s.off_contour, std::abs(geometry.level_set(x)) / std::hypot(gx, gy));
          }
        const int piece = piece_of(props);
        ++s.points_of_piece[piece];
        const Tensor<1, 2> normal = na / na.norm();
        if (piece == 0)
          s.normals_follow_pieces &= normal[0] < -0.9;
        if (piece == 1)
          s.normals_follow_pieces &= normal[1] < -0.9;
        ++s.n_surface;
      }
    return s;
  }

  /** The perimeter of an ellipse: the periodic trapezoidal rule, exact to round-off here. */
  double
  ellipse_perimeter(const double a, const double b)
  {
    const unsigned int m   = 4000;
    double             sum = 0.;
    for (unsigned int k = 0; k < m; ++k)
      {
        const double t = 2. * M_PI * k / m;
        sum += std::hypot(a * std::sin(t), b * std::cos(t));
      }
    return sum * 2. * M_PI / m;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(3);

  const double a = 0.7, b = 0.4;
  const double area = M_PI * a * b, perimeter = ellipse_perimeter(a, b);
  // Largest curvature a/b^2 (at the ends of the long axis).
  const double      kappa_max = a / (b * b);
  const std::string ellipse =
    " set Level set = ((x - 1)/a)^2 + ((y - 1)/b)^2 - 1\n set Level set constants = a=0.7, b=0.4";

  std::cout << "Ellipse, semi-axes 0.7 and 0.4 at (1, 1), in [0, 2]^2; 4 x 4 points per cell, "
               "4 surface points per cell length:"
            << std::endl;
  {
    double e_a[3];
    bool   volume_ok = true, closed = true, moment_ok = true, on_contour = true, short_ok = true,
         chord_ok = true;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const unsigned int cells   = 20u << k;
        const double       h       = 2. / cells;
        const double       spacing = h / 4.;
        const auto         s       = generate(ellipse, cells, 4, 4);
        e_a[k]                     = std::abs(s.area - perimeter);
        // Sub-cell sampling: each sub-cell the contour crosses is counted whole or not at all,
        // so |sum V_0 - area| <= the area of the cut sub-cells <= perimeter x sub-cell diagonal.
        volume_ok &= std::abs(s.volume - area) <= perimeter * std::sqrt(2.) * h / 4.;
        // A_0 is the chord of the element: shorter than its arc by at most
        // (length x curvature)^2 / 24 relative.
        chord_ok &= s.area <= perimeter * (1. + 1e-12) &&
                    perimeter - s.area <= perimeter * std::pow(spacing * kappa_max, 2) / 24.;
        // The N_0 A_0 are chords rotated: their sum telescopes around the closed contour.
        closed &= s.normal_area.norm() < 1e-12 * perimeter;
        // The midpoint rule for the integral of x (x) n over an element of length l errs by
        // l^3 kappa / 12 (x) t t: in sum at most l^2 / 12 x (the total curvature 2 pi).
        Tensor<2, 2> I;
        I[0][0] = I[1][1]         = 1.;
        const double moment_error = (s.moment - area * I).norm();
        moment_ok &= moment_error <= spacing * spacing / 12. * 2. * M_PI * 1.5;
        on_contour &= s.off_contour < 1e-10 * h;
        short_ok &= s.longest <= spacing;
        std::cout << "  " << cells << " x " << cells << " cells: " << s.n_volume
                  << " volume points, " << s.n_surface << " surface points; sum V_0 error "
                  << std::scientific << std::abs(s.volume - area) / area << ", sum A_0 error "
                  << e_a[k] / perimeter << ", |sum x(x)N A - area I| " << moment_error
                  << std::defaultfloat << std::endl;
      }
    const double rate = std::log2(e_a[1] / e_a[2]);
    std::cout << "  perimeter error rate " << std::fixed << std::setprecision(1) << rate
              << std::defaultfloat << std::setprecision(3) << std::endl;
    report("sum V_0 = pi a b within perimeter x sub-cell diagonal", volume_ok);
    report("sum A_0 below the perimeter by at most (l kappa_max)^2/24", chord_ok);
    report("sum A_0 converges with rate >= 1.8", rate >= 1.8);
    report("sum N_0 A_0 = 0 to 1e-12", closed);
    report("sum x (x) N_0 A_0 = area I within 1.5 x l^2/12 x 2 pi", moment_ok);
    report("surface points on the zero contour to 1e-10 h", on_contour);
    report("no element longer than h/n_s", short_ok);
  }

  std::cout << "Rectangle [0.3, 1.4] x [0.3, 1.1] as a level set and as a box, 20 x 20 cells, 4 "
               "points per cell:"
            << std::endl;
  {
    const auto level =
      generate(" set Level set = max(abs(x - 0.85) - 0.55, abs(y - 0.7) - 0.4)", 20, 4, 4);
    const auto box = generate(" set Boxes = 0.3, 0.3 : 1.4, 1.1", 20, 4, 4);
    std::cout << "  " << level.n_volume << " and " << box.n_volume << " volume points" << std::endl;
    report("the same volume points, sum V_0 = 0.88 to 1e-12",
           level.n_volume == box.n_volume && std::abs(level.volume - 0.88) < 1e-12 &&
             std::abs(box.volume - 0.88) < 1e-12);
    report("sum A_0 = 3.8 to 1e-9", std::abs(level.area - 3.8) < 1e-9);
    report("sum N_0 A_0 = 0 to 1e-12", level.normal_area.norm() < 1e-12);
    report("left and bottom pieces get only their sides' points",
           level.normals_follow_pieces && level.points_of_piece.at(0) > 0 &&
             level.points_of_piece.at(1) > 0);
  }

  std::cout << "Quarter ellipse, semi-axes 0.7 and 0.4, straight sides at x = 0.5 and y = 0.5:"
            << std::endl;
  {
    const auto s =
      generate(" set Level set = max(((x - 0.5)/a)^2 + ((y - 0.5)/b)^2 - 1, max(0.5 - x, 0.5 - y))"
               "\n set Level set constants = a=0.7, b=0.4",
               40,
               4,
               4);
    const double quarter = area / 4., length = perimeter / 4. + a + b;
    std::cout << "  sum V_0 error " << std::scientific << std::abs(s.volume - quarter) / quarter
              << ", sum A_0 error " << std::abs(s.area - length) / length << std::defaultfloat
              << std::endl;
    report("sum V_0 = pi a b / 4 within the arc's perimeter x sub-cell diagonal",
           std::abs(s.volume - quarter) <= perimeter / 4. * std::sqrt(2.) * 0.05 / 4.);
    // Elements end at the two kinks (where the arc meets the sides), so that only the chords of
    // the arc are short of it.
    report("sum A_0 = arc + sides within the chord bound of the arc",
           s.area <= length * (1. + 1e-12) &&
             length - s.area <= perimeter / 4. * std::pow(0.0125 * kappa_max, 2) / 24.);
    // The midpoint rule on the arc as for the ellipse; exact on the straight sides.
    Tensor<2, 2> I;
    I[0][0] = I[1][1] = 1.;
    report("sum x (x) N_0 A_0 = area I within 1.5 x l^2/12 x pi/2",
           (s.moment - quarter * I).norm() <= 0.0125 * 0.0125 / 12. * M_PI / 2. * 1.5);
    report("sum N_0 A_0 = 0 to 1e-12", s.normal_area.norm() < 1e-12);
    report("left and bottom pieces get only their sides' points", s.normals_follow_pieces);
  }

  std::cout << (all_ok ? "all level-set body checks passed" : "SOME LEVEL-SET BODY CHECKS FAILED")
            << std::endl;
  return all_ok ? 0 : 1;
}

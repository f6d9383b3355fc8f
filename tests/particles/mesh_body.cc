// Material points of a body given by a Gmsh mesh ("Geometry/Mesh file"):
// - 2D, the gripper finger of prm/gripper_finger.msh (quadrilaterals with straight sides): sum V_0
//   = the mesh's area and sum x (x) N_0 A_0 = area I to round-off (Gauss points integrate the
//   bilinear Jacobians exactly), sum N_0 A_0 = 0 to round-off, the area against the finger's exact
//   shape within the area between the cap and its chords, the length of each physical group, and
//   the boundary pieces selected by group number and name, as a scene generates them; the same
//   sums for the finger in triangles (centroids of equal sub-triangles);
// - 3D, a cylinder of hexahedra written by deal.II's GridOut in Gmsh format: sum V_0 = the mesh's
//   volume, sum N_0 A_0 = 0 and sum x (x) N_0 A_0 = volume I to round-off (the bilinear faces'
//   normals are integrated exactly), and the volume that of the prism over the octagon that
//   the mesh's round surface is; the same sums on a tetrahedron.
#include <gelmpm/particles/material_point_generator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <fstream>
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

  template <int dim>
  Tensor<2, dim>
  unit_tensor()
  {
    Tensor<2, dim> I;
    for (unsigned int d = 0; d < dim; ++d)
      I[d][d] = 1.;
    return I;
  }

  template <int dim>
  double
  mesh_measure(const Geometry<dim> &geometry)
  {
    double measure = 0.;
    for (const auto &cell : geometry.mesh().active_cell_iterators())
      measure += cell->measure();
    return measure;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const std::string finger = std::string(SOURCE_DIR) + "/../../prm/gripper_finger.msh";

  std::cout << "2D: the gripper finger (prm/gripper_finger.msh), elements of at most 0.01:"
            << std::endl;
  {
    Geometry<2> geometry;
    geometry.read_mesh(finger);
    const double area   = mesh_measure(geometry);
    double       volume = 0.;
    for (const auto &e : geometry.mesh_volume_elements(3, 0.01))
      volume += e.volume;
    Tensor<1, 2>                  sum_na;
    Tensor<2, 2>                  moment;
    std::map<std::string, double> length_of_group;
    double                        longest = 0.;
    for (const auto &e : geometry.mesh_surface_elements(0.01))
      {
        sum_na += e.normal_area;
        moment += outer_product(e.centre, e.normal_area);
        length_of_group[e.group_name] += e.normal_area.norm();
        longest = std::max(longest, e.normal_area.norm());
      }
    std::cout << "  " << geometry.mesh().n_active_cells() << " cells, area " << area << "; groups:";
    for (const auto &[name, length] : length_of_group)
      std::cout << " " << name << " " << length;
    std::cout << std::endl;
    report("sum V_0 = the mesh's area to 1e-12", std::abs(volume - area) < 1e-12 * area);
    report("sum N_0 A_0 = 0 to 1e-12", sum_na.norm() < 1e-12);
    report("sum x (x) N_0 A_0 = area I to 1e-12",
           (moment - area * unit_tensor<2>()).norm() < 1e-12 * area);
    // The finger: a trapezoid (base 0.3, top 0.16, height 1) and a half disk of radius 0.08.
    // The mesh replaces the cap by chords no longer than the mesh size (0.04): each chord of
    // length l cuts off l^3 / (12 r) of the disk.
    const double r = 0.08, exact = 0.5 * (0.3 + 0.16) * 1. + 0.5 * M_PI * r * r;
    const double cut = M_PI * r * 0.04 * 0.04 / (12. * r);
    std::cout << "  exact finger area " << exact << ", mesh area below it by " << std::scientific
              << std::setprecision(2) << exact - area << std::defaultfloat << std::setprecision(4)
              << " (bound " << cut << ")" << std::endl;
    report("mesh area below the exact finger by at most the cap's chord segments",
           exact - area >= 0. && exact - area <= cut);
    const double side = std::hypot(0.07, 1.);
    report("base 0.3, inner and outer sides sqrt(0.07^2 + 1) to 1e-12",
           std::abs(length_of_group["base"] - 0.3) < 1e-12 &&
             std::abs(length_of_group["inner"] - side) < 1e-12 &&
             std::abs(length_of_group["outer"] - side) < 1e-12);
    report("tip shorter than the half circle by at most (l/r)^2/24 relative",
           length_of_group["tip"] <= M_PI * r &&
             length_of_group["tip"] >= M_PI * r * (1. - std::pow(0.04 / r, 2) / 24.));
    report("no surface element longer than 0.01", longest <= 0.01 * (1. + 1e-12));
  }

  std::cout << "2D: the same finger in triangles (tests/particles/gripper_finger_triangles.msh):"
            << std::endl;
  {
    Geometry<2> geometry;
    geometry.read_mesh(std::string(SOURCE_DIR) + "/gripper_finger_triangles.msh");
    const double area   = mesh_measure(geometry);
    double       volume = 0.;
    unsigned int n      = 0;
    for (const auto &e : geometry.mesh_volume_elements(3, 0.01))
      {
        volume += e.volume;
        ++n;
      }
    Tensor<1, 2>                  sum_na;
    Tensor<2, 2>                  moment;
    std::map<std::string, double> length_of_group;
    for (const auto &e : geometry.mesh_surface_elements(0.01))
      {
        sum_na += e.normal_area;
        moment += outer_product(e.centre, e.normal_area);
        length_of_group[e.group_name] += e.normal_area.norm();
      }
    std::cout << "  " << geometry.mesh().n_active_cells() << " triangles, area " << area << ", "
              << n << " volume points" << std::endl;
    report("sum V_0 = the mesh's area to 1e-12", std::abs(volume - area) < 1e-12 * area);
    report("sum N_0 A_0 = 0 to 1e-12", sum_na.norm() < 1e-12);
    report("sum x (x) N_0 A_0 = area I to 1e-12",
           (moment - area * unit_tensor<2>()).norm() < 1e-12 * area);
    report("base 0.3, inner and outer sides sqrt(0.07^2 + 1) to 1e-12",
           std::abs(length_of_group["base"] - 0.3) < 1e-12 &&
             std::abs(length_of_group["inner"] - std::hypot(0.07, 1.)) < 1e-12 &&
             std::abs(length_of_group["outer"] - std::hypot(0.07, 1.)) < 1e-12);
  }

  std::cout << "2D: the finger as a scene generates it, pieces 'base' (boundary id 1) and "
               "'inner' (boundary id inner):"
            << std::endl;
  {
    ParameterHandler               prm;
    const std::vector<std::string> pieces = {"base", "inner"};
    BackgroundGrid<2>::declare_parameters(prm);
    Geometry<2>::declare_parameters(prm);
    BoundaryConditions<2>::declare_parameters(prm, pieces);
    MaterialPointGenerator<2>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Background grid\n set Lower corner = -0.6, 0\n set Upper corner = 0.9, 1.6\n"
      " set Cells = 60, 64\nend\n"
      "subsection Geometry\n set Mesh file = gripper_finger.msh\nend\n"
      "subsection Material points\n set Points per cell = 3\nend\n"
      "subsection Boundary conditions\n"
      " subsection base\n  set Selector = boundary id 1\n  set Displacement = fixed\n end\n"
      " subsection inner\n  set Selector = boundary id inner\n"
      "  set Chemical potential = prescribed\n end\n"
      "end\n");
    BackgroundGrid<2>         grid;
    Geometry<2>               geometry;
    BoundaryConditions<2>     bcs;
    MaterialPointGenerator<2> generator;
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm, std::string(SOURCE_DIR) + "/../../prm");
    bcs.parse_parameters(prm, pieces);
    generator.parse_parameters(prm);
    Triangulation<2> tria;
    MappingQ1<2>     mapping;
    grid.create_triangulation(tria);
    Particles::ParticleHandler<2> particles(tria, mapping, PropertyLayout<2>::n_properties);
    generator.generate(geometry, grid, tria, bcs, 1.2801, -0.146, particles);

    using Layout                 = PropertyLayout<2>;
    double                volume = 0.;
    std::map<int, double> length_of_piece;
    unsigned int          n_volume = 0, n_surface = 0;
    bool                  in_grid = true;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        in_grid &= grid.contains(p.get_location());
        if (kind_of(props) == PointKind::volume)
          {
            volume += props[Layout::measure_0];
            ++n_volume;
          }
        else
          {
            length_of_piece[piece_of(props)] += props[Layout::measure_0];
            ++n_surface;
          }
      }
    const double area = mesh_measure(geometry);
    std::cout << "  " << n_volume << " volume points, " << n_surface << " surface points"
              << std::endl;
    report("sum V_0 = the mesh's area to 1e-12", std::abs(volume - area) < 1e-12 * area);
    report("piece 'base' (boundary id 1) has the base, length 0.3",
           std::abs(length_of_piece[0] - 0.3) < 1e-12);
    report("piece 'inner' (boundary id inner) has the inner side",
           std::abs(length_of_piece[1] - std::hypot(0.07, 1.)) < 1e-12);
    report("every point in the grid", in_grid);
  }

  std::cout << "3D: a cylinder of radius 0.3 and length 1 (hexahedra, written by GridOut as .msh):"
            << std::endl;
  {
    Triangulation<3> cylinder;
    GridGenerator::cylinder(cylinder, 0.3, 0.5);
    cylinder.refine_global(1);
    {
      std::ofstream out("cylinder.msh");
      out << std::setprecision(17);
      GridOut().write_msh(cylinder, out);
    }
    Geometry<3> geometry;
    geometry.read_mesh("cylinder.msh");
    const double volume_mesh = mesh_measure(geometry);
    double       volume      = 0.;
    for (const auto &e : geometry.mesh_volume_elements(2, 0.05))
      volume += e.volume;
    Tensor<1, 3> sum_na;
    Tensor<2, 3> moment;
    double       area = 0.;
    for (const auto &e : geometry.mesh_surface_elements(0.05))
      {
        sum_na += e.normal_area;
        moment += outer_product(e.centre, e.normal_area);
        area += e.normal_area.norm();
      }
    const double exact = M_PI * 0.3 * 0.3 * 1.;
    std::cout << "  " << geometry.mesh().n_active_cells() << " cells, volume " << volume_mesh
              << " (exact cylinder " << exact << "), surface " << area << std::endl;
    report("sum V_0 = the mesh's volume to 1e-12", std::abs(volume - volume_mesh) < 1e-12);
    report("sum N_0 A_0 = 0 to 1e-12", sum_na.norm() < 1e-12);
    report("sum x (x) N_0 A_0 = volume I to 1e-12",
           (moment - volume * unit_tensor<3>()).norm() < 1e-12);
    // The written mesh has straight edges: its round surface is a prism over the octagon of the
    // 8 boundary vertices of the refined cross-section, whose volume it has exactly.
    const double octagon = 0.5 * 8 * std::sin(2. * M_PI / 8) * 0.3 * 0.3 * 1.;
    std::cout << "  prism over the inscribed octagon: volume " << octagon << std::endl;
    report("sum V_0 = the volume of the prism over the inscribed octagon to 1e-12",
           std::abs(volume - octagon) < 1e-12);
  }

  std::cout << "3D: the tetrahedron with corners 0, e_x, e_y, e_z (one tetrahedron, written here):"
            << std::endl;
  {
    {
      std::ofstream out("tetrahedron.msh");
      out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
             "4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n";
    }
    Geometry<3> geometry;
    geometry.read_mesh("tetrahedron.msh");
    double       volume = 0.;
    unsigned int n      = 0;
    for (const auto &e : geometry.mesh_volume_elements(3, 0.2))
      {
        volume += e.volume;
        ++n;
      }
    Tensor<1, 3> sum_na;
    Tensor<2, 3> moment;
    double       area = 0.;
    for (const auto &e : geometry.mesh_surface_elements(0.2))
      {
        sum_na += e.normal_area;
        moment += outer_product(e.centre, e.normal_area);
        area += e.normal_area.norm();
      }
    std::cout << "  " << n << " volume points, surface " << area << std::endl;
    report("sum V_0 = 1/6 to 1e-12", std::abs(volume - 1. / 6.) < 1e-12);
    report("sum A_0 = 3/2 + sqrt(3)/2 to 1e-12", std::abs(area - 1.5 - std::sqrt(3.) / 2.) < 1e-12);
    report("sum N_0 A_0 = 0 to 1e-12", sum_na.norm() < 1e-12);
    report("sum x (x) N_0 A_0 = volume I to 1e-12",
           (moment - (1. / 6.) * unit_tensor<3>()).norm() < 1e-12);
  }

  std::cout << (all_ok ? "all mesh body checks passed" : "SOME MESH BODY CHECKS FAILED")
            << std::endl;
  return all_ok ? 0 : 1;
}

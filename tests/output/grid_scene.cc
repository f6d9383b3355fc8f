// Output/Write grid in a whole run: the §4.1 scene (a 0.2 x 1 block in the corner of a 0.5 x 4
// grid of 20 x 160 cells, Q2-Q2SD, 6 x 6 points per cell) runs one step with the grid written at
// t = 0 and after the step; both .vtu files are read back with VTK. Checked: 3,200 cells; the
// block covers 8 x 40 displacement cells and touches the grid's left and bottom edges, so that
// in closed form its interior cells number 7 x 39 and its boundary cells 8 + 40 - 1 (the mu block
// of 4 x 20 cells: 3 x 19 and 4 + 20 - 1, each covering 4 displacement cells); 36 volume points
// in each cell with material; at t = 0 du = 0 and mu/(k_BT) = mu_0 of the material at every
// vertex of a cell with material, NaN elsewhere; after the step, whose cells were classified
// from the initial positions, the same classification, finite fields on cells with material,
// and the top moving up; grid.pvd lists both times.
#include <gelmpm/core/parameters.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/simulator.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include "../vtu_reader.h"

using namespace GelMPM;

namespace
{
  const char *scene = R"(
set Dimension = 2
subsection Output
  set Directory  = grid_run
  set Write grid = true
  set Test mode  = true
end
subsection Background grid
  set Lower corner = 0, 0
  set Upper corner = 0.5, 4
  set Cells        = 20, 160
end
subsection Geometry
  set Boxes = 0, 0 : 0.2, 1
end
subsection Material points
  set Points per cell = 6
end
subsection Boundary conditions
  set Pieces = top, bottom, sides
  subsection top
    set Selector           = ny > 0.5
    set Displacement       = tangential
    set Chemical potential = prescribed
  end
  subsection bottom
    set Selector     = ny < -0.5
    set Displacement = fixed
  end
  subsection sides
    set Selector     = abs(nx) > 0.5
    set Displacement = normal
  end
end
subsection Time stepping
  set Initial step = 1e-4
  set End time     = 1e-4
end
)";

  /** What one grid file holds, cell by cell. */
  struct GridSummary
  {
    unsigned int                n_cells = 0;
    std::array<unsigned int, 3> u_kinds{}, mu_kinds{};
    unsigned int                material_cells_with_36_points = 0;
    unsigned int                n_volume_points               = 0;
    bool                        nan_without_material          = true;
    bool                        finite_with_material          = true;
    double                      mu_min = std::numeric_limits<double>::max(), mu_max = -mu_min;
    double                      du_norm_max = 0., du_y_max = -1.;
  };

  GridSummary
  read(const std::string &file_name)
  {
    const auto  file = GelMPMTests::read_vtu(file_name);
    GridSummary s;
    s.n_cells = file.cells.size();
    for (const char *name :
         {"u_cell_kind", "mu_cell_kind", "n_volume_points", "displacement_increment", "mu_over_kT"})
      if (file.array(name) == nullptr)
        {
          std::cout << "field " << name << " missing  FAIL" << std::endl;
          s.n_cells = 0;
          return s;
        }
    // Cell fields are point data constant on each cell's own points (DataOut).
    const auto &du = file.field("displacement_increment");
    for (const auto &cell : file.cells)
      {
        const std::size_t first    = cell[0];
        const long        u_kind   = std::lround(file.field("u_cell_kind")(first));
        const long        n_points = std::lround(file.field("n_volume_points")(first));
        ++s.u_kinds[u_kind];
        ++s.mu_kinds[std::lround(file.field("mu_cell_kind")(first))];
        s.n_volume_points += n_points;
        s.material_cells_with_36_points += (u_kind < 2 && n_points == 36);
        for (const std::size_t id : cell)
          {
            const double mu = file.field("mu_over_kT")(id);
            const double dx = du(id, 0);
            const double dy = du(id, 1);
            if (u_kind == 2)
              s.nan_without_material &= std::isnan(mu) && std::isnan(dx) && std::isnan(dy);
            else
              {
                s.finite_with_material &=
                  std::isfinite(mu) && std::isfinite(dx) && std::isfinite(dy);
                s.mu_min      = std::min(s.mu_min, mu);
                s.mu_max      = std::max(s.mu_max, mu);
                s.du_norm_max = std::max(s.du_norm_max, std::hypot(dx, dy));
                s.du_y_max    = std::max(s.du_y_max, dy);
              }
          }
      }
    return s;
  }

  /** Print and check what both outputs share: cell count and classification. */
  bool
  check_classification(const GridSummary &s)
  {
    const unsigned int                m = 8, n = 40; // displacement cells of the block
    const std::array<unsigned int, 3> u_expected = {
      {(m - 1) * (n - 1), m + n - 1, 20 * 160 - m * n}};
    const std::array<unsigned int, 3> mu_expected = {
      {4 * (m / 2 - 1) * (n / 2 - 1), 4 * (m / 2 + n / 2 - 1), 20 * 160 - m * n}};
    const bool ok = s.n_cells == 3200 && s.u_kinds == u_expected && s.mu_kinds == mu_expected &&
                    s.material_cells_with_36_points == m * n && s.n_volume_points == 11520;
    std::cout << "  cells " << s.n_cells << "; u interior/boundary/outer " << s.u_kinds[0] << "/"
              << s.u_kinds[1] << "/" << s.u_kinds[2] << "; mu kind on u cells " << s.mu_kinds[0]
              << "/" << s.mu_kinds[1] << "/" << s.mu_kinds[2] << "; volume points "
              << s.n_volume_points << ", 36 in each of " << s.material_cells_with_36_points
              << " cells" << (ok ? " (as in closed form)" : "  FAIL") << std::endl;
    std::cout << "  NaN on cells without material: "
              << (s.nan_without_material ? "yes" : "no  FAIL")
              << "; finite on cells with material: "
              << (s.finite_with_material ? "yes" : "no  FAIL") << std::endl;
    return ok && s.nan_without_material && s.finite_with_material;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream("grid_scene.prm") << scene;

  int status;
  {
    // The run's log is not part of this test's output.
    std::ostringstream       log;
    std::streambuf          *saved     = std::cout.rdbuf(log.rdbuf());
    const auto               structure = SceneStructure::read("grid_scene.prm", {});
    dealii::ParameterHandler prm;
    Simulator<2>::declare_parameters(prm, structure);
    read_scene_file(prm, "grid_scene.prm", {});
    Simulator<2> simulator(prm, structure, "grid_scene.prm");
    status = simulator.run();
    std::cout.rdbuf(saved);
  }
  bool ok = status == 0;
  std::cout << "run finished with status " << status << std::endl;

  const FloryRehnerGel<2> gel; // the scene's material is the default (Table 1)
  const GridSummary       initial = read("grid_run/grid-00000.vtu");
  std::cout << "t = 0:" << std::endl;
  ok &= check_classification(initial);
  const bool initial_fields = initial.du_norm_max == 0. &&
                              std::abs(initial.mu_min - gel.mu_0()) < 1e-6 &&
                              std::abs(initial.mu_max - gel.mu_0()) < 1e-6;
  std::cout << "  du = 0 and mu/(k_BT) = mu_0 = " << std::setprecision(5) << gel.mu_0()
            << " on cells with material: " << (initial_fields ? "yes" : "no  FAIL") << std::endl;
  ok &= initial_fields;

  const GridSummary after = read("grid_run/grid-00001.vtu");
  std::cout << "after one step:" << std::endl;
  ok &= check_classification(after);
  const bool moved = after.du_y_max > 0.;
  std::cout << "  the top moves up (largest du_y > 0): " << (moved ? "yes" : "no  FAIL")
            << std::endl;
  ok &= moved;

  std::ifstream      pvd("grid_run/grid.pvd");
  std::ostringstream text;
  text << pvd.rdbuf();
  const bool series = text.str().find("timestep=\"0\"") != std::string::npos &&
                      text.str().find("timestep=\"0.0001\"") != std::string::npos &&
                      text.str().find("grid-00001.vtu") != std::string::npos;
  std::cout << "grid.pvd lists t = 0 and t = 1e-4 with their files: "
            << (series ? "yes" : "no  FAIL") << std::endl;
  ok &= series;
  return ok ? 0 : 1;
}

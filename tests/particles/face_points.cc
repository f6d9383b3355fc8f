// Material points on a face between two background cells survive sorting (sort_into_cells): the
// §4.3 column (x in [1, 2], y in [1, 9] on a 17.5 x 10 grid of 350 x 200 cells, so that its sides
// and ends run along grid lines) with 2 x 2 volume points per cell and 2 surface points per cell
// length. deal.II's sort_particles_into_subdomains_and_cells() alone deletes surface points that
// lie on the grid lines (round-off puts them just outside both neighbouring cells); with
// sort_into_cells() every point is kept, with its id, position and properties, in a cell whose
// closure contains it.
// The same for the §4.1 layer (0.2 x 1 in a 0.5 x 4 grid) on 40 x 320 cells with 6 x 6 points per
// cell, whose top lies on a grid line: deal.II's sort alone deletes points there (which once
// stopped that run in its first step with 'material point(s) left the background grid'), and
// sort_into_cells() keeps every point.
#include <gelmpm/particles/material_point_generator.h>
#include <gelmpm/particles/point_location.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>

using namespace dealii;
using namespace GelMPM;

namespace
{
  struct Scene
  {
    BackgroundGrid<2>             grid;
    Geometry<2>                   geometry;
    BoundaryConditions<2>         bcs;
    MaterialPointGenerator<2>     generator;
    Triangulation<2>              tria;
    MappingQ1<2>                  mapping;
    Particles::ParticleHandler<2> particles;

    explicit Scene(const std::string &scene =
                     "subsection Background grid\n"
                     " set Upper corner = 17.5, 10\n set Cells = 350, 200\nend\n"
                     "subsection Geometry\n set Boxes = 1, 1 : 2, 9\nend\n"
                     "subsection Material points\n set Points per cell = 2\nend\n")
    {
      ParameterHandler prm;
      BackgroundGrid<2>::declare_parameters(prm);
      Geometry<2>::declare_parameters(prm);
      BoundaryConditions<2>::declare_parameters(prm, {});
      MaterialPointGenerator<2>::declare_parameters(prm);
      prm.parse_input_from_string(scene);
      grid.parse_parameters(prm);
      geometry.parse_parameters(prm);
      bcs.parse_parameters(prm, {});
      generator.parse_parameters(prm);
      grid.create_triangulation(tria);
      particles.initialize(tria, mapping, PropertyLayout<2>::n_properties);
      generator.generate(geometry, grid, tria, bcs, 1.2801, -0.146, particles);
    }

    /** Position and kind of every point by id. */
    std::map<types::particle_index, std::array<double, 3>>
    snapshot() const
    {
      std::map<types::particle_index, std::array<double, 3>> points;
      for (const auto &p : particles)
        points[p.get_id()] = {
          {p.get_location()[0], p.get_location()[1], p.get_properties()[PropertyLayout<2>::kind]}};
      return points;
    }
  };
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;

  {
    Scene              plain;
    const unsigned int before = plain.particles.n_global_particles();
    plain.particles.sort_particles_into_subdomains_and_cells();
    const unsigned int lost = before - plain.particles.n_global_particles();
    std::cout << "points generated: " << before << "; deal.II's sort alone deletes " << lost
              << (lost > 0 ? " (points on grid lines)" : "") << std::endl;
  }

  Scene              scene;
  const auto         before   = scene.snapshot();
  const unsigned int put_back = sort_into_cells(scene.particles, scene.grid, scene.tria);
  const auto         after    = scene.snapshot();
  const bool kept = after == before && scene.particles.n_global_particles() == before.size();
  std::cout << "sort_into_cells puts back " << put_back
            << " points; every point kept with its id, position and kind: "
            << (kept ? "yes" : "no  FAIL") << std::endl;
  ok &= kept && put_back > 0;

  bool in_cell = true;
  for (auto particle = scene.particles.begin(); particle != scene.particles.end(); ++particle)
    in_cell &=
      particle->get_surrounding_cell()->point_inside(particle->get_location()) ||
      particle->get_surrounding_cell()->bounding_box().point_inside(particle->get_location(),
                                                                    1e-12);
  std::cout << "every point lies in the closure of its cell: " << (in_cell ? "yes" : "no  FAIL")
            << std::endl;
  ok &= in_cell;

  // A second sort (the next step) keeps them too.
  sort_into_cells(scene.particles, scene.grid, scene.tria);
  const bool again = scene.snapshot() == before;
  std::cout << "a second sort keeps every point: " << (again ? "yes" : "no  FAIL") << std::endl;
  ok &= again;

  // The §4.1 layer on 40 x 320 cells (prm/constrained_swelling.prm with 'Background grid/Cells =
  // 40, 320').
  {
    const std::string  layer = "subsection Background grid\n"
                               " set Upper corner = 0.5, 4\n set Cells = 40, 320\nend\n"
                               "subsection Geometry\n set Boxes = 0, 0 : 0.2, 1\nend\n"
                               "subsection Material points\n set Points per cell = 6\nend\n";
    Scene              plain(layer);
    const unsigned int n = plain.particles.n_global_particles();
    plain.particles.sort_particles_into_subdomains_and_cells();
    const unsigned int lost = n - plain.particles.n_global_particles();
    std::cout << "§4.1 layer on 40 x 320: points generated: " << n
              << "; deal.II's sort alone deletes " << lost
              << (lost > 0 ? " (points on grid lines)" : "") << std::endl;
    Scene      kept(layer);
    const auto points = kept.snapshot();
    sort_into_cells(kept.particles, kept.grid, kept.tria);
    sort_into_cells(kept.particles, kept.grid, kept.tria);
    const bool same = kept.snapshot() == points && kept.particles.n_global_particles() == n;
    std::cout << "§4.1 layer on 40 x 320: two sorts by sort_into_cells keep every point: "
              << (same ? "yes" : "no  FAIL") << std::endl;
    ok &= same;
  }
  return ok ? 0 : 1;
}

// ParticleOutput writes what ParaView reads: the .vtu files are read back with VTK's XML reader
// (through Python, tests/vtu_reader.h) and the point count, the point positions and the field
// values (kind, mu_over_kT, J, phi, the displacement vector, the Cauchy stress of a stress-free
// point) compared with what was written (1e-12); the .pvd series lists the output times.
#include <gelmpm/io/particle_output.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "../vtu_reader.h"

using namespace dealii;
using namespace GelMPM;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Triangulation<2>                 tria;
  GridGenerator::subdivided_hyper_rectangle(tria, {4, 4}, Point<2>(0, 0), Point<2>(1, 1));
  MappingQ1<2>                  mapping;
  Particles::ParticleHandler<2> particles(tria, mapping, PropertyLayout<2>::n_properties);

  const FloryRehnerGel<2> gel;
  using Layout = PropertyLayout<2>;
  std::vector<double> props(Layout::n_properties, 0.);
  const unsigned int  n = 7;
  for (unsigned int i = 0; i < n; ++i)
    {
      const Point<2> x(0.1 + 0.1 * i, 0.2 + 0.05 * i);
      props[Layout::kind] = (i % 2) ? 2 : 0;
      props[Layout::mu]   = gel.mu_0();
      props[Layout::F] = props[Layout::F + 3] = gel.lambda_0() * (1. + 0.01 * i);
      // Plane strain: the out-of-plane stretch stays lambda_0.
      props[Layout::out_of_plane]   = gel.lambda_0();
      props[Layout::position_0]     = x[0] - 0.01 * i;
      props[Layout::position_0 + 1] = x[1];
      const auto cell               = GridTools::find_active_cell_around_point(tria, x);
      particles.insert_particle(x,
                                mapping.transform_real_to_unit_cell(cell, x),
                                i,
                                cell,
                                make_array_view(props));
    }
  particles.update_cached_numbers();

  std::filesystem::create_directories("vtu");
  const MaterialRegions<2> one_gel(gel);
  ParticleOutput<2>        output("vtu", one_gel);
  output.write(particles, 0.);
  output.write(particles, 0.25);

  const auto file = GelMPMTests::read_vtu("vtu/particles-00001.vtu");
  bool       ok   = file.points.size() == n;
  std::cout << "points read back: " << file.points.size() << std::endl;

  double error = 0.;
  for (const char *name : {"kind", "mu_over_kT", "J", "phi", "displacement", "cauchy_stress"})
    {
      const bool present = file.array(name) != nullptr;
      ok &= present;
      std::cout << "field " << name << " present: " << (present ? "yes" : "no  FAIL") << std::endl;
    }
  if (ok)
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto &x = file.points[i];
        // Points are written in the order the handler iterates them; match them by position.
        const unsigned int k       = std::lround((x[0] - 0.1) / 0.1);
        const double       stretch = gel.lambda_0() * (1. + 0.01 * k);
        const double       J       = gel.lambda_0() * stretch * stretch;
        error                      = std::max({error,
                                               std::abs(x[1] - (0.2 + 0.05 * k)),
                                               std::abs(file.field("kind")(i) - ((k % 2) ? 2 : 0)),
                                               std::abs(file.field("mu_over_kT")(i) - gel.mu_0()),
                                               std::abs(file.field("J")(i) - J),
                                               std::abs(file.field("phi")(i) - (1. - 1. / J)),
                                               std::abs(file.field("displacement")(i, 0) - 0.01 * k)});
        if (k == 0) // stress-free initial state
          for (unsigned int c = 0; c < 9; ++c)
            error = std::max(error, std::abs(file.field("cauchy_stress")(i, c)));
      }
  const bool values_ok = error < 1e-6; // the .vtu stores single precision by default
  ok &= values_ok;
  std::cout << "values equal to what was written (single precision): "
            << (values_ok ? "yes" : "no  FAIL") << std::endl;

  std::ifstream      pvd("vtu/particles.pvd");
  std::ostringstream text;
  text << pvd.rdbuf();
  const bool series = text.str().find("timestep=\"0.25\"") != std::string::npos &&
                      text.str().find("particles-00001.vtu") != std::string::npos;
  ok &= series;
  std::cout << "pvd lists time 0.25 with its file: " << (series ? "yes" : "no  FAIL") << std::endl;
  return ok ? 0 : 1;
}

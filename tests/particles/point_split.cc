// Splitting material points where the grid is refined during a run (split_points_to_leaves(),
// 'Background grid/Refinement band'):
// - points generated on the uniform grid and split after the grid is refined (levels 1 and 2,
//   in one go or level by level; 2D and 3D) are the points the generator makes on the refined
//   grid: the same count, positions within 1e-12, V_0, A_0 and N_0 A_0 within 1e-14 relative;
// - after an affine deformation (x = c + G (X - c), F = lambda_0 G) in an axisymmetric scene the
//   children lie at c + G (X_c - c) within 1e-12 and the sums of V_0, V_n, N_0 A_0 and N_n A_n
//   over the body are the parent's within 1e-13 relative; the hoop stretch is lambda_0 r / R;
// - a point of a mesh element (spacing -1) stays whole;
// - coarsened again, the split volume points merge back into the points they came from: every
//   property and position within 1e-12, the sums of V_0 and V_n within 1e-13 relative.
#include <gelmpm/particles/material_point_generator.h>
#include <gelmpm/particles/point_refinement.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace dealii;
using namespace GelMPM;

namespace
{
  bool all_ok = true;

  void
  report(const std::string &what, const bool ok)
  {
    all_ok &= ok;
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
  }

  template <int dim>
  struct Record
  {
    Point<dim>          x;
    std::vector<double> properties;
  };

  template <int dim>
  std::vector<Record<dim>>
  records(const Particles::ParticleHandler<dim> &particles)
  {
    std::vector<Record<dim>> result;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        result.push_back({p.get_location(), std::vector<double>(props.begin(), props.end())});
      }
    std::sort(result.begin(), result.end(), [](const auto &a, const auto &b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(a.x[d] - b.x[d]) > 1e-9)
          return a.x[d] < b.x[d];
      return a.properties[0] < b.properties[0];
    });
    return result;
  }

  template <int dim>
  std::string
  scene(const std::string &boxes, const std::string &grid_extra)
  {
    const std::string upper = dim == 2 ? "2, 2" : "2, 2, 2";
    const std::string cells = dim == 2 ? "8, 8" : "4, 4, 4";
    const std::string body  = dim == 2 ? "0.5, 0.5 : 1.5, 1.25" : "0.5, 0.5, 0.5 : 1.5, 1.5, 1.5";
    return "subsection Background grid\n set Upper corner = " + upper + "\n set Cells = " + cells +
           "\n set Refinement boxes = " + boxes + "\n" + grid_extra +
           "end\n"
           "subsection Geometry\n set Boxes = " +
           body +
           "\nend\n"
           "subsection Material points\n set Points per cell = 3\nend\n";
  }

  /** The points the generator makes on the grid of @p text. */
  template <int dim>
  struct Generated
  {
    FloryRehnerGel<dim>             material;
    BackgroundGrid<dim>             grid;
    MaterialRegions<dim>            regions;
    Triangulation<dim>              tria;
    MappingQ1<dim>                  mapping;
    Particles::ParticleHandler<dim> particles;
    MaterialPointGenerator<dim>     generator;

    explicit Generated(const std::string &text)
    {
      ParameterHandler               prm;
      const std::vector<std::string> pieces = {};
      FloryRehnerGel<dim>::declare_parameters(prm);
      MaterialRegions<dim>::declare_parameters(prm, {});
      BackgroundGrid<dim>::declare_parameters(prm);
      Geometry<dim>::declare_parameters(prm);
      BoundaryConditions<dim>::declare_parameters(prm, pieces);
      MaterialPointGenerator<dim>::declare_parameters(prm);
      prm.parse_input_from_string(text);
      material.parse_parameters(prm);
      regions.parse_parameters(prm, {}, material);
      grid.parse_parameters(prm);
      Geometry<dim> geometry;
      geometry.parse_parameters(prm);
      BoundaryConditions<dim> bcs;
      bcs.parse_parameters(prm, pieces);
      generator.parse_parameters(prm);
      grid.create_triangulation(tria);
      particles.initialize(tria, mapping, PropertyLayout<dim>::n_properties);
      generator.generate(geometry, grid, tria, bcs, regions, particles);
    }

    unsigned long
    split_like(const BackgroundGrid<dim> &refined)
    {
      grid.refinement_boxes  = refined.refinement_boxes;
      grid.refinement_levels = refined.refinement_levels;
      return split_points_to_leaves(particles, grid, regions, generator.points_per_cell, tria);
    }
  };

  template <int dim>
  void
  compare(const std::vector<Record<dim>> &split, const std::vector<Record<dim>> &generated)
  {
    using Layout    = PropertyLayout<dim>;
    bool   same     = split.size() == generated.size();
    double position = 0., measure = 0., normal = 0.;
    for (unsigned int i = 0; same && i < split.size(); ++i)
      {
        const auto &a = split[i].properties, &b = generated[i].properties;
        position = std::max(position, split[i].x.distance(generated[i].x));
        for (unsigned int d = 0; d < dim; ++d)
          {
            position =
              std::max(position, std::abs(a[Layout::position_0 + d] - b[Layout::position_0 + d]));
            normal =
              std::max(normal,
                       std::abs(a[Layout::normal_area_0 + d] - b[Layout::normal_area_0 + d]) /
                         std::max(1e-300, std::abs(b[Layout::measure_0])));
          }
        measure = std::max(measure, std::abs(a[Layout::measure_0] / b[Layout::measure_0] - 1.));
        same &= a[Layout::kind] == b[Layout::kind] &&
                a[Layout::spacing_level] == b[Layout::spacing_level];
      }
    report("the same " + std::to_string(generated.size()) + " points, kinds and spacing levels",
           same);
    report("positions X_0 and x within 1e-12", same && position < 1e-12);
    report("V_0 and A_0 within 1e-14 relative", same && measure < 1e-14);
    report("N_0 A_0 within 1e-14 relative", same && normal < 1e-14);
  }

  template <int dim>
  void
  split_against_generated(const std::string &boxes, const unsigned int levels, const bool stepwise)
  {
    const std::string extra = " set Refinement levels = " + std::to_string(levels) + "\n";
    Generated<dim>    refined(scene<dim>(boxes, extra));
    Generated<dim>    uniform(scene<dim>("", ""));
    if (stepwise)
      for (unsigned int l = 1; l < levels; ++l)
        {
          Generated<dim> partly(
            scene<dim>(boxes, " set Refinement levels = " + std::to_string(l) + "\n"));
          uniform.split_like(partly.grid);
        }
    const unsigned long added = uniform.split_like(refined.grid);
    std::cout << "  " << added << " points added" << std::endl;
    compare(records(uniform.particles), records(refined.particles));
  }

  /**
   * The axisymmetric scene's points deformed by x = G X (F = lambda_0 G, the hoop stretch
   * lambda_0 r / R = 1.3 lambda_0), then split by a box refined once.
   */
  void
  split_deformed_axisymmetric()
  {
    using Layout            = PropertyLayout<2>;
    const std::string extra = " set Coordinate system = axisymmetric\n";
    Generated<2>      uniform(scene<2>("", extra));
    Generated<2>      refined(scene<2>("0, 1 : 2, 2", extra));
    Tensor<2, 2>      G;
    G[0][0] = 1.3, G[1][0] = 0.2, G[1][1] = 0.9;
    const double        lambda_0            = uniform.regions[0].lambda_0();
    const double        J                   = 1.3 * determinant(G);
    const auto          G_inverse_transpose = transpose(invert(G));
    std::vector<double> before(4, 0.), after(4, 0.);
    const auto sums = [](const Particles::ParticleHandler<2> &particles, std::vector<double> &s) {
      for (const auto &p : particles)
        {
          const auto props  = p.get_properties();
          const bool volume = kind_of(props) == PointKind::volume;
          s[volume ? 0 : 2] += props[Layout::measure_0];
          s[volume ? 1 : 3] += props[Layout::measure_n];
        }
    };
    Tensor<1, 2> normal_before, normal_n_before;
    bool         first = true;
    for (auto p = uniform.particles.begin(); p != uniform.particles.end(); ++p)
      {
        auto     props = p->get_properties();
        Point<2> X;
        for (unsigned int d = 0; d < 2; ++d)
          X[d] = props[Layout::position_0 + d];
        const Point<2> x(G * X);
        p->set_location(x);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            props[Layout::F + 2 * i + j] = lambda_0 * G[i][j];
        props[Layout::out_of_plane] = lambda_0 * x[0] / X[0];
        props[Layout::measure_n]    = J * props[Layout::measure_0];
        Tensor<1, 2> na0;
        for (unsigned int d = 0; d < 2; ++d)
          na0[d] = props[Layout::normal_area_0 + d];
        const Tensor<1, 2> nan = J * (G_inverse_transpose * na0);
        for (unsigned int d = 0; d < 2; ++d)
          props[Layout::normal_area_n + d] = nan[d];
        normal_before += na0;
        normal_n_before += nan;
        // A mesh element's point: never split.
        if (first && kind_of(props) == PointKind::volume && X[1] > 1.1)
          props[Layout::spacing_level] = -1, first = false;
      }
    sums(uniform.particles, before);
    std::vector<Record<2>> volume_before;
    for (const auto &r : records(uniform.particles))
      if (kind_of(r.properties) == PointKind::volume)
        volume_before.push_back(r);
    // The deformed body reaches y = 0.2 * 1.5 + 0.9 * 1.25 = 1.425: the box over y >= 1 holds
    // its top in the current configuration.
    uniform.split_like(refined.grid);
    sums(uniform.particles, after);
    double       position = 0., hoop = 0., consistency = 0.;
    unsigned int unsplit = 0;
    Tensor<1, 2> normal_after, normal_n_after;
    for (const auto &p : uniform.particles)
      {
        const auto props = p.get_properties();
        Point<2>   X;
        for (unsigned int d = 0; d < 2; ++d)
          {
            X[d] = props[Layout::position_0 + d];
            normal_after[d] += props[Layout::normal_area_0 + d];
            normal_n_after[d] += props[Layout::normal_area_n + d];
          }
        const Point<2> x = p.get_location();
        position         = std::max(position, x.distance(Point<2>(G * X)));
        hoop = std::max(hoop, std::abs(props[Layout::out_of_plane] - lambda_0 * x[0] / X[0]));
        consistency =
          std::max(consistency, std::abs(props[Layout::measure_n] / props[Layout::measure_0] - J));
        unsplit += props[Layout::spacing_level] < 0;
      }
    report("children at x = G X_c within 1e-12", position < 1e-12);
    report("hoop stretch lambda_0 r / R within 1e-13", hoop < 1e-13);
    report("V_n / V_0 and A_n / A_0 of every point J within 1e-13", consistency < 1e-13);
    const char *names[4] = {"V_0", "V_n", "A_0", "A_n"};
    for (unsigned int k = 0; k < 4; ++k)
      report(std::string("sum ") + names[k] + " kept within 1e-13 relative",
             std::abs(after[k] / before[k] - 1.) < 1e-13);
    report("sum N_0 A_0 and N_n A_n kept within 1e-13 of A_0",
           (normal_after - normal_before).norm() < 1e-13 * before[2] &&
             (normal_n_after - normal_n_before).norm() < 1e-13 * before[2]);
    report("the point of spacing -1 kept whole", unsplit == 1);
    report("points were split",
           uniform.particles.n_global_particles() > refined.particles.n_global_particles() / 2);

    // Coarsened again: the children merge back into the points they came from.
    uniform.grid.refinement_boxes.clear();
    uniform.grid.refinement_levels = 0;
    const unsigned long removed    = merge_points_to_leaves(uniform.particles,
                                                         uniform.grid,
                                                         uniform.regions,
                                                         uniform.generator.points_per_cell,
                                                         uniform.tria);
    std::cout << "  " << removed << " points removed by merging" << std::endl;
    std::vector<Record<2>> volume_after;
    for (const auto &r : records(uniform.particles))
      if (kind_of(r.properties) == PointKind::volume)
        volume_after.push_back(r);
    bool   same_count = volume_after.size() == volume_before.size();
    double largest    = 0.;
    for (unsigned int i = 0; same_count && i < volume_after.size(); ++i)
      {
        largest = std::max(largest, volume_after[i].x.distance(volume_before[i].x));
        for (unsigned int k = 0; k < Layout::n_properties; ++k)
          largest =
            std::max(largest,
                     std::abs(volume_after[i].properties[k] - volume_before[i].properties[k]) /
                       std::max(1., std::abs(volume_before[i].properties[k])));
      }
    report("merged back: the volume points before the split, their number", same_count);
    report("merged back: positions and every property within 1e-12 (relative above 1)",
           same_count && largest < 1e-12);
    std::vector<double> merged(4, 0.);
    sums(uniform.particles, merged);
    report("merged back: sum V_0 and V_n kept within 1e-13 relative",
           std::abs(merged[0] / before[0] - 1.) < 1e-13 &&
             std::abs(merged[1] / before[1] - 1.) < 1e-13);
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::cout << "2D, a box refined once over the body's top:" << std::endl;
  split_against_generated<2>("0, 1 : 2, 2", 1, false);
  std::cout << "2D, refined twice, in one go:" << std::endl;
  split_against_generated<2>("0.75, 1 : 2, 2", 2, false);
  std::cout << "2D, refined twice, level by level:" << std::endl;
  split_against_generated<2>("0.75, 1 : 2, 2", 2, true);
  std::cout << "3D, a box refined once over a corner of the body:" << std::endl;
  split_against_generated<3>("1, 1, 1 : 2, 2, 2", 1, false);
  std::cout << "Axisymmetric, deformed by x = G X, refined once over its top:" << std::endl;
  split_deformed_axisymmetric();
  return all_ok ? 0 : 1;
}

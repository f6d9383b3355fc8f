#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/fem/fem_bilayer.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  std::vector<FloryRehnerGel<2>>
  FemBilayer::layer_materials(const double chi_passive)
  {
    const FloryRehnerGel<2> table_1;
    const double            lambda_0 =
      FloryRehnerGel<2>::lambda_0_from_mu_0(table_1.mu_0(), chi_passive, table_1.N_nu());
    return {table_1,
            FloryRehnerGel<2>(table_1.shear_modulus(),
                              chi_passive,
                              table_1.N_nu(),
                              table_1.diffusivity(),
                              lambda_0)};
  }


  FemBilayer::FemBilayer(const Parameters &parameters)
    : FemBilayer(parameters, layer_materials(parameters.chi_passive))
  {}


  FemBilayer::FemBilayer(const Parameters                     &parameters,
                         const std::vector<FloryRehnerGel<2>> &materials)
    : parameters(parameters)
    , materials_(materials)
  {
    if (materials_.size() != 2)
      throw std::invalid_argument("a bilayer needs the gels of two layers, not " +
                                  std::to_string(materials_.size()));
    if (!(parameters.length > 0.) || !(parameters.thickness > 0.))
      throw std::invalid_argument("the strip's length and thickness must be positive");
    require(parameters.cells >= 2 && parameters.cells % 2 == 0,
            "FE peer/Cells",
            "is " + std::to_string(parameters.cells) +
              ", but the cells through the thickness must be even: the interface of the layers "
              "is a mesh line",
            "give an even number, e.g. 8");
    const double along = parameters.cells * parameters.length / 2. / parameters.thickness;
    if (std::abs(along - std::round(along)) > 1e-9)
      throw std::invalid_argument("square cells need cells x length / (2 thickness) to be a whole "
                                  "number of cells along the half strip");
    require(parameters.ramp_time > 0.,
            "FE peer/Ramp time",
            "is " + entry_value(parameters.ramp_time) +
              ", but the bath's ramp needs a positive time",
            "give the scene's ramp time, e.g. 1 (tau_d)");

    dealii::GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {static_cast<unsigned int>(std::round(along)), parameters.cells},
      dealii::Point<2>(0., 0.),
      dealii::Point<2>(parameters.length / 2., parameters.thickness),
      true);
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(cell->center()[1] < parameters.thickness / 2. ? passive : active);

    system_ = std::make_unique<FemMixedSystem<2>>(
      materials_,
      triangulation,
      parameters.u_degree,
      FemMixedSystem<2>::Formulation::previously_converged_lagrangian);
    system_->constrain_displacement(symmetry, {0});
    system_->constrain_displacement_at_vertex(dealii::Point<2>(0., 0.), {1});
    for (const auto id : {end, bottom, top})
      system_->prescribe_chemical_potential(id, bath_chemical_potential(0.));
    system_->setup();
  }


  double
  FemBilayer::bath_chemical_potential(const double t) const
  {
    const double s = t / parameters.ramp_time;
    return parameters.mu_bath * std::min(s, 1.) + parameters.mu_start * std::max(1. - s, 0.);
  }


  FemRunResult
  FemBilayer::run(const TimeStepping                      &time_stepping,
                  const NewtonSettings                    &newton,
                  const LinearSolver                      &linear_solver,
                  const std::function<void(const Step &)> &on_step)
  {
    const double volume = system_->volume();
    return run_fem_time_loop<2>(
      *system_,
      materials_.front(),
      time_stepping,
      newton,
      linear_solver,
      [&](const double, const double t_end) {
        for (const auto id : {end, bottom, top})
          system_->set_chemical_potential(id, bath_chemical_potential(t_end));
      },
      [&](const FemStep &step) {
        if (!on_step)
          return;
        Step record;
        static_cast<FemStep &>(record) = step;
        const auto surface             = lower_surface();
        record.curvature               = fitted_curvature(surface);
        // The last point is the lower corner of the free end.
        record.tip_deflection = surface.back()[1];
        record.relative_volume_change =
          system_->deformation_summary().deformed_volume / volume - 1.;
        on_step(record);
      });
  }


  std::vector<dealii::Point<2>>
  FemBilayer::lower_surface() const
  {
    auto samples = system_->boundary_samples(bottom, 8);
    std::sort(samples.begin(), samples.end(), [](const auto &a, const auto &b) {
      return a.X[0] < b.X[0];
    });
    // Face ends appear once per face: keep one.
    const double tolerance = relative_position_tolerance * parameters.length;
    samples.erase(std::unique(samples.begin(),
                              samples.end(),
                              [&](const auto &a, const auto &b) {
                                return std::abs(a.X[0] - b.X[0]) < tolerance;
                              }),
                  samples.end());
    std::vector<dealii::Point<2>> points;
    for (const auto &sample : samples)
      points.emplace_back(sample.X + sample.u);
    return points;
  }


  double
  FemBilayer::fitted_curvature(const std::vector<dealii::Point<2>> &points)
  {
    // Kasa: x^2 + y^2 = 2 a x + 2 b y + c in the least-squares sense, R^2 = c + a^2 + b^2
    // (the fit of contrib/benchmarks/bilayer.py). Normal equations, 3 x 3, about the centroid,
    // which leaves R unchanged and keeps them well conditioned.
    if (points.size() < 3)
      throw std::invalid_argument("a circle needs at least three points");
    dealii::Point<2> centroid;
    for (const auto &p : points)
      centroid += p / static_cast<double>(points.size());
    dealii::FullMatrix<double> normal(3, 3);
    dealii::Vector<double>     rhs(3), c(3);
    for (const auto &point : points)
      {
        const dealii::Point<2> p(point - centroid);
        const double           row[3] = {2. * p[0], 2. * p[1], 1.};
        const double           r2     = p.square();
        for (unsigned int i = 0; i < 3; ++i)
          {
            rhs(i) += row[i] * r2;
            for (unsigned int j = 0; j < 3; ++j)
              normal(i, j) += row[i] * row[j];
          }
      }
    normal.gauss_jordan();
    normal.vmult(c, rhs);
    return 1. / std::sqrt(c(2) + c(0) * c(0) + c(1) * c(1));
  }


  const FemMixedSystem<2> &
  FemBilayer::system() const
  {
    return *system_;
  }


  const std::vector<FloryRehnerGel<2>> &
  FemBilayer::materials() const
  {
    return materials_;
  }
} // namespace GelMPM

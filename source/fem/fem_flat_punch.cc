#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/fem/fem_flat_punch.h>

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace GelMPM
{
  FloryRehnerGel<2>
  FemFlatPunch::scene_material()
  {
    constexpr double chi = 0.1, N_nu = 7.299e-3;
    return FloryRehnerGel<2>(1.,
                             chi,
                             N_nu,
                             1.,
                             FloryRehnerGel<2>::lambda_0_from_mu_0(0., chi, N_nu));
  }


  FemFlatPunch::FemFlatPunch(const FloryRehnerGel<2> &material, const Parameters &parameters)
    : material(material)
    , parameters(parameters)
  {
    if (!(parameters.size > 0.))
      throw std::invalid_argument("the gel's size must be positive");
    if (parameters.cells == 0)
      throw std::invalid_argument("the mesh needs at least one cell in each direction");
    require(parameters.punch_width > 0. && parameters.punch_width < parameters.size,
            "FE peer/Punch width",
            "is " + entry_value(parameters.punch_width) + ", outside the gel's width (0, " +
              entry_value(parameters.size) + ")",
            "give the width of the scene's punch piece, e.g. 0.25");
    const double edge_cells = parameters.cells * parameters.punch_width / parameters.size;
    if (std::abs(edge_cells - std::round(edge_cells)) > 1e-9)
      {
        std::string fix;
        for (unsigned int n = parameters.cells + 1; n <= parameters.cells + 1000 && fix.empty();
             ++n)
          {
            const double cells_under_punch = n * parameters.punch_width / parameters.size;
            if (std::abs(cells_under_punch - std::round(cells_under_punch)) < 1e-9)
              fix = ", e.g. " + std::to_string(n);
          }
        throw InputError("FE peer/Cells",
                         "is " + std::to_string(parameters.cells) +
                           ", which puts the punch's edge inside a cell, but it must fall on a "
                           "mesh vertex",
                         "give cells such that cells x 'Punch width' / size is a whole number" +
                           fix);
      }
    require(parameters.ramp_time > 0.,
            "FE peer/Ramp time",
            "is " + entry_value(parameters.ramp_time) +
              ", but the punch's motion needs a positive time",
            "give the scene's ramp time, e.g. 3.125e-6 (tau_d)");

    dealii::GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                      {parameters.cells, parameters.cells},
                                                      dealii::Point<2>(0., 0.),
                                                      dealii::Point<2>(parameters.size,
                                                                       parameters.size),
                                                      true);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto face : cell->face_indices())
        if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == free_top &&
            cell->face(face)->center()[0] < parameters.punch_width)
          cell->face(face)->set_boundary_id(punch);

    system_ = std::make_unique<FemMixedSystem<2>>(
      material,
      triangulation,
      parameters.u_degree,
      FemMixedSystem<2>::Formulation::previously_converged_lagrangian);
    system_->constrain_displacement(bottom, {1});
    system_->constrain_displacement(left, {0});
    system_->constrain_displacement(right, {0});
    system_->constrain_displacement(punch, {1});
    system_->prescribe_chemical_potential(free_top, parameters.mu_top);
    system_->setup();
  }


  double
  FemFlatPunch::punch_displacement(const double t) const
  {
    return -parameters.depth * std::min(t / parameters.ramp_time, 1.);
  }


  FemRunResult
  FemFlatPunch::run(const TimeStepping                      &time_stepping,
                    const NewtonSettings                    &newton,
                    const LinearSolver                      &linear_solver,
                    const std::function<void(const Step &)> &on_step)
  {
    const double volume = system_->volume();
    return run_fem_time_loop<2>(
      *system_,
      material,
      time_stepping,
      newton,
      linear_solver,
      [&](const double t_begin, const double t_end) {
        system_->set_displacement_increment(punch,
                                            1,
                                            punch_displacement(t_end) -
                                              punch_displacement(t_begin));
      },
      [&](const FemStep &step) {
        if (!on_step)
          return;
        Step record;
        static_cast<FemStep &>(record) = step;
        record.punch_displacement      = punch_displacement(step.t_over_tau_d);
        record.deformation             = system_->deformation_summary();
        record.relative_volume_change  = record.deformation.deformed_volume / volume - 1.;
        record.punch_force             = system_->boundary_force(punch);
        on_step(record);
      });
  }


  std::vector<FemMixedSystem<2>::BoundarySample>
  FemFlatPunch::top_samples(const unsigned int per_face) const
  {
    auto       samples = system_->boundary_samples(punch, per_face);
    const auto free    = system_->boundary_samples(free_top, per_face);
    samples.insert(samples.end(), free.begin(), free.end());
    std::sort(samples.begin(), samples.end(), [](const auto &a, const auto &b) {
      return a.X[0] < b.X[0];
    });
    // Face ends appear once per face: keep one.
    const double tolerance = relative_position_tolerance * parameters.size;
    samples.erase(std::unique(samples.begin(),
                              samples.end(),
                              [&](const auto &a, const auto &b) {
                                return std::abs(a.X[0] - b.X[0]) < tolerance;
                              }),
                  samples.end());
    return samples;
  }


  const FemMixedSystem<2> &
  FemFlatPunch::system() const
  {
    return *system_;
  }
} // namespace GelMPM

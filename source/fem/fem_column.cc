#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/fem/fem_column.h>

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  FemColumn::FemColumn(const FloryRehnerGel<2> &material, const Parameters &parameters)
    : material(material)
    , parameters(parameters)
  {
    if (!(parameters.width > 0.) || !(parameters.height > 0.))
      throw std::invalid_argument("the column's width and height must be positive");
    if (parameters.cells == 0)
      throw std::invalid_argument("the mesh needs at least one cell across the width");
    require(parameters.ramp_time > 0.,
            "FE peer/Ramp time",
            "is " + entry_value(parameters.ramp_time) +
              ", but the ramp of mu needs a positive time",
            "give the scene's t_inc, e.g. 0.75 (tau_d)");
    // Square cells: as many along the height as the aspect ratio asks for.
    const double along = parameters.cells * parameters.height / parameters.width;
    if (std::abs(along - std::round(along)) > 1e-9)
      throw std::invalid_argument("cells x height / width must be a whole number (square cells)");

    dealii::GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {parameters.cells, static_cast<unsigned int>(std::round(along))},
      dealii::Point<2>(0., 0.),
      dealii::Point<2>(parameters.width, parameters.height),
      true);

    system_ = std::make_unique<FemMixedSystem<2>>(
      material,
      triangulation,
      parameters.u_degree,
      FemMixedSystem<2>::Formulation::previously_converged_lagrangian);
    system_->constrain_displacement(bottom, {1});
    system_->constrain_displacement(top, {1});
    system_->constrain_displacement_at_vertex(dealii::Point<2>(0., 0.), {0});
    system_->prescribe_chemical_potential(left, boundary_chemical_potential(0.));
    system_->prescribe_chemical_potential(right, boundary_chemical_potential(0.));
    system_->setup();
    signature_ = std::make_unique<FemTangentSignature<2>>(*system_, parameters.drained_onset);
  }


  double
  FemColumn::characteristic_length() const
  {
    return 0.5 * parameters.width;
  }


  double
  FemColumn::boundary_chemical_potential(const double t) const
  {
    return material.mu_0() * (1. - std::min(t / parameters.ramp_time, 1.));
  }


  FemRunResult
  FemColumn::run(const TimeStepping                      &time_stepping,
                 const NewtonSettings                    &newton,
                 const LinearSolver                      &linear_solver,
                 const double                             bisection_tolerance,
                 const double                             unstable_step,
                 const std::function<void(const Step &)> &on_step)
  {
    // Times are in tau_d of the width; another length would silently rescale the ramp.
    if (std::abs(time_stepping.characteristic_length - characteristic_length()) >
        relative_position_tolerance * characteristic_length())
      throw std::invalid_argument("the column's times are in tau_d = (H/2)^2/D: 'Characteristic "
                                  "length' must be " +
                                  std::to_string(characteristic_length()));

    FemSignatureControl control;
    control.stable = [&]() {
      const auto &signature = signature_->evaluate();
      return parameters.drained_onset ? signature.drained_stable() : signature.stable();
    };
    control.bisection_tolerance = bisection_tolerance;
    control.unstable_step       = unstable_step;
    return run_fem_time_loop<2>(
      *system_,
      material,
      time_stepping,
      newton,
      linear_solver,
      [&](const double, const double t_end) {
        // Backward Euler: the boundary data of the step's end.
        const double mu = boundary_chemical_potential(t_end);
        system_->set_chemical_potential(left, mu);
        system_->set_chemical_potential(right, mu);
      },
      [&](const FemStep &step) {
        if (!on_step)
          return;
        Step record;
        static_cast<FemStep &>(record) = step;
        record.boundary_mu             = boundary_chemical_potential(step.t_over_tau_d);
        // Judged on the converged attempt before update(): the tangent of this step's state.
        record.signature = signature_->last();
        record.relative_volume_change =
          system_->deformation_summary().deformed_volume / system_->volume() - 1.;
        on_step(record);
      },
      control);
  }


  FemSignature
  FemColumn::signature()
  {
    return signature_->evaluate();
  }


  const FemMixedSystem<2> &
  FemColumn::system() const
  {
    return *system_;
  }
} // namespace GelMPM

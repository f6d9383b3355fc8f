#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_constrained_swelling.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace GelMPM
{
  namespace
  {
    // Boundary ids of a colorized subdivided_hyperrectangle.
    constexpr dealii::types::boundary_id left = 0, right = 1, bottom = 2, top = 3;
  } // namespace


  FemConstrainedSwelling::FemConstrainedSwelling(const FloryRehnerGel<2> &material,
                                                 const Parameters        &parameters)
    : material(material)
    , parameters(parameters)
  {
    // The entries of gelmpm-fem-swelling's section 'FE peer' (PeerInput).
    require(parameters.width > 0.,
            "FE peer/Width",
            "is " + entry_value(parameters.width) + ", but the layer needs a positive width",
            "give the width of the layer in h_0, e.g. 0.2");
    if (!(parameters.height > 0.))
      throw std::invalid_argument("the layer's height must be positive");
    if (parameters.cells_x == 0 || parameters.cells_y == 0)
      throw std::invalid_argument("the mesh needs at least one cell in each direction");
    require(parameters.grading >= 1.,
            "FE peer/Grading",
            "is " + entry_value(parameters.grading) +
              ", below 1: the cells would grow towards the top instead of shrinking",
            "give an exponent of at least 1 (1: uniform)");

    std::vector<std::vector<double>> steps(2);
    steps[0].assign(parameters.cells_x, parameters.width / parameters.cells_x);
    const unsigned int n        = parameters.cells_y;
    double             previous = 0.;
    for (unsigned int i = 1; i <= n; ++i)
      {
        const double y =
          parameters.height * (1. - std::pow(1. - double(i) / n, parameters.grading));
        steps[1].push_back(y - previous);
        previous = y;
      }
    dealii::GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                      steps,
                                                      dealii::Point<2>(0., 0.),
                                                      dealii::Point<2>(parameters.width,
                                                                       parameters.height),
                                                      true);

    system_ = std::make_unique<FemMixedSystem<2>>(material,
                                                  triangulation,
                                                  parameters.u_degree,
                                                  parameters.formulation);
    system_->constrain_displacement(bottom, {0, 1});
    system_->constrain_displacement(left, {0});
    system_->constrain_displacement(right, {0});
    system_->constrain_displacement(top, {0});
    system_->prescribe_chemical_potential(top, parameters.mu_top);
    system_->setup();
  }


  bool
  FemConstrainedSwelling::run(const TimeStepping                      &time_stepping,
                              const NewtonSettings                    &newton,
                              const LinearSolver                      &linear_solver,
                              const std::function<void(const Step &)> &on_step)
  {
    // The boundary data of §4.1 do not change in time: nothing to prescribe per step.
    const FemRunResult result =
      run_fem_time_loop<2>(*system_,
                           material,
                           time_stepping,
                           newton,
                           linear_solver,
                           {},
                           [&](const FemStep &step) {
                             if (!on_step)
                               return;
                             Step record;
                             static_cast<FemStep &>(record) = step;
                             record.delta_h_over_h0 =
                               system_->mean_boundary_displacement(top, 1) / parameters.height;
                             on_step(record);
                           });
    failure_          = result.failure;
    newton_iterations = result.newton_iterations;
    return result.completed;
  }


  const std::string &
  FemConstrainedSwelling::failure() const
  {
    return failure_;
  }


  const FemMixedSystem<2> &
  FemConstrainedSwelling::system() const
  {
    return *system_;
  }


  unsigned int
  FemConstrainedSwelling::total_newton_iterations() const
  {
    return newton_iterations;
  }
} // namespace GelMPM

#include <gelmpm/fem/fem_constrained_swelling.h>

#include <deal.II/base/timer.h>
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
    if (!(parameters.width > 0.) || !(parameters.height > 0.))
      throw std::invalid_argument("the layer's width and height must be positive");
    if (parameters.cells_x == 0 || parameters.cells_y == 0)
      throw std::invalid_argument("the mesh needs at least one cell in each direction");
    if (!(parameters.grading >= 1.))
      throw std::invalid_argument("the grading exponent must be at least 1 (1: uniform)");

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
    // The solver's factorisation refers to this system's matrix: release it when the run ends.
    struct ReleaseFactorisation
    {
      const LinearSolver &solver;
      ~ReleaseFactorisation()
      {
        solver.new_pattern();
      }
    } release{linear_solver};
    linear_solver.new_pattern();

    const double tau_d  = std::pow(time_stepping.characteristic_length, 2) / material.diffusivity();
    const double volume = system_->volume();
    const double scale_u  = material.shear_modulus() * std::pow(volume, 1. / 2.);
    const double scale_mu = material.kT_over_nu() * volume;
    dealii::TimerOutput timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);

    double                 time = 0., dt = time_stepping.initial_step;
    unsigned int           step = 0;
    dealii::Vector<double> solution;
    newton_iterations = 0;
    failure_.clear();
    while (time < time_stepping.end_time * (1. - 1e-12))
      {
        if (step >= time_stepping.maximum_steps)
          {
            failure_ = "stopped after the maximum number of steps (" +
                       std::to_string(time_stepping.maximum_steps) + ")";
            return false;
          }
        for (unsigned int attempt = 1;; ++attempt)
          {
            const double step_dt = time_stepping.next_step(time, dt);
            system_->initial_guess(solution);
            const NewtonReport report = solve_newton(*system_,
                                                     solution,
                                                     step_dt * tau_d,
                                                     newton,
                                                     linear_solver,
                                                     scale_u,
                                                     scale_mu,
                                                     timer);
            if (!report.converged)
              {
                dt = step_dt * time_stepping.cut_factor;
                if (dt < time_stepping.minimum_step)
                  {
                    std::ostringstream message;
                    message << "the step at t/tau_d = " << time << " failed (" << report.failure
                            << ") and would fall below the minimum step";
                    failure_ = message.str();
                    return false;
                  }
                continue;
              }
            system_->update(solution);
            const bool shortened = step_dt < std::min(dt, time_stepping.cap(time)) * (1. - 1e-12);
            time += step_dt;
            ++step;
            newton_iterations += report.iterations;

            Step record;
            record.number            = step;
            record.t_over_tau_d      = time;
            record.dt_over_tau_d     = step_dt;
            record.newton_iterations = report.iterations;
            record.attempts          = attempt;
            record.residual_u        = report.residual_u;
            record.residual_mu       = report.residual_mu;
            record.delta_h_over_h0 =
              system_->mean_boundary_displacement(top, 1) / parameters.height;
            if (on_step)
              on_step(record);

            if (!shortened)
              dt = step_dt;
            if (report.iterations < time_stepping.growth_below)
              dt *= time_stepping.growth_factor;
            break;
          }
      }
    return true;
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

#include <gelmpm/fem/fem_time_loop.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace GelMPM
{
  FemRunSettings
  fem_run_settings(const std::map<std::string, std::string> &time_stepping,
                   const std::map<std::string, std::string> &newton)
  {
    dealii::ParameterHandler prm;
    TimeStepping::declare_parameters(prm);
    NewtonSettings::declare_parameters(prm);
    for (const auto &[section, entries] :
         {std::make_pair("Time stepping", &time_stepping), std::make_pair("Newton", &newton)})
      {
        prm.enter_subsection(section);
        for (const auto &[entry, value] : *entries)
          prm.set(entry, value);
        prm.leave_subsection();
      }
    FemRunSettings settings;
    settings.time_stepping.parse_parameters(prm);
    settings.newton.parse_parameters(prm);
    return settings;
  }


  template <int dim>
  FemRunResult
  run_fem_time_loop(FemMixedSystem<dim>                        &system,
                    const FloryRehnerGel<dim>                  &material,
                    const TimeStepping                         &time_stepping,
                    const NewtonSettings                       &newton,
                    const LinearSolver                         &linear_solver,
                    const std::function<void(double, double)>  &prescribe,
                    const std::function<void(const FemStep &)> &on_step)
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
    const double volume = system.volume();
    const double scale_u  = material.shear_modulus() * std::pow(volume, (dim - 1.) / dim);
    const double scale_mu = material.kT_over_nu() * volume;
    dealii::TimerOutput timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);

    FemRunResult           result;
    double                 time = 0., dt = time_stepping.initial_step;
    unsigned int           step = 0;
    dealii::Vector<double> solution;
    while (time < time_stepping.end_time * (1. - 1e-12))
      {
        if (step >= time_stepping.maximum_steps)
          {
            result.failure = "stopped after the maximum number of steps (" +
                             std::to_string(time_stepping.maximum_steps) + ")";
            return result;
          }
        for (unsigned int attempt = 1;; ++attempt)
          {
            const double step_dt = time_stepping.next_step(time, dt);
            if (prescribe)
              prescribe(time, time + step_dt);
            system.initial_guess(solution);
            const NewtonReport report = solve_newton(system,
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
                    result.failure = message.str();
                    return result;
                  }
                continue;
              }
            system.update(solution);
            const bool shortened = step_dt < std::min(dt, time_stepping.cap(time)) * (1. - 1e-12);
            time += step_dt;
            ++step;
            result.t_over_tau_d = time;
            result.newton_iterations += report.iterations;

            FemStep record;
            record.number            = step;
            record.t_over_tau_d      = time;
            record.dt_over_tau_d     = step_dt;
            record.newton_iterations = report.iterations;
            record.attempts          = attempt;
            record.residual_u        = report.residual_u;
            record.residual_mu       = report.residual_mu;
            if (on_step)
              on_step(record);

            if (!shortened)
              dt = step_dt;
            if (report.iterations < time_stepping.growth_below)
              dt *= time_stepping.growth_factor;
            break;
          }
      }
    result.completed = true;
    return result;
  }


  template FemRunResult
  run_fem_time_loop<2>(FemMixedSystem<2> &,
                       const FloryRehnerGel<2> &,
                       const TimeStepping &,
                       const NewtonSettings &,
                       const LinearSolver &,
                       const std::function<void(double, double)> &,
                       const std::function<void(const FemStep &)> &);
  template FemRunResult
  run_fem_time_loop<3>(FemMixedSystem<3> &,
                       const FloryRehnerGel<3> &,
                       const TimeStepping &,
                       const NewtonSettings &,
                       const LinearSolver &,
                       const std::function<void(double, double)> &,
                       const std::function<void(const FemStep &)> &);
} // namespace GelMPM

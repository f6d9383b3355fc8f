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
                    const std::function<void(const FemStep &)> &on_step,
                    const FemSignatureControl                  &signature)
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
    StepControl            control(time_stepping,
                        signature.bisection_tolerance,
                        signature.unstable_step,
                        signature.signature_control);
    dealii::Vector<double> solution;
    while (!control.finished())
      {
        if (control.out_of_steps())
          {
            result.failure = "stopped after the maximum number of steps (" +
                             std::to_string(time_stepping.maximum_steps) + ")";
            return result;
          }
        for (unsigned int attempt = 1;; ++attempt)
          {
            const double t_begin = control.time();
            const double step_dt = control.attempt();
            if (prescribe)
              prescribe(t_begin, t_begin + step_dt);
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
                if (!control.cut_step())
                  {
                    std::ostringstream message;
                    message << "the step at t/tau_d = " << t_begin << " failed (" << report.failure
                            << ") and would fall below the minimum step";
                    result.failure = message.str();
                    return result;
                  }
                continue;
              }
            if (signature.stable)
              {
                // The signature reads the tangent at the converged state, which a modified
                // Newton iteration need not have assembled.
                if (!report.tangent_at_solution)
                  system.assemble(solution, step_dt * tau_d, true);
                const auto verdict = control.judge_signature(signature.stable());
                if (verdict == StepControl::Verdict::retake ||
                    verdict == StepControl::Verdict::shorten)
                  continue;
                if (verdict == StepControl::Verdict::onset)
                  result.onsets.push_back(control.bracket());
              }
            system.update(solution);
            control.accept(report.iterations);
            result.t_over_tau_d = control.time();
            result.newton_iterations += report.iterations;

            FemStep record;
            record.number            = control.step();
            record.t_over_tau_d      = control.time();
            record.dt_over_tau_d     = step_dt;
            record.newton_iterations = report.iterations;
            record.attempts          = attempt;
            record.residual_u        = report.residual_u;
            record.residual_mu       = report.residual_mu;
            if (on_step)
              on_step(record);
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
                       const std::function<void(const FemStep &)> &,
                       const FemSignatureControl &);
  template FemRunResult
  run_fem_time_loop<3>(FemMixedSystem<3> &,
                       const FloryRehnerGel<3> &,
                       const TimeStepping &,
                       const NewtonSettings &,
                       const LinearSolver &,
                       const std::function<void(double, double)> &,
                       const std::function<void(const FemStep &)> &,
                       const FemSignatureControl &);
} // namespace GelMPM

#include <gelmpm/fem/fem_time_loop.h>
#include <gelmpm/solvers/time_loop.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <algorithm>
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


  namespace
  {
    /**
     * The body-fitted peer as a SteppedModel: its boundary data come from the scene's
     * callback, its first iterate is the last state with the prescribed values, and its update
     * keeps the converged state.
     *
     * Its error estimates are those of the material points (MixedSystem::local_error_estimate:
     * Milne's device on the linear predictor) taken at the unknowns instead of the points: the
     * difference of a step's increments (du, and the change of mu) from the last step's scaled
     * by dt / dt_last, per displacement unknown (a component at a node: the largest component
     * bounds a node's motion within a factor sqrt(dim)) and per mu unknown, as a root mean
     * square over the unknowns (not weighted by volume; the peer's meshes are uniform or nearly
     * so) or as their largest value. 'Largest increment' is in cells of the material point
     * grid, which the peer has not: refused.
     */
    template <int dim>
    class FemModel : public SteppedModel
    {
    public:
      FemModel(FemMixedSystem<dim>                       &system,
               const std::function<void(double, double)> &prescribe,
               const double                               characteristic_length)
        : fem_system(system)
        , prescribe(prescribe)
        , characteristic_length(characteristic_length)
      {}

      NewtonSystem &
      system() override
      {
        return fem_system;
      }

      void
      prepare_attempt(const double t_begin,
                      const double dt,
                      const double,
                      dealii::Vector<double> &solution) override
      {
        if (prescribe)
          prescribe(t_begin, t_begin + dt);
        fem_system.initial_guess(solution);
      }

      bool
      estimates_errors() const override
      {
        return true;
      }

      bool
      measures_motion_in_cells() const override
      {
        return false;
      }

      double
      increment_deviation(const dealii::Vector<double> &solution, const double ratio) const override
      {
        double largest = 0.;
        for (unsigned int i = 0; i < fem_system.n_u_dofs() && i < last_increment.size(); ++i)
          largest = std::max(largest, std::abs(solution(i) - ratio * last_increment(i)));
        return largest;
      }

      double
      local_error(const dealii::Vector<double> &solution,
                  const double                  ratio,
                  const bool                    largest) const override
      {
        if (last_increment.size() != solution.size())
          return 0.;
        const unsigned int n_u    = fem_system.n_u_dofs();
        const double       weight = ratio / (2. * ratio + 1.);
        const auto        &state  = fem_system.state();
        double             u_sum = 0., mu_sum = 0., u_max = 0., mu_max = 0.;
        for (unsigned int i = 0; i < solution.size(); ++i)
          {
            const double change     = i < n_u ? solution(i) : solution(i) - state(i);
            const double difference = change - ratio * last_increment(i);
            const double square     = difference * difference;
            if (i < n_u)
              {
                u_sum += square;
                u_max = std::max(u_max, square);
              }
            else
              {
                mu_sum += square;
                mu_max = std::max(mu_max, square);
              }
          }
        const unsigned int n_mu = solution.size() - n_u;
        const double       u_error =
          weight * std::sqrt(largest ? u_max : dim * u_sum / std::max(n_u, 1u));
        const double mu_error = weight * std::sqrt(largest ? mu_max : mu_sum / std::max(n_mu, 1u));
        return std::max(u_error / characteristic_length, mu_error);
      }

      void
      update(const dealii::Vector<double> &solution, const double) override
      {
        // The step's increments, the next step's predictor: du as solved, mu as changed.
        const auto &state = fem_system.state();
        last_increment    = solution;
        for (unsigned int i = fem_system.n_u_dofs(); i < solution.size(); ++i)
          last_increment(i) = solution(i) - state(i);
        fem_system.update(solution);
      }

    private:
      FemMixedSystem<dim>                       &fem_system;
      const std::function<void(double, double)> &prescribe;
      double                                     characteristic_length;
      dealii::Vector<double>                     last_increment;
    };


    /** The peer's callbacks as a StepObserver: the signature, the brackets, on_step. */
    template <int dim>
    class FemObserver : public StepObserver
    {
    public:
      FemObserver(FemMixedSystem<dim>                        &system,
                  TimeLoop                                   &loop,
                  const FemSignatureControl                  &signature,
                  const std::function<void(const FemStep &)> &on_step,
                  FemRunResult                               &result)
        : system(system)
        , loop(loop)
        , signature(signature)
        , on_step(on_step)
        , result(result)
      {}

      StepControl::Verdict
      judge_attempt(const dealii::Vector<double> &solution,
                    const double                  dt,
                    const NewtonReport           &report) override
      {
        if (!signature.stable)
          return StepControl::Verdict::accept;
        // The signature reads the tangent at the converged state, which a modified Newton
        // iteration need not have assembled.
        if (!report.tangent_at_solution)
          system.assemble(solution, dt * loop.scales().tau_d, true);
        const auto verdict = loop.control().judge_signature(signature.stable());
        if (verdict == StepControl::Verdict::onset)
          result.onsets.push_back(loop.control().bracket());
        return verdict;
      }

      void
      accepted(const AcceptedStep &step, const dealii::Vector<double> &) override
      {
        result.t_over_tau_d = step.time;
        result.newton_iterations += step.report.iterations;
        FemStep record;
        record.number            = step.number;
        record.t_over_tau_d      = step.time;
        record.dt_over_tau_d     = step.dt;
        record.newton_iterations = step.report.iterations;
        record.attempts          = step.attempts;
        record.residual_u        = step.report.residual_u;
        record.residual_mu       = step.report.residual_mu;
        if (on_step)
          on_step(record);
      }

    private:
      FemMixedSystem<dim>                        &system;
      TimeLoop                                   &loop;
      const FemSignatureControl                  &signature;
      const std::function<void(const FemStep &)> &on_step;
      FemRunResult                               &result;
    };
  } // namespace


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

    const RunScales     scales = RunScales::of(dim,
                                           time_stepping.characteristic_length,
                                           material.diffusivity(),
                                           material.shear_modulus(),
                                           material.kT_over_nu(),
                                           system.volume());
    dealii::TimerOutput timer(std::cout,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    // The peer's tools report through their callbacks: the loop's own lines are not printed.
    dealii::ConditionalOStream silent(std::cout, false);

    FemRunResult     result;
    FemModel<dim>    model(system, prescribe, time_stepping.characteristic_length);
    TimeLoop         loop(model,
                  time_stepping,
                  newton,
                  linear_solver,
                  scales,
                  silent,
                  timer,
                  signature.bisection_tolerance,
                  signature.unstable_step,
                  signature.signature_control);
    FemObserver<dim> observer(system, loop, signature, on_step, result);
    loop.add_observer(observer);
    switch (loop.run())
      {
        case TimeLoop::Outcome::finished:
        case TimeLoop::Outcome::equilibrium:
        case TimeLoop::Outcome::ended_early:
          result.completed = true;
          break;
        case TimeLoop::Outcome::out_of_steps:
          result.failure = "stopped after the maximum number of steps (" +
                           std::to_string(time_stepping.maximum_steps) + ")";
          break;
        case TimeLoop::Outcome::failed:
          result.failure = loop.failure();
          break;
        case TimeLoop::Outcome::interrupted:
        case TimeLoop::Outcome::interrupted_within_step:
          result.failure = "stopped by a signal";
          break;
      }
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

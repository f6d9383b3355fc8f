#include <gelmpm/core/input_error.h>
#include <gelmpm/solvers/newton.h>

#include <cmath>

namespace GelMPM
{
  void
  NewtonSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations",
                      "15",
                      dealii::Patterns::Integer(1),
                      "Newton iterations before a step counts as failed (and is retried with a "
                      "smaller step).");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      dealii::Patterns::Double(0.),
                      "Both residual blocks must fall below this, relative to their natural "
                      "scales: G |Omega_0|^((dim-1)/dim) for the displacement block and "
                      "(k_BT/nu) |Omega_0| for the chemical-potential block.");
    prm.leave_subsection();
  }


  void
  NewtonSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    maximum_iterations = prm.get_integer("Maximum iterations");
    tolerance          = prm.get_double("Tolerance");
    prm.leave_subsection();
    require(tolerance > 0. && tolerance < 1.,
            "Newton/Tolerance",
            "must lie strictly between 0 and 1",
            "use e.g. 1e-10");
  }


  template <int dim>
  NewtonReport
  solve_newton(MixedSystem<dim>       &system,
               dealii::Vector<double> &solution,
               const double            dt,
               const NewtonSettings   &settings,
               const LinearSolver     &linear_solver,
               const double            scale_u,
               const double            scale_mu,
               dealii::TimerOutput    &timer)
  {
    NewtonReport           report;
    dealii::Vector<double> increment(solution.size());
    for (unsigned int k = 0;; ++k)
      {
        try
          {
            dealii::TimerOutput::Scope scope(timer, "assembly");
            system.assemble(solution, dt, true);
          }
        catch (const NonPhysicalState &e)
          {
            report.failure = e.what();
            return report;
          }
        report.residual_u  = system.residual_norm_u() / scale_u;
        report.residual_mu = system.residual_norm_mu() / scale_mu;
        if (!std::isfinite(report.residual_u) || !std::isfinite(report.residual_mu))
          {
            report.failure = "the residual is not finite";
            return report;
          }
        if (report.residual_u <= settings.tolerance && report.residual_mu <= settings.tolerance)
          {
            report.converged = true;
            return report;
          }
        if (k == settings.maximum_iterations)
          {
            report.failure = "no convergence in " + std::to_string(k) + " Newton iterations";
            return report;
          }
        try
          {
            dealii::TimerOutput::Scope scope(timer, "solve");
            linear_solver.solve(system.matrix(), increment, system.residual());
          }
        catch (const std::exception &e)
          {
            report.failure = e.what();
            return report;
          }
        solution -= increment;
        report.iterations = k + 1;
      }
  }


  template NewtonReport
  solve_newton<2>(MixedSystem<2> &,
                  dealii::Vector<double> &,
                  const double,
                  const NewtonSettings &,
                  const LinearSolver &,
                  const double,
                  const double,
                  dealii::TimerOutput &);
  template NewtonReport
  solve_newton<3>(MixedSystem<3> &,
                  dealii::Vector<double> &,
                  const double,
                  const NewtonSettings &,
                  const LinearSolver &,
                  const double,
                  const double,
                  dealii::TimerOutput &);
} // namespace GelMPM

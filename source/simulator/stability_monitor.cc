#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/simulator/stability_monitor.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <sstream>
#include <utility>

namespace GelMPM
{
  template <int dim>
  void
  StabilityMonitor<dim>::check_settings(const StabilitySettings &settings,
                                        const Scene<dim>        &scene,
                                        const TimeStepping      &time_stepping)
  {
    require(!settings.enabled() || scene.nitsche.symmetry > 0.,
            "Stability/Inertia",
            "needs a symmetric tangent, but 'Nitsche/Variant = skew-symmetric'",
            "use the symmetric Nitsche variant or switch the stability analysis off");
    // Both are dense analyses of the whole tangent, made for small discretisations: they read
    // the matrix's rows on the rank that holds them, which on several ranks is a part.
    for (const auto &[on, entry] :
         {std::make_pair(settings.inf_sup, "Stability/Inf-sup constant"),
          std::make_pair(settings.condition, "Stability/Condition number")})
      require(!on || !Collective::is_parallel(scene.communicator),
              entry,
              "is a dense analysis of the whole tangent and is computed on one MPI rank only, but "
              "the run has " +
                std::to_string(dealii::Utilities::MPI::n_mpi_processes(scene.communicator)) +
                " ranks",
              "run the scene on one rank (without mpirun) or set the entry to false");
    require(settings.perturbation_direction.size() >= dim,
            "Stability/Perturbation direction",
            "has fewer components than the scene's dimension " + std::to_string(dim),
            "give one component per coordinate direction");
    double in_plane = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      in_plane += settings.perturbation_direction[d] * settings.perturbation_direction[d];
    require(settings.perturbation_amplitude == 0. || in_plane > 0.,
            "Stability/Perturbation direction",
            "has no component in the scene's " + std::to_string(dim) +
              " coordinate directions (a third component is ignored in 2D)",
            "give the direction the gel is to leave the unstable branch in, e.g. '1, 0'");
    // Bracket ends closer than this are one time for the step arithmetic (times are sums of
    // many steps, compared to relative_time_tolerance): a narrower bracket would end at zero
    // width, both of its ends on the same side of the loss of stability.
    const double narrowest_bracket = 100. * relative_time_tolerance * time_stepping.end_time;
    if (settings.bisection_tolerance > 0. && settings.bisection_tolerance < narrowest_bracket)
      {
        std::ostringstream problem, fix;
        problem << "is " << settings.bisection_tolerance
                << ", below 1e-10 times 'Time stepping/End time' (" << narrowest_bracket
                << "), the narrowest bracket that the step arithmetic resolves";
        fix << "give at least " << narrowest_bracket
            << " (tau_d), e.g. 1e-3, or 0 for no bisection";
        throw InputError("Stability/Bisection tolerance", problem.str(), fix.str());
      }
  }


  template <int dim>
  StabilityMonitor<dim>::StabilityMonitor(
    const StabilitySettings                                   &settings,
    Scene<dim>                                                &scene,
    const LinearSolver                                        &linear_solver,
    TimeLoop                                                  &loop,
    StatisticsFile                                            &statistics,
    StatisticsFile                                            &stability_file,
    dealii::ConditionalOStream                                &log,
    dealii::TimerOutput                                       &timer,
    const std::function<void(const std::string &, double)>    &write_event,
    const std::function<void(const dealii::Vector<double> &)> &record_mode)
    : settings(settings)
    , scene(scene)
    , linear_solver(linear_solver)
    , loop(loop)
    , statistics(statistics)
    , stability_file(stability_file)
    , log(log)
    , timer(timer)
    , write_event(write_event)
    , record_mode(record_mode)
  {}


  template <int dim>
  StepControl::Verdict
  StabilityMonitor<dim>::judge_attempt(const dealii::Vector<double> &solution,
                                       const double                  dt,
                                       const NewtonReport           &report)
  {
    perturb = false;
    if (!settings.enabled())
      return StepControl::Verdict::accept;
    {
      dealii::TimerOutput::Scope scope(timer, "stability");
      const bool reads_factorization = settings.inertia || settings.n_eigenvalues > 0;
      const SymmetricFactorization *factorization =
        reads_factorization ? newton_factorization(report) : nullptr;
      const bool reused = factorization != nullptr;
      if (reads_factorization && settings.signature_source ==
                                   StabilitySettings::SignatureSource::last_newton_factorisation)
        ++(reused ? n_signatures_reused : n_signatures_fresh);
      // What reads the tangent itself (K_uu, the dense estimates) reads the converged one.
      if (!report.tangent_at_solution && (!reused || reads_tangent()))
        scene.system->assemble(solution, dt * loop.scales().tau_d, true);
      // The Newton solver's LDL^T of the converged tangent gives the signature, and is the
      // factorisation the next step's modified Newton starts from.
      if (reads_factorization && !reused && linear_solver.uses_ldlt())
        {
          linear_solver.factorize(scene.system->matrix());
          loop.count_factorization();
          factorization = linear_solver.symmetric_factorization();
        }
      // The iterative drained criterion's AMG takes the rigid-body modes from these points.
      const std::vector<double> points = settings.iterative_drained()
                                           ? scene.spaces->u_dof_greville_points()
                                           : std::vector<double>();
      last_result                      = analyse_stability(
        scene.system->matrix(),
        scene.spaces->n_u_dofs(),
        settings,
        [this]() {
          return scene.system->mu_mass_matrix();
        },
        factorization,
        dim,
        &points);
    }
    const auto verdict = judge_signature(last_result);
    if (verdict == StepControl::Verdict::retake || verdict == StepControl::Verdict::shorten)
      return verdict;
    record_columns(last_result);
    if (record_mode && last_result.mode.size() == scene.spaces->n_u_dofs())
      record_mode(last_result.mode);
    // Leave the unstable branch at the bracketed critical time (doc/method.md).
    ended_at_onset = verdict == StepControl::Verdict::onset && settings.end_at_onset;
    perturb        = verdict == StepControl::Verdict::onset && !ended_at_onset &&
              settings.perturbation_amplitude > 0. &&
              (last_result.mode.size() == scene.spaces->n_u_dofs() ||
               last_result.drained_mode.size() == scene.spaces->n_u_dofs());
    return verdict;
  }


  template <int dim>
  const SymmetricFactorization *
  StabilityMonitor<dim>::newton_factorization(const NewtonReport &report) const
  {
    // Only a factorisation of the tangent at the iterate before the converged one: one kept
    // from an earlier iterate or step (modified Newton) is of an older state.
    if (settings.signature_source !=
          StabilitySettings::SignatureSource::last_newton_factorisation ||
        report.factorizations == 0 || !report.last_solve_fresh || !linear_solver.uses_ldlt())
      return nullptr;
    return linear_solver.symmetric_factorization();
  }


  template <int dim>
  bool
  StabilityMonitor<dim>::reads_tangent() const
  {
    return settings.drained_onset || settings.inf_sup || settings.condition;
  }


  template <int dim>
  std::string
  StabilityMonitor<dim>::signature_sources() const
  {
    if (settings.signature_source != StabilitySettings::SignatureSource::last_newton_factorisation)
      return "";
    return std::to_string(n_signatures_reused) + " signatures from Newton's last factorisation, " +
           std::to_string(n_signatures_fresh) + " from the converged tangent";
  }


  template <int dim>
  void
  StabilityMonitor<dim>::attempt_rejected()
  {
    announced_bracketing = false;
  }


  template <int dim>
  bool
  StabilityMonitor<dim>::before_update(dealii::Vector<double> &solution, const double)
  {
    if (!perturb)
      return false;
    perturb_along_mode(last_result.drained_mode.size() == scene.spaces->n_u_dofs()
                         ? last_result.drained_mode
                         : last_result.mode,
                       solution);
    perturb = false;
    return true;
  }


  template <int dim>
  bool
  StabilityMonitor<dim>::end_requested() const
  {
    return ended_at_onset;
  }


  template <int dim>
  void
  StabilityMonitor<dim>::record_columns(const StabilityReport &result)
  {
    if (settings.inertia)
      {
        statistics.set("n_pos", result.inertia.n_positive);
        statistics.set("n_neg", result.inertia.n_negative);
        statistics.set("n_zero", result.inertia.n_zero);
        if (settings.drained_onset && !settings.iterative_drained())
          statistics.set("n_neg_uu", result.drained_inertia.n_negative);
      }
    for (unsigned int k = 0; k < result.drained_eigenvalues.size(); ++k)
      statistics.set("drained_eig_" + std::to_string(k + 1), result.drained_eigenvalues[k]);
    for (unsigned int k = 0; k < result.eigenvalues.size(); ++k)
      statistics.set("eig_" + std::to_string(k + 1), result.eigenvalues[k]);
    if (settings.inf_sup)
      statistics.set("inf_sup", result.inf_sup);
    if (settings.condition)
      statistics.set("condition_number", result.condition_number);
  }


  template <int dim>
  StepControl::Verdict
  StabilityMonitor<dim>::judge_signature(const StabilityReport &result)
  {
    if (!settings.detects_onset())
      return StepControl::Verdict::accept;
    const bool tangent_stable = result.inertia.n_positive == scene.spaces->n_u_dofs() &&
                                result.inertia.n_negative == scene.spaces->n_mu_dofs() &&
                                result.inertia.n_zero == 0;
    // Until the first onset the drained criterion (K_uu positive definite: no mode grows) brackets
    // it independently of the step; from then on the tangent's signature (no mode grows faster
    // than 1/dt) controls the steps. Without the tangent's signature (the iterative drained
    // criterion alone) the drained criterion judges every state.
    const bool use_drained =
      settings.drained_onset && (!loop.control().onset_seen() || !settings.inertia);
    const bool drained_stable =
      settings.iterative_drained()
        ? result.drained_eigenvalues.empty() || result.drained_eigenvalues[0] > 0.
        : result.drained_inertia.n_negative == 0 && result.drained_inertia.n_zero == 0;
    const bool   stable  = use_drained ? drained_stable : tangent_stable;
    const double t_end   = loop.control().time() + loop.control().attempt_size();
    const auto   verdict = loop.control().judge_signature(stable);
    switch (verdict)
      {
        case StepControl::Verdict::retake:
          if (!announced_bracketing)
            log << "    the state loses stability ("
                << (use_drained ? "K_uu indefinite" : "signature not (n_u, n_mu, 0)")
                << ") between t = " << loop.control().time() << " and " << t_end
                << "; bisecting to 'Stability/Bisection tolerance' = "
                << settings.bisection_tolerance << std::endl;
          announced_bracketing = true;
          return verdict;
        case StepControl::Verdict::shorten:
          log << "    the signature at t = " << t_end
              << " with dt = " << loop.control().attempt_size() << " is ("
              << result.inertia.n_positive << ", " << result.inertia.n_negative << ", "
              << result.inertia.n_zero << "): a mode grows faster than 1/dt; retrying "
              << "with dt = " << loop.control().proposed_step() << std::endl;
          return verdict;
        case StepControl::Verdict::step_dependent:
          log << "    with shorter steps the state at t = " << t_end
              << " is stable: the loss of stability depends on the step size; bracketing ended"
              << std::endl;
          break;
        case StepControl::Verdict::regained:
          log << "    the signature is (n_u, n_mu, 0) again at t/tau_d = " << t_end << ": stable"
              << std::endl;
          break;
        case StepControl::Verdict::onset:
          report_onset(result);
          break;
        case StepControl::Verdict::accept:
          break;
      }
    announced_bracketing = loop.control().bracketing();
    if (settings.inertia ? tangent_stable : stable)
      {
        last_stable_inertia = result.inertia;
        last_eigenvalue     = result.eigenvalues.empty() ? 0. : result.eigenvalues[0];
      }
    return verdict;
  }


  template <int dim>
  void
  StabilityMonitor<dim>::report_onset(const StabilityReport &result)
  {
    const auto &bracket = loop.control().bracket();
    log << "    loss of stability between t/tau_d = " << bracket.t_stable << " (stable) and "
        << bracket.t_unstable;
    if (settings.inertia)
      log << ": signature (" << result.inertia.n_positive << ", " << result.inertia.n_negative
          << ", " << result.inertia.n_zero << "), expected (" << scene.spaces->n_u_dofs() << ", "
          << scene.spaces->n_mu_dofs() << ", 0)";
    if (settings.iterative_drained() && !result.drained_eigenvalues.empty())
      log << (settings.inertia ? "; " : ": ")
          << "lambda_min(K_uu) = " << result.drained_eigenvalues[0]
          << " (drained criterion, LOBPCG)";
    else if (settings.drained_onset)
      log << "; K_uu has " << result.drained_inertia.n_negative
          << " negative eigenvalue(s) (drained criterion)";
    log << std::endl;
    stability_file.set("t_stable", bracket.t_stable);
    stability_file.set("t_unstable", bracket.t_unstable);
    if (settings.inertia)
      {
        stability_file.set("n_neg_stable", last_stable_inertia.n_negative);
        stability_file.set("n_neg_unstable", result.inertia.n_negative);
        stability_file.set("n_zero_unstable", result.inertia.n_zero);
      }
    if (settings.iterative_drained() && !result.drained_eigenvalues.empty())
      stability_file.set("drained_eig_1_unstable", result.drained_eigenvalues[0]);
    stability_file.set("n_dofs_u", scene.spaces->n_u_dofs());
    stability_file.set("n_dofs_mu", scene.spaces->n_mu_dofs());
    if (!result.eigenvalues.empty())
      {
        stability_file.set("eig_1_stable", last_eigenvalue);
        stability_file.set("eig_1_unstable", result.eigenvalues[0]);
      }
    stability_file.write_row();

    // Written as the event happens. The points still hold the state of the bracket's stable end
    // (the converged attempt is applied after the stability analysis): mu_boundary is taken there,
    // at most 'Bisection tolerance' earlier.
    write_event("bifurcation", bracket.t_unstable);
  }


  template <int dim>
  void
  StabilityMonitor<dim>::perturb_along_mode(const dealii::Vector<double> &mode,
                                            dealii::Vector<double>       &solution) const
  {
    // The eigenvector's sign and size are arbitrary: scale it to a largest control-point
    // displacement of 'Perturbation amplitude', signed so that the control point that moves
    // most along 'Perturbation direction' moves forwards.
    double      largest = 0., along = 0.;
    const auto &d = settings.perturbation_direction;
    for (unsigned int i = 0; i + dim <= mode.size(); i += dim)
      {
        double norm2 = 0., projection = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          {
            norm2 += mode(i + c) * mode(i + c);
            projection += mode(i + c) * d[c];
          }
        largest = std::max(largest, std::sqrt(norm2));
        if (std::abs(projection) > std::abs(along))
          along = projection;
      }
    if (!(largest > 0.))
      return;
    const double scale = settings.perturbation_amplitude / largest * (along < 0. ? -1. : 1.);
    for (unsigned int i = 0; i < mode.size(); ++i)
      solution(i) += scale * mode(i);
    log << "    perturbed along the critical mode: largest control-point displacement "
        << settings.perturbation_amplitude << std::endl;
  }


  template class StabilityMonitor<2>;
  template class StabilityMonitor<3>;
} // namespace GelMPM

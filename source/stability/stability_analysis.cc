#include <gelmpm/core/input_error.h>
#include <gelmpm/stability/condition_number.h>
#include <gelmpm/stability/displacement_block_amg.h>
#include <gelmpm/stability/drained_eigenvalues.h>
#include <gelmpm/stability/inf_sup.h>
#include <gelmpm/stability/schur_eigenvalues.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/utilities.h>

namespace GelMPM
{
  void
  StabilitySettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    prm.declare_entry("Inertia",
                      "false",
                      dealii::Patterns::Bool(),
                      "After every converged step, the signature (n+, n-, n0) of the tangent from "
                      "its symmetric LDL^T factorisation (MUMPS): columns n_pos, n_neg, n_zero. A "
                      "stable state has (n_dofs_u, n_dofs_mu, 0). Needs the symmetric Nitsche "
                      "variant.");
    prm.declare_entry(
      "Schur eigenvalues",
      "0",
      dealii::Patterns::Integer(0, 50),
      "k > 0: after every converged step, the k eigenvalues of smallest magnitude of "
      "the Schur complement S = K_uu - K_umu K_mumu^-1 K_muu (paper eq. (63)), by "
      "ARPACK in shift-invert mode: columns eig_1 ... eig_k. 0: off.");
    prm.declare_entry("Inf-sup constant",
                      "false",
                      dealii::Patterns::Bool(),
                      "After every converged step, the discrete inf-sup constant beta_h of the "
                      "undrained (dt -> 0) saddle-point problem: beta_h^2 is the smallest "
                      "eigenvalue of K_muu K_uu^-1 K_umu q = beta^2 M q, M the mass matrix of the "
                      "mu basis (column inf_sup). Dense LAPACK: for grids with at most 8000 "
                      "displacement unknowns (the inf-sup study of doc/inf_sup.md).");
    prm.declare_entry(
      "Bisection tolerance",
      "0",
      dealii::Patterns::Double(0.),
      "With 'Inertia' (or the iterative drained criterion, 'Eigensolver'): when "
      "the signature leaves (n_dofs_u, n_dofs_mu, 0) within a step, retake the step from the last stable state with halved steps until "
      "the critical time is bracketed to this width (in tau_d); the bracket goes "
      "to the log and to stability.csv. 0: no bisection (the bracket is the step "
      "that lost stability).");
    prm.declare_entry("Write mode",
                      "false",
                      dealii::Patterns::Bool(),
                      "With 'Schur eigenvalues' >= 1: at every output time, the eigenvector of the "
                      "smallest Schur eigenvalue of the last converged step as a displacement "
                      "field on the background grid (mode-NNNNN.vtu, mode.pvd; field "
                      "displacement_increment, scaled to a largest coefficient of 1): the shape in "
                      "which the gel is about to lose, or has lost, stability.");
    prm.declare_entry(
      "Onset criterion",
      "tangent",
      dealii::Patterns::Selection("tangent|drained"),
      "What brackets a loss of stability. 'tangent' (needs 'Inertia'): the signature "
      "of the tangent K(dt), which leaves (n_dofs_u, n_dofs_mu, 0) when some mode "
      "grows faster than 1/dt, so the time found depends on the step. 'drained': "
      "its displacement block K_uu (mu held), which has a negative eigenvalue "
      "exactly when some mode grows at all (sigma > 0), independent of the step; "
      "with 'Eigensolver' by factorisation (needs 'Inertia') one more LDL^T per "
      "step, column n_neg_uu, iteratively the smallest eigenvalues of K_uu, "
      "columns drained_eig_1 ... (doc/method.md, 'Going through an "
      "instability').");
    prm.declare_entry(
      "Eigensolver",
      "automatic",
      dealii::Patterns::Selection("automatic|factorisation|iterative"),
      "How 'Onset criterion = drained' looks at K_uu. 'factorisation': its inertia from "
      "an LDL^T factorisation (MUMPS), column n_neg_uu; unstable when it has a negative "
      "or a zero pivot. 'iterative': no factorisation: the 'Drained eigenvalues' "
      "smallest eigenvalues of K_uu by LOBPCG (Trilinos Anasazi) preconditioned by the "
      "algebraic multigrid of K_uu that 'Linear solver/Solver = Krylov' uses, columns "
      "drained_eig_1 ... drained_eig_k; unstable when lambda_min < 0, and the "
      "perturbation follows lambda_min's eigenvector. 'Inertia' is then not needed; "
      "if it or 'Schur eigenvalues' is asked for, the whole tangent is still "
      "factorised for it. 'automatic': iterative with 'Linear solver/Solver = Krylov', "
      "factorisation otherwise (doc/method.md, 'Stability without a factorisation').");
    prm.declare_entry("Drained eigenvalues",
                      "3",
                      dealii::Patterns::Integer(1, 20),
                      "With 'Eigensolver' iterative and 'Onset criterion = drained': how many of "
                      "the smallest (algebraic) eigenvalues of K_uu are computed and recorded "
                      "(columns drained_eig_1 ... drained_eig_k). One is the criterion; a few "
                      "more show which modes approach zero next (a 3D column's two sways).");
    prm.declare_entry("Signature step control",
                      "false",
                      dealii::Patterns::Bool(),
                      "With 'Inertia': after the first bracketed loss of stability, a converged "
                      "attempt whose signature is not (n_dofs_u, n_dofs_mu, 0) is retaken with the "
                      "step times 'Time stepping/Cut factor' (down to 'Minimum step'). The "
                      "signature of the tangent at step dt counts the modes that grow faster than "
                      "1/dt, so the steps follow the fastest growing mode and backward Euler "
                      "resolves its growth instead of damping it (paper §4.3: 'adaptive "
                      "time-stepping based on monitoring the signature'; doc/method.md).");
    prm.declare_entry(
      "Step while unstable",
      "0",
      dealii::Patterns::Double(0.),
      "With 'Inertia': while the signature of the accepted state is not (n_dofs_u, "
      "n_dofs_mu, 0), no step is longer than this (tau_d). Backward Euler damps a "
      "mode that grows at rate sigma once sigma dt > 2, so long steps keep a run on "
      "an unstable branch; choose it so that sigma dt stays below about 1 "
      "(doc/method.md, 'Going through an instability'). 0: no such cap.");
    prm.declare_entry(
      "Perturbation amplitude",
      "0",
      dealii::Patterns::Double(0.),
      "With 'Inertia' and 'Schur eigenvalues' >= 1, or the iterative drained "
      "criterion: when a loss of stability has been bracketed, the displacement of the unstable state is perturbed along "
      "the critical mode (with 'Onset criterion = drained' the eigenvector of the "
      "negative eigenvalue of K_uu, otherwise that of the smallest Schur eigenvalue), "
      "scaled so that its largest control-point displacement is this amplitude (in the "
      "scene's length unit), so that the run leaves the unstable branch at the "
      "critical time in a chosen direction. 0: no perturbation (the run relies on "
      "round-off to leave a symmetric branch, late and in a random direction).");
    prm.declare_entry(
      "Perturbation direction",
      "1, 0, 0",
      dealii::Patterns::List(dealii::Patterns::Double(), 2, 3),
      "The sign of the perturbation: the control point that the critical mode moves "
      "most along this direction moves forwards (e.g. '1, 0' sways a column "
      "towards +x). One component per dimension; a third one is ignored in 2D.");
    prm.declare_entry("End at onset",
                      "false",
                      dealii::Patterns::Bool(),
                      "With 'Inertia' (or the iterative drained criterion) and a 'Bisection "
                      "tolerance': end the run (exit status 0, "
                      "the state at the bracket's unstable end written) once the first loss of "
                      "stability is bracketed. For onset studies, which need nothing after it "
                      "(contrib/benchmarks/column_onset_convergence.py).");
    prm.declare_entry("Condition number",
                      "false",
                      dealii::Patterns::Bool(),
                      "After every converged step, an estimate of the 1-norm condition "
                      "number of the tangent (column condition_number). Dense: for grids with at "
                      "most 10000 unknowns in all (the Nitsche penalty study of doc/extremes.md).");
    prm.declare_entry(
      "Signature from",
      "converged tangent",
      dealii::Patterns::Selection("converged tangent|last Newton factorisation"),
      "Which LDL^T factorisation gives 'Inertia' and 'Schur eigenvalues'. 'converged tangent': "
      "the tangent at the converged state, factorised for the analysis (one factorisation per "
      "converged attempt more than Newton's). 'last Newton factorisation': the one Newton's "
      "last iteration made and solved with, of the tangent at the iterate before the converged "
      "state; nothing is factorised for the signature. Its signature is the converged "
      "tangent's unless an eigenvalue of the tangent lies closer to zero than the last Newton "
      "update moves it (quadratic convergence: that update is about the square of the one "
      "before), so a bracketed loss of stability moves by at most one bisection step; the "
      "Schur eigenvalues and their mode are likewise that tangent's, apart from the converged "
      "one's by that amount. Where Newton's last iteration solved with a factorisation kept "
      "from an earlier iterate or step ('Newton/Reuse contraction' > 0), made none, or the run "
      "solves by Krylov, the converged tangent is factorised as with 'converged tangent'. The "
      "drained criterion's K_uu, the inf-sup constant and the condition number are always the "
      "converged tangent's. Needs 'Inertia' or 'Schur eigenvalues' and MUMPS's LDL^T in double "
      "precision (doc/method.md, 'Going through an instability'; doc/performance.md, 'Fewer "
      "factorisations').");
    prm.leave_subsection();
  }


  void
  StabilitySettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    inertia                = prm.get_bool("Inertia");
    n_eigenvalues          = prm.get_integer("Schur eigenvalues");
    inf_sup                = prm.get_bool("Inf-sup constant");
    condition              = prm.get_bool("Condition number");
    bisection_tolerance    = prm.get_double("Bisection tolerance");
    write_mode             = prm.get_bool("Write mode");
    unstable_step          = prm.get_double("Step while unstable");
    signature_control      = prm.get_bool("Signature step control");
    drained_onset          = prm.get("Onset criterion") == "drained";
    perturbation_amplitude = prm.get_double("Perturbation amplitude");
    end_at_onset           = prm.get_bool("End at onset");
    perturbation_direction.clear();
    for (const auto &item : dealii::Utilities::split_string_list(prm.get("Perturbation direction")))
      perturbation_direction.push_back(dealii::Utilities::string_to_double(item));
    const std::string eigensolver_choice = prm.get("Eigensolver");
    n_drained_eigenvalues                = prm.get_integer("Drained eigenvalues");
    signature_source                     = prm.get("Signature from") == "last Newton factorisation"
                                             ? SignatureSource::last_newton_factorisation
                                             : SignatureSource::converged_tangent;
    prm.leave_subsection();
    // 'automatic' follows the linear solver: a run that solves by Krylov has no factorisation to
    // spare, one that factorises anyway keeps the inertia.
    std::string solver = "automatic", precision = "double";
    if (prm.subsection_path_exists({"Linear solver"}))
      {
        prm.enter_subsection("Linear solver");
        solver    = prm.get("Solver");
        precision = prm.get("Precision");
        prm.leave_subsection();
      }
    const bool krylov = solver == "Krylov";
    check_signature_source(solver, precision);
    eigensolver = eigensolver_choice == "iterative" || (eigensolver_choice == "automatic" && krylov)
                    ? Eigensolver::iterative
                    : Eigensolver::factorisation;
    require(eigensolver_choice != "iterative" || drained_onset,
            "Stability/Eigensolver",
            "is 'iterative', which computes the smallest eigenvalues of K_uu for 'Onset criterion "
            "= drained', but the criterion is 'tangent' (the signature of the whole tangent, "
            "which only its factorisation gives)",
            "set 'Onset criterion = drained', or 'Eigensolver = automatic' or 'factorisation'");
    require(unstable_step == 0. || inertia,
            "Stability/Step while unstable",
            "needs the signature of the tangent, but 'Stability/Inertia = false'",
            "set 'Inertia = true' or the step to 0");
    require(!drained_onset || inertia || eigensolver == Eigensolver::iterative,
            "Stability/Onset criterion",
            "'drained' by factorisation needs the signature of the tangent, but "
            "'Stability/Inertia = false'",
            "set 'Inertia = true', or 'Eigensolver = iterative' (no factorisation), or 'Onset "
            "criterion = tangent'");
    require(!signature_control || inertia,
            "Stability/Signature step control",
            "needs the signature of the tangent, but 'Stability/Inertia = false'",
            "set 'Inertia = true' or 'Signature step control = false'");
    require(perturbation_amplitude == 0. || (inertia && n_eigenvalues > 0) || iterative_drained(),
            "Stability/Perturbation amplitude",
            "needs the signature and the critical mode, but 'Inertia' is false or 'Schur "
            "eigenvalues' is 0 (and the drained criterion is not iterative)",
            "set 'Inertia = true' and 'Schur eigenvalues' to at least 1, or 'Onset criterion = "
            "drained' with 'Eigensolver = iterative', or the amplitude to 0");
    double direction_norm = 0.;
    for (const double d : perturbation_direction)
      direction_norm += d * d;
    require(perturbation_amplitude == 0. || direction_norm > 0.,
            "Stability/Perturbation direction",
            "is the zero vector",
            "give the direction the gel is to leave the unstable branch in, e.g. '1, 0'");
    require(bisection_tolerance == 0. || detects_onset(),
            "Stability/Bisection tolerance",
            "needs the signature of the tangent, but 'Stability/Inertia = false'",
            "set 'Inertia = true' (or the iterative drained criterion: 'Onset criterion = "
            "drained', 'Eigensolver = iterative'), or the tolerance to 0");
    require(!end_at_onset || detects_onset(),
            "Stability/End at onset",
            "needs the signature of the tangent, but 'Stability/Inertia = false'",
            "set 'Inertia = true' (or the iterative drained criterion: 'Onset criterion = "
            "drained', 'Eigensolver = iterative'), or 'End at onset = false'");
    require(!write_mode || n_eigenvalues > 0,
            "Stability/Write mode",
            "needs the eigenvector of the smallest Schur eigenvalue, but 'Schur eigenvalues' is 0",
            "set 'Schur eigenvalues' to at least 1 or 'Write mode' to false");
  }


  void
  StabilitySettings::check_signature_source(const std::string &solver,
                                            const std::string &precision) const
  {
    if (signature_source != SignatureSource::last_newton_factorisation)
      return;
    require(inertia || n_eigenvalues > 0,
            "Stability/Signature from",
            "is 'last Newton factorisation', but neither 'Inertia' nor 'Schur eigenvalues' reads "
            "a factorisation",
            "set 'Inertia = true', or 'Signature from = converged tangent'");
    require(solver != "KLU" && solver != "Krylov",
            "Stability/Signature from",
            "is 'last Newton factorisation', but with 'Linear solver/Solver = " + solver +
              "' Newton makes no LDL^T factorisation",
            "set 'Linear solver/Solver = MUMPS' (or 'automatic'), or 'Signature from = converged "
            "tangent'");
    require(precision != "single",
            "Stability/Signature from",
            "is 'last Newton factorisation', but Newton's factors are in single precision "
            "('Linear solver/Precision = single'), which the stability analysis does not read "
            "(near an onset they cannot be refined)",
            "set 'Linear solver/Precision = double', or 'Signature from = converged tangent'");
  }


  bool
  StabilitySettings::iterative_drained() const
  {
    return drained_onset && eigensolver == Eigensolver::iterative;
  }


  bool
  StabilitySettings::detects_onset() const
  {
    return inertia || iterative_drained();
  }


  bool
  StabilitySettings::enabled() const
  {
    return inertia || n_eigenvalues > 0 || inf_sup || condition || iterative_drained();
  }


  bool
  StabilitySettings::needs_mode() const
  {
    return write_mode || perturbation_amplitude > 0.;
  }


  std::vector<std::string>
  StabilitySettings::columns() const
  {
    std::vector<std::string> c;
    if (inertia)
      c = {"n_pos", "n_neg", "n_zero"};
    if (drained_onset && !iterative_drained())
      c.push_back("n_neg_uu");
    if (iterative_drained())
      for (unsigned int k = 0; k < n_drained_eigenvalues; ++k)
        c.push_back("drained_eig_" + std::to_string(k + 1));
    for (unsigned int k = 0; k < n_eigenvalues; ++k)
      c.push_back("eig_" + std::to_string(k + 1));
    if (inf_sup)
      c.push_back("inf_sup");
    if (condition)
      c.push_back("condition_number");
    return c;
  }


  StabilityReport
  analyse_stability(const dealii::TrilinosWrappers::SparseMatrix      &K,
                    const unsigned int                                 n_u,
                    const StabilitySettings                           &settings,
                    const std::function<dealii::FullMatrix<double>()> &mass_mu,
                    const SymmetricFactorization                      *given_factorization,
                    const unsigned int                                 dim,
                    const std::vector<double>                         *u_dof_points)
  {
    StabilityReport report;
    if (settings.inertia || settings.n_eigenvalues > 0)
      {
        SymmetricFactorization own_factorization;
        if (!given_factorization)
          own_factorization.factorize(K);
        const SymmetricFactorization &factorization =
          given_factorization ? *given_factorization : own_factorization;
        report.inertia = factorization.inertia();
        if (settings.drained_onset && !settings.iterative_drained())
          {
            SymmetricFactorization displacement_block;
            displacement_block.factorize(K, n_u);
            report.drained_inertia = displacement_block.inertia();
            // K_uu alone is its own "Schur complement" (no mu block): the same shift-invert
            // Lanczos gives its eigenvalue nearest zero. The perturbation at the onset follows
            // this mode, not the Schur mode of the short bracketing step: that one is nearly
            // isochoric, and the next short step relaxes it elastically (doc/method.md).
            if (settings.perturbation_amplitude > 0. && report.drained_inertia.n_negative > 0)
              {
                // Near the onset the negative eigenvalue is the one nearest zero; of the three
                // nearest, take the lowest (the values come in algebraic order).
                auto drained        = smallest_schur_eigenvalues(displacement_block, n_u, 3, true);
                report.drained_mode = std::move(drained.vectors[0]);
              }
          }
        if (settings.n_eigenvalues > 0)
          {
            auto eigen         = smallest_schur_eigenvalues(factorization,
                                                    n_u,
                                                    settings.n_eigenvalues,
                                                    settings.needs_mode());
            report.eigenvalues = std::move(eigen.values);
            if (!eigen.vectors.empty())
              report.mode = std::move(eigen.vectors[0]);
          }
      }
    if (settings.iterative_drained())
      {
        if (!u_dof_points)
          throw std::logic_error("analyse_stability(): the iterative drained criterion needs the "
                                 "points of the displacement unknowns");
        // No factorisation: LOBPCG with the AMG of K_uu. Every row of K_uu takes part, the
        // diagonal-only ones (held on the axis) with their diagonal as eigenvalue, as their 1 x 1
        // pivots do in the inertia of the factorisation path.
        DisplacementBlockAMG block;
        block.setup(K, n_u, dim, *u_dof_points);
        const bool want_mode = settings.perturbation_amplitude > 0.;
        auto       drained =
          smallest_drained_eigenvalues(block, settings.n_drained_eigenvalues, want_mode);
        report.drained_eigenvalues = drained.values;
        report.drained_iterations  = drained.iterations;
        if (want_mode && drained.values[0] < 0.)
          report.drained_mode = std::move(drained.vectors[0]);
      }
    if (settings.inf_sup)
      report.inf_sup = discrete_inf_sup_constant(K, n_u, mass_mu());
    if (settings.condition)
      report.condition_number = condition_number_estimate(K);
    return report;
  }
} // namespace GelMPM

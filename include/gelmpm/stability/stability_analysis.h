#ifndef gelmpm_stability_stability_analysis_h
#define gelmpm_stability_stability_analysis_h

#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The "Stability" section: what the stability analysis of paper §3.6 computes after every
   * converged step. Off by default; when off it costs nothing.
   *
   * - Inertia: the signature (n+, n-, n0) of the tangent at the converged state, from its LDL^T
   *   factorisation (columns n_pos, n_neg, n_zero of statistics.csv). A stable state has
   *   (n_dofs_u, n_dofs_mu, 0).
   * - Schur eigenvalues: the k eigenvalues of smallest magnitude of the Schur complement of
   *   eq. (63) (columns eig_1 ... eig_k), by ARPACK through the same factorisation.
   * - Inf-sup constant: beta_h of the undrained saddle-point problem (column inf_sup), see
   *   discrete_inf_sup_constant(); dense, for small discretisations.
   * - Bisection tolerance: with the inertia, the width to which the time where the signature
   *   leaves (n_u, n_mu, 0) is bracketed by retaking the step (Simulator; stability.csv).
   * - Write mode: the eigenvector of the smallest Schur eigenvalue on the background grid.
   * - Step while unstable, Perturbation amplitude and direction: how a run goes through a loss
   *   of stability (StepControl; Simulator; doc/method.md, "Going through an instability").
   * - Condition number: LAPACK's 1-norm estimate for the tangent (column condition_number);
   *   dense, for small discretisations.
   * - Signature from: the LDL^T of the converged tangent, made for the analysis, or the one
   *   Newton's last iteration made (the tangent at the iterate before the converged state).
   * - Eigensolver: how the drained criterion ('Onset criterion = drained') looks at K_uu. By
   *   factorisation, its inertia from a second LDL^T (column n_neg_uu); iteratively, its
   *   'Drained eigenvalues' smallest eigenvalues by LOBPCG with the AMG of K_uu
   *   (smallest_drained_eigenvalues(); columns drained_eig_1 ... drained_eig_k), lambda_min < 0
   *   being the criterion and its eigenvector the perturbation. Iteratively, the drained onset
   *   needs no factorisation at all: 'Inertia' and 'Schur eigenvalues', if asked for explicitly,
   *   still factorise the whole tangent. 'automatic' (default): iterative when 'Linear
   *   solver/Solver = Krylov', by factorisation otherwise (doc/method.md, "Stability without a
   *   factorisation").
   */
  struct StabilitySettings
  {
    /** How the drained criterion analyses K_uu (automatic is resolved by parse_parameters()). */
    enum class Eigensolver
    {
      factorisation,
      iterative
    };

    bool         inertia       = false;
    unsigned int n_eigenvalues = 0;
    bool         inf_sup       = false;
    bool         condition     = false;
    /** Width (tau_d) to which a loss of stability is bracketed; 0: off. */
    double bisection_tolerance = 0.;
    /** Write the critical mode (eigenvector of the smallest Schur eigenvalue) for ParaView. */
    bool write_mode = false;
    /** Bracket the onset with the inertia of K_uu (drained, dt-independent) instead of K's. */
    bool drained_onset = false;
    /** After a bracketed loss of stability, retake unstable attempts shorter (StepControl). */
    bool signature_control = false;
    /** Largest step (tau_d) while the signature is not (n_u, n_mu, 0); 0: no such cap. */
    double unstable_step = 0.;
    /** Largest control-point displacement of the perturbation along the critical mode at a
     * bracketed loss of stability (scene length unit); 0: no perturbation. */
    double perturbation_amplitude = 0.;
    /** The perturbation is signed so that it moves forwards along this direction. */
    std::vector<double> perturbation_direction;
    /** End the run once the first loss of stability is bracketed (an onset study needs no
     * more). */
    bool end_at_onset = false;
    /** With 'Onset criterion = drained': the inertia of K_uu (LDL^T) or its smallest eigenvalues
     * (LOBPCG). */
    Eigensolver eigensolver = Eigensolver::factorisation;
    /** Iterative drained criterion: how many of the smallest eigenvalues of K_uu. */
    unsigned int n_drained_eigenvalues = 3;

    /** Which LDL^T gives the inertia and the Schur eigenvalues ('Signature from'). */
    enum class SignatureSource
    {
      /** The tangent assembled at the converged state, factorised for the analysis. */
      converged_tangent,
      /**
       * The factorisation Newton's last iteration made, of the tangent at the iterate before
       * the converged state, where it made one (else as converged_tangent).
       */
      last_newton_factorisation
    };
    SignatureSource signature_source = SignatureSource::converged_tangent;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Throw InputError where 'Signature from = last Newton factorisation' has nothing to read
     * (no 'Inertia', no 'Schur eigenvalues') or Newton makes no double-precision LDL^T
     * ('Linear solver/Solver' @p solver KLU or Krylov, 'Precision' @p precision single).
     */
    void
    check_signature_source(const std::string &solver, const std::string &precision) const;

    /** Whether the drained criterion takes the smallest eigenvalues of K_uu by LOBPCG. */
    bool
    iterative_drained() const;

    /** Whether a loss of stability is detected (and bracketed): the tangent's signature or the
     * iterative drained criterion. */
    bool
    detects_onset() const;

    /** Whether anything is to be computed. */
    bool
    enabled() const;

    /** Whether the eigenvector of the smallest Schur eigenvalue is needed. */
    bool
    needs_mode() const;

    /** The statistics columns it fills. */
    std::vector<std::string>
    columns() const;
  };


  /** What the stability analysis of one state found. */
  struct StabilityReport
  {
    Inertia inertia;
    /** With 'Onset criterion = drained' by factorisation: the inertia of the displacement block
     * K_uu. */
    Inertia drained_inertia;
    /** With the iterative drained criterion: the smallest eigenvalues of K_uu, ascending. */
    std::vector<double> drained_eigenvalues;
    /** Their LOBPCG iterations. */
    unsigned int        drained_iterations = 0;
    std::vector<double> eigenvalues;
    double              inf_sup = 0.;
    /** With 'Write mode': the eigenvector of eigenvalues[0] (displacement unknowns). */
    dealii::Vector<double> mode;
    /**
     * With 'Onset criterion = drained' and a perturbation, when K_uu is indefinite: the
     * eigenvector of the lowest of the three eigenvalues of K_uu nearest zero (by factorisation)
     * or of lambda_min (iterative); at a bracketed onset, its small negative eigenvalue: the mode
     * that grows at a drained onset (displacement unknowns; empty otherwise).
     */
    dealii::Vector<double> drained_mode;
    double                 condition_number = 0.;
  };


  /**
   * Compute what @p settings ask for at the symmetric tangent @p K (displacement unknowns first,
   * @p n_u of them): the LDL^T factorisation for the inertia and the Schur eigenvalues, and, with
   * the mass matrix of the mu basis that @p mass_mu returns (called only then), the inf-sup
   * constant. @p factorization, if given, is an LDL^T factorisation of @p K already made (the
   * Newton solver's), used instead of factorising @p K again. The iterative drained criterion
   * needs the layout of the displacement unknowns for the AMG's rigid-body modes: @p dim
   * components per DoF and @p u_dof_points (DisplacementBlockAMG::setup()).
   */
  StabilityReport
  analyse_stability(const dealii::TrilinosWrappers::SparseMatrix      &K,
                    const unsigned int                                 n_u,
                    const StabilitySettings                           &settings,
                    const std::function<dealii::FullMatrix<double>()> &mass_mu,
                    const SymmetricFactorization                      *factorization = nullptr,
                    const unsigned int                                 dim           = 2,
                    const std::vector<double>                         *u_dof_points  = nullptr);
} // namespace GelMPM

#endif

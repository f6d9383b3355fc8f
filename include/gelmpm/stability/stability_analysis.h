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
   */
  struct StabilitySettings
  {
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

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

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
    /** With 'Onset criterion = drained': the inertia of the displacement block K_uu. */
    Inertia             drained_inertia;
    std::vector<double> eigenvalues;
    double              inf_sup = 0.;
    /** With 'Write mode': the eigenvector of eigenvalues[0] (displacement unknowns). */
    dealii::Vector<double> mode;
    /**
     * With 'Onset criterion = drained' and a perturbation, when K_uu is indefinite: the
     * eigenvector of the lowest of the three eigenvalues of K_uu nearest zero (at a bracketed
     * onset, its small negative eigenvalue), the mode that grows at a drained onset
     * (displacement unknowns; empty otherwise).
     */
    dealii::Vector<double> drained_mode;
    double                 condition_number = 0.;
  };


  /**
   * Compute what @p settings ask for at the symmetric tangent @p K (displacement unknowns first,
   * @p n_u of them): the LDL^T factorisation for the inertia and the Schur eigenvalues, and, with
   * the mass matrix of the mu basis that @p mass_mu returns (called only then), the inf-sup
   * constant. @p factorization, if given, is an LDL^T factorisation of @p K already made (the
   * Newton solver's), used instead of factorising @p K again.
   */
  StabilityReport
  analyse_stability(const dealii::TrilinosWrappers::SparseMatrix      &K,
                    const unsigned int                                 n_u,
                    const StabilitySettings                           &settings,
                    const std::function<dealii::FullMatrix<double>()> &mass_mu,
                    const SymmetricFactorization                      *factorization = nullptr);
} // namespace GelMPM

#endif

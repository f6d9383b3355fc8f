#ifndef gelmpm_fem_fem_column_h
#define gelmpm_fem_fem_column_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/fem/fem_signature.h>
#include <gelmpm/fem/fem_time_loop.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <memory>

namespace GelMPM
{
  /**
   * @brief Swell-induced buckling of a gel column (paper §4.3, the scene of
   * prm/column_buckling.prm) with the body-fitted FemMixedSystem: an independent check of the
   * time at which the column loses stability. The column [0, H] x [0, 8H] of the initial
   * (pre-swollen) configuration on a uniform conforming mesh of n x 8n square cells.
   *
   * Boundary conditions as in the scene:
   * - left and right faces: traction free, mu = mu_0 (1 - min(t / t_inc, 1)) with mu_0 the
   *   material's (eq. (22) from lambda_0), so that the solvent enters across the width;
   * - top and bottom: rollers (u_y = 0, i.e. u.N = 0) and no flux: the column cannot lengthen,
   *   and axial compression builds up as it swells;
   * - against the rigid motion in x that the rollers allow: u_x = 0 at the bottom-left corner
   *   vertex. The scene holds u.N = 0 on the lowest 0.05H of the left face instead, which is a
   *   union of faces only for n = 20; a vertex is enough, since the pre-buckling state is
   *   uniform along the column (the rollers make it that of an infinitely long column), so
   *   that a segment and a point hold the same translation, and the pin does not stiffen the
   *   buckling mode.
   *
   * The ramp is applied at the end time of every attempt (prescribe(t_begin, t_end) of
   * run_fem_time_loop, FemMixedSystem::set_chemical_potential), backward Euler as the scene's
   * Function of t.
   *
   * The stability of every converged attempt is judged by the signature of the tangent
   * (FemTangentSignature, §3.6) and a loss of stability is bracketed by StepControl, which
   * retakes steps from the last stable state (FemSignatureControl). Without a perturbation the
   * run follows the symmetric (straight) branch past the onset; it measures the onset, not the
   * post-buckling shape.
   */
  class FemColumn
  {
  public:
    struct Parameters
    {
      double       width     = 1.;
      double       height    = 8.;
      unsigned int cells     = 4;    // across the width; 8 times as many along the height
      double       ramp_time = 0.75; // t_inc, tau_d
      unsigned int u_degree  = 2;
      /** Bracket the onset where K_uu becomes indefinite (as 'Stability/Onset criterion =
       * drained'), not where the signature of the tangent leaves (n_u, n_mu, 0). */
      bool drained_onset = false;
    };

    /** What a converged step did. */
    struct Step : FemStep
    {
      /** Prescribed mu/k_BT on the left and right faces at the step's end. */
      double boundary_mu = 0.;
      /** The signature of the tangent at the converged state of the step. */
      FemSignature signature;
      /** Volume change int (det F_n - 1) dV_0 over |Omega_0|: the solvent taken up so far,
       * which drives the axial compression. */
      double relative_volume_change = 0.;
    };

    /** Boundary ids of the mesh. */
    static constexpr dealii::types::boundary_id left = 0, right = 1, bottom = 2, top = 3;

    /** tau_d = (H/2)^2/D (paper §4.3): the 'Characteristic length' of the run. */
    double
    characteristic_length() const;

    /**
     * Builds the mesh and the system. Throws InputError naming the entry of the tool's section
     * 'FE peer' on a value its mesh cannot take, std::invalid_argument on other invalid
     * parameters.
     */
    FemColumn(const FloryRehnerGel<2> &material, const Parameters &parameters);

    /**
     * Run to time_stepping.end_time (whose 'Characteristic length' must be
     * characteristic_length()), calling @p on_step after every converged step. Bracket a loss of
     * stability to @p bisection_tolerance (tau_d; 0: none); while unstable, steps are at most
     * @p unstable_step (0: no cap). Throws std::invalid_argument for another characteristic
     * length.
     */
    FemRunResult
    run(const TimeStepping                      &time_stepping,
        const NewtonSettings                    &newton,
        const LinearSolver                      &linear_solver,
        const double                             bisection_tolerance,
        const double                             unstable_step,
        const std::function<void(const Step &)> &on_step);

    /** Prescribed mu/k_BT on the left and right faces at time @p t (tau_d). */
    double
    boundary_chemical_potential(const double t) const;

    /** The signature of the tangent last assembled (evaluated afresh). */
    FemSignature
    signature();

    const FemMixedSystem<2> &
    system() const;

  private:
    const FloryRehnerGel<2>                &material;
    Parameters                              parameters;
    dealii::Triangulation<2>                triangulation;
    std::unique_ptr<FemMixedSystem<2>>      system_;
    std::unique_ptr<FemTangentSignature<2>> signature_;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_fem_fem_flat_punch_h
#define gelmpm_fem_fem_flat_punch_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/fem/fem_time_loop.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <memory>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Flat punch indentation of a swollen gel (paper §4.2, the scene of prm/flat_punch.prm)
   * with the body-fitted FemMixedSystem: the gel [0, H] x [0, H] of the initial (swollen)
   * configuration on a uniform conforming mesh of n x n cells.
   *
   * Boundary conditions as in the scene: a frictionless, impermeable punch on the top for
   * x <= punch width, u_y = -depth min(t / ramp time, 1) there and u_x free; the rest of the top
   * traction free with mu = mu_top; rollers (u.N = 0) and no flux on the bottom, left and right.
   * The material is the caller's (the scene's: swollen in equilibrium with the solvent,
   * mu_0 = mu_top = 0). The punch edge must fall on a mesh vertex: n times the punch width over H
   * must be a whole number.
   *
   * The time loop is the material point simulator's (run_fem_time_loop). The mesh is the mesh of
   * Omega_0 for the whole run: cells distort with the material, and the run stops when a step
   * cannot converge even at the minimum step (typically a quadrature point with J <= 1, i.e. a
   * cell folding over near the punch edge). deformation_summary() after each step measures how
   * far the mesh is from that.
   */
  class FemFlatPunch
  {
  public:
    struct Parameters
    {
      double       size        = 1.;
      unsigned int cells       = 20;
      double       punch_width = 0.25;
      double       depth       = 0.09;
      double       ramp_time   = 3.125e-6; // tau_d
      unsigned int u_degree    = 2;
      double       mu_top      = 0.;
    };

    /** What a converged step did. */
    struct Step : FemStep
    {
      /** Punch displacement u_y (negative: into the gel), in units of H. */
      double                                punch_displacement = 0.;
      FemMixedSystem<2>::DeformationSummary deformation;
      /** Volume change int (det F_n - 1) dV_0 over |Omega_0|: the solvent taken up (> 0) or
       * squeezed out (< 0); 0 for an undrained (incompressible) response. */
      double relative_volume_change = 0.;
      /** The force of the punch on the gel (per unit thickness, in G H; y < 0 while it pushes
       * down): the consistent reaction at the held punch DoFs (FemMixedSystem::boundary_force),
       * the MPM's `punch_force_x`, `punch_force_y` of prm/flat_punch.prm. */
      dealii::Tensor<1, 2> punch_force;
    };

    /** Boundary ids of the mesh. */
    static constexpr dealii::types::boundary_id left = 0, right = 1, bottom = 2, free_top = 3,
                                                punch = 4;

    /** The material of prm/flat_punch.prm: Table 1, swollen in equilibrium with the solvent
     * (mu_0 = 0, lambda_0 = 2.3488 from eq. (22)). */
    static FloryRehnerGel<2>
    scene_material();

    /**
     * Builds the mesh and the system. Throws InputError naming the entry of the tool's section
     * 'FE peer' on a value its mesh cannot take, std::invalid_argument on other invalid
     * parameters.
     */
    FemFlatPunch(const FloryRehnerGel<2> &material, const Parameters &parameters);

    /** Run to time_stepping.end_time, calling @p on_step after every converged step. */
    FemRunResult
    run(const TimeStepping                      &time_stepping,
        const NewtonSettings                    &newton,
        const LinearSolver                      &linear_solver,
        const std::function<void(const Step &)> &on_step);

    /**
     * The converged fields along the whole top (punch and free part), ordered by the initial x,
     * at @p per_face + 1 points per face, without repeated points.
     */
    std::vector<FemMixedSystem<2>::BoundarySample>
    top_samples(const unsigned int per_face) const;

    /** Prescribed punch displacement u_y at time @p t (tau_d). */
    double
    punch_displacement(const double t) const;

    const FemMixedSystem<2> &
    system() const;

  private:
    const FloryRehnerGel<2>           &material;
    Parameters                         parameters;
    dealii::Triangulation<2>           triangulation;
    std::unique_ptr<FemMixedSystem<2>> system_;
  };
} // namespace GelMPM

#endif

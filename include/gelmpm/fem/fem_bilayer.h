#ifndef gelmpm_fem_fem_bilayer_h
#define gelmpm_fem_fem_bilayer_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/fem/fem_time_loop.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <memory>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The bilayer actuator of prm/bilayer_actuator.prm with the body-fitted FemMixedSystem
   * and two materials: an independent check of the curvature the MPM computes with material
   * regions (doc/own_scenes.md, §6).
   *
   * Half a strip, 0 < x < length/2, 0 < y < thickness of the initial configuration, on n_x x n_y
   * square cells (n_y through the thickness, even, so that the interface y = thickness/2 is a
   * mesh line; n_x = n_y length / (2 thickness)). The upper layer is the Table 1 gel
   * (material_id 0), the lower one the passive gel of chi = chi_passive (material_id 1). Both
   * start stress-free in equilibrium with the Table 1 mu_0, each at its own lambda_0 from
   * eq. (22) (FloryRehnerGel::lambda_0_from_mu_0), as the scene's region does.
   *
   * Boundary conditions as in the scene: the plane x = 0 is a plane of symmetry (u_x = 0, no
   * flux); its lowest point (0, 0) is pinned in y; the lower face, the upper face and the free
   * end are in a bath of mu(t)/k_BT = mu_bath min(t/t_ramp, 1) + mu_start max(1 - t/t_ramp, 0)
   * (the scene: -0.04 min(t, 1) - 0.1459745 max(1 - t, 0)), applied at the end time of every
   * attempt (backward Euler, as the scene's Function of t).
   */
  class FemBilayer
  {
  public:
    struct Parameters
    {
      double       length      = 4.;  // the whole strip; half of it is meshed
      double       thickness   = 0.2; // both layers, each half of it
      unsigned int cells       = 8;   // through the thickness
      double       chi_passive = 0.3;
      double       mu_bath     = -0.04;
      double       mu_start    = -0.1459745;
      double       ramp_time   = 1.; // tau_d = thickness^2 / D
      unsigned int u_degree    = 2;
    };

    /** What a converged step did. */
    struct Step : FemStep
    {
      /** Curvature 1/R of the circle fitted to the lower surface (current positions). */
      double curvature = 0.;
      /** u_y of the lower corner of the free end (x = length/2, y = 0). */
      double tip_deflection = 0.;
      /** int (det F_n - 1) dV_0 / |Omega_0|: the solvent taken up. */
      double relative_volume_change = 0.;
    };

    /** Boundary ids of the mesh. */
    static constexpr dealii::types::boundary_id symmetry = 0, end = 1, bottom = 2, top = 3;
    /** material_ids of the two layers. */
    static constexpr dealii::types::material_id active = 0, passive = 1;

    /** The gels of the two layers, indexed by material_id: Table 1 and the passive one. */
    static std::vector<FloryRehnerGel<2>>
    layer_materials(const double chi_passive);

    /**
     * Builds the mesh and the system with the layers of layer_materials(chi_passive). Throws
     * InputError naming the entry of gelmpm-fem-bilayer's section 'FE peer' on a value its mesh
     * cannot take, std::invalid_argument on other invalid parameters.
     */
    explicit FemBilayer(const Parameters &parameters);

    /**
     * The same with the gels @p materials of the layers, indexed by material_id (the active
     * upper layer first), e.g. a scene's 'Material/Regions'; Parameters::chi_passive is not used.
     */
    FemBilayer(const Parameters &parameters, const std::vector<FloryRehnerGel<2>> &materials);

    /** Run to time_stepping.end_time, calling @p on_step after every converged step. */
    FemRunResult
    run(const TimeStepping                      &time_stepping,
        const NewtonSettings                    &newton,
        const LinearSolver                      &linear_solver,
        const std::function<void(const Step &)> &on_step);

    /** The bath's mu/k_BT at time @p t (tau_d). */
    double
    bath_chemical_potential(const double t) const;

    /** The current positions x = X + u_n of the lower surface, ordered by X, 8 per face. */
    std::vector<dealii::Point<2>>
    lower_surface() const;

    /** 1/R of the least-squares (Kasa) circle through @p points. */
    static double
    fitted_curvature(const std::vector<dealii::Point<2>> &points);

    const FemMixedSystem<2> &
    system() const;

    const std::vector<FloryRehnerGel<2>> &
    materials() const;

  private:
    Parameters                         parameters;
    std::vector<FloryRehnerGel<2>>     materials_;
    dealii::Triangulation<2>           triangulation;
    std::unique_ptr<FemMixedSystem<2>> system_;
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_fem_fem_constrained_swelling_h
#define gelmpm_fem_fem_constrained_swelling_h

#include <gelmpm/fem/fem_mixed_system.h>
#include <gelmpm/fem/fem_time_loop.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/time_stepping.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <memory>

namespace GelMPM
{
  /**
   * @brief Constrained swelling of a gel layer (paper §4.1) with the body-fitted FemMixedSystem:
   * the layer [0, width] x [0, height] (initial configuration, lengths in h_0) on a conforming
   * mesh, fixed bottom (u = 0), rollers on the sides (u_x = 0), on the top mu = mu_top for t > 0
   * and u_x = 0 (the tangential constraint of §4.1); traction free and impermeable elsewhere.
   *
   * The time loop is the material point simulator's (run_fem_time_loop).
   */
  class FemConstrainedSwelling
  {
  public:
    struct Parameters
    {
      double       width   = 0.2;
      double       height  = 1.;
      unsigned int cells_x = 2;
      unsigned int cells_y = 20;
      /** Node grading towards the top in y: y_i = h (1 - (1 - i/n)^g); 1 is uniform. */
      double                         grading  = 1.;
      unsigned int                   u_degree = 2;
      double                         mu_top   = 0.;
      FemMixedSystem<2>::Formulation formulation =
        FemMixedSystem<2>::Formulation::previously_converged_lagrangian;
    };

    /** What a converged step did: the loop's record and the thickness change. */
    struct Step : FemStep
    {
      /** Mean top displacement over the initial thickness. */
      double delta_h_over_h0 = 0.;
    };

    /**
     * Builds the mesh and the system. Throws InputError naming the entry of the tool's section
     * 'FE peer' on a value its mesh cannot take, std::invalid_argument on other invalid
     * parameters.
     */
    FemConstrainedSwelling(const FloryRehnerGel<2> &material, const Parameters &parameters);

    /**
     * Run from t = 0 to time_stepping.end_time, calling @p on_step after every converged step.
     * Returns false when a step would fall below the minimum step or the maximum number of steps
     * is reached (the message is in failure()).
     */
    bool
    run(const TimeStepping                      &time_stepping,
        const NewtonSettings                    &newton,
        const LinearSolver                      &linear_solver,
        const std::function<void(const Step &)> &on_step);

    /** Why run() stopped early. */
    const std::string &
    failure() const;

    const FemMixedSystem<2> &
    system() const;

    /** Total Newton iterations of the converged steps of the last run(). */
    unsigned int
    total_newton_iterations() const;

  private:
    const FloryRehnerGel<2>           &material;
    Parameters                         parameters;
    dealii::Triangulation<2>           triangulation;
    std::unique_ptr<FemMixedSystem<2>> system_;
    std::string                        failure_;
    unsigned int                       newton_iterations = 0;
  };
} // namespace GelMPM

#endif

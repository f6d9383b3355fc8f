#ifndef gelmpm_simulator_simulator_h
#define gelmpm_simulator_simulator_h

#include <gelmpm/core/parameters.h>
#include <gelmpm/simulator/checkpointer.h>
#include <gelmpm/simulator/material_point_model.h>
#include <gelmpm/simulator/run_record.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/stability_monitor.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/run_progress.h>
#include <gelmpm/solvers/time_loop.h>
#include <gelmpm/solvers/time_stepping.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A GelMPM run: reads a scene's parameters, checks them, and carries the scene out.
   *
   * The conductor of a run. Its parts each own one job: the Scene (gel, grid, body, boundary,
   * points, spaces, system, and the checks of the scene's own sections), the RunRecord (the
   * output directory and every file and log line about the steps), the Checkpointer (when a
   * checkpoint is due, writing it, resuming from it), the TimeLoop (the steps, driving the
   * MaterialPointModel) and the StabilityMonitor. The simulator builds them in order, checks
   * what needs more than one of them, and, as a StepObserver of the loop, tells the record and
   * the checkpointer what happened.
   *
   * Construction parses and validates every parameter and throws InputError on bad input, so
   * that nothing is written before the whole scene is known to be consistent. run() creates the
   * output directory, writes the parameters as used, and then advances the coupled problem in
   * time: per step the grid is reset, the cells re-classified, the extended bases rebuilt,
   * Newton solves for (du, mu), and the material points are updated (paper Fig. 2b). A step
   * whose Newton iteration fails is retried from the last converged state with a smaller step.
   *
   * @tparam dim Space dimension (2: plane strain; 3).
   */
  template <int dim>
  class Simulator : private StepObserver
  {
  public:
    /** Declare every section a scene may contain, for the given structure. */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const SceneStructure &structure);

    /**
     * Read and check all parameters from @p prm (filled from @p scene_file and overrides).
     * Throws InputError on inconsistent input. With @p resume, the run continues from the
     * checkpoint in the output directory, which is read and checked here too (InputError if
     * there is none, if it is damaged, or if it was written by another version or for other
     * parameters).
     */
    Simulator(dealii::ParameterHandler &prm,
              const SceneStructure     &structure,
              const std::string        &scene_file,
              const bool                resume = false);

    /** Releases the direct solver before the system whose matrix it factorised. */
    ~Simulator();

    /**
     * The table of the boundary pieces: surface points, initial area and the range of each
     * component of the initial normal, so that a selector that takes the wrong points shows at
     * once; with material regions, theirs: volume points, initial volume and the constants that
     * differ from the section 'Material' (printed by run() and by `gelmpm --check`).
     */
    void
    print_piece_table() const;

    /** Run the scene. Returns 0 on success, 1 if the run stopped early (no convergence). */
    int
    run();

  private:
    void
    print_header();
    /** The scene's material points, and the counts and scales the run derives from them. */
    void
    create_material_points();
    /**
     * Why a run that cannot converge at @p t (tau_d) may fail there, from boundary_jump: a
     * jump of the boundary's chemical potential swells a layer thinner than a cell until
     * solvent has diffused across one, at t ~ (h/L)^2; empty otherwise.
     */
    std::string
    jump_hint(const double t) const;
    /** Create the system, the model, the loop and its observers; write the initial state (or
     * resume). */
    void
    start();
    /** The stability monitor, as the loop's second observer. */
    void
    add_stability_monitor();
    /**
     * End the run on @p signal after the last accepted step: write its output unless written,
     * say so, and return the conventional status 128 + @p signal. Not @p between_steps (stopped
     * between the attempts of a step), the checkpoint leaves out the factorisation, which is of
     * a rejected attempt.
     */
    int
    stop_on_signal(const int signal, const bool between_steps = true);
    /** The run that 'Time stepping/End at equilibrium' ended: said, and an event where the
     * run writes events (its last output and checkpoint are written as at the end time). */
    void
    end_at_equilibrium();
    /** The run that cannot converge beyond the current time: said, with why; status 1. */
    int
    stop_on_failure();
    /**
     * Steps until the end time: 0, 1 if the run stopped early, 128 + the signal if a signal
     * asked it to stop (printed).
     */
    int
    advance_to_end();
    /** What the run cost, at its end (not in test mode). */
    void
    print_costs() const;
    /** The time (tau_d) and the number of the last accepted step (0 before the loop exists). */
    double
    current_time() const;
    unsigned int
    current_step() const;

    /** StepObserver: the points per cell for the grid output, before the step's attempts. */
    void
    step_begins() override;
    /** StepObserver: the boundary pieces' forces and fluxes at the converged state. */
    bool
    before_update(dealii::Vector<double> &solution, const double dt) override;
    /** StepObserver: statistics, log line and output of an accepted step. */
    void
    accepted(const AcceptedStep &step, const dealii::Vector<double> &solution) override;
    /** StepObserver: a checkpoint when one is due. */
    void
    between_steps() override;

    // First, so that the wall time of a run counts its set-up.
    RunProgress::Clock::time_point run_start = RunProgress::Clock::now();
    SceneStructure                 structure;
    Scene<dim>                     scene;
    LinearSolver                   linear_solver;
    NewtonSettings                 newton;
    TimeStepping                   time_stepping;
    StabilitySettings              stability;

    std::string                scene_file;
    dealii::ConditionalOStream pcout;
    // Errors and stops, which every rank meets together, are reported by rank 0 alone.
    dealii::ConditionalOStream pcerr;
    dealii::TimerOutput        timer;
    RunRecord<dim>             record;
    Checkpointer<dim>          checkpointer;

    std::string parameters_as_used;
    /** The largest jump of a prescribed chemical potential at t = 0 away from mu_0, in words
     * (empty: none above a tenth of |mu_0|). */
    std::string                              boundary_jump;
    std::unique_ptr<MaterialPointModel<dim>> model;
    std::unique_ptr<TimeLoop>                loop;
    std::unique_ptr<StabilityMonitor<dim>>   monitor; // with the stability analysis
    std::unique_ptr<RunProgress>             progress;

    unsigned int n_volume_points  = 0;
    unsigned int n_surface_points = 0;
    double       body_volume      = 0.;
    // tau_d and Newton's residual scales, from the gel and the initial body (handed to the loop).
    RunScales scales;
  };


  /**
   * Read @p scene_file with @p overrides, check it and run it, as `gelmpm` does: for tests and
   * tools that run a whole scene in-process. Returns Simulator::run()'s status; throws InputError
   * on bad input.
   */
  template <int dim>
  int
  run_scene_file(const std::string &scene_file, const std::vector<ParameterOverride> &overrides);
} // namespace GelMPM

#endif

#ifndef gelmpm_simulator_simulator_h
#define gelmpm_simulator_simulator_h

#include <gelmpm/core/parameters.h>
#include <gelmpm/core/sparse_entries.h>
#include <gelmpm/io/checkpoint.h>
#include <gelmpm/io/directory_lock.h>
#include <gelmpm/io/grid_output.h>
#include <gelmpm/io/output_settings.h>
#include <gelmpm/io/particle_output.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/boundary_balance.h>
#include <gelmpm/simulator/material_point_model.h>
#include <gelmpm/simulator/observables.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/stability_monitor.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/run_progress.h>
#include <gelmpm/solvers/step_control.h>
#include <gelmpm/solvers/time_loop.h>
#include <gelmpm/solvers/time_stepping.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A GelMPM run: reads a scene's parameters, checks them, and carries the scene out.
   *
   * The scene itself (gel, grid, body, boundary, points, spaces, system) is a Scene; the steps
   * are the TimeLoop's, which drives the MaterialPointModel of the scene and tells its observers
   * (this simulator and the StabilityMonitor) what happens. The simulator keeps the
   * configuration, the files, the output and the checkpoints: as a StepObserver it records each
   * accepted step (statistics.csv, the log, ParaView output when due) and writes checkpoints
   * between steps.
   *
   * Construction parses and validates every parameter and throws InputError on bad input, so
   * that nothing is written before the whole scene is known to be consistent. run() creates the
   * output directory, writes the parameters as used, generates the material points and then
   * advances the coupled problem in time: per step the grid is reset, the cells re-classified,
   * the extended bases rebuilt, Newton solves for (du, mu), and the material points are updated
   * (paper Fig. 2b). A step whose Newton iteration fails is retried from the last converged
   * state with a smaller step.
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
     * once (printed by run() and by `gelmpm --check`).
     */
    void
    print_piece_table() const;

    /** Run the scene. Returns 0 on success, 1 if the run stopped early (no convergence). */
    int
    run();

    /**
     * Say once when the step that began at @p t_begin extrapolated control points inexactly next
     * to the grid's edge; accept such control points from the first accepted step on.
     */
    void
    note_inexact_extrapolation(const double t_begin);

    /** The pores' self-contact and crease events since the last step, into events.csv. */
    void
    record_pore_events();

    /** One row of events.csv: @p name at @p t_over_tau_d, of pore @p pore (0: none). */
    void
    write_event(const std::string &name, const double t_over_tau_d, const int pore);

  private:
    void
    print_header();

    /** Create and lock the output directory, remove earlier output, write the parameters. */
    void
    prepare_output_directory();
    /** Remove the files an earlier run wrote to the output directory (only names gelmpm writes). */
    void
    remove_earlier_output() const;
    /** The scene's material points, and the counts and scales the run derives from them. */
    void
    create_material_points();
    /** InputError if no boundary condition holds the body against a rigid motion. */
    void
    check_rigid_motions() const;
    /** InputError if the extended bases cannot be built on the initial configuration. */
    void
    check_grid_resolves_body();
    /**
     * InputError if a boundary function is not finite on its piece during the run. Notes a jump
     * of a prescribed chemical potential at t = 0 (boundary_jump).
     */
    void
    check_boundary_values();

    /**
     * Why a run that cannot converge at @p t (tau_d) may fail there, from boundary_jump: a
     * jump of the boundary's chemical potential swells a layer thinner than a cell until
     * solvent has diffused across one, at t ~ (h/L)^2; empty otherwise.
     */
    std::string
    jump_hint(const double t) const;

    /** prepare_output_directory()'s work, on the one rank that does it. */
    void
    prepare_output_directory_here();

    /** The volume points in each cell of the background grid, over all ranks. */
    std::vector<unsigned int>
    volume_points_per_cell() const;
    /** InputError if the run would overwrite the scene file's own directory. */
    void
    check_output_directory(bool resume) const;
    /** The columns of the rigid obstacles: per obstacle <name>_force_x, ..., <name>_contact_area,
     * <name>_contact_radius. */
    std::vector<std::string>
    obstacle_columns() const;

    void
    open_statistics();
    /** Create the system and the output files; write the initial state (or resume). */
    void
    start();
    /**
     * Whether a checkpoint is due after the step just taken ('Checkpoint/Interval steps' and
     * 'Interval minutes'; at the end of the run).
     */
    bool
    checkpoint_due() const;
    /**
     * Write the checkpoint of the state after the last converged step (CheckpointHeader, the
     * material points, serialize_run_state()), with the .csv files on the disk first.
     */
    void
    write_checkpoint(const bool with_tangent = true);
    /**
     * Continue from the checkpoint read by the constructor: the material points and the run's
     * state, the .csv files cut back and the ParaView series rewritten to where they were.
     */
    void
    restore_checkpoint();
    /**
     * Write or read (boost serialization) everything besides the material points that the next
     * step, the output schedule and the files read: time, step, the step control, the last step
     * (predictor), the chemical-potential coefficients of the initial guess, the stability
     * bracketing, the observables' events and the ParaView series.
     */
    template <class Archive>
    void
    serialize_run_state(Archive &ar);
    /**
     * End the run on @p signal after the last accepted step: write its output unless written,
     * say so, and return the conventional status 128 + @p signal. Not @p between_steps (stopped
     * between the attempts of a step), the checkpoint leaves out the factorisation, which is of
     * a rejected attempt.
     */
    int
    stop_on_signal(const int signal, const bool between_steps = true);
    /**
     * Steps until the end time: 0, 1 if the run stopped early, 128 + the signal if a signal
     * asked it to stop (printed).
     */
    int
    advance_to_end();
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
    /** The step line of the log for the step just accepted. */
    void
    print_step_line(const NewtonReport &report, const double step_dt) const;
    /** One row of statistics.csv; @p solution is the converged step's (nullptr initially). */
    void
    record_statistics(const NewtonReport           &report,
                      const unsigned int            attempts,
                      const dealii::Vector<double> *solution);
    /** Keep the critical @p mode of the converged step for the next output (mode.pvd). */
    void
    record_mode(const dealii::Vector<double> &mode);
    void
    write_output();
    /** Record the initial grid for GridOutput: cells classified from the points, du = 0, mu_0. */
    void
    record_initial_grid();
    // First, so that the wall time of a run counts its set-up.
    RunProgress::Clock::time_point run_start = RunProgress::Clock::now();
    SceneStructure                 structure;
    Scene<dim>                     scene;
    OutputSettings                 output_settings;
    LinearSolver                   linear_solver;
    NewtonSettings                 newton;
    TimeStepping                   time_stepping;
    Observables<dim>               observables;
    BoundaryBalance<dim>           balance;
    StabilitySettings              stability;

    std::string scene_file;
    std::string parameters_as_used;
    /** The largest jump of a prescribed chemical potential at t = 0 away from mu_0, in words
     * (empty: none above a tenth of |mu_0|). */
    std::string                boundary_jump;
    dealii::ConditionalOStream pcout;
    // Errors and stops, which every rank meets together, are reported by rank 0 alone.
    dealii::ConditionalOStream pcerr;
    dealii::TimerOutput        timer;

    std::unique_ptr<ParticleOutput<dim>>     particle_output;
    std::unique_ptr<GridOutput<dim>>         grid_output;
    std::unique_ptr<GridOutput<dim>>         mode_output;           // with Stability/Write mode
    bool                                     mode_recorded = false; // with Output/Write grid
    std::vector<unsigned int>                grid_volume_points;    // per cell, start of the step
    StatisticsFile                           statistics;
    StatisticsFile                           stability_file; // stability.csv, with the inertia
    StatisticsFile                           events_file;    // events.csv (inertia or pores)
    std::unique_ptr<MaterialPointModel<dim>> model;
    std::unique_ptr<TimeLoop>                loop;
    std::unique_ptr<StabilityMonitor<dim>>   monitor; // with the stability analysis
    std::unique_ptr<RunProgress>             progress;
    bool                                     inexact_extrapolation_noted = false;
    // The pieces' terms of the step being accepted, taken before a kick moves its state.
    std::vector<typename MixedSystem<dim>::PieceBalance> balances;
    /** The rigid obstacles' reactions of the step being accepted. */
    std::vector<typename MixedSystem<dim>::ObstacleReaction> reactions;

    // Held by rank 0 from the preparation of the output directory to the end of the run.
    std::unique_ptr<DirectoryLock> output_lock;

    CheckpointSettings checkpoint_settings;
    // Read from a checkpoint: the factorisation to restore at the first step (see
    // serialize_run_state()).
    std::vector<bool>                     resumed_classification;
    SparseEntries                         resumed_tangent;
    std::unique_ptr<CheckpointReader>     resume_from;     // with --resume, until restored
    std::chrono::steady_clock::time_point last_checkpoint; // or the start
    unsigned int checkpoint_step = dealii::numbers::invalid_unsigned_int; // of the last one

    unsigned int n_volume_points  = 0;
    unsigned int n_surface_points = 0;
    double       body_volume      = 0.;
    // tau_d and Newton's residual scales, from the gel and the initial body (handed to the loop).
    RunScales    scales;
    unsigned int output_step = dealii::numbers::invalid_unsigned_int; // of the last output
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

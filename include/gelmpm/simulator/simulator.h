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
#include <gelmpm/simulator/observables.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/run_progress.h>
#include <gelmpm/solvers/step_control.h>
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
   * The scene itself (gel, grid, body, boundary, points, spaces, system) is a Scene; the
   * simulator adds what a run needs around it: time stepping, Newton, output, statistics and the
   * stability analysis.
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
  class Simulator
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
    /** How advance() ended. */
    enum class StepOutcome
    {
      accepted,   ///< a converged step was taken
      failed,     ///< the step size fell below the minimum
      interrupted ///< a stop signal arrived before an attempt; the last accepted state stands
    };

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
    /** InputError if the extended bases cannot be built on the initial configuration. */
    void
    check_grid_resolves_body();
    /** InputError if a boundary function is not finite on its piece during the run. */
    void
    check_boundary_values();

    /** prepare_output_directory()'s work, on the one rank that does it. */
    void
    prepare_output_directory_here();

    /** The volume points in each cell of the background grid, over all ranks. */
    std::vector<unsigned int>
    volume_points_per_cell() const;
    /** InputError if the run would overwrite the scene file's own directory. */
    void
    check_output_directory() const;
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
    /**
     * Take one converged step. A stop signal is looked for before every attempt, so that a step
     * whose attempts keep failing can be stopped within one attempt.
     */
    StepOutcome
    advance();
    /** The step line of the log for the step just accepted. */
    void
    print_step_line(const NewtonReport &report, const double step_dt) const;
    /** One row of statistics.csv; @p solution is the converged step's (nullptr initially). */
    void
    record_statistics(const NewtonReport           &report,
                      const unsigned int            attempts,
                      const dealii::Vector<double> *solution);
    /** The stability columns of statistics.csv for a converged step. */
    void
    record_stability(const StabilityReport &result);
    /**
     * Hand the signature of a converged attempt to the step control (bracketing of a loss of
     * stability, steps while unstable) and log what it decided.
     */
    StepControl::Verdict
    judge_signature(const StabilityReport &result);
    /** A bracketed loss of stability: to the log and to stability.csv. */
    void
    report_onset(const StabilityReport &result);
    /**
     * Add 'Stability/Perturbation amplitude' times the critical @p mode (displacement unknowns,
     * scaled and signed by 'Perturbation direction') to the converged @p solution.
     */
    void
    perturb_along_mode(const dealii::Vector<double> &mode, dealii::Vector<double> &solution) const;
    /** Keep the critical @p mode of the converged step for the next output (mode.pvd). */
    void
    record_mode(const dealii::Vector<double> &mode);
    void
    write_output();
    /** Record the initial grid for GridOutput: cells classified from the points, du = 0, mu_0. */
    void
    record_initial_grid();
    /** Chemical-potential coefficients of every control point of the mu grid, from a solution. */
    void
    store_mu_coefficients(const dealii::Vector<double> &solution);
    /**
     * Initial guess for a step of @p dt: du = 0, or with 'Newton/Initial displacement =
     * extrapolated' the last step's motion scaled to @p dt; mu from the points or from the last
     * converged coefficients ('Newton/Initial chemical potential').
     */
    void
    initial_guess(dealii::Vector<double> &solution, const double dt = 0.) const;
    /**
     * With 'Time stepping/Displacement tolerance': whether the converged @p solution of a step of
     * @p dt may be accepted by the error control (else the step was cut, and @p failure says
     * why).
     */
    bool
    error_acceptable(const dealii::Vector<double> &solution, const double dt, std::string &failure);

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

    std::string                scene_file;
    std::string                parameters_as_used;
    dealii::ConditionalOStream pcout;
    // Errors and stops, which every rank meets together, are reported by rank 0 alone.
    dealii::ConditionalOStream pcerr;
    dealii::TimerOutput        timer;

    std::unique_ptr<ParticleOutput<dim>> particle_output;
    std::unique_ptr<GridOutput<dim>>     grid_output;
    std::unique_ptr<GridOutput<dim>>     mode_output;           // with Stability/Write mode
    bool                                 mode_recorded = false; // with Output/Write grid
    std::vector<unsigned int>            grid_volume_points;    // per cell, start of the step
    StatisticsFile                       statistics;
    StatisticsFile                       stability_file; // stability.csv, with the inertia
    StatisticsFile                       events_file;    // events.csv (inertia or pores)
    std::unique_ptr<StepControl>         control;
    std::unique_ptr<RunProgress>         progress;
    bool                                 announced_bracketing        = false;
    bool                                 inexact_extrapolation_noted = false;
    bool                                 ended_at_onset              = false; // End at onset
    Inertia                              last_stable_inertia;
    double                               last_eigenvalue = 0.;
    std::vector<double>                  mu_coefficients; // per mu control point
    // Over all attempts of the run, for the summary at its end.
    unsigned long n_newton_iterations = 0, n_factorizations = 0, n_new_patterns = 0;
    unsigned long n_repartitions = 0;
    // Steps accepted although their error estimate exceeds its tolerance whatever the step: said
    // once when it first happens, counted in the summary.
    unsigned long n_uncontrolled_errors = 0;
    // On several ranks: the ratio of the largest number of points on a rank to the mean above
    // which the grid is partitioned anew (a repartition costs about one grid reset).
    static constexpr double largest_imbalance         = 1.1;
    double                  imbalance_after_partition = 1.;
    std::vector<bool>       mu_known;                // coefficient holds a current value
    std::vector<double>     mu_projection;           // points' mu on the step's basis
    std::vector<double>     displacement_projection; // last step's motion on the step's basis
    double                  last_dt = 0.;            // the last accepted step (0 before the first)

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
    double       time             = 0.; // in tau_d
    unsigned int step             = 0;
    unsigned int output_step      = dealii::numbers::invalid_unsigned_int; // of the last output
    double       tau_d            = 1.; // L^2 / D, physical time of one tau_d
    double       scale_u          = 1.;
    double       scale_mu         = 1.;
    double       next_output_time = 0.;
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

#ifndef gelmpm_simulator_run_record_h
#define gelmpm_simulator_run_record_h

#include <gelmpm/io/directory_lock.h>
#include <gelmpm/io/grid_output.h>
#include <gelmpm/io/output_settings.h>
#include <gelmpm/io/particle_output.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/simulator/boundary_balance.h>
#include <gelmpm/simulator/material_point_model.h>
#include <gelmpm/simulator/observables.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/solvers/newton.h>
#include <gelmpm/solvers/run_progress.h>
#include <gelmpm/solvers/time_loop.h>
#include <gelmpm/stability/stability_analysis.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The record of a GelMPM run: its output directory and everything written there or to
   * the log about the steps.
   *
   * It owns the 'Output' section and the directory it names (checked before anything is
   * written, created, locked for the run, cleared of an earlier run's files, with the parameters
   * as used), what is measured at an accepted step ('Observables', 'Boundary balance' and the
   * obstacles' reactions) and the files that hold it: statistics.csv, stability.csv (rows the
   * StabilityMonitor writes), events.csv, the ParaView series of the material points, the
   * background grid and the critical mode, and the log's line per step and its notes.
   *
   * The record only writes: it decides nothing about the run. The Simulator tells it what
   * happened (an accepted step, an event, the end); the Checkpointer asks it for the files'
   * lengths and its part of the run's state, and rewinds the files to a checkpoint. Kept apart
   * from the Simulator so that the files of a run have one owner, and the conductor of the run
   * reads as the sequence of a run.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RunRecord
  {
  public:
    /**
     * Read 'Output', 'Observables' and 'Boundary balance' (InputError on bad values) for the run
     * of @p scene, read from @p scene_file, with the stability analysis @p stability (its
     * columns and files). The log is @p log, the output's time goes to @p timer.
     */
    RunRecord(dealii::ParameterHandler       &prm,
              const std::vector<std::string> &boundary_pieces,
              const std::string              &scene_file,
              Scene<dim>                     &scene,
              const StabilitySettings        &stability,
              dealii::ConditionalOStream     &log,
              dealii::TimerOutput            &timer);

    /** The 'Output' section. */
    const OutputSettings &
    settings() const;

    /** InputError if the run would write into the scene file's own directory (and more: see
     * GelMPM::check_output_directory()); @p resume: the directory holds the run to continue. */
    void
    check_output_directory(const bool resume) const;

    /**
     * Create and lock the output directory, remove an earlier run's output unless @p resume,
     * write @p parameters_as_used (parameters.prm) and the scene file (original.prm). Rank 0
     * does it; the lock is held until the record is destroyed.
     */
    void
    prepare_directory(const std::string &parameters_as_used, const bool resume);

    /**
     * Make the ParaView outputs and set the observables' scales for the system just created;
     * record the initial grid unless @p resume (with the first iterate of @p model).
     */
    void
    create_outputs(const MaterialPointModel<dim> &model, const bool resume);

    /**
     * From here on the step and time are @p loop's, the wall time @p progress's, the times
     * scaled by @p scales (tau_d); @p end_time for the log's percentage.
     */
    void
    attach(const TimeLoop    &loop,
           const RunProgress &progress,
           const RunScales   &scales,
           const double       end_time);

    /**
     * Open statistics.csv, and stability.csv and events.csv where the run writes them; with
     * @p resumed_sizes (the lengths a checkpoint recorded) continue each file from there.
     */
    void
    open_files(const std::map<std::string, std::uint64_t> *resumed_sizes = nullptr);

    /** The initial state: its row of statistics.csv and its output. */
    void
    record_initial_state();

    /** Before a step's attempts: the points per cell for the grid's output. */
    void
    step_begins();

    /**
     * The boundary pieces' terms and the obstacles' reactions at the converged @p solution of a
     * step of length @p dt, before a kick moves it.
     */
    void
    take_balances(const dealii::Vector<double> &solution, const double dt);

    /** An accepted step: the grid's state, its row of statistics.csv, its log line. */
    void
    record_step(const AcceptedStep &step, const dealii::Vector<double> &solution);

    /**
     * Say once that the step that began at @p t_begin extrapolated @p n_inexact control points
     * inexactly next to the grid's edge.
     */
    void
    note_inexact_extrapolation(const unsigned int n_inexact, const double t_begin);

    /** The pores' self-contact and crease events since the last step, into events.csv. */
    void
    record_pore_events();

    /**
     * The columns of the gel's contact with itself for @p solution, and the event 'self_contact'
     * when parts of its surface touch where none did at the last accepted step.
     */
    void
    record_self_contact(const dealii::Vector<double> &solution);

    /** Whether the run writes events.csv: with a stability analysis that detects an onset or
     * an observable that has events (as open_files() opens it). */
    bool
    writes_events() const;

    /** One row of events.csv: @p name at @p t_over_tau_d, of pore @p pore (0: none). */
    void
    write_event(const std::string &name, const double t_over_tau_d, const int pore);

    /** Keep the critical @p mode of the converged step for the next output (mode.pvd). */
    void
    record_mode(const dealii::Vector<double> &mode);

    /** Whether the critical mode is written ('Stability/Write mode'). */
    bool
    writes_mode() const;

    /** The ParaView output of the current state. */
    void
    write_output();

    /** Whether the current step's output is written. */
    bool
    output_written() const;

    /** In test mode, the last row of statistics.csv but its wall-clock columns, to the log. */
    void
    print_final_row() const;

    /** statistics.csv, for the StabilityMonitor's columns. */
    StatisticsFile &
    statistics();

    /** stability.csv, for the StabilityMonitor's rows. */
    StatisticsFile &
    stability_rows();

    /**
     * The bytes of each file a checkpoint must find again: the .csv files as written, and the
     * files the ParaView series list.
     */
    std::map<std::string, std::uint64_t>
    file_sizes() const;

    /** Put the .csv files on the disk (rank 0; before a checkpoint counts their rows). */
    void
    sync_files() const;

    /** After a resume: rewrite the ParaView series to where the checkpoint left them. */
    void
    restore_series();

    /**
     * Boost serialization of the record's counters (the step of the last output, whether the
     * inexact extrapolation was said, whether a mode is recorded). With serialize_series(), in
     * the checkpoint's order (Checkpointer::serialize_run_state()).
     */
    template <class Archive>
    void
    serialize_counters(Archive &ar)
    {
      ar &output_step &inexact_extrapolation_noted &mode_recorded;
      // Only with 'Contact/Self contact', so that the checkpoints of other scenes stay as they
      // were.
      if (scene.contact.self_contact.enabled())
        ar &self_touching;
    }

    /** Boost serialization of the observables' events, the balances' sums and the series. */
    template <class Archive>
    void
    serialize_series(Archive &ar)
    {
      ar &observables &balance &*particle_output;
      if (grid_output)
        ar &*grid_output;
      if (mode_output)
        ar &*mode_output;
    }

  private:
    /** prepare_directory()'s work, on the one rank that does it. */
    void
    prepare_directory_here(const std::string &parameters_as_used, const bool resume);
    /** Remove the files an earlier run wrote to the output directory (only names gelmpm writes). */
    void
    remove_earlier_output() const;
    /** The columns of statistics.csv. */
    std::vector<std::string>
    statistics_columns() const;
    /** The columns of stability.csv. */
    std::vector<std::string>
    stability_columns() const;
    /** The columns of the rigid obstacles: per obstacle <name>_force_x, ..., <name>_contact_area,
     * <name>_contact_radius. */
    std::vector<std::string>
    obstacle_columns() const;
    /** The obstacles' reactions into the current row; zero unless @p known (the initial row). */
    void
    set_obstacle_columns(const bool known);
    /** One row of statistics.csv; @p solution is the converged step's (nullptr initially). */
    void
    record_statistics(const NewtonReport           &report,
                      const unsigned int            attempts,
                      const dealii::Vector<double> *solution);
    /** The step line of the log for the step just accepted. */
    void
    print_step_line(const NewtonReport &report, const double step_dt) const;
    /** Record the initial grid for GridOutput: cells classified from the points, du = 0, mu_0. */
    void
    record_initial_grid(const MaterialPointModel<dim> &model);
    /** The time (tau_d) and the number of the last accepted step (0 before the loop exists). */
    double
    current_time() const;
    unsigned int
    current_step() const;

    OutputSettings              output_settings;
    std::string                 scene_file;
    Scene<dim>                 &scene;
    const StabilitySettings    &stability;
    dealii::ConditionalOStream &log;
    dealii::TimerOutput        &timer;
    Observables<dim>            observables;
    BoundaryBalance<dim>        balance;

    const TimeLoop    *loop     = nullptr;
    const RunProgress *progress = nullptr;
    double             tau_d    = 1.;
    double             end_time = 0.;

    // Held by rank 0 from the preparation of the output directory to the end of the run.
    std::unique_ptr<DirectoryLock> output_lock;

    StatisticsFile                       statistics_file;
    StatisticsFile                       stability_file; // stability.csv, with the inertia
    StatisticsFile                       events_file;    // events.csv (inertia or pores)
    std::unique_ptr<ParticleOutput<dim>> particle_output;
    std::unique_ptr<GridOutput<dim>>     grid_output;
    std::unique_ptr<GridOutput<dim>>     mode_output;                 // with Stability/Write mode
    bool                                 mode_recorded = false;       // with Output/Write grid
    std::vector<unsigned int>            grid_volume_points;          // per cell, start of the step
    unsigned int output_step = dealii::numbers::invalid_unsigned_int; // of the last output
    bool         inexact_extrapolation_noted = false;
    // Whether the gel's surface touched itself at the last accepted step ('Contact/Self contact').
    bool self_touching = false;
    // The pieces' terms of the step being accepted, taken before a kick moves its state.
    std::vector<typename MixedSystem<dim>::PieceBalance> balances;
    /** The rigid obstacles' reactions of the step being accepted. */
    std::vector<typename MixedSystem<dim>::ObstacleReaction> reactions;
  };
} // namespace GelMPM

#endif

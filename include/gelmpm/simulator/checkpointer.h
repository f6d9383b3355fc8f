#ifndef gelmpm_simulator_checkpointer_h
#define gelmpm_simulator_checkpointer_h

#include <gelmpm/core/sparse_entries.h>
#include <gelmpm/io/checkpoint.h>
#include <gelmpm/simulator/material_point_model.h>
#include <gelmpm/simulator/run_record.h>
#include <gelmpm/simulator/scene.h>
#include <gelmpm/simulator/stability_monitor.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/solvers/time_loop.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The checkpoints of a GelMPM run ('Checkpoint' section): when one is due, writing it,
   * and continuing a run from one (`gelmpm --resume`).
   *
   * A checkpoint is the state between two steps (doc/architecture.md, "A checkpoint is the
   * state between two steps"): the CheckpointHeader (parameters, step, time, the lengths of the
   * run's files), the material points, and the run's state (serialize_run_state()): the loop's,
   * the model's, the record's counters, the stability monitor's, the record's series, and the
   * factorised tangent with the classification of its pattern. The order of that archive is the
   * file format: kept as it is, so that a checkpoint of an earlier build still resumes.
   *
   * With --resume the checkpoint is opened and checked when the run is set up (read()), before
   * anything is written, and restored once the run's parts exist (restore()). Kept apart from
   * the Simulator so that what a checkpoint holds, and in which order, is in one place.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class Checkpointer
  {
  public:
    /**
     * Read 'Checkpoint' (InputError on bad values) for the run of @p scene solved with
     * @p linear_solver (whose factorisation a checkpoint holds) and recorded by @p record.
     */
    Checkpointer(dealii::ParameterHandler   &prm,
                 Scene<dim>                 &scene,
                 const LinearSolver         &linear_solver,
                 RunRecord<dim>             &record,
                 dealii::ConditionalOStream &log,
                 dealii::TimerOutput        &timer);

    /** Whether the run writes checkpoints. */
    bool
    enabled() const;

    /**
     * Open the checkpoint in the output directory to continue the run of @p parameters_as_used
     * to @p end_time. InputError if there is none, if it is damaged, if it was written by
     * another version or for other parameters, if @p end_time lies before it, or if a file it
     * counts is shorter than it was then.
     */
    void
    read(const std::string &parameters_as_used, const double end_time);

    /** Whether the run continues from a checkpoint not yet restored. */
    bool
    resuming() const;

    /**
     * The run's parts a checkpoint holds, once they exist; the interval in minutes counts from
     * here. @p parameters_as_used go into every checkpoint's header; @p monitor may be null.
     */
    void
    attach(TimeLoop                &loop,
           MaterialPointModel<dim> &model,
           StabilityMonitor<dim>   *monitor,
           const std::string       &parameters_as_used);

    /**
     * Whether a checkpoint is due after the step just taken ('Checkpoint/Interval steps' and
     * 'Interval minutes'; at the end of the run).
     */
    bool
    due() const;

    /**
     * Write the checkpoint of the state after the last converged step, with the .csv files on
     * the disk first. Without @p with_tangent (stopped between the attempts of a step) the
     * factorisation, which is of a rejected attempt, is left out.
     */
    void
    write(const bool with_tangent = true);

    /** Write one unless the last accepted step has one (the run is stopping). */
    void
    write_unless_written(const bool with_tangent);

    /**
     * Continue from the checkpoint read(): the material points and the run's state, the record's
     * files cut back and its ParaView series rewritten to where they were.
     */
    void
    restore();

  private:
    /** The material points of every rank, each rank's as its own archive (on rank 0). */
    std::vector<std::string>
    gather_points() const;
    /** The factorised tangent's entries of every rank (on rank 0) and its pattern's classes. */
    void
    gather_tangent(const bool with_tangent);
    /** The material points of the checkpoint, each on the rank that owns its cell. */
    void
    load_points();
    /**
     * Write or read (boost serialization) everything besides the material points that the next
     * step, the output schedule and the files read, in the file's order: the loop (time, step,
     * the step control, the last step), the model (the chemical-potential coefficients of the
     * initial guess), the record's counters, the stability bracketing, the record's series (the
     * observables' events, the ParaView series), the factorisation.
     */
    template <class Archive>
    void
    serialize_run_state(Archive &ar);

    CheckpointSettings          settings;
    Scene<dim>                 &scene;
    const LinearSolver         &linear_solver;
    RunRecord<dim>             &record;
    dealii::ConditionalOStream &log;
    dealii::TimerOutput        &timer;

    TimeLoop                *loop    = nullptr;
    MaterialPointModel<dim> *model   = nullptr;
    StabilityMonitor<dim>   *monitor = nullptr;
    std::string              parameters;

    // Read from a checkpoint: the factorisation to restore at the first step (see
    // serialize_run_state()).
    std::vector<bool>                     resumed_classification;
    SparseEntries                         resumed_tangent;
    std::unique_ptr<CheckpointReader>     resume_from;     // with --resume, until restored
    std::chrono::steady_clock::time_point last_checkpoint; // or the start
    unsigned int checkpoint_step = dealii::numbers::invalid_unsigned_int; // of the last one
  };
} // namespace GelMPM

#endif

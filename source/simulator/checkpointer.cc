#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/point_serialization.h>
#include <gelmpm/simulator/checkpointer.h>
#include <gelmpm/solvers/time_stepping.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace GelMPM
{
  template <int dim>
  Checkpointer<dim>::Checkpointer(dealii::ParameterHandler   &prm,
                                  Scene<dim>                 &scene,
                                  const LinearSolver         &linear_solver,
                                  RunRecord<dim>             &record,
                                  dealii::ConditionalOStream &log,
                                  dealii::TimerOutput        &timer)
    : scene(scene)
    , linear_solver(linear_solver)
    , record(record)
    , log(log)
    , timer(timer)
  {
    settings.parse_parameters(prm);
  }


  template <int dim>
  bool
  Checkpointer<dim>::enabled() const
  {
    return settings.enabled();
  }


  template <int dim>
  void
  Checkpointer<dim>::read(const std::string &parameters_as_used, const double end_time)
  {
    const std::string &directory = record.settings().directory;
    resume_from =
      std::make_unique<CheckpointReader>(directory, checkpoint_parameters(parameters_as_used));
    const auto &header = resume_from->header();
    if (end_time < header.time * (1. - relative_time_tolerance))
      {
        std::ostringstream problem, fix;
        problem << "is " << end_time << ", before the time of the checkpoint in '" << directory
                << "' (t/tau_d = " << header.time << ", step " << header.step
                << "): a resumed run cannot go back";
        fix << "give an End time of at least " << header.time
            << " to continue the run, or run the scene from the start (without --resume)";
        throw InputError("Time stepping/End time", problem.str(), fix.str());
      }
    for (const auto &[name, size] : header.file_sizes)
      {
        const std::string path = directory + "/" + name;
        std::error_code   error;
        const auto        found = std::filesystem::file_size(path, error);
        require(!error && found >= size,
                "",
                "cannot resume: the checkpoint at step " + std::to_string(header.step) +
                  " needs '" + path + "' as it was then (" + std::to_string(size) +
                  " bytes), but it " +
                  (error ? "cannot be read (" + error.message() + ")"
                         : "has only " + std::to_string(found) + " bytes"),
                "restore the file, or run the scene from the start (without --resume)");
      }
  }


  template <int dim>
  bool
  Checkpointer<dim>::resuming() const
  {
    return resume_from != nullptr;
  }


  template <int dim>
  void
  Checkpointer<dim>::attach(TimeLoop                &loop,
                            MaterialPointModel<dim> &model,
                            StabilityMonitor<dim>   *monitor,
                            const std::string       &parameters_as_used)
  {
    this->loop      = &loop;
    this->model     = &model;
    this->monitor   = monitor;
    parameters      = checkpoint_parameters(parameters_as_used);
    last_checkpoint = std::chrono::steady_clock::now();
  }


  template <int dim>
  bool
  Checkpointer<dim>::due() const
  {
    const unsigned int step = loop->step();
    if (!settings.enabled() || checkpoint_step == step)
      return false;
    const std::chrono::duration<double, std::ratio<60>> since =
      std::chrono::steady_clock::now() - last_checkpoint;
    return (settings.interval_steps > 0 && step % settings.interval_steps == 0) ||
           (settings.interval_minutes > 0. && since.count() >= settings.interval_minutes) ||
           loop->control().finished();
  }


  template <int dim>
  template <class Archive>
  void
  Checkpointer<dim>::serialize_run_state(Archive &ar)
  {
    ar &*loop &*model;
    record.serialize_counters(ar);
    if (monitor)
      ar &*monitor;
    record.serialize_series(ar);
    // The factorisation the next step's first Newton iteration may solve with (modified
    // Newton), as the entries it was made of and the classification of their pattern: a resumed
    // run refactorises them if its first grid reset gives that classification again.
    // (gather_tangent() takes them.)
    ar &resumed_classification &resumed_tangent;
  }


  template <int dim>
  std::vector<std::string>
  Checkpointer<dim>::gather_points() const
  {
    std::ostringstream bytes;
    {
      boost::archive::binary_oarchive ar(bytes);
      save_material_points(ar, scene.particles);
    }
    if (Collective::is_parallel(scene.communicator))
      return dealii::Utilities::MPI::gather(scene.communicator, bytes.str(), 0);
    return {bytes.str()};
  }


  template <int dim>
  void
  Checkpointer<dim>::gather_tangent(const bool with_tangent)
  {
    resumed_classification = scene.system->classification_of_pattern();
    // Stopped between the attempts of a step, the factorisation is of a rejected attempt: the
    // resumed run factorises afresh.
    resumed_tangent = with_tangent ? linear_solver.entries_of_factorization() : SparseEntries();
    if (!Collective::is_parallel(scene.communicator))
      return;
    const auto parts = dealii::Utilities::MPI::gather(scene.communicator, resumed_tangent, 0);
    resumed_tangent.clear();
    for (const auto &part : parts)
      resumed_tangent.append(part);
  }


  template <int dim>
  void
  Checkpointer<dim>::write(const bool with_tangent)
  {
    dealii::TimerOutput::Scope scope(timer, "checkpoint");
    const auto                 begin = std::chrono::steady_clock::now();
    CheckpointHeader           header;
    header.parameters = parameters;
    header.step       = loop->step();
    header.time       = loop->time();
    header.file_sizes = record.file_sizes();
    // Every rank's points, as its own archive, and the factorised tangent's entries of every
    // rank, gathered on rank 0, which writes the file.
    const auto points = gather_points();
    gather_tangent(with_tangent);
    std::uintmax_t size = 0;
    Collective::on_root(scene.communicator, [&]() {
      record.sync_files();
      size = write_checkpoint(record.settings().directory,
                              header,
                              [&](boost::archive::binary_oarchive &ar) {
                                ar << points;
                                serialize_run_state(ar);
                              });
    });
    resumed_classification.clear();
    resumed_tangent.clear();
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_step = loop->step();
    log << "  checkpoint at step " << checkpoint_step;
    if (!record.settings().test_mode)
      log << " (" << std::setprecision(3) << size / 1e6 << " MB in "
          << std::chrono::duration<double>(last_checkpoint - begin).count() << " s)"
          << std::setprecision(6);
    log << std::endl;
  }


  template <int dim>
  void
  Checkpointer<dim>::write_unless_written(const bool with_tangent)
  {
    if (settings.enabled() && checkpoint_step != loop->step())
      write(with_tangent);
  }


  template <int dim>
  void
  Checkpointer<dim>::load_points()
  {
    std::vector<std::string> points;
    resume_from->archive() >> points;
    scene.particles.clear_particles();
    for (const auto &part : points)
      {
        std::istringstream              bytes(part);
        boost::archive::binary_iarchive part_archive(bytes);
        load_material_points(part_archive, scene.particles, *scene.triangulation);
      }
    scene.particles.update_cached_numbers();
    // The saved points may sit elsewhere than the initial ones the grid was partitioned for.
    scene.balance_partition();
  }


  template <int dim>
  void
  Checkpointer<dim>::restore()
  {
    load_points();
    serialize_run_state(resume_from->archive());
    model->restore_factorization(resumed_classification, resumed_tangent);
    resumed_classification.clear();
    resumed_tangent.clear();
    record.open_files(&resume_from->header().file_sizes);
    record.restore_series();
    std::error_code ignored;
    std::filesystem::remove(checkpoint_path(record.settings().directory) + ".tmp", ignored);
    // From the first accepted step on the run accepts inexact extrapolations.
    if (loop->step() > 0)
      scene.spaces->tolerate_inexact_extrapolation();
    const auto changes = adjusted_parameters(resume_from->header().parameters, parameters);
    resume_from.reset();
    checkpoint_step = loop->step();
    log << "  resumed from the checkpoint at step " << checkpoint_step
        << ", t/tau_d = " << loop->time() << std::endl;
    for (const auto &change : changes)
      log << "  changed since the checkpoint: " << change << std::endl;
  }


  template class Checkpointer<2>;
  template class Checkpointer<3>;
} // namespace GelMPM

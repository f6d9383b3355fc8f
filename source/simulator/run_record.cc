#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/io/output_directory.h>
#include <gelmpm/simulator/run_record.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <regex>
#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  RunRecord<dim>::RunRecord(dealii::ParameterHandler       &prm,
                            const std::vector<std::string> &boundary_pieces,
                            const std::string              &scene_file,
                            Scene<dim>                     &scene,
                            const StabilitySettings        &stability,
                            dealii::ConditionalOStream     &log,
                            dealii::TimerOutput            &timer)
    : scene_file(scene_file)
    , scene(scene)
    , stability(stability)
    , log(log)
    , timer(timer)
  {
    output_settings.parse_parameters(prm);
    observables.parse_parameters(prm, boundary_pieces);
    balance.parse_parameters(prm, boundary_pieces);
    observables.set_communicator(scene.communicator);
    balance.set_communicator(scene.communicator);
  }


  template <int dim>
  const OutputSettings &
  RunRecord<dim>::settings() const
  {
    return output_settings;
  }


  template <int dim>
  void
  RunRecord<dim>::check_output_directory(const bool resume) const
  {
    GelMPM::check_output_directory(output_settings.directory,
                                   "Output/Directory",
                                   scene_file,
                                   resume);
    // A run writes parameters.prm before its first statistics.csv row: a statistics.csv alone is
    // another program's (the body-fitted peer's), which removing the earlier output would delete.
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path  directory(output_settings.directory);
    require(resume || !fs::is_regular_file(directory / "statistics.csv", error) ||
              fs::exists(directory / "parameters.prm", error),
            "Output/Directory",
            "is '" + output_settings.directory +
              "', which holds a statistics.csv that no gelmpm run wrote (no parameters.prm "
              "beside it: a body-fitted peer's results?), which the run would delete",
            "give the run a directory of its own, e.g. --set \"Output/Directory=mpm\"");
  }


  template <int dim>
  void
  RunRecord<dim>::prepare_directory(const std::string &parameters_as_used, const bool resume)
  {
    Collective::on_root(scene.communicator, [&]() {
      prepare_directory_here(parameters_as_used, resume);
    });
  }


  template <int dim>
  void
  RunRecord<dim>::prepare_directory_here(const std::string &parameters_as_used, const bool resume)
  {
    std::error_code error;
    std::filesystem::create_directories(output_settings.directory, error);
    require(!error,
            "Output/Directory",
            "'" + output_settings.directory + "' cannot be created (" + error.message() + ")",
            "choose a directory you can write to");
    // Before anything in it is touched: another run may be writing into it.
    output_lock = std::make_unique<DirectoryLock>(output_settings.directory);
    if (!resume)
      remove_earlier_output();
    {
      const std::string path = output_settings.directory + "/parameters.prm";
      std::ofstream     out  = open_partial(path + ".tmp", path);
      out << parameters_as_used;
      commit_file(out, path + ".tmp", path);
    }
    std::filesystem::copy_file(scene_file,
                               output_settings.directory + "/original.prm",
                               std::filesystem::copy_options::overwrite_existing);
  }


  template <int dim>
  void
  RunRecord<dim>::remove_earlier_output() const
  {
    // Only the names this program writes: a particles-00042.vtu of a longer earlier run would
    // otherwise sit next to this run's series as if it belonged to it.
    std::error_code error;
    for (const auto &entry : std::filesystem::directory_iterator(output_settings.directory, error))
      if (entry.is_regular_file() &&
          std::regex_match(entry.path().filename().string(), run_output_names()))
        std::filesystem::remove(entry.path(), error);
  }


  template <int dim>
  void
  RunRecord<dim>::create_outputs(const MaterialPointModel<dim> &model, const bool resume)
  {
    observables.set_grid_spacing(scene.spaces->h_u());
    if (scene.contact.enabled())
      {
        // Touching: within 1% of a cell of the plane (points that start on a plane's edge of a
        // quarter pore lie a quarter cell away).
        observables.set_contact_planes(scene.contact.planes(scene.grid.lower, scene.grid.upper),
                                       0.01 * scene.spaces->h_u());
      }
    particle_output = std::make_unique<ParticleOutput<dim>>(output_settings.directory,
                                                            scene.regions,
                                                            scene.communicator);
    if (output_settings.write_grid)
      {
        grid_output =
          std::make_unique<GridOutput<dim>>(output_settings.directory, *scene.triangulation);
        if (!resume)
          record_initial_grid(model);
      }
    if (stability.write_mode)
      mode_output =
        std::make_unique<GridOutput<dim>>(output_settings.directory, *scene.triangulation, "mode");
  }


  template <int dim>
  void
  RunRecord<dim>::record_initial_grid(const MaterialPointModel<dim> &model)
  {
    grid_volume_points = scene.volume_points_per_cell();
    std::vector<bool> has_material(grid_volume_points.size());
    for (unsigned int c = 0; c < has_material.size(); ++c)
      has_material[c] = grid_volume_points[c] > 0;
    scene.spaces->reinit(has_material);
    dealii::Vector<double> solution;
    model.initial_guess(solution);
    grid_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, solution);
  }


  template <int dim>
  void
  RunRecord<dim>::attach(const TimeLoop    &loop,
                         const RunProgress &progress,
                         const RunScales   &scales,
                         const double       end_time)
  {
    this->loop     = &loop;
    this->progress = &progress;
    tau_d          = scales.tau_d;
    this->end_time = end_time;
  }


  template <int dim>
  std::vector<std::string>
  RunRecord<dim>::statistics_columns() const
  {
    std::vector<std::string> columns = {"step",
                                        "time",
                                        "t_over_tau_d",
                                        "dt",
                                        "newton_iterations",
                                        "attempts",
                                        "residual_u",
                                        "residual_mu",
                                        "n_dofs_u",
                                        "n_dofs_mu",
                                        "n_active_cells",
                                        "n_particles"};
    for (const auto &c : stability.columns())
      columns.push_back(c);
    if (scene.contact.enabled())
      for (const char *name : {"contact_points", "contact_penetration"})
        columns.push_back(name);
    if (scene.contact.self_contact.enabled())
      for (const char *name : {"self_contact_points",
                               "self_contact_force",
                               "self_contact_area",
                               "self_contact_penetration"})
        columns.push_back(name);
    if (scene.contact.self_contact.enabled() && scene.contact.self_contact.separate_faces)
      columns.push_back("self_contact_copies");
    for (const auto &c : obstacle_columns())
      columns.push_back(c);
    for (const auto &c : observables.columns())
      columns.push_back(c);
    for (const auto &c : balance.columns())
      columns.push_back(c);
    // Wall times differ from run to run: not in test mode, whose output is compared.
    if (!output_settings.test_mode)
      columns.push_back("wall_time");
    return columns;
  }


  template <int dim>
  std::vector<std::string>
  RunRecord<dim>::stability_columns() const
  {
    std::vector<std::string> columns = {"t_stable", "t_unstable", "n_dofs_u", "n_dofs_mu"};
    if (stability.inertia)
      for (const char *name : {"n_neg_stable", "n_neg_unstable", "n_zero_unstable"})
        columns.push_back(name);
    if (stability.n_eigenvalues > 0)
      for (const char *name : {"eig_1_stable", "eig_1_unstable"})
        columns.push_back(name);
    if (stability.iterative_drained())
      columns.push_back("drained_eig_1_unstable");
    return columns;
  }


  template <int dim>
  std::vector<std::string>
  RunRecord<dim>::obstacle_columns() const
  {
    std::vector<std::string> columns;
    for (const auto &obstacle : scene.obstacles)
      {
        for (unsigned int d = 0; d < dim; ++d)
          columns.push_back(obstacle.name + "_force_" + "xyz"[d]);
        columns.push_back(obstacle.name + "_contact_area");
        columns.push_back(obstacle.name + "_contact_radius");
      }
    return columns;
  }


  template <int dim>
  void
  RunRecord<dim>::open_files(const std::map<std::string, std::uint64_t> *resumed_sizes)
  {
    // A resumed run continues its files where the checkpoint left them.
    const auto open =
      [&](StatisticsFile &file, const std::string &name, const std::vector<std::string> &columns) {
        const std::string path = output_settings.directory + "/" + name;
        // Rank 0 writes; the others keep the same rows in memory.
        file.write_here(dealii::Utilities::MPI::this_mpi_process(scene.communicator) == 0);
        if (resumed_sizes == nullptr)
          return file.open(path, columns);
        const auto size = resumed_sizes->find(name);
        if (size == resumed_sizes->end())
          throw std::runtime_error("the checkpoint does not know '" + path + "'");
        file.resume(path, columns, size->second);
      };
    open(statistics_file, "statistics.csv", statistics_columns());
    if (stability.detects_onset())
      open(stability_file, "stability.csv", stability_columns());
    if (writes_events())
      open(events_file, "events.csv", {"event", "time", "t_over_tau_d", "mu_boundary", "pore"});
  }


  template <int dim>
  void
  RunRecord<dim>::record_initial_state()
  {
    statistics_file.set("dt", 0.);
    balance.record_initial(scene.particles, scene.regions, statistics_file);
    record_statistics(NewtonReport(), 0, nullptr);
    write_output();
  }


  template <int dim>
  void
  RunRecord<dim>::step_begins()
  {
    if (grid_output || mode_output)
      grid_volume_points = scene.volume_points_per_cell();
  }


  template <int dim>
  void
  RunRecord<dim>::take_balances(const dealii::Vector<double> &solution, const double dt)
  {
    balances.clear();
    if (balance.enabled())
      balances = scene.system->boundary_balances(solution, dt * tau_d);
    reactions.clear();
    if (!scene.obstacles.empty())
      reactions = scene.system->obstacle_reactions(solution);
  }


  template <int dim>
  void
  RunRecord<dim>::record_step(const AcceptedStep &step, const dealii::Vector<double> &solution)
  {
    if (grid_output)
      grid_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, solution);
    statistics_file.set("dt", step.dt);
    balance.record_step(balances, step.dt * tau_d, scene.particles, scene.regions, statistics_file);
    record_statistics(step.report, step.attempts, &solution);
    print_step_line(step.report, step.dt);
  }


  template <int dim>
  void
  RunRecord<dim>::record_statistics(const NewtonReport           &report,
                                    const unsigned int            attempts,
                                    const dealii::Vector<double> *solution)
  {
    auto &row = statistics_file;
    row.set("step", current_step());
    row.set("time", current_time() * tau_d);
    row.set("t_over_tau_d", current_time());
    row.set("newton_iterations", report.iterations);
    row.set("attempts", attempts);
    row.set("residual_u", report.residual_u);
    row.set("residual_mu", report.residual_mu);
    row.set("n_particles", scene.particles.n_global_particles());
    if (!output_settings.test_mode && progress)
      row.set("wall_time", progress->elapsed());
    if (scene.system && current_step() > 0)
      {
        row.set("n_dofs_u", scene.spaces->n_u_dofs());
        row.set("n_dofs_mu", scene.spaces->n_mu_dofs());
        row.set("n_active_cells", scene.system->n_active_cells());
      }
    std::function<std::pair<double, double>()> dirichlet_errors;
    if (solution != nullptr)
      dirichlet_errors = [&]() {
        return scene.system->dirichlet_errors(*solution);
      };
    if (scene.contact.enabled() && solution != nullptr)
      {
        const auto [active, penetration] = scene.system->contact_state(*solution);
        row.set("contact_points", active);
        row.set("contact_penetration", penetration);
      }
    if (scene.contact.self_contact.enabled() && solution != nullptr)
      record_self_contact(*solution);
    set_obstacle_columns(solution != nullptr);
    observables.evaluate(scene.particles, scene.regions, dirichlet_errors, row);
    row.write_row();
    record_pore_events();
  }


  template <int dim>
  void
  RunRecord<dim>::record_self_contact(const dealii::Vector<double> &solution)
  {
    const auto state = scene.system->self_contact_state(solution);
    statistics_file.set("self_contact_points", state.points);
    statistics_file.set("self_contact_force", state.force);
    statistics_file.set("self_contact_area", state.area);
    statistics_file.set("self_contact_penetration", state.penetration);
    if (scene.contact.self_contact.separate_faces)
      statistics_file.set("self_contact_copies", scene.system->point_cache().n_function_copies());
    if (state.points > 0 && !self_touching)
      {
        // The pore of the deepest point where pores are observed (their walls' first contact).
        const unsigned int pore = observables.pore_of(state.deepest_X0);
        write_event("self_contact", current_time(), pore);
        log << "  event: self_contact of the gel's surface"
            << (pore > 0 ? " (pore " + std::to_string(pore) + ")" : "")
            << " at t/tau_d = " << current_time() << '\n';
      }
    self_touching = state.points > 0;
  }


  template <int dim>
  void
  RunRecord<dim>::set_obstacle_columns(const bool known)
  {
    // The obstacles' reactions of the converged state (take_balances()); none at the start.
    const auto columns = obstacle_columns();
    for (unsigned int k = 0, c = 0; k < scene.obstacles.size(); ++k)
      {
        const bool here = known && k < reactions.size();
        for (unsigned int d = 0; d < dim; ++d)
          statistics_file.set(columns[c++], here ? reactions[k].force[d] : 0.);
        statistics_file.set(columns[c++], here ? reactions[k].area : 0.);
        statistics_file.set(columns[c++], here ? reactions[k].radius : 0.);
      }
  }


  template <int dim>
  void
  RunRecord<dim>::note_inexact_extrapolation(const unsigned int n_inexact, const double t_begin)
  {
    if (n_inexact == 0 || inexact_extrapolation_noted)
      return;
    log << "  note: from t/tau_d = " << t_begin << ", " << n_inexact
        << " boundary control point(s) next to the grid's edge are extrapolated inexactly "
           "(the body has moved within q cells of it; a larger 'Background grid' avoids "
           "it; doc/method.md, \"Discretisation\")\n";
    inexact_extrapolation_noted = true;
  }


  template <int dim>
  void
  RunRecord<dim>::record_pore_events()
  {
    for (const auto &[name, pore] : observables.new_events(scene.particles))
      {
        write_event(name, current_time(), pore);
        log << "  event: " << name << (pore > 0 ? " of pore " + std::to_string(pore) : "")
            << " at t/tau_d = " << current_time() << '\n';
      }
  }


  template <int dim>
  bool
  RunRecord<dim>::writes_events() const
  {
    return stability.detects_onset() || observables.writes_events() ||
           scene.contact.self_contact.enabled();
  }


  template <int dim>
  void
  RunRecord<dim>::write_event(const std::string &name, const double t_over_tau_d, const int pore)
  {
    events_file.set("event", name);
    events_file.set("time", t_over_tau_d * tau_d);
    events_file.set("t_over_tau_d", t_over_tau_d);
    if (const auto mu = observables.boundary_chemical_potential(scene.particles))
      events_file.set("mu_boundary", *mu);
    if (pore > 0)
      events_file.set("pore", pore);
    else
      events_file.set("pore", std::string());
    events_file.write_row();
  }


  template <int dim>
  void
  RunRecord<dim>::record_mode(const dealii::Vector<double> &mode)
  {
    // The mode as a displacement field (mu = 0), scaled to a largest coefficient of one: the
    // eigenvector's sign and size are arbitrary.
    dealii::Vector<double> field(scene.spaces->n_dofs());
    const double           largest = mode.linfty_norm();
    for (unsigned int i = 0; i < mode.size(); ++i)
      field(i) = (largest > 0.) ? mode(i) / largest : 0.;
    mode_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, field);
    mode_recorded = true;
  }


  template <int dim>
  bool
  RunRecord<dim>::writes_mode() const
  {
    return mode_output != nullptr;
  }


  template <int dim>
  void
  RunRecord<dim>::write_output()
  {
    dealii::TimerOutput::Scope scope(timer, "output");
    output_step = current_step();
    if (output_settings.write_particles)
      particle_output->write(scene.particles, current_time());
    if (grid_output)
      grid_output->write(current_time());
    observables.write_surfaces(scene.particles, output_settings.directory);
    if (mode_output && mode_recorded)
      mode_output->write(current_time());
  }


  template <int dim>
  bool
  RunRecord<dim>::output_written() const
  {
    return output_step == current_step();
  }


  template <int dim>
  void
  RunRecord<dim>::print_step_line(const NewtonReport &report, const double step_dt) const
  {
    log << "  step " << std::setw(5) << current_step() << "  t/tau_d = " << std::setw(11)
        << std::setprecision(5) << current_time() << "  dt = " << std::setw(10) << step_dt
        << "  Newton " << std::setw(2) << report.iterations;
    if (report.damped_iterations > 0)
      log << " (" << report.damped_iterations << " damped)";
    log << "  |R_u| " << std::setprecision(2) << report.residual_u << "  |R_mu| "
        << report.residual_mu;
    if (loop->newton().log_failures && !report.history.empty())
      log << "  (first: " << report.history[0][0] << ", " << report.history[0][1] << ")";
    // Wall times differ from run to run: not in test mode, whose log is compared.
    if (!output_settings.test_mode)
      {
        log << "  wall " << format_duration(progress->elapsed()) << " (" << std::setprecision(3)
            << 100. * current_time() / end_time << "%";
        const double remaining = progress->remaining();
        if (remaining >= 0. && !loop->control().finished())
          {
            log << ", end in ~" << format_duration(remaining);
            // The assumption the estimate stands on, so that the reader can judge it.
            if (progress->assumed_rate() > 0.)
              log << " at dt/t " << format_percent(progress->assumed_rate());
          }
        log << ")";
      }
    log << std::setprecision(6) << std::endl;
  }


  template <int dim>
  void
  RunRecord<dim>::print_final_row() const
  {
    if (!output_settings.test_mode || statistics_file.rows().empty())
      return;
    // The final row of statistics.csv, without timings, for comparison with a reference.
    const auto &row = statistics_file.rows().back();
    for (unsigned int c = 0; c < row.size(); ++c)
      if (statistics_file.columns()[c] != "time")
        log << "  final " << statistics_file.columns()[c] << " = " << row[c] << '\n';
  }


  template <int dim>
  StatisticsFile &
  RunRecord<dim>::statistics()
  {
    return statistics_file;
  }


  template <int dim>
  StatisticsFile &
  RunRecord<dim>::stability_rows()
  {
    return stability_file;
  }


  template <int dim>
  std::map<std::string, std::uint64_t>
  RunRecord<dim>::file_sizes() const
  {
    std::map<std::string, std::uint64_t> sizes;
    // The rows up to here must be on the disk when the checkpoint that counts them is.
    for (const auto &[file, name] : {std::make_pair(&statistics_file, "statistics.csv"),
                                     std::make_pair(&stability_file, "stability.csv"),
                                     std::make_pair(&events_file, "events.csv")})
      if (file->bytes() > 0)
        sizes[name] = file->bytes();
    // And every file the .pvd series list, so that a resumed run never lists one that is gone.
    std::vector<std::string> listed;
    if (particle_output)
      for (const auto &[t, name] : particle_output->times_and_names())
        listed.push_back(name);
    for (const auto *output : {grid_output.get(), mode_output.get()})
      if (output)
        for (const auto &[t, name] : output->times_and_names())
          listed.push_back(name);
    for (const auto &name : listed)
      {
        std::error_code error;
        const auto size = std::filesystem::file_size(output_settings.directory + "/" + name, error);
        if (!error)
          sizes[name] = size;
      }
    return sizes;
  }


  template <int dim>
  void
  RunRecord<dim>::sync_files() const
  {
    for (const auto &[file, name] : {std::make_pair(&statistics_file, "statistics.csv"),
                                     std::make_pair(&stability_file, "stability.csv"),
                                     std::make_pair(&events_file, "events.csv")})
      if (file->bytes() > 0)
        sync_to_disk(output_settings.directory + "/" + name);
  }


  template <int dim>
  void
  RunRecord<dim>::restore_series()
  {
    if (output_settings.write_particles)
      particle_output->restore_files();
    if (grid_output)
      grid_output->restore_files();
    if (mode_output)
      mode_output->restore_files();
  }


  template <int dim>
  double
  RunRecord<dim>::current_time() const
  {
    return loop ? loop->time() : 0.;
  }


  template <int dim>
  unsigned int
  RunRecord<dim>::current_step() const
  {
    return loop ? loop->step() : 0;
  }


  template class RunRecord<2>;
  template class RunRecord<3>;
} // namespace GelMPM

#include <gelmpm/core/collective.h>
#include <gelmpm/core/stop_request.h>
#include <gelmpm/core/version.h>
#include <gelmpm/io/piece_table.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/simulator.h>
#include <gelmpm/simulator/symmetry_planes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/revision.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace GelMPM
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(dealii::ParameterHandler &prm, const SceneStructure &structure)
  {
    SceneStructure::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    Scene<dim>::declare_parameters(prm,
                                   structure.boundary_pieces,
                                   structure.material_regions,
                                   structure.obstacles);
    LinearSolver::declare_parameters(prm);
    NewtonSettings::declare_parameters(prm);
    TimeStepping::declare_parameters(prm);
    Observables<dim>::declare_parameters(prm);
    BoundaryBalance<dim>::declare_parameters(prm);
    StabilitySettings::declare_parameters(prm);
    CheckpointSettings::declare_parameters(prm);
  }


  template <int dim>
  Simulator<dim>::Simulator(dealii::ParameterHandler &prm,
                            const SceneStructure     &structure,
                            const std::string        &scene_file,
                            const bool                resume)
    : structure(structure)
    , scene(prm,
            structure.boundary_pieces,
            scene_file.empty() ? "" : std::filesystem::path(scene_file).parent_path().string(),
            MPI_COMM_WORLD,
            structure.material_regions,
            structure.obstacles)
    , scene_file(scene_file)
    , pcout(std::cout, dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , pcerr(std::cerr, dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
    , record(prm, structure.boundary_pieces, scene_file, scene, stability, pcout, timer)
    , checkpointer(prm, scene, linear_solver, record, pcout, timer)
  {
    linear_solver.parse_parameters(prm);
    // The symmetric Nitsche variant keeps the tangent symmetric (NitscheSettings): LDL^T.
    linear_solver.set_symmetric(scene.nitsche.symmetry > 0.);
    linear_solver.keep_factorized_values(checkpointer.enabled());
    newton.parse_parameters(prm);
    time_stepping.parse_parameters(prm);
    time_stepping.check_resolvable(newton.tolerance, NewtonSettings::smallest_tolerance);
    stability.parse_parameters(prm);
    StabilityMonitor<dim>::check_settings(stability, scene, time_stepping);
    // What the first step would find wrong, found here, before anything is written: a body
    // outside the grid or a piece that selects nothing (the points), a grid too coarse for the
    // body (the extended bases), a boundary value that is not finite.
    {
      dealii::TimerOutput::Scope scope(timer, "scene set-up");
      create_material_points();
      scene.check_grid_resolves_body();
      boundary_jump = scene.check_boundary_values(time_stepping.end_time);
      record.check_output_directory(resume);
    }

    std::ostringstream used;
    prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
    parameters_as_used = used.str();
    if (resume)
      checkpointer.read(parameters_as_used, time_stepping.end_time);
    // Last: a scene with a mistake found above may leave its body free as well.
    scene.check_rigid_motions();
  }


  template <int dim>
  std::string
  Simulator<dim>::jump_hint(const double t) const
  {
    const double h                   = scene.grid.smallest_cell_size();
    const double cell_diffusion_time = std::pow(h / time_stepping.characteristic_length, 2);
    if (boundary_jump.empty() || !(t < cell_diffusion_time))
      return "";
    std::ostringstream hint;
    hint << boundary_jump << ", and the run failed before solvent could diffuse across one cell "
         << "(at t/tau_d ~ (h/L)^2 = " << cell_diffusion_time
         << "): the layer the jump swells is thinner than a cell, its points distort more at "
            "every step until Newton finds no state, and shorter steps do not resolve it. Ramp "
            "the prescribed value from mu_0 instead (e.g. over 50 tau_d, as "
            "tests/simulator/free_swelling_scene.prm does), which lets the gel swell more evenly";
    return hint.str();
  }


  template <int dim>
  Simulator<dim>::~Simulator()
  {
    // The direct solver's factorisation refers to the tangent of the system: release it first.
    linear_solver.new_pattern();
  }


  template <int dim>
  void
  Simulator<dim>::print_header()
  {
    pcout << "GelMPM: hydrogel scene '" << std::filesystem::path(scene_file).filename().string()
          << "', " << dim << "D"
          << (dim == 2 ? (scene.grid.axisymmetric ? " (axisymmetric)" : " (plane strain)") : "")
          << ", " << scene.discretisation.name()
          << (scene.discretisation.extension ? ", extended B-splines" : "") << '\n';
    // The unknowns are those of the meridian plane: every mode the analysis can find is one.
    if (scene.grid.axisymmetric && stability.enabled())
      pcout << "  stability: axisymmetric modes only (a body of revolution may lose stability "
               "first in a mode that varies with the angle, which this analysis does not see)\n";
    if (!record.settings().test_mode)
      pcout << "  GelMPM " << GELMPM_VERSION << " (" << GELMPM_GIT_REVISION << "), deal.II "
            << DEAL_II_PACKAGE_VERSION << ", "
            << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI rank(s), "
            << dealii::MultithreadInfo::n_threads() << " thread(s)\n"
            << "  output directory: " << record.settings().directory << '\n';
  }


  template <int dim>
  void
  Simulator<dim>::print_piece_table() const
  {
    const bool        axisymmetric = scene.grid.axisymmetric;
    const std::string table =
      piece_table(scene.particles, structure.boundary_pieces, axisymmetric, scene.communicator) +
      region_table(scene.particles, scene.regions, axisymmetric, scene.communicator) +
      symmetry_plane_notes(roller_planes(scene.particles,
                                         scene.boundary_conditions,
                                         scene.communicator),
                           scene.grid,
                           scene.discretisation.displacement_degree,
                           scene.discretisation.subdivision);
    pcout << table << scene.contact.self_contact.notes();
  }


  template <int dim>
  void
  Simulator<dim>::create_material_points()
  {
    scene.create_material_points();

    unsigned int n_volume = 0, n_surface = 0;
    double       volume = 0.;
    for (const auto &p : scene.particles)
      if (kind_of(p.get_properties()) == PointKind::volume)
        {
          ++n_volume;
          volume += p.get_properties()[PropertyLayout<dim>::measure_0];
        }
      else
        ++n_surface;
    n_volume_points  = dealii::Utilities::MPI::sum(n_volume, scene.communicator);
    n_surface_points = dealii::Utilities::MPI::sum(n_surface, scene.communicator);
    body_volume      = dealii::Utilities::MPI::sum(volume, scene.communicator);

    scales = RunScales::of(dim,
                           time_stepping.characteristic_length,
                           scene.material.diffusivity(),
                           scene.material.shear_modulus(),
                           scene.material.kT_over_nu(),
                           body_volume);
  }


  template <int dim>
  void
  Simulator<dim>::start()
  {
    progress = std::make_unique<RunProgress>(time_stepping, run_start);
    scene.create_system();
    model = std::make_unique<MaterialPointModel<dim>>(scene,
                                                      linear_solver,
                                                      newton,
                                                      time_stepping.characteristic_length,
                                                      timer);
    record.create_outputs(*model, checkpointer.resuming());
    const auto &output = record.settings();
    loop               = std::make_unique<TimeLoop>(*model,
                                      time_stepping,
                                      newton,
                                      linear_solver,
                                      scales,
                                      pcout,
                                      timer,
                                      stability.bisection_tolerance,
                                      stability.unstable_step,
                                      stability.signature_control,
                                      output.interval_steps,
                                      output.interval_time);
    // Registered first: the pieces' balances are taken before the monitor's kick moves the state.
    loop->add_observer(*this);
    if (stability.enabled())
      add_stability_monitor();
    record.attach(*loop, *progress, scales, time_stepping.end_time);
    checkpointer.attach(*loop, *model, monitor.get(), parameters_as_used);
    if (checkpointer.resuming())
      return checkpointer.restore();
    record.open_files();
    record.record_initial_state();
  }


  template <int dim>
  void
  Simulator<dim>::add_stability_monitor()
  {
    std::function<void(const dealii::Vector<double> &)> keep_mode;
    if (record.writes_mode())
      keep_mode = [this](const dealii::Vector<double> &mode) {
        record.record_mode(mode);
      };
    monitor = std::make_unique<StabilityMonitor<dim>>(
      stability,
      scene,
      linear_solver,
      *loop,
      record.statistics(),
      record.stability_rows(),
      pcout,
      timer,
      [this](const std::string &name, const double t_over_tau_d) {
        record.write_event(name, t_over_tau_d, 0);
      },
      keep_mode);
    loop->add_observer(*monitor);
  }


  template <int dim>
  int
  Simulator<dim>::advance_to_end()
  {
    progress->begin_stepping();
    switch (loop->run())
      {
        case TimeLoop::Outcome::finished:
          return 0;
        case TimeLoop::Outcome::equilibrium:
          end_at_equilibrium();
          return 0;
        case TimeLoop::Outcome::ended_early:
          pcout << "gelmpm: ended at the bracketed loss of stability ('Stability/End at onset')"
                << std::endl;
          return 0;
        case TimeLoop::Outcome::interrupted:
          return stop_on_signal(loop->signal());
        case TimeLoop::Outcome::interrupted_within_step:
          return stop_on_signal(loop->signal(), false);
        case TimeLoop::Outcome::out_of_steps:
          {
            std::ostringstream message;
            message << "gelmpm: stopped after 'Time stepping/Maximum steps' = "
                    << time_stepping.maximum_steps << " steps at t/tau_d = " << current_time();
            pcout << message.str() << std::endl;
            pcerr << message.str() << std::endl;
            return 1;
          }
        case TimeLoop::Outcome::failed:
          return stop_on_failure();
      }
    return 1;
  }


  template <int dim>
  void
  Simulator<dim>::end_at_equilibrium()
  {
    const auto &control = loop->control();
    pcout << "gelmpm: reached equilibrium at t/tau_d = " << current_time()
          << " (criterion 'Time stepping/End at equilibrium' = " << time_stepping.end_at_equilibrium
          << ": the largest relative change of J or of a position per tau_d was "
          << control.last_rate() << " on the last step, below it on two steps in a row)"
          << std::endl;
    if (record.writes_events())
      record.write_event("equilibrium", current_time(), 0);
  }


  template <int dim>
  int
  Simulator<dim>::stop_on_failure()
  {
    // In the log and on stderr, where a failed run's message is looked for.
    std::ostringstream message;
    message << "gelmpm: the run cannot converge beyond t/tau_d = " << current_time()
            << "; results up to there are in " << record.settings().directory;
    // Why, on stderr too: the log's line per attempt is not where one looks first.
    if (!loop->failure().empty())
      message << ": " << loop->failure();
    if (const auto hint = jump_hint(current_time()); !hint.empty())
      message << "; " << hint;
    if (!loop->round_off_hint().empty())
      message << " (" << loop->round_off_hint() << ")";
    pcout << message.str() << std::endl;
    pcerr << message.str() << std::endl;
    record.write_output();
    return 1;
  }


  template <int dim>
  void
  Simulator<dim>::step_begins()
  {
    record.step_begins();
  }


  template <int dim>
  bool
  Simulator<dim>::before_update(dealii::Vector<double> &solution, const double dt)
  {
    // The pieces' terms at the converged state, before a kick moves it.
    record.take_balances(solution, dt);
    return false;
  }


  template <int dim>
  void
  Simulator<dim>::accepted(const AcceptedStep &step, const dealii::Vector<double> &solution)
  {
    progress->step_accepted(step.time, step.dt);
    record.note_inexact_extrapolation(scene.spaces->n_inexact_extrapolations(), step.t_begin);
    // The initial body was checked strictly; from here on its motion cannot be helped.
    scene.spaces->tolerate_inexact_extrapolation();
    record.record_step(step, solution);
    if (step.output_due || (monitor && monitor->end_requested()))
      record.write_output();
  }


  template <int dim>
  void
  Simulator<dim>::between_steps()
  {
    if (checkpointer.due())
      checkpointer.write();
  }


  template <int dim>
  int
  Simulator<dim>::stop_on_signal(const int signal, const bool between_steps)
  {
    // Before the last output, which the uninterrupted run would not write: the resumed run
    // drops it from the series.
    checkpointer.write_unless_written(between_steps);
    if (!record.output_written())
      record.write_output();
    pcerr << "gelmpm: " << signal_name(signal) << " received: stopped after step " << current_step()
          << " at t/tau_d = " << current_time()
          << " with a complete last output; the results are in " << record.settings().directory
          << std::endl;
    return 128 + signal;
  }


  template <int dim>
  int
  Simulator<dim>::run()
  {
    print_header();
    record.prepare_directory(parameters_as_used, checkpointer.resuming());
    pcout << "  material points: " << n_volume_points << " volume, " << n_surface_points
          << " surface; body volume " << body_volume << '\n';
    print_piece_table();
    int status = 0;
    try
      {
        start();
        status = advance_to_end();
      }
    catch (const std::runtime_error &e)
      {
        pcerr << "gelmpm: the run stopped: " << e.what()
              << "; what was written up to t/tau_d = " << current_time() << " is kept in "
              << record.settings().directory << std::endl;
        status = 1;
      }
    catch (const std::exception &e)
      {
        // Not a failure the ranks found together (a library's logic error): on several ranks
        // the others may be waiting in a collective call, and leaving would wait for them in
        // the destructors' collective calls. End the whole job from here.
        if (!Collective::is_parallel(scene.communicator))
          throw;
        std::cerr << "gelmpm: the run failed on rank "
                  << dealii::Utilities::MPI::this_mpi_process(scene.communicator) << ": "
                  << e.what() << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    if (status == 0)
      pcout << "gelmpm: reached t/tau_d = " << current_time() << " in " << current_step()
            << " steps" << std::endl;
    if (loop && loop->uncontrolled_errors() > 0)
      pcout << "gelmpm: " << loop->uncontrolled_errors()
            << " step(s) accepted with an error estimate above its tolerance whatever the step "
               "(a perturbation's jump or the points' integration noise)"
            << std::endl;
    if (loop && loop->armijo_retries().first > 0)
      pcout << "gelmpm: " << loop->armijo_retries().first
            << " failed attempt(s) retried with Armijo's line search ('Newton/Line search = "
               "adaptive'); "
            << loop->armijo_retries().second << " step(s) accepted with it" << std::endl;
    if (scene.system && scene.system->n_borrowed_increments() > 0)
      pcout << "gelmpm: " << scene.system->n_borrowed_increments()
            << " surface point update(s) took the nearest volume point's increment, their own "
               "leaving the physical range where the surface folds (doc/method.md, \"Two faces "
               "on one grid\")"
            << std::endl;
    if (record.settings().test_mode)
      record.print_final_row();
    else
      print_costs();
    return status;
  }


  template <int dim>
  void
  Simulator<dim>::print_costs() const
  {
    if (loop)
      pcout << "gelmpm: " << loop->newton_iterations() << " Newton iterations, "
            << loop->factorizations() << " factorisations (" << linear_solver.name() << "), "
            << model->new_patterns() << " sparsity patterns";
    if (loop && model->kept_markings() > 0)
      pcout << ", " << model->kept_markings()
            << " step(s) on the last step's refinement (the new one too thin for the extension "
               "at the body's boundary)";
    if (loop && model->budget_limited_steps() > 0)
      pcout << ", " << model->budget_limited_steps()
            << " step(s) with levels of the moving refinement dropped to keep within "
               "'Background grid/Refinement budget'";
    if (loop && model->unseen_passes().first > 0)
      pcout << ", " << model->unseen_passes().first << " step(s) in which "
            << model->unseen_passes().second
            << " surface point(s) passed through the gel's own surface unseen by the step's "
               "self-contact pairs ('Contact/Self contact/Retake unseen passes = true' retakes "
               "them shorter)";
    if (loop && model->steps_over_budget() > 0)
      pcout << ", " << model->steps_over_budget()
            << " step(s) beyond 'Background grid/Refinement budget' without moving refinement "
               "(the body outgrew the budget)";
    if (loop && loop->newton().reuse_contraction > 0.)
      {
        // Why the modified Newton iteration factorised, where it did not reuse.
        const auto &fresh = loop->fresh_tangents();
        pcout << ", fresh tangents: " << fresh.without_reuse << " without one kept, "
              << fresh.contraction << " on the contraction, " << fresh.step_ratio
              << " on the step ratio, " << fresh.reuses << " on the reuse count, "
              << fresh.discarded << " after a discarded update";
      }
    if (loop && monitor && !monitor->signature_sources().empty())
      pcout << ", " << monitor->signature_sources();
    if (loop && loop->switch_updates().first > 0)
      pcout << ", " << loop->switch_updates().first
            << " updates of the contact seals held in Newton (" << loop->switch_updates().second
            << " steps taken with a seal still flipping at the contact edge)";
    if (loop && Collective::is_parallel(scene.communicator))
      pcout << ", " << dealii::Utilities::MPI::n_mpi_processes(scene.communicator)
            << " ranks, partitioned anew " << model->repartitions() << " times";
    if (linear_solver.iterative())
      {
        const auto [iterations, solves] = linear_solver.krylov_iterations();
        pcout << ", " << iterations << " Krylov iterations in " << solves << " solves ("
              << (solves > 0 ? double(iterations) / solves : 0.) << " per solve), displacement "
              << "block by " << linear_solver.krylov_preconditioner();
      }
    if (loop)
      pcout << std::endl;
    // The high-water mark of each rank's resident memory (VmHWM).
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    const double mb = memory.VmHWM / 1024.;
    pcout << "gelmpm: peak memory " << std::setprecision(4)
          << dealii::Utilities::MPI::max(mb, scene.communicator) << " MB / "
          << dealii::Utilities::MPI::sum(mb, scene.communicator) << " MB" << std::setprecision(6)
          << std::endl;
    pcout << "gelmpm: results are in " << record.settings().directory
          << " (open particles.pvd in ParaView; statistics.csv per step)" << std::endl;
    timer.print_summary();
  }


  template <int dim>
  int
  run_scene_file(const std::string &scene_file, const std::vector<ParameterOverride> &overrides)
  {
    const auto               structure = SceneStructure::read(scene_file, overrides);
    dealii::ParameterHandler prm;
    Simulator<dim>::declare_parameters(prm, structure);
    read_scene_file(prm, scene_file, overrides);
    Simulator<dim> simulator(prm, structure, scene_file);
    return simulator.run();
  }


  template <int dim>
  double
  Simulator<dim>::current_time() const
  {
    return loop ? loop->time() : 0.;
  }


  template <int dim>
  unsigned int
  Simulator<dim>::current_step() const
  {
    return loop ? loop->step() : 0;
  }


  template class Simulator<2>;
  template class Simulator<3>;
  template int
  run_scene_file<2>(const std::string &, const std::vector<ParameterOverride> &);
  template int
  run_scene_file<3>(const std::string &, const std::vector<ParameterOverride> &);
} // namespace GelMPM

#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/stop_request.h>
#include <gelmpm/core/version.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/io/piece_table.h>
#include <gelmpm/particles/point_location.h>
#include <gelmpm/particles/point_serialization.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/revision.h>
#include <deal.II/grid/grid_tools.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace GelMPM
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(dealii::ParameterHandler &prm, const SceneStructure &structure)
  {
    SceneStructure::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    Scene<dim>::declare_parameters(prm, structure.boundary_pieces, structure.material_regions);
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
            structure.material_regions)
    , scene_file(scene_file)
    , pcout(std::cout, dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , pcerr(std::cerr, dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
  {
    output_settings.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    // The symmetric Nitsche variant keeps the tangent symmetric (NitscheSettings): LDL^T.
    linear_solver.set_symmetric(scene.nitsche.symmetry > 0.);
    newton.parse_parameters(prm);
    time_stepping.parse_parameters(prm);
    newton.minimum_iterations = time_stepping.tolerance > 0. ? 1 : 0;
    observables.parse_parameters(prm, structure.boundary_pieces);
    balance.parse_parameters(prm, structure.boundary_pieces);
    stability.parse_parameters(prm);
    checkpoint_settings.parse_parameters(prm);
    linear_solver.keep_factorized_values(checkpoint_settings.enabled());
    require(!stability.enabled() || scene.nitsche.symmetry > 0.,
            "Stability/Inertia",
            "needs a symmetric tangent, but 'Nitsche/Variant = skew-symmetric'",
            "use the symmetric Nitsche variant or switch the stability analysis off");
    // With 2 x 2 points per cell the swollen cells at a cut boundary hold too few points to keep
    // the B-spline stiffness definite: §4.1 stops at 11.3 tau_d, every step size failing, while
    // 3 x 3 runs to the end with degree 2 and 3.
    require(scene.generator.points_per_cell >= 3,
            "Material points/Points per cell",
            "is " + std::to_string(scene.generator.points_per_cell) +
              ": with fewer than 3 points per cell and direction the cells at the body's boundary "
              "hold too few points to keep the stiffness definite once the gel swells",
            "use at least 3 (the paper: 5 to 8)");
    // Both are dense analyses of the whole tangent, made for small discretisations: they read
    // the matrix's rows on the rank that holds them, which on several ranks is a part.
    for (const auto &[on, entry] :
         {std::make_pair(stability.inf_sup, "Stability/Inf-sup constant"),
          std::make_pair(stability.condition, "Stability/Condition number")})
      require(!on || !Collective::is_parallel(scene.communicator),
              entry,
              "is a dense analysis of the whole tangent and is computed on one MPI rank only, but "
              "the run has " +
                std::to_string(dealii::Utilities::MPI::n_mpi_processes(scene.communicator)) +
                " ranks",
              "run the scene on one rank (without mpirun) or set the entry to false");
    require(!linear_solver.iterative() || !Collective::is_parallel(scene.communicator),
            "Linear solver/Solver",
            "is Krylov, which reads the blocks of the tangent on one MPI rank, but the run has " +
              std::to_string(dealii::Utilities::MPI::n_mpi_processes(scene.communicator)) +
              " ranks",
            "run the scene on one rank or use MUMPS");
    require(stability.perturbation_direction.size() >= dim,
            "Stability/Perturbation direction",
            "has fewer components than the scene's dimension " + std::to_string(dim),
            "give one component per coordinate direction");
    {
      double in_plane = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        in_plane += stability.perturbation_direction[d] * stability.perturbation_direction[d];
      require(stability.perturbation_amplitude == 0. || in_plane > 0.,
              "Stability/Perturbation direction",
              "has no component in the scene's " + std::to_string(dim) +
                " coordinate directions (a third component is ignored in 2D)",
              "give the direction the gel is to leave the unstable branch in, e.g. '1, 0'");
    }
    // Bracket ends closer than this are one time for the step arithmetic (times are sums of
    // many steps, compared to relative_time_tolerance): a narrower bracket would end at zero
    // width, both of its ends on the same side of the loss of stability.
    const double narrowest_bracket = 100. * relative_time_tolerance * time_stepping.end_time;
    if (stability.bisection_tolerance > 0. && stability.bisection_tolerance < narrowest_bracket)
      {
        std::ostringstream problem, fix;
        problem << "is " << stability.bisection_tolerance
                << ", below 1e-10 times 'Time stepping/End time' (" << narrowest_bracket
                << "), the narrowest bracket that the step arithmetic resolves";
        fix << "give at least " << narrowest_bracket
            << " (tau_d), e.g. 1e-3, or 0 for no bisection";
        throw InputError("Stability/Bisection tolerance", problem.str(), fix.str());
      }
    // Checks that need more than one section: build the spaces once (odd cell counts with
    // subdivision are reported here, before anything is written).
    // The material points too: a body outside the grid or a piece that selects nothing is
    // bad input, found here.
    {
      dealii::TimerOutput::Scope scope(timer, "scene set-up");
      create_material_points();
      check_grid_resolves_body();
      check_boundary_values();
      check_output_directory();
    }

    std::ostringstream used;
    prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
    parameters_as_used = used.str();

    if (resume)
      {
        resume_from        = std::make_unique<CheckpointReader>(output_settings.directory,
                                                         checkpoint_parameters(parameters_as_used));
        const auto &header = resume_from->header();
        if (time_stepping.end_time < header.time * (1. - relative_time_tolerance))
          {
            std::ostringstream problem, fix;
            problem << "is " << time_stepping.end_time << ", before the time of the checkpoint in '"
                    << output_settings.directory << "' (t/tau_d = " << header.time << ", step "
                    << header.step << "): a resumed run cannot go back";
            fix << "give an End time of at least " << header.time
                << " to continue the run, or run the scene from the start (without --resume)";
            throw InputError("Time stepping/End time", problem.str(), fix.str());
          }
        for (const auto &[name, size] : header.file_sizes)
          {
            const std::string path = output_settings.directory + "/" + name;
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
  }


  template <int dim>
  void
  Simulator<dim>::check_grid_resolves_body()
  {
    // The first step builds the extended bases of the initial configuration: build them here,
    // where a grid too coarse for the body is still bad input.
    const auto        volume_points = volume_points_per_cell();
    std::vector<bool> has_material(volume_points.size());
    for (unsigned int c = 0; c < has_material.size(); ++c)
      has_material[c] = volume_points[c] > 0;
    try
      {
        scene.spaces->reinit(has_material);
      }
    catch (const std::runtime_error &e)
      {
        throw InputError("Background grid/Cells",
                         "cannot carry the body's initial configuration: " + std::string(e.what()),
                         "refine the grid or enlarge it ('Background grid/Upper corner')");
      }
  }


  template <int dim>
  std::vector<unsigned int>
  Simulator<dim>::volume_points_per_cell() const
  {
    auto count = GridOutput<dim>::count_volume_points(scene.particles, scene.spaces->u_space());
    if (Collective::is_parallel(scene.communicator))
      dealii::Utilities::MPI::sum(count, scene.communicator, count);
    return count;
  }


  template <int dim>
  void
  Simulator<dim>::check_boundary_values()
  {
    // Up to 64 surface points spread over each piece and times over the run: enough to catch
    // an expression that is not finite (1/0, log(-1)) before the run cuts its steps without
    // saying why.
    std::vector<std::vector<dealii::Point<dim>>> points(scene.boundary_conditions.n_pieces());
    // (piece, X_0) of the surface points of every rank, in the order of the ranks, so that
    // every rank checks the same samples and fails or passes with the others.
    std::vector<double> local;
    for (const auto &p : scene.particles)
      {
        const auto props = p.get_properties();
        const int  piece = piece_of(props);
        if (piece < 0)
          continue;
        local.push_back(piece);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(props[PropertyLayout<dim>::position_0 + d]);
      }
    for (const auto &part : dealii::Utilities::MPI::all_gather(scene.communicator, local))
      for (std::size_t k = 0; k < part.size(); k += dim + 1)
        {
          dealii::Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = part[k + 1 + d];
          points[static_cast<unsigned int>(part[k])].push_back(x);
        }
    std::vector<std::vector<dealii::Point<dim>>> samples(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const std::size_t stride = points[i].size() / 64 + 1;
        for (std::size_t k = 0; k < points[i].size(); k += stride)
          samples[i].push_back(points[i][k]);
      }
    std::vector<double> times;
    for (unsigned int k = 0; k <= 8; ++k)
      times.push_back(time_stepping.end_time * k / 8.);
    const double largest_mu = scene.regions.largest_swelling_chemical_potential();
    for (unsigned int i = 0; i < scene.boundary_conditions.n_pieces(); ++i)
      scene.boundary_conditions.piece(i).check_values(samples[i], times, largest_mu);
  }


  template <int dim>
  void
  Simulator<dim>::check_output_directory() const
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path  scene_directory = fs::absolute(scene_file, error).parent_path();
    // A run removes an earlier run's files from its directory and rewrites original.prm: run in
    // a result's directory, it would destroy the result it was started from.
    require(!fs::exists(output_settings.directory, error) ||
              !fs::equivalent(output_settings.directory, scene_directory, error),
            "Output/Directory",
            "'" + output_settings.directory + "' is the directory of the scene file '" +
              scene_file +
              "', whose results (parameters.prm, original.prm, statistics.csv, "
              ".vtu files) the run would overwrite",
            "give the run another directory, e.g. --set \"Output/Directory=rerun\"");
    // What creating or writing into it would fail on only once the run starts.
    const std::string &directory = output_settings.directory;
    if (fs::is_symlink(fs::symlink_status(directory, error)) && !fs::exists(directory, error))
      throw InputError("Output/Directory",
                       "is '" + directory + "', a symbolic link to '" +
                         fs::read_symlink(directory, error).string() + "', which does not exist",
                       "create the directory the link points to, or give another directory");
    require(!fs::exists(directory, error) || fs::is_directory(directory, error),
            "Output/Directory",
            "is '" + directory + "', which is a file, not a directory",
            "move that file away, or give the run another directory, e.g. --set "
            "\"Output/Directory=rerun\"");
    if (fs::is_directory(directory, error) && ::access(directory.c_str(), W_OK | X_OK) != 0)
      throw InputError("Output/Directory",
                       "is '" + directory + "', which this user cannot write into (" +
                         std::strerror(errno) + ")",
                       "give the directory write permission, or give another directory");
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
          << "', " << dim << "D" << (dim == 2 ? " (plane strain)" : "") << ", "
          << scene.discretisation.name()
          << (scene.discretisation.extension ? ", extended B-splines" : "") << '\n';
    if (!output_settings.test_mode)
      pcout << "  GelMPM " << GELMPM_VERSION << " (" << GELMPM_GIT_REVISION << "), deal.II "
            << DEAL_II_PACKAGE_VERSION << ", "
            << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI rank(s), "
            << dealii::MultithreadInfo::n_threads() << " thread(s)\n"
            << "  output directory: " << output_settings.directory << '\n';
  }


  template <int dim>
  void
  Simulator<dim>::print_piece_table() const
  {
    const std::string table =
      piece_table(scene.particles, structure.boundary_pieces, scene.communicator);
    pcout << table;
  }


  template <int dim>
  void
  Simulator<dim>::prepare_output_directory()
  {
    Collective::on_root(scene.communicator, [this]() {
      prepare_output_directory_here();
    });
  }


  template <int dim>
  void
  Simulator<dim>::prepare_output_directory_here()
  {
    std::error_code error;
    std::filesystem::create_directories(output_settings.directory, error);
    require(!error,
            "Output/Directory",
            "'" + output_settings.directory + "' cannot be created (" + error.message() + ")",
            "choose a directory you can write to");
    // Before anything in it is touched: another run may be writing into it.
    output_lock = std::make_unique<DirectoryLock>(output_settings.directory);
    if (!resume_from)
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
  Simulator<dim>::remove_earlier_output() const
  {
    // Only the names this program writes: a particles-00042.vtu of a longer earlier run would
    // otherwise sit next to this run's series as if it belonged to it.
    const std::regex ours("(particles|grid|mode)(-[0-9]{5}(\\.[0-9]{4})?\\.p?vtu|\\.pvd)(\\.tmp)?|"
                          "(statistics|stability|events)\\.csv|parameters\\.prm|original\\.prm|"
                          "checkpoint\\.bin(\\.tmp)?|surface_.+-[0-9]{5}\\.csv(\\.tmp)?");
    std::error_code  error;
    for (const auto &entry : std::filesystem::directory_iterator(output_settings.directory, error))
      if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), ours))
        std::filesystem::remove(entry.path(), error);
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
    observables.set_communicator(scene.communicator);
    balance.set_communicator(scene.communicator);

    tau_d    = std::pow(time_stepping.characteristic_length, 2) / scene.material.diffusivity();
    scale_u  = scene.material.shear_modulus() * std::pow(body_volume, (dim - 1.) / dim);
    scale_mu = scene.material.kT_over_nu() * body_volume;
  }


  template <int dim>
  void
  Simulator<dim>::open_statistics()
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
    for (const auto &c : observables.columns())
      columns.push_back(c);
    for (const auto &c : balance.columns())
      columns.push_back(c);
    // Wall times differ from run to run: not in test mode, whose output is compared.
    if (!output_settings.test_mode)
      columns.push_back("wall_time");
    // A resumed run continues its files where the checkpoint left them.
    const auto open = [this](StatisticsFile                 &file,
                             const std::string              &name,
                             const std::vector<std::string> &file_columns) {
      const std::string path = output_settings.directory + "/" + name;
      // Rank 0 writes; the others keep the same rows in memory.
      file.write_here(dealii::Utilities::MPI::this_mpi_process(scene.communicator) == 0);
      if (!resume_from)
        return file.open(path, file_columns);
      const auto &sizes = resume_from->header().file_sizes;
      const auto  size  = sizes.find(name);
      if (size == sizes.end())
        throw std::runtime_error("the checkpoint does not know '" + path + "'");
      file.resume(path, file_columns, size->second);
    };
    open(statistics, "statistics.csv", columns);
    if (stability.inertia)
      {
        std::vector<std::string> bracket_columns = {"t_stable",
                                                    "t_unstable",
                                                    "n_dofs_u",
                                                    "n_dofs_mu",
                                                    "n_neg_stable",
                                                    "n_neg_unstable",
                                                    "n_zero_unstable"};
        if (stability.n_eigenvalues > 0)
          for (const char *name : {"eig_1_stable", "eig_1_unstable"})
            bracket_columns.push_back(name);
        open(stability_file, "stability.csv", bracket_columns);
      }
    if (stability.inertia || observables.writes_events())
      open(events_file, "events.csv", {"event", "time", "t_over_tau_d", "mu_boundary", "pore"});
  }


  template <int dim>
  void
  Simulator<dim>::record_statistics(const NewtonReport           &report,
                                    const unsigned int            attempts,
                                    const dealii::Vector<double> *solution)
  {
    statistics.set("step", step);
    statistics.set("time", time * tau_d);
    statistics.set("t_over_tau_d", time);
    statistics.set("newton_iterations", report.iterations);
    statistics.set("attempts", attempts);
    statistics.set("residual_u", report.residual_u);
    statistics.set("residual_mu", report.residual_mu);
    statistics.set("n_particles", scene.particles.n_global_particles());
    if (!output_settings.test_mode && progress)
      statistics.set("wall_time", progress->elapsed());
    if (scene.system && step > 0)
      {
        statistics.set("n_dofs_u", scene.spaces->n_u_dofs());
        statistics.set("n_dofs_mu", scene.spaces->n_mu_dofs());
        statistics.set("n_active_cells", scene.system->n_active_cells());
      }
    std::function<std::pair<double, double>()> dirichlet_errors;
    if (solution != nullptr)
      dirichlet_errors = [&]() {
        return scene.system->dirichlet_errors(*solution);
      };
    if (scene.contact.enabled() && solution != nullptr)
      {
        const auto [active, penetration] = scene.system->contact_state(*solution);
        statistics.set("contact_points", active);
        statistics.set("contact_penetration", penetration);
      }
    observables.evaluate(scene.particles, scene.regions, dirichlet_errors, statistics);
    statistics.write_row();
    record_pore_events();
  }


  template <int dim>
  void
  Simulator<dim>::record_stability(const StabilityReport &result)
  {
    if (stability.inertia)
      {
        statistics.set("n_pos", result.inertia.n_positive);
        statistics.set("n_neg", result.inertia.n_negative);
        statistics.set("n_zero", result.inertia.n_zero);
        if (stability.drained_onset)
          statistics.set("n_neg_uu", result.drained_inertia.n_negative);
      }
    for (unsigned int k = 0; k < result.eigenvalues.size(); ++k)
      statistics.set("eig_" + std::to_string(k + 1), result.eigenvalues[k]);
    if (stability.inf_sup)
      statistics.set("inf_sup", result.inf_sup);
    if (stability.condition)
      statistics.set("condition_number", result.condition_number);
  }


  template <int dim>
  StepControl::Verdict
  Simulator<dim>::judge_signature(const StabilityReport &result)
  {
    if (!stability.inertia)
      return StepControl::Verdict::accept;
    const bool tangent_stable = result.inertia.n_positive == scene.spaces->n_u_dofs() &&
                                result.inertia.n_negative == scene.spaces->n_mu_dofs() &&
                                result.inertia.n_zero == 0;
    // Until the first onset the drained criterion (K_uu positive definite: no mode grows) brackets
    // it independently of the step; from then on the tangent's signature (no mode grows faster
    // than 1/dt) controls the steps.
    const bool use_drained = stability.drained_onset && !control->onset_seen();
    const bool stable =
      use_drained ? (result.drained_inertia.n_negative == 0 && result.drained_inertia.n_zero == 0)
                  : tangent_stable;
    const double t_end   = control->time() + control->attempt_size();
    const auto   verdict = control->judge_signature(stable);
    switch (verdict)
      {
        case StepControl::Verdict::retake:
          if (!announced_bracketing)
            pcout << "    the state loses stability ("
                  << (use_drained ? "K_uu indefinite" : "signature not (n_u, n_mu, 0)")
                  << ") between t = " << control->time() << " and " << t_end
                  << "; bisecting to 'Stability/Bisection tolerance' = "
                  << stability.bisection_tolerance << std::endl;
          announced_bracketing = true;
          return verdict;
        case StepControl::Verdict::shorten:
          pcout << "    the signature at t = " << t_end << " with dt = " << control->attempt_size()
                << " is (" << result.inertia.n_positive << ", " << result.inertia.n_negative << ", "
                << result.inertia.n_zero << "): a mode grows faster than 1/dt; retrying "
                << "with dt = " << control->proposed_step() << std::endl;
          return verdict;
        case StepControl::Verdict::step_dependent:
          pcout << "    with shorter steps the state at t = " << t_end
                << " is stable: the loss of stability depends on the step size; bracketing ended"
                << std::endl;
          break;
        case StepControl::Verdict::regained:
          pcout << "    the signature is (n_u, n_mu, 0) again at t/tau_d = " << t_end << ": stable"
                << std::endl;
          break;
        case StepControl::Verdict::onset:
          report_onset(result);
          break;
        case StepControl::Verdict::accept:
          break;
      }
    announced_bracketing = control->bracketing();
    if (tangent_stable)
      {
        last_stable_inertia = result.inertia;
        last_eigenvalue     = result.eigenvalues.empty() ? 0. : result.eigenvalues[0];
      }
    return verdict;
  }


  template <int dim>
  void
  Simulator<dim>::report_onset(const StabilityReport &result)
  {
    const auto &bracket = control->bracket();
    pcout << "    loss of stability between t/tau_d = " << bracket.t_stable << " (stable) and "
          << bracket.t_unstable << ": signature (" << result.inertia.n_positive << ", "
          << result.inertia.n_negative << ", " << result.inertia.n_zero << "), expected ("
          << scene.spaces->n_u_dofs() << ", " << scene.spaces->n_mu_dofs() << ", 0)";
    if (stability.drained_onset)
      pcout << "; K_uu has " << result.drained_inertia.n_negative
            << " negative eigenvalue(s) (drained criterion)";
    pcout << std::endl;
    stability_file.set("t_stable", bracket.t_stable);
    stability_file.set("t_unstable", bracket.t_unstable);
    stability_file.set("n_neg_stable", last_stable_inertia.n_negative);
    stability_file.set("n_neg_unstable", result.inertia.n_negative);
    stability_file.set("n_zero_unstable", result.inertia.n_zero);
    stability_file.set("n_dofs_u", scene.spaces->n_u_dofs());
    stability_file.set("n_dofs_mu", scene.spaces->n_mu_dofs());
    if (!result.eigenvalues.empty())
      {
        stability_file.set("eig_1_stable", last_eigenvalue);
        stability_file.set("eig_1_unstable", result.eigenvalues[0]);
      }
    stability_file.write_row();

    // Written as the event happens. The points still hold the state of the bracket's stable end
    // (the converged attempt is applied after the stability analysis): mu_boundary is taken there,
    // at most 'Bisection tolerance' earlier.
    write_event("bifurcation", bracket.t_unstable, 0);
  }


  template <int dim>
  void
  Simulator<dim>::note_inexact_extrapolation(const double t_begin)
  {
    if (scene.spaces->n_inexact_extrapolations() > 0 && !inexact_extrapolation_noted)
      {
        pcout << "  note: from t/tau_d = " << t_begin << ", "
              << scene.spaces->n_inexact_extrapolations()
              << " boundary control point(s) next to the grid's edge are extrapolated inexactly "
                 "(the body has moved within q cells of it; a larger 'Background grid' avoids "
                 "it; doc/method.md, \"Discretisation\")\n";
        inexact_extrapolation_noted = true;
      }
    // The initial body was checked strictly; from here on its motion cannot be helped.
    scene.spaces->tolerate_inexact_extrapolation();
  }


  template <int dim>
  void
  Simulator<dim>::record_pore_events()
  {
    for (const auto &[name, pore] : observables.new_events(scene.particles))
      {
        write_event(name, time, pore);
        pcout << "  event: " << name << (pore > 0 ? " of pore " + std::to_string(pore) : "")
              << " at t/tau_d = " << time << '\n';
      }
  }


  template <int dim>
  void
  Simulator<dim>::write_event(const std::string &name, const double t_over_tau_d, const int pore)
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
  Simulator<dim>::perturb_along_mode(const dealii::Vector<double> &mode,
                                     dealii::Vector<double>       &solution) const
  {
    // The eigenvector's sign and size are arbitrary: scale it to a largest control-point
    // displacement of 'Perturbation amplitude', signed so that the control point that moves
    // most along 'Perturbation direction' moves forwards.
    double      largest = 0., along = 0.;
    const auto &d = stability.perturbation_direction;
    for (unsigned int i = 0; i + dim <= mode.size(); i += dim)
      {
        double norm2 = 0., projection = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          {
            norm2 += mode(i + c) * mode(i + c);
            projection += mode(i + c) * d[c];
          }
        largest = std::max(largest, std::sqrt(norm2));
        if (std::abs(projection) > std::abs(along))
          along = projection;
      }
    if (!(largest > 0.))
      return;
    const double scale = stability.perturbation_amplitude / largest * (along < 0. ? -1. : 1.);
    for (unsigned int i = 0; i < mode.size(); ++i)
      solution(i) += scale * mode(i);
    pcout << "    perturbed along the critical mode: largest control-point displacement "
          << stability.perturbation_amplitude << std::endl;
  }


  template <int dim>
  void
  Simulator<dim>::record_mode(const dealii::Vector<double> &mode)
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
  void
  Simulator<dim>::write_output()
  {
    dealii::TimerOutput::Scope scope(timer, "output");
    output_step = step;
    if (output_settings.write_particles)
      particle_output->write(scene.particles, time);
    if (grid_output)
      grid_output->write(time);
    observables.write_surfaces(scene.particles, output_settings.directory);
    if (mode_output && mode_recorded)
      mode_output->write(time);
  }


  template <int dim>
  void
  Simulator<dim>::record_initial_grid()
  {
    grid_volume_points = volume_points_per_cell();
    std::vector<bool> has_material(grid_volume_points.size());
    for (unsigned int c = 0; c < has_material.size(); ++c)
      has_material[c] = grid_volume_points[c] > 0;
    scene.spaces->reinit(has_material);
    dealii::Vector<double> solution;
    initial_guess(solution);
    grid_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, solution);
  }


  template <int dim>
  void
  Simulator<dim>::store_mu_coefficients(const dealii::Vector<double> &solution)
  {
    const auto        &mu  = scene.spaces->mu();
    const unsigned int n_u = scene.spaces->n_u_dofs();
    for (unsigned int i = 0; i < mu_coefficients.size(); ++i)
      {
        const unsigned int dof = mu.dof_of_control_point(i);
        mu_known[i]            = true;
        if (dof != dealii::numbers::invalid_unsigned_int)
          mu_coefficients[i] = solution(n_u + dof);
        else if (mu.control_point_kind(i) == ControlPointKind::boundary)
          {
            double value = 0.;
            for (const auto &[interior, weight] : mu.extrapolation_weights(i))
              value += weight * solution(n_u + mu.dof_of_control_point(interior));
            mu_coefficients[i] = value;
          }
        else
          mu_known[i] = false;
      }
  }


  template <int dim>
  void
  Simulator<dim>::initial_guess(dealii::Vector<double> &solution, const double dt) const
  {
    solution.reinit(scene.spaces->n_dofs());
    if (!displacement_projection.empty() && last_dt > 0.)
      for (unsigned int i = 0; i < displacement_projection.size(); ++i)
        solution(i) = dt / last_dt * displacement_projection[i];
    const auto        &mu  = scene.spaces->mu();
    const unsigned int n_u = scene.spaces->n_u_dofs();
    // With 'Newton/Initial chemical potential = points' every coefficient starts from the
    // projection of the points' mu; otherwise only those that held no value in the last step
    // (newly covered by material), where a stale coefficient would put a stress jump into the
    // first residual that short (undrained) steps cannot absorb.
    const std::vector<double> &from_points     = mu_projection;
    const bool                 all_from_points = newton.mu_from_points && !from_points.empty();
    for (unsigned int i = 0; i < mu_coefficients.size(); ++i)
      {
        const unsigned int dof = mu.dof_of_control_point(i);
        if (dof != dealii::numbers::invalid_unsigned_int)
          solution(n_u + dof) = (all_from_points || (!mu_known[i] && !from_points.empty()))
                                  ? from_points[dof]
                                  : mu_coefficients[i];
      }
  }


  template <int dim>
  bool
  Simulator<dim>::error_acceptable(const dealii::Vector<double> &solution,
                                   const double                  dt,
                                   std::string                  &failure)
  {
    // The first step has no predictor: its estimate would be the whole motion.
    const bool displacement_rule = time_stepping.displacement_tolerance > 0.;
    // A step far longer than the last (after a landing on a stop time) would amplify the last
    // step's noise into its predictor: no estimate of the tolerance rule for it.
    const bool tolerance_rule =
      time_stepping.tolerance > 0. &&
      (time_stepping.tolerance_until_onset
         ? !control->onset_seen()
         : (time_stepping.tolerance_until == 0. || time < time_stepping.tolerance_until)) &&
      StepControl::estimate_applies(dt, last_dt);
    if (!(displacement_rule || tolerance_rule) || !(last_dt > 0.))
      return true;
    const double difference =
      displacement_rule ? scene.system->largest_increment_deviation(solution, dt / last_dt) : 0.;
    double local_error = 0.;
    if (tolerance_rule)
      {
        const auto error =
          scene.system->local_error_estimate(solution, dt / last_dt, time_stepping.error_largest);
        local_error = std::max(error.displacement / time_stepping.characteristic_length,
                               error.chemical_potential);
      }
    const auto excess = control->error_excess(difference, local_error, dt);
    if (control->judge_error(excess))
      {
        if (control->error_uncontrolled() && n_uncontrolled_errors++ == 0)
          pcout << "    the step's error estimate exceeds its tolerance " << excess.factor
                << " times whatever the step: a jump in the last step (a perturbation) or the "
                   "points' integration noise, not an error of this one; accepted (such steps "
                   "are accepted without a word from here on and counted at the end)"
                << std::endl;
        return true;
      }
    std::ostringstream why;
    why << "the error estimate exceeds ";
    if (displacement_rule && difference > time_stepping.displacement_tolerance)
      why << "'Time stepping/Displacement tolerance' (a point's motion differs from the last "
             "step's by "
          << difference << ")";
    else
      why << "'Time stepping/Tolerance' (local error " << local_error << " against "
          << control->tolerated_local_error(dt) << ")";
    failure = why.str();
    return false;
  }


  template <int dim>
  typename Simulator<dim>::StepOutcome
  Simulator<dim>::advance()
  {
    {
      dealii::TimerOutput::Scope scope(timer, "grid reset");
      if (grid_output || mode_output)
        grid_volume_points = volume_points_per_cell();
      // A grid reset that changes the classification gives the tangent a new sparsity pattern;
      // the factorisation of the old one goes first, while the matrix it refers to still
      // exists. Otherwise it stays, and Newton may start from it (modified Newton).
      if (scene.system->setup(scene.particles, [this] {
            linear_solver.new_pattern();
          }))
        ++n_new_patterns;
      if (linear_solver.iterative())
        linear_solver.set_block_structure(scene.spaces->n_u_dofs(),
                                          dim,
                                          scene.spaces->u_dof_greville_points());
      if (!resumed_tangent.empty())
        {
          if (scene.system->restore_tangent(resumed_classification, resumed_tangent))
            linear_solver.factorize(scene.system->matrix());
          resumed_tangent.clear();
          resumed_classification.clear();
        }
      // The points and the basis are fixed for the attempts of the step: project mu once, and
      // only if some coefficient will start from it.
      bool needed = newton.mu_from_points;
      for (unsigned int i = 0; i < mu_known.size() && !needed; ++i)
        needed = !mu_known[i] && scene.spaces->mu().dof_of_control_point(i) !=
                                   dealii::numbers::invalid_unsigned_int;
      mu_projection           = needed ? scene.system->mu_from_points() : std::vector<double>();
      displacement_projection = (newton.extrapolate_displacement && last_dt > 0.)
                                  ? scene.system->displacement_from_points(1.)
                                  : std::vector<double>();
    }
    dealii::Vector<double> solution;
    for (unsigned int attempt = 1;; ++attempt)
      {
        // On several ranks a signal reaches them at different moments: they stop together, at
        // the first attempt where any of them has it.
        if (dealii::Utilities::MPI::max(stop_signal(), scene.communicator) != 0)
          return StepOutcome::interrupted;
        const double t_begin = control->time();
        const double step_dt = control->attempt();
        scene.system->set_boundary_values(t_begin + step_dt, t_begin);
        initial_guess(solution, step_dt);
        NewtonReport report = solve_newton(*scene.system,
                                           solution,
                                           step_dt * tau_d,
                                           newton,
                                           linear_solver,
                                           scale_u,
                                           scale_mu,
                                           timer);
        n_newton_iterations += report.iterations;
        n_factorizations += report.factorizations;
        if (report.converged && time_stepping.largest_increment > 0.)
          {
            const double moved = scene.system->largest_displacement_increment(solution);
            if (moved > time_stepping.largest_increment * scene.spaces->h_u())
              {
                report.converged = false;
                std::ostringstream why;
                why << "a material point moves " << moved / scene.spaces->h_u()
                    << " cells, more than 'Time stepping/Largest increment' = "
                    << time_stepping.largest_increment;
                report.failure = why.str();
              }
          }
        if (report.converged && !error_acceptable(solution, step_dt, report.failure))
          {
            pcout << "    step " << control->step() + 1 << " at t = " << t_begin
                  << " with dt = " << step_dt << " retaken (" << report.failure
                  << "); retrying with dt = " << control->proposed_step() << std::endl;
            announced_bracketing = false;
            continue;
          }
        if (!report.converged)
          {
            pcout << "    step " << control->step() + 1 << " at t = " << t_begin
                  << " with dt = " << step_dt << " failed (" << report.failure << ")";
            if (newton.log_failures)
              {
                pcout << "\n      Newton: scaled |R_u|, |R_mu| at the start of each iteration, "
                         "damping taken:";
                for (const auto &h : report.history)
                  pcout << "\n        " << h[0] << "  " << h[1] << "  " << h[2];
                pcout << "\n     ";
              }
            if (control->bracketing())
              pcout << "; bracketing of the loss of stability abandoned";
            announced_bracketing = false;
            if (!control->cut_step())
              {
                pcout << "; the step would fall below 'Time stepping/Minimum step' = "
                      << time_stepping.minimum_step << std::endl;
                return StepOutcome::failed;
              }
            pcout << "; retrying with dt = " << control->proposed_step() << std::endl;
            continue;
          }

        bool            perturb = false;
        StabilityReport result;
        if (stability.enabled())
          {
            {
              dealii::TimerOutput::Scope scope(timer, "stability");
              if (!report.tangent_at_solution)
                scene.system->assemble(solution, step_dt * tau_d, true);
              // The Newton solver's LDL^T of the converged tangent gives the signature, and is
              // the factorisation the next step's modified Newton starts from.
              const SymmetricFactorization *factorization = nullptr;
              if ((stability.inertia || stability.n_eigenvalues > 0) && linear_solver.uses_ldlt())
                {
                  linear_solver.factorize(scene.system->matrix());
                  ++n_factorizations;
                  factorization = linear_solver.symmetric_factorization();
                }
              result = analyse_stability(
                scene.system->matrix(),
                scene.spaces->n_u_dofs(),
                stability,
                [this]() {
                  return scene.system->mu_mass_matrix();
                },
                factorization);
            }
            const auto verdict = judge_signature(result);
            if (verdict == StepControl::Verdict::retake || verdict == StepControl::Verdict::shorten)
              continue;
            record_stability(result);
            if (mode_output && result.mode.size() == scene.spaces->n_u_dofs())
              record_mode(result.mode);
            // Leave the unstable branch at the bracketed critical time (doc/method.md).
            ended_at_onset = verdict == StepControl::Verdict::onset && stability.end_at_onset;
            perturb        = verdict == StepControl::Verdict::onset && !ended_at_onset &&
                      stability.perturbation_amplitude > 0. &&
                      result.mode.size() == scene.spaces->n_u_dofs();
          }
        // The piece's terms at the converged state, before a kick moves it.
        std::vector<typename MixedSystem<dim>::PieceBalance> balances;
        if (balance.enabled())
          balances = scene.system->boundary_balances(solution, step_dt * tau_d);
        if (perturb)
          perturb_along_mode(result.drained_mode.size() == scene.spaces->n_u_dofs()
                               ? result.drained_mode
                               : result.mode,
                             solution);
        {
          dealii::TimerOutput::Scope scope(timer, "update");
          const auto                 n_before = scene.particles.n_global_particles();
          try
            {
              scene.system->update_particles(solution);
            }
          catch (const std::runtime_error &e)
            {
              std::ostringstream when;
              when << "at t/tau_d = " << t_begin + step_dt << ", " << e.what();
              throw std::runtime_error(when.str());
            }
          sort_into_cells(scene.particles, scene.grid, *scene.triangulation);
          // The body moves and changes the points per rank: partition the grid anew when the
          // most loaded rank holds much more than its share (its time sets the step's).
          // The partition cannot split a cell: where whole cells leave an imbalance, the run
          // waits until the imbalance has grown beyond what the last partition left.
          const double imbalance = scene.imbalance();
          if (imbalance > std::max(largest_imbalance, 1.05 * imbalance_after_partition))
            {
              scene.balance_partition();
              imbalance_after_partition = scene.imbalance();
              ++n_repartitions;
            }
          if (scene.particles.n_global_particles() != n_before)
            throw std::runtime_error(
              std::to_string(n_before - scene.particles.n_global_particles()) +
              " material point(s) left the background grid at t = " +
              std::to_string(t_begin + step_dt) +
              " tau_d; enlarge the grid ('Background grid/Upper corner')");
          store_mu_coefficients(solution);
          if (grid_output)
            grid_output->record(scene.spaces->u(),
                                scene.spaces->mu(),
                                grid_volume_points,
                                solution);
        }
        control->accept(report.iterations);
        note_inexact_extrapolation(t_begin);
        // The kick is no motion to continue: the next step starts without a predictor.
        last_dt = perturb ? 0. : step_dt;
        time    = control->time();
        step    = control->step();
        progress->step_accepted(time, step_dt);
        statistics.set("dt", step_dt);
        balance.record_step(balances, step_dt * tau_d, scene.particles, scene.regions, statistics);
        record_statistics(report, attempt, &solution);
        print_step_line(report, step_dt);

        const bool interval_due =
          (output_settings.interval_steps > 0 && step % output_settings.interval_steps == 0) ||
          (output_settings.interval_time > 0. &&
           time >= next_output_time * (1. - relative_time_tolerance));
        // The next multiple of the interval after this time, in one step: a loop that adds the
        // interval would run for ever when it is tiny against the time.
        if (output_settings.interval_time > 0. &&
            next_output_time <= time * (1. + relative_time_tolerance))
          next_output_time =
            (std::floor(time * (1. + relative_time_tolerance) / output_settings.interval_time) +
             1.) *
            output_settings.interval_time;
        if (control->at_stop_time() || interval_due || control->finished() || ended_at_onset)
          write_output();
        return StepOutcome::accepted;
      }
  }


  template <int dim>
  void
  Simulator<dim>::print_step_line(const NewtonReport &report, const double step_dt) const
  {
    pcout << "  step " << std::setw(5) << step << "  t/tau_d = " << std::setw(11)
          << std::setprecision(5) << time << "  dt = " << std::setw(10) << step_dt << "  Newton "
          << std::setw(2) << report.iterations;
    if (report.damped_iterations > 0)
      pcout << " (" << report.damped_iterations << " damped)";
    pcout << "  |R_u| " << std::setprecision(2) << report.residual_u << "  |R_mu| "
          << report.residual_mu;
    if (newton.log_failures && !report.history.empty())
      pcout << "  (first: " << report.history[0][0] << ", " << report.history[0][1] << ")";
    // Wall times differ from run to run: not in test mode, whose log is compared.
    if (!output_settings.test_mode)
      {
        pcout << "  wall " << format_duration(progress->elapsed()) << " (" << std::setprecision(3)
              << 100. * time / time_stepping.end_time << "%";
        const double remaining = progress->remaining();
        if (remaining >= 0. && !control->finished())
          pcout << ", end in ~" << format_duration(remaining);
        pcout << ")";
      }
    pcout << std::setprecision(6) << std::endl;
  }


  template <int dim>
  int
  Simulator<dim>::advance_to_end()
  {
    progress->begin_stepping();
    while (!control->finished())
      {
        // On several ranks a signal reaches them at different moments: they stop together,
        // at the first step boundary where any of them has it.
        if (const int signal = dealii::Utilities::MPI::max(stop_signal(), scene.communicator))
          return stop_on_signal(signal);
        if (control->out_of_steps())
          {
            std::ostringstream message;
            message << "gelmpm: stopped after 'Time stepping/Maximum steps' = "
                    << time_stepping.maximum_steps << " steps at t/tau_d = " << time;
            pcout << message.str() << std::endl;
            pcerr << message.str() << std::endl;
            return 1;
          }
        const StepOutcome outcome = advance();
        if (outcome == StepOutcome::interrupted)
          return stop_on_signal(dealii::Utilities::MPI::max(stop_signal(), scene.communicator),
                                false);
        if (outcome == StepOutcome::failed)
          {
            // In the log and on stderr, where a failed run's message is looked for.
            std::ostringstream message;
            message << "gelmpm: the run cannot converge beyond t/tau_d = " << time
                    << "; results up to there are in " << output_settings.directory;
            pcout << message.str() << std::endl;
            pcerr << message.str() << std::endl;
            write_output();
            return 1;
          }
        if (ended_at_onset)
          {
            pcout << "gelmpm: ended at the bracketed loss of stability ('Stability/End at "
                     "onset')"
                  << std::endl;
            return 0;
          }
        if (checkpoint_due())
          write_checkpoint();
      }
    return 0;
  }


  template <int dim>
  bool
  Simulator<dim>::checkpoint_due() const
  {
    if (!checkpoint_settings.enabled() || checkpoint_step == step)
      return false;
    const std::chrono::duration<double, std::ratio<60>> since =
      std::chrono::steady_clock::now() - last_checkpoint;
    return (checkpoint_settings.interval_steps > 0 &&
            step % checkpoint_settings.interval_steps == 0) ||
           (checkpoint_settings.interval_minutes > 0. &&
            since.count() >= checkpoint_settings.interval_minutes) ||
           control->finished();
  }


  template <int dim>
  template <class Archive>
  void
  Simulator<dim>::serialize_run_state(Archive &ar)
  {
    ar &time &step &output_step &next_output_time                          &last_dt;
    ar &mu_coefficients                                                    &mu_known;
    ar &announced_bracketing &inexact_extrapolation_noted &last_eigenvalue &mode_recorded;
    ar &last_stable_inertia.n_positive &last_stable_inertia.n_negative &last_stable_inertia.n_zero;
    ar &*control &observables &balance                                &*particle_output;
    if (grid_output)
      ar &*grid_output;
    if (mode_output)
      ar &*mode_output;
    // The factorisation the next step's first Newton iteration may solve with (modified
    // Newton), as the entries it was made of and the classification of their pattern: a resumed
    // run refactorises them if its first grid reset gives that classification again.
    // (write_checkpoint() gathers them.)
    ar &resumed_classification &resumed_tangent;
  }


  template <int dim>
  void
  Simulator<dim>::write_checkpoint(const bool with_tangent)
  {
    dealii::TimerOutput::Scope scope(timer, "checkpoint");
    const auto                 begin = std::chrono::steady_clock::now();
    CheckpointHeader           header;
    header.parameters = checkpoint_parameters(parameters_as_used);
    header.step       = step;
    header.time       = time;
    // The rows up to here must be on the disk when the checkpoint that counts them is.
    for (const auto &[file, name] : {std::make_pair(&statistics, "statistics.csv"),
                                     std::make_pair(&stability_file, "stability.csv"),
                                     std::make_pair(&events_file, "events.csv")})
      if (file->bytes() > 0)
        header.file_sizes[name] = file->bytes();
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
          header.file_sizes[name] = size;
      }
    // Every rank's points, as its own archive, and the factorised tangent's entries of every
    // rank, gathered on rank 0, which writes the file.
    std::string my_points;
    {
      std::ostringstream bytes;
      {
        boost::archive::binary_oarchive ar(bytes);
        save_material_points(ar, scene.particles);
      }
      my_points = bytes.str();
    }
    std::vector<std::string> points = {my_points};
    resumed_classification          = scene.system->classification_of_pattern();
    // Stopped between the attempts of a step, the factorisation is of a rejected attempt: the
    // resumed run factorises afresh.
    resumed_tangent = with_tangent ? linear_solver.entries_of_factorization() : SparseEntries();
    if (Collective::is_parallel(scene.communicator))
      {
        points           = dealii::Utilities::MPI::gather(scene.communicator, my_points, 0);
        const auto parts = dealii::Utilities::MPI::gather(scene.communicator, resumed_tangent, 0);
        resumed_tangent.clear();
        for (const auto &part : parts)
          resumed_tangent.append(part);
      }
    std::uintmax_t size = 0;
    Collective::on_root(scene.communicator, [&]() {
      for (const auto &[file, name] : {std::make_pair(&statistics, "statistics.csv"),
                                       std::make_pair(&stability_file, "stability.csv"),
                                       std::make_pair(&events_file, "events.csv")})
        if (file->bytes() > 0)
          sync_to_disk(output_settings.directory + "/" + name);
      size = GelMPM::write_checkpoint(output_settings.directory,
                                      header,
                                      [&](boost::archive::binary_oarchive &ar) {
                                        ar << points;
                                        serialize_run_state(ar);
                                      });
    });
    resumed_classification.clear();
    resumed_tangent.clear();
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_step = step;
    pcout << "  checkpoint at step " << step;
    if (!output_settings.test_mode)
      pcout << " (" << std::setprecision(3) << size / 1e6 << " MB in "
            << std::chrono::duration<double>(last_checkpoint - begin).count() << " s)"
            << std::setprecision(6);
    pcout << std::endl;
  }


  template <int dim>
  void
  Simulator<dim>::restore_checkpoint()
  {
    auto                    &ar = resume_from->archive();
    std::vector<std::string> points;
    ar >> points;
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
    serialize_run_state(ar);
    open_statistics();
    if (output_settings.write_particles)
      particle_output->restore_files();
    if (grid_output)
      grid_output->restore_files();
    if (mode_output)
      mode_output->restore_files();
    std::error_code ignored;
    std::filesystem::remove(checkpoint_path(output_settings.directory) + ".tmp", ignored);
    // From the first accepted step on the run accepts inexact extrapolations (advance()).
    if (step > 0)
      scene.spaces->tolerate_inexact_extrapolation();
    resume_from.reset();
    checkpoint_step = step;
    pcout << "  resumed from the checkpoint at step " << step << ", t/tau_d = " << time
          << std::endl;
  }


  template <int dim>
  void
  Simulator<dim>::start()
  {
    progress = std::make_unique<RunProgress>(time_stepping, run_start);
    scene.create_system();
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
    mu_coefficients.assign(scene.spaces->mu_space().n_functions(), scene.material.mu_0());
    mu_known.assign(scene.spaces->mu_space().n_functions(), true);
    if (output_settings.write_grid)
      {
        grid_output =
          std::make_unique<GridOutput<dim>>(output_settings.directory, *scene.triangulation);
        if (!resume_from)
          record_initial_grid();
      }
    if (stability.write_mode)
      mode_output =
        std::make_unique<GridOutput<dim>>(output_settings.directory, *scene.triangulation, "mode");
    control         = std::make_unique<StepControl>(time_stepping,
                                            stability.bisection_tolerance,
                                            stability.unstable_step,
                                            stability.signature_control);
    last_checkpoint = std::chrono::steady_clock::now();
    if (resume_from)
      return restore_checkpoint();
    open_statistics();
    next_output_time = output_settings.interval_time;

    statistics.set("dt", 0.);
    balance.record_initial(scene.particles, scene.regions, statistics);
    record_statistics(NewtonReport(), 0, nullptr);
    write_output();
  }


  template <int dim>
  int
  Simulator<dim>::stop_on_signal(const int signal, const bool between_steps)
  {
    // Before the last output, which the uninterrupted run would not write: the resumed run
    // drops it from the series.
    if (checkpoint_settings.enabled() && checkpoint_step != step)
      write_checkpoint(between_steps);
    if (output_step != step)
      write_output();
    pcerr << "gelmpm: " << signal_name(signal) << " received: stopped after step " << step
          << " at t/tau_d = " << time << " with a complete last output; the results are in "
          << output_settings.directory << std::endl;
    return 128 + signal;
  }


  template <int dim>
  int
  Simulator<dim>::run()
  {
    print_header();
    prepare_output_directory();
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
              << "; what was written up to t/tau_d = " << time << " is kept in "
              << output_settings.directory << std::endl;
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
      pcout << "gelmpm: reached t/tau_d = " << time << " in " << step << " steps" << std::endl;
    if (n_uncontrolled_errors > 0)
      pcout << "gelmpm: " << n_uncontrolled_errors
            << " step(s) accepted with an error estimate above its tolerance whatever the step "
               "(a perturbation's jump or the points' integration noise)"
            << std::endl;
    if (!output_settings.test_mode)
      pcout << "gelmpm: " << n_newton_iterations << " Newton iterations, " << n_factorizations
            << " factorisations (" << linear_solver.name() << "), " << n_new_patterns
            << " sparsity patterns";
    if (!output_settings.test_mode && Collective::is_parallel(scene.communicator))
      pcout << ", " << dealii::Utilities::MPI::n_mpi_processes(scene.communicator)
            << " ranks, partitioned anew " << n_repartitions << " times";
    if (!output_settings.test_mode && linear_solver.iterative())
      {
        const auto [iterations, solves] = linear_solver.krylov_iterations();
        pcout << ", " << iterations << " Krylov iterations in " << solves << " solves ("
              << (solves > 0 ? double(iterations) / solves : 0.) << " per solve)";
      }
    if (!output_settings.test_mode)
      pcout << std::endl;
    if (!output_settings.test_mode)
      {
        // The high-water mark of each rank's resident memory (VmHWM).
        dealii::Utilities::System::MemoryStats memory;
        dealii::Utilities::System::get_memory_stats(memory);
        const double mb = memory.VmHWM / 1024.;
        pcout << "gelmpm: peak memory " << std::setprecision(4)
              << dealii::Utilities::MPI::max(mb, scene.communicator) << " MB / "
              << dealii::Utilities::MPI::sum(mb, scene.communicator) << " MB"
              << std::setprecision(6) << std::endl;
      }
    if (output_settings.test_mode && !statistics.rows().empty())
      {
        // The final row of statistics.csv, without timings, for comparison with a reference.
        const auto &row = statistics.rows().back();
        for (unsigned int c = 0; c < row.size(); ++c)
          if (statistics.columns()[c] != "time")
            pcout << "  final " << statistics.columns()[c] << " = " << row[c] << '\n';
      }
    if (!output_settings.test_mode)
      {
        pcout << "gelmpm: results are in " << output_settings.directory
              << " (open particles.pvd in ParaView; statistics.csv per step)" << std::endl;
        timer.print_summary();
      }
    return status;
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


  template class Simulator<2>;
  template class Simulator<3>;
  template int
  run_scene_file<2>(const std::string &, const std::vector<ParameterOverride> &);
  template int
  run_scene_file<3>(const std::string &, const std::vector<ParameterOverride> &);
} // namespace GelMPM

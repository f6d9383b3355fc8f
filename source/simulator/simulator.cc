#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/stop_request.h>
#include <gelmpm/core/version.h>
#include <gelmpm/io/file_writing.h>
#include <gelmpm/io/output_directory.h>
#include <gelmpm/io/piece_table.h>
#include <gelmpm/particles/point_location.h>
#include <gelmpm/particles/point_serialization.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/rigid_motion.h>
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
#include <sys/stat.h>
#include <unistd.h>

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
  {
    output_settings.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    // The symmetric Nitsche variant keeps the tangent symmetric (NitscheSettings): LDL^T.
    linear_solver.set_symmetric(scene.nitsche.symmetry > 0.);
    newton.parse_parameters(prm);
    time_stepping.parse_parameters(prm);
    time_stepping.check_resolvable(newton.tolerance, NewtonSettings::smallest_tolerance);
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
      check_output_directory(resume);
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
    // Last: a scene with a mistake found above may leave its body free as well.
    check_rigid_motions();
  }


  template <int dim>
  void
  Simulator<dim>::check_rigid_motions() const
  {
    const auto motions = unheld_rigid_motions(scene.particles,
                                              scene.boundary_conditions,
                                              scene.contact,
                                              scene.grid.lower,
                                              scene.grid.upper,
                                              scene.communicator,
                                              scene.grid.axisymmetric);
    if (motions.empty())
      return;
    std::string list;
    for (unsigned int i = 0; i < motions.size(); ++i)
      list += (i == 0 ? "" : i + 1 == motions.size() ? " and " : ", ") + motions[i];
    // The tangent is singular along them: the solver gives the body an arbitrary amount of
    // them, made of round-off (a quarter square free on all sides ended its swelling 6 % of
    // its size off its symmetric position, without a word).
    throw InputError("Boundary conditions",
                     "leave the body free in " + list +
                       ": no piece prescribes the displacement along such a motion and no "
                       "contact plane lies across it, so the tangent is singular and the solves "
                       "move the body by an arbitrary amount of it made of round-off",
                     "give the pieces on the body's planes of symmetry 'Displacement = normal', "
                     "or hold a piece by 'Displacement = fixed'");
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
    scene.check_obstacles(times);

    // A prescribed chemical potential that starts away from the body's mu_0 (the functions are
    // at t = 0 now): said only if the run then fails (jump_hint()).
    const double mu_0    = scene.regions[0].mu_0();
    double       largest = 0.1 * std::abs(mu_0);
    for (unsigned int i = 0; i < scene.boundary_conditions.n_pieces(); ++i)
      {
        const auto &piece = scene.boundary_conditions.piece(i);
        if (!piece.chemical_potential_prescribed())
          continue;
        for (const auto &x : samples[i])
          if (const double mu = piece.chemical_potential_value().value(x);
              std::abs(mu - mu_0) > largest)
            {
              largest = std::abs(mu - mu_0);
              std::ostringstream words;
              words << "the chemical potential prescribed on '" << piece.name
                    << "' jumps at t = 0 from the gel's mu_0/(k_BT) = " << mu_0 << " to " << mu;
              boundary_jump = words.str();
            }
      }
  }


  template <int dim>
  std::string
  Simulator<dim>::jump_hint(const double t) const
  {
    double h = scene.grid.cell_size(0);
    for (unsigned int d = 1; d < dim; ++d)
      h = std::min(h, scene.grid.cell_size(d));
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
  void
  Simulator<dim>::check_output_directory(const bool resume) const
  {
    GelMPM::check_output_directory(output_settings.directory,
                                   "Output/Directory",
                                   scene_file,
                                   resume);
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
    std::error_code error;
    for (const auto &entry : std::filesystem::directory_iterator(output_settings.directory, error))
      if (entry.is_regular_file() &&
          std::regex_match(entry.path().filename().string(), run_output_names()))
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

    scales = RunScales::of(dim,
                           time_stepping.characteristic_length,
                           scene.material.diffusivity(),
                           scene.material.shear_modulus(),
                           scene.material.kT_over_nu(),
                           body_volume);
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
    for (const auto &c : obstacle_columns())
      columns.push_back(c);
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
    if (stability.detects_onset())
      {
        std::vector<std::string> bracket_columns = {"t_stable",
                                                    "t_unstable",
                                                    "n_dofs_u",
                                                    "n_dofs_mu"};
        if (stability.inertia)
          for (const char *name : {"n_neg_stable", "n_neg_unstable", "n_zero_unstable"})
            bracket_columns.push_back(name);
        if (stability.n_eigenvalues > 0)
          for (const char *name : {"eig_1_stable", "eig_1_unstable"})
            bracket_columns.push_back(name);
        if (stability.iterative_drained())
          bracket_columns.push_back("drained_eig_1_unstable");
        open(stability_file, "stability.csv", bracket_columns);
      }
    if (stability.detects_onset() || observables.writes_events())
      open(events_file, "events.csv", {"event", "time", "t_over_tau_d", "mu_boundary", "pore"});
  }


  template <int dim>
  std::vector<std::string>
  Simulator<dim>::obstacle_columns() const
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
  Simulator<dim>::record_statistics(const NewtonReport           &report,
                                    const unsigned int            attempts,
                                    const dealii::Vector<double> *solution)
  {
    statistics.set("step", current_step());
    statistics.set("time", current_time() * scales.tau_d);
    statistics.set("t_over_tau_d", current_time());
    statistics.set("newton_iterations", report.iterations);
    statistics.set("attempts", attempts);
    statistics.set("residual_u", report.residual_u);
    statistics.set("residual_mu", report.residual_mu);
    statistics.set("n_particles", scene.particles.n_global_particles());
    if (!output_settings.test_mode && progress)
      statistics.set("wall_time", progress->elapsed());
    if (scene.system && current_step() > 0)
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
    // The obstacles' reactions of the converged state (before_update()); none at the start.
    const auto columns = obstacle_columns();
    for (unsigned int k = 0, c = 0; k < scene.obstacles.size(); ++k)
      {
        const bool known = solution != nullptr && k < reactions.size();
        for (unsigned int d = 0; d < dim; ++d)
          statistics.set(columns[c++], known ? reactions[k].force[d] : 0.);
        statistics.set(columns[c++], known ? reactions[k].area : 0.);
        statistics.set(columns[c++], known ? reactions[k].radius : 0.);
      }
    observables.evaluate(scene.particles, scene.regions, dirichlet_errors, statistics);
    statistics.write_row();
    record_pore_events();
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
        write_event(name, current_time(), pore);
        pcout << "  event: " << name << (pore > 0 ? " of pore " + std::to_string(pore) : "")
              << " at t/tau_d = " << current_time() << '\n';
      }
  }


  template <int dim>
  void
  Simulator<dim>::write_event(const std::string &name, const double t_over_tau_d, const int pore)
  {
    events_file.set("event", name);
    events_file.set("time", t_over_tau_d * scales.tau_d);
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
  void
  Simulator<dim>::record_initial_grid()
  {
    grid_volume_points = volume_points_per_cell();
    std::vector<bool> has_material(grid_volume_points.size());
    for (unsigned int c = 0; c < has_material.size(); ++c)
      has_material[c] = grid_volume_points[c] > 0;
    scene.spaces->reinit(has_material);
    dealii::Vector<double> solution;
    model->initial_guess(solution);
    grid_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, solution);
  }


  template <int dim>
  void
  Simulator<dim>::print_step_line(const NewtonReport &report, const double step_dt) const
  {
    pcout << "  step " << std::setw(5) << current_step() << "  t/tau_d = " << std::setw(11)
          << std::setprecision(5) << current_time() << "  dt = " << std::setw(10) << step_dt
          << "  Newton " << std::setw(2) << report.iterations;
    if (report.damped_iterations > 0)
      pcout << " (" << report.damped_iterations << " damped)";
    pcout << "  |R_u| " << std::setprecision(2) << report.residual_u << "  |R_mu| "
          << report.residual_mu;
    if (loop->newton().log_failures && !report.history.empty())
      pcout << "  (first: " << report.history[0][0] << ", " << report.history[0][1] << ")";
    // Wall times differ from run to run: not in test mode, whose log is compared.
    if (!output_settings.test_mode)
      {
        pcout << "  wall " << format_duration(progress->elapsed()) << " (" << std::setprecision(3)
              << 100. * current_time() / time_stepping.end_time << "%";
        const double remaining = progress->remaining();
        if (remaining >= 0. && !loop->control().finished())
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
    switch (loop->run())
      {
        case TimeLoop::Outcome::finished:
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
          {
            // In the log and on stderr, where a failed run's message is looked for.
            std::ostringstream message;
            message << "gelmpm: the run cannot converge beyond t/tau_d = " << current_time()
                    << "; results up to there are in " << output_settings.directory;
            // Why, on stderr too: the log's line per attempt is not where one looks first.
            if (!loop->failure().empty())
              message << ": " << loop->failure();
            if (const auto hint = jump_hint(current_time()); !hint.empty())
              message << "; " << hint;
            if (!loop->round_off_hint().empty())
              message << " (" << loop->round_off_hint() << ")";
            pcout << message.str() << std::endl;
            pcerr << message.str() << std::endl;
            write_output();
            return 1;
          }
      }
    return 1;
  }


  template <int dim>
  void
  Simulator<dim>::step_begins()
  {
    if (grid_output || mode_output)
      grid_volume_points = volume_points_per_cell();
  }


  template <int dim>
  bool
  Simulator<dim>::before_update(dealii::Vector<double> &solution, const double dt)
  {
    // The pieces' terms at the converged state, before a kick moves it.
    balances.clear();
    if (balance.enabled())
      balances = scene.system->boundary_balances(solution, dt * scales.tau_d);
    reactions.clear();
    if (!scene.obstacles.empty())
      reactions = scene.system->obstacle_reactions(solution);
    return false;
  }


  template <int dim>
  void
  Simulator<dim>::accepted(const AcceptedStep &step, const dealii::Vector<double> &solution)
  {
    if (grid_output)
      grid_output->record(scene.spaces->u(), scene.spaces->mu(), grid_volume_points, solution);
    note_inexact_extrapolation(step.t_begin);
    progress->step_accepted(step.time, step.dt);
    statistics.set("dt", step.dt);
    balance.record_step(balances,
                        step.dt * scales.tau_d,
                        scene.particles,
                        scene.regions,
                        statistics);
    record_statistics(step.report, step.attempts, &solution);
    print_step_line(step.report, step.dt);
    if (step.output_due || (monitor && monitor->end_requested()))
      write_output();
  }


  template <int dim>
  void
  Simulator<dim>::between_steps()
  {
    if (checkpoint_due())
      write_checkpoint();
  }


  template <int dim>
  bool
  Simulator<dim>::checkpoint_due() const
  {
    const unsigned int step = current_step();
    if (!checkpoint_settings.enabled() || checkpoint_step == step)
      return false;
    const std::chrono::duration<double, std::ratio<60>> since =
      std::chrono::steady_clock::now() - last_checkpoint;
    return (checkpoint_settings.interval_steps > 0 &&
            step % checkpoint_settings.interval_steps == 0) ||
           (checkpoint_settings.interval_minutes > 0. &&
            since.count() >= checkpoint_settings.interval_minutes) ||
           loop->control().finished();
  }


  template <int dim>
  template <class Archive>
  void
  Simulator<dim>::serialize_run_state(Archive &ar)
  {
    ar &*loop &*model &output_step &inexact_extrapolation_noted &mode_recorded;
    if (monitor)
      ar &*monitor;
    ar &observables &balance &*particle_output;
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
    header.step       = current_step();
    header.time       = current_time();
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
    checkpoint_step = current_step();
    pcout << "  checkpoint at step " << checkpoint_step;
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
    model->restore_factorization(resumed_classification, resumed_tangent);
    resumed_classification.clear();
    resumed_tangent.clear();
    open_statistics();
    if (output_settings.write_particles)
      particle_output->restore_files();
    if (grid_output)
      grid_output->restore_files();
    if (mode_output)
      mode_output->restore_files();
    std::error_code ignored;
    std::filesystem::remove(checkpoint_path(output_settings.directory) + ".tmp", ignored);
    // From the first accepted step on the run accepts inexact extrapolations (accepted()).
    if (current_step() > 0)
      scene.spaces->tolerate_inexact_extrapolation();
    resume_from.reset();
    checkpoint_step = current_step();
    pcout << "  resumed from the checkpoint at step " << checkpoint_step
          << ", t/tau_d = " << current_time() << std::endl;
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
    model           = std::make_unique<MaterialPointModel<dim>>(scene,
                                                      linear_solver,
                                                      newton,
                                                      time_stepping.characteristic_length,
                                                      timer);
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
    loop = std::make_unique<TimeLoop>(*model,
                                      time_stepping,
                                      newton,
                                      linear_solver,
                                      scales,
                                      pcout,
                                      timer,
                                      stability.bisection_tolerance,
                                      stability.unstable_step,
                                      stability.signature_control,
                                      output_settings.interval_steps,
                                      output_settings.interval_time);
    // Registered first: the pieces' balances are taken before the monitor's kick moves the state.
    loop->add_observer(*this);
    if (stability.enabled())
      {
        std::function<void(const dealii::Vector<double> &)> keep_mode;
        if (mode_output)
          keep_mode = [this](const dealii::Vector<double> &mode) {
            record_mode(mode);
          };
        monitor = std::make_unique<StabilityMonitor<dim>>(
          stability,
          scene,
          linear_solver,
          *loop,
          statistics,
          stability_file,
          pcout,
          timer,
          [this](const std::string &name, const double t_over_tau_d) {
            write_event(name, t_over_tau_d, 0);
          },
          keep_mode);
        loop->add_observer(*monitor);
      }
    last_checkpoint = std::chrono::steady_clock::now();
    if (resume_from)
      return restore_checkpoint();
    open_statistics();

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
    if (checkpoint_settings.enabled() && checkpoint_step != current_step())
      write_checkpoint(between_steps);
    if (output_step != current_step())
      write_output();
    pcerr << "gelmpm: " << signal_name(signal) << " received: stopped after step " << current_step()
          << " at t/tau_d = " << current_time()
          << " with a complete last output; the results are in " << output_settings.directory
          << std::endl;
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
              << "; what was written up to t/tau_d = " << current_time() << " is kept in "
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
      pcout << "gelmpm: reached t/tau_d = " << current_time() << " in " << current_step()
            << " steps" << std::endl;
    if (loop && loop->uncontrolled_errors() > 0)
      pcout << "gelmpm: " << loop->uncontrolled_errors()
            << " step(s) accepted with an error estimate above its tolerance whatever the step "
               "(a perturbation's jump or the points' integration noise)"
            << std::endl;
    if (!output_settings.test_mode && loop)
      pcout << "gelmpm: " << loop->newton_iterations() << " Newton iterations, "
            << loop->factorizations() << " factorisations (" << linear_solver.name() << "), "
            << model->new_patterns() << " sparsity patterns";
    if (!output_settings.test_mode && loop && Collective::is_parallel(scene.communicator))
      pcout << ", " << dealii::Utilities::MPI::n_mpi_processes(scene.communicator)
            << " ranks, partitioned anew " << model->repartitions() << " times";
    if (!output_settings.test_mode && linear_solver.iterative())
      {
        const auto [iterations, solves] = linear_solver.krylov_iterations();
        pcout << ", " << iterations << " Krylov iterations in " << solves << " solves ("
              << (solves > 0 ? double(iterations) / solves : 0.) << " per solve), displacement "
              << "block by " << linear_solver.krylov_preconditioner();
      }
    if (!output_settings.test_mode && loop)
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

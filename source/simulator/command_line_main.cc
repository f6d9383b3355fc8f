// What the gelmpm executable does with its command line (source/main.cc calls it): see
// include/gelmpm/simulator/command_line_main.h.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/serial_blas.h>
#include <gelmpm/core/stop_request.h>
#include <gelmpm/core/units.h>
#include <gelmpm/simulator/command_line_main.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/simulator.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  /**
   * Without a scene, --print-parameters shows one subsection of each kind that a scene names
   * (a boundary piece, a material region, an obstacle), under a placeholder name.
   */
  GelMPM::SceneStructure
  template_structure()
  {
    GelMPM::SceneStructure structure;
    structure.boundary_pieces  = {"<piece>"};
    structure.material_regions = {"<region>"};
    structure.obstacles        = {"<obstacle>"};
    return structure;
  }


  /**
   * @p listing (print_parameters_with_patterns() of the template_structure()) with a comment
   * above each placeholder subsection that says it is a template and where its name comes from.
   */
  std::string
  mark_templates(const std::string &listing)
  {
    const std::vector<std::pair<std::string, std::string>> notes = {
      {"<piece>", "'Boundary conditions/Pieces'"},
      {"<region>", "'Material/Regions'"},
      {"<obstacle>", "'Contact/Obstacles'"}};
    std::istringstream in(listing);
    std::ostringstream out;
    for (std::string line; std::getline(in, line);)
      {
        const auto indent = line.find_first_not_of(' ');
        for (const auto &[name, list] : notes)
          if (indent != std::string::npos && line.substr(indent) == "subsection " + name)
            out << line.substr(0, indent) << "# TEMPLATE: one subsection like this per name in "
                << list << ", named\n"
                << line.substr(0, indent) << "# by it ('" << name
                << "' stands for the name); 'gelmpm --print-parameters scene.prm'\n"
                << line.substr(0, indent) << "# lists a scene's own.\n";
        out << line << '\n';
      }
    return out.str();
  }


  template <int dim>
  int
  run_scene(const GelMPM::CommandLine &cl, const GelMPM::SceneStructure &structure)
  {
    dealii::ParameterHandler prm;
    GelMPM::Simulator<dim>::declare_parameters(prm, structure);
    GelMPM::Units::declare_parameters(prm);
    GelMPM::Units units;
    if (!cl.scene_file.empty())
      {
        GelMPM::read_scene_file(prm, cl.scene_file, cl.overrides);
        // Before anything reads the parameters: a scene of laboratory values becomes normalised.
        units = GelMPM::Units::convert_scene(prm);
      }

    if (cl.print_parameters)
      {
        std::ostringstream listing;
        GelMPM::print_parameters_with_patterns(prm, listing);
        const std::string annotated = GelMPM::Units::annotate_reference(listing.str());
        std::cout << (cl.scene_file.empty() ? mark_templates(annotated) : annotated);
        return 0;
      }

    const bool             root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    GelMPM::Simulator<dim> simulator(prm, structure, cl.scene_file, cl.resume);
    if (root)
      units.print_conversions(std::cout);
    if (cl.check_only)
      {
        simulator.print_piece_table();
        std::cout << "gelmpm: scene '" << cl.scene_file << "' is valid\n";
        return 0;
      }
    const int status = simulator.run();
    // While the run still holds its output directory: statistics.csv in laboratory units.
    if (root && units.enabled())
      units.write_statistics(prm.get(std::vector<std::string>{"Output"}, "Directory"));
    return status;
  }
} // namespace


namespace
{
  /** Print @p what on rank 0 and return the largest @p status of all ranks (collective). */
  int
  report_collective_error(const char *prefix, const char *what, const int status)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << prefix << what << std::endl;
    return dealii::Utilities::MPI::max(status, MPI_COMM_WORLD);
  }
} // namespace


namespace GelMPM
{
  int
  run_command_line(int argc, char **argv)
  {
    // Quiet deal.II's own abort-on-exception printing: every error below is reported once.
    dealii::deal_II_exceptions::disable_abort_on_exception();
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, dealii::numbers::invalid_unsigned_int);
    GelMPM::install_stop_handlers();
    GelMPM::SerialBlasScope::use_one_thread_unless_set();
    try
      {
        const auto cl = GelMPM::CommandLine::parse(argc, argv);
        if (cl.help)
          {
            std::cout << GelMPM::CommandLine::usage();
            return 0;
          }
        const auto structure = cl.scene_file.empty()
                                 ? template_structure()
                                 : GelMPM::SceneStructure::read(cl.scene_file, cl.overrides);
        return structure.dimension == 2 ? run_scene<2>(cl, structure) : run_scene<3>(cl, structure);
      }
    // On several ranks, input errors and failures of a run are found by all ranks together
    // (core/collective.h): rank 0 reports them, and all leave with the same status. Anything else
    // may be one rank's alone: it reports with its rank and ends the whole job.
    catch (const GelMPM::InputError &e)
      {
        return report_collective_error("gelmpm: error: ", e.what(), 2);
      }
    catch (const std::runtime_error &e)
      {
        return report_collective_error("gelmpm: the run failed: ", e.what(), 1);
      }
    catch (const std::exception &e)
      {
        const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
        std::cerr << "gelmpm: the run failed";
        if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
          std::cerr << " on rank " << rank;
        std::cerr << ": " << e.what() << std::endl;
        if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
          MPI_Abort(MPI_COMM_WORLD, 1);
        return 1;
      }
  }
} // namespace GelMPM

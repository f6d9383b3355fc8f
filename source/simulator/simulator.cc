#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/revision.h>

#include <gelmpm/core/input_error.h>
#include <gelmpm/core/version.h>
#include <gelmpm/simulator/simulator.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace GelMPM
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(dealii::ParameterHandler &prm,
                                     const SceneStructure &    structure)
  {
    (void)structure;
    SceneStructure::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
  }


  template <int dim>
  Simulator<dim>::Simulator(dealii::ParameterHandler &prm,
                            const SceneStructure &    structure,
                            const std::string &       scene_file)
    : structure(structure)
    , scene_file(scene_file)
    , pcout(std::cout, dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    output_settings.parse_parameters(prm);

    std::ostringstream used;
    prm.print_parameters(used, dealii::ParameterHandler::ShortPRM);
    parameters_as_used = used.str();
  }


  template <int dim>
  void
  Simulator<dim>::print_header()
  {
    pcout << "GelMPM: hydrogel scene '" << std::filesystem::path(scene_file).filename().string()
          << "', " << dim << "D" << (dim == 2 ? " (plane strain)" : "") << '\n';
    if (!output_settings.test_mode)
      pcout << "  GelMPM " << GELMPM_VERSION << " (" << GELMPM_GIT_REVISION << "), deal.II "
            << DEAL_II_PACKAGE_VERSION << " (" << DEAL_II_GIT_SHORTREV << "), "
            << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI rank(s), "
            << dealii::MultithreadInfo::n_threads() << " thread(s)\n"
            << "  output directory: " << output_settings.directory << '\n';
  }


  template <int dim>
  void
  Simulator<dim>::prepare_output_directory() const
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::error_code error;
    std::filesystem::create_directories(output_settings.directory, error);
    require(!error,
            "Output/Directory",
            "'" + output_settings.directory + "' cannot be created (" + error.message() + ")",
            "choose a directory you can write to");
    std::ofstream(output_settings.directory + "/parameters.prm") << parameters_as_used;
    std::filesystem::copy_file(scene_file,
                               output_settings.directory + "/original.prm",
                               std::filesystem::copy_options::overwrite_existing);
  }


  template <int dim>
  void
  Simulator<dim>::run()
  {
    print_header();
    prepare_output_directory();
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace GelMPM

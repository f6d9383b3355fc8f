#ifndef gelmpm_simulator_simulator_h
#define gelmpm_simulator_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <gelmpm/io/output_settings.h>
#include <gelmpm/simulator/scene_structure.h>

#include <string>

namespace GelMPM
{
  /**
   * @brief A GelMPM run: reads a scene's parameters, checks them, and carries the scene out.
   *
   * Construction parses and validates every parameter and throws InputError on bad input, so
   * that nothing is written before the whole scene is known to be consistent. run() creates the
   * output directory, writes the parameters as used, and then does what the scene asks for.
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
     * Throws InputError on inconsistent input.
     */
    Simulator(dealii::ParameterHandler &prm,
              const SceneStructure &    structure,
              const std::string &       scene_file);

    /** Run the scene. */
    void
    run();

  private:
    /** Print the run header: versions, threads, ranks (omitted in test mode). */
    void
    print_header();

    /** Create the output directory and write parameters.prm and original.prm into it. */
    void
    prepare_output_directory() const;

    SceneStructure             structure;
    OutputSettings             output_settings;
    std::string                scene_file;
    std::string                parameters_as_used;
    dealii::ConditionalOStream pcout;
  };
} // namespace GelMPM

#endif

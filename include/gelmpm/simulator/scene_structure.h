#ifndef gelmpm_simulator_scene_structure_h
#define gelmpm_simulator_scene_structure_h

#include <gelmpm/core/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief What a scene file must say before the rest of it can be declared: the space dimension
   * and the names of the boundary pieces, of the material regions and of the obstacles (each gets
   * a subsection of its own).
   *
   * Read in a first pass over the scene file that ignores every other entry (as ASPECT reads
   * "Dimension" before dispatching to its 2D or 3D simulator).
   */
  struct SceneStructure
  {
    /** Space dimension, 2 or 3. */
    unsigned int dimension = 2;
    /** Names of the boundary pieces, in the order given ("Boundary conditions/Pieces"). */
    std::vector<std::string> boundary_pieces;
    /** Names of the material regions, in the order given ("Material/Regions"). */
    std::vector<std::string> material_regions;
    /** Names of the rigid obstacles, in the order given ("Contact/Obstacles"). */
    std::vector<std::string> obstacles;

    /** Declare the entries this structure is read from. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the structure from @p prm (declared by declare_parameters()). */
    static SceneStructure
    parse_parameters(const dealii::ParameterHandler &prm);

    /** First pass over @p file_name (with overrides); throws InputError. */
    static SceneStructure
    read(const std::string &file_name, const std::vector<ParameterOverride> &overrides);
  };
} // namespace GelMPM

#endif

#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/simulator/scene_structure.h>

#include <deal.II/base/utilities.h>

#include <set>

namespace GelMPM
{
  void
  SceneStructure::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
      "Dimension",
      "2",
      dealii::Patterns::Integer(2, 3),
      "Space dimension of the scene. In 2D the gel is in plane strain (the "
      "out-of-plane stretch stays at the initial stretch lambda_0), or axisymmetric "
      "with 'Background grid/Coordinate system = axisymmetric'.");
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Pieces",
                      "",
                      dealii::Patterns::List(dealii::Patterns::Anything()),
                      "Comma-separated names of the pieces the body's boundary is split into. "
                      "Each name gets a subsection 'Boundary conditions/<name>' that selects the "
                      "piece and sets its displacement and chemical-potential conditions. A "
                      "boundary point belongs to the first piece whose selector it satisfies; "
                      "points of no piece are traction-free and impermeable.");
    prm.leave_subsection();
    prm.enter_subsection("Contact");
    prm.declare_entry("Obstacles",
                      "",
                      dealii::Patterns::List(dealii::Patterns::Anything()),
                      "Comma-separated names of rigid obstacles with a prescribed motion (a "
                      "plane, a sphere or a flat punch). Each name gets a subsection "
                      "'Contact/<name>' with its shape, geometry and motion; their contact with "
                      "the free pieces is imposed as 'Method' says, and statistics.csv gets the "
                      "columns <name>_force_x, ..., <name>_contact_area and "
                      "<name>_contact_radius (doc/statistics.md). Empty: none.");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    prm.declare_entry("Regions",
                      "",
                      dealii::Patterns::List(dealii::Patterns::Anything()),
                      "Comma-separated names of the regions of the body with a gel of their own "
                      "(e.g. a bilayer: 'active'). Each name gets a subsection 'Material/<name>' "
                      "that selects the region and gives the constants that differ from this "
                      "section's; the rest of the body is of this section's gel. Regions are "
                      "bonded. Empty: one gel.");
    prm.leave_subsection();
  }


  SceneStructure
  SceneStructure::parse_parameters(const dealii::ParameterHandler &prm)
  {
    SceneStructure s;
    s.dimension = prm.get_integer("Dimension");
    auto &p     = const_cast<dealii::ParameterHandler &>(prm);
    p.enter_subsection("Boundary conditions");
    s.boundary_pieces = dealii::Utilities::split_string_list(p.get("Pieces"), ',');
    p.leave_subsection();
    p.enter_subsection("Contact");
    s.obstacles = dealii::Utilities::split_string_list(p.get("Obstacles"), ',');
    p.leave_subsection();
    p.enter_subsection("Material");
    s.material_regions = dealii::Utilities::split_string_list(p.get("Regions"), ',');
    p.leave_subsection();

    check_section_names(s.boundary_pieces, "Boundary conditions/Pieces", "piece");
    // A region's subsection sits beside the section's own entries and subsections.
    check_section_names(s.material_regions, "Material/Regions", "region");
    // An obstacle's subsection sits beside the section's entries.
    check_section_names(s.obstacles, "Contact/Obstacles", "obstacle");
    return s;
  }


  SceneStructure
  SceneStructure::read(const std::string                    &file_name,
                       const std::vector<ParameterOverride> &overrides)
  {
    dealii::ParameterHandler prm;
    declare_parameters(prm);
    read_scene_file(prm, file_name, overrides, /*skip_undefined=*/true);
    return parse_parameters(prm);
  }
} // namespace GelMPM

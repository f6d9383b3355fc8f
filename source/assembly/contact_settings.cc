#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/core/input_error.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    const std::vector<std::string> side_names = {"left", "right", "bottom", "top", "back", "front"};
  }


  void
  ContactSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Method",
      "none",
      Patterns::Selection("none|penalty|nitsche"),
      "Contact of free surfaces with the planes of symmetry listed in 'Grid "
      "sides' and the rigid 'Obstacles' (doc/method.md, \"Contact\"): none; penalty (beta_c max(g, 0) on "
      "penetrating surface points); nitsche (symmetric Nitsche terms of a roller "
      "on the active points, consistent).");
    prm.declare_entry("Grid sides",
                      "",
                      Patterns::Anything(),
                      "The sides of the background grid that are planes of symmetry, as a "
                      "comma-separated list of left (lower x), right (upper x), bottom (lower y), "
                      "top (upper y), back (lower z), front (upper z), or 'all'. Surface points "
                      "of pieces with a free displacement may touch them but not cross.");
    prm.declare_entry("Penalty",
                      "1000",
                      Patterns::Double(0.),
                      "gamma_c: the contact penalty is beta_c = gamma_c G / h_u (both methods). At "
                      "most 1e8.");
    prm.declare_entry(
      "Active set factor",
      "1",
      Patterns::Double(0., 1.),
      "nitsche: a surface point is in contact where f beta_c g - sigma_n > 0, f this factor "
      "(sigma_n the normal traction, negative in compression; g the penetration). 1: Nitsche's "
      "augmented active set. Where the gel is pressed over a whole face by a stiff beta_c, the "
      "weakly imposed gap wiggles from point to point by more than sigma_n/beta_c and the points "
      "switch in and out from one Newton iteration to the next; a smaller factor (e.g. 0.01) "
      "lets the traction decide within that noise (doc/flat_punch.md, \"A rigid punch\"). "
      "The terms of an active point are the same. Not used by the penalty method.");
    SelfContactSettings::declare_parameters(prm);
    prm.leave_subsection();
  }


  void
  ContactSettings::parse_parameters(dealii::ParameterHandler       &prm,
                                    const unsigned int              dim,
                                    const std::vector<std::string> &obstacle_names)
  {
    obstacles = obstacle_names;
    prm.enter_subsection("Contact");
    const std::string name = prm.get("Method");
    method                 = name == "penalty"   ? Method::penalty
                             : name == "nitsche" ? Method::nitsche
                                                 : Method::none;
    penalty                = prm.get_double("Penalty");
    active_set_factor      = prm.get_double("Active set factor");
    sides                  = dealii::Utilities::split_string_list(prm.get("Grid sides"), ',');
    self_contact.parse_parameters(prm);
    prm.leave_subsection();

    const std::vector<std::string> allowed(side_names.begin(), side_names.begin() + 2 * dim);
    const bool all = std::find(sides.begin(), sides.end(), "all") != sides.end();
    require(!all || sides.size() == 1,
            "Contact/Grid sides",
            "names 'all' (every side) together with other sides",
            "write 'all' alone, or list the sides without it");
    if (all)
      sides = allowed;
    for (auto side = sides.begin(); side != sides.end(); ++side)
      {
        require(std::find(allowed.begin(), allowed.end(), *side) != allowed.end(),
                "Contact/Grid sides",
                "names '" + *side + "', which is not a side of a " + std::to_string(dim) + "D grid",
                dim == 2 ? "list some of left, right, bottom, top, or write 'all'"
                         : "list some of left, right, bottom, top, back, front, or write 'all'");
        require(std::find(sides.begin(), side, *side) == side,
                "Contact/Grid sides",
                "names '" + *side + "' twice",
                "list each side once");
      }
    // PointRecord::contact_held holds one bit per rigid obstacle.
    require(obstacles.size() <= 63,
            "Contact/Obstacles",
            "names " + std::to_string(obstacles.size()) +
              " obstacles, more than the 63 a run holds",
            "join obstacles of one shape into fewer, or split the scene");
    require(penalty > 0., "Contact/Penalty", "must be positive", "give gamma_c > 0 (e.g. 1000)");
    require(active_set_factor > 0.,
            "Contact/Active set factor",
            "is 0, which would make every surface point under compression a contact point "
            "whatever its distance from the obstacle",
            "give a factor in (0, 1], e.g. 1 (Nitsche's active set) or 0.01");
    if (penalty > largest_penalty)
      {
        std::ostringstream problem;
        problem << "is " << penalty
                << ", above 1e8: the condition number of the tangent grows in proportion to it "
                   "and the linear solves would keep no digit";
        throw InputError("Contact/Penalty", problem.str(), "give gamma_c of e.g. 1000");
      }
    require(method == Method::none || !sides.empty() || !obstacles.empty(),
            "Contact/Grid sides",
            "is empty while 'Contact/Method' is " + name + " and 'Contact/Obstacles' is empty",
            "name the grid sides that are planes of symmetry, e.g. 'all', or the obstacles");
    require(method != Method::none || obstacles.empty(),
            "Contact/Method",
            "is none while 'Contact/Obstacles' names obstacles",
            "set 'Contact/Method = penalty' (or nitsche) to impose the contact with them");
  }


  template <int dim>
  std::vector<ContactSettings::Plane>
  ContactSettings::planes(const dealii::Point<dim> &lower, const dealii::Point<dim> &upper) const
  {
    std::vector<Plane> result;
    for (const auto &side : sides)
      {
        const auto index =
          std::find(side_names.begin(), side_names.end(), side) - side_names.begin();
        const unsigned int axis = index / 2;
        const bool         high = index % 2 == 1;
        result.push_back({axis, high ? upper[axis] : lower[axis], high ? 1. : -1.});
      }
    return result;
  }


  template std::vector<ContactSettings::Plane>
  ContactSettings::planes<2>(const dealii::Point<2> &, const dealii::Point<2> &) const;
  template std::vector<ContactSettings::Plane>
  ContactSettings::planes<3>(const dealii::Point<3> &, const dealii::Point<3> &) const;
} // namespace GelMPM

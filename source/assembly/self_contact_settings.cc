#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/assembly/self_contact_settings.h>
#include <gelmpm/core/input_error.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <sstream>

namespace GelMPM
{
  void
  SelfContactSettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Self contact");
    prm.declare_entry(
      "Method",
      "none",
      Patterns::Selection("none|penalty|nitsche"),
      "Contact of the gel's boundary with itself (doc/method.md, \"Contact of the gel with "
      "itself\"): none (off: no term, no cost); penalty (the surface points of 'Pieces' against "
      "the other face, frictionless, beta_s g on a point behind it); nitsche (the same pairs, "
      "Nitsche's terms with the point's own normal traction on the augmented active set "
      "beta_s g - sigma_n < 0, each face's points weighted by one "
      "half, 'Nitsche/Variant' their symmetry). Each point touches the tangent plane of the "
      "nearest facing point ('Other face'; in 2D also the segments of the surface "
      "polylines).");
    prm.declare_entry(
      "Penalty",
      "100",
      Patterns::Double(0.),
      "gamma_s: the self-contact penalty is beta_s = gamma_s G / h_u. At most 1e8. 100: a "
      "penetration of sigma_n h_u / (100 G), 2.4e-5 on the blocks of "
      "tests/simulator/self_contact_blocks (reaction 0.24 % from the closed form); with 1000 "
      "the creasing film and the 2 x 2 lattice stop where their faces first touch, Newton "
      "failing on the stiff active set (doc/method.md, \"Two faces on one grid\"). Nitsche's "
      "method needs about 1000 for its stabilisation (with 100 the pressed blocks' third step "
      "does not converge).");
    prm.declare_entry("Pieces",
                      "",
                      Patterns::Anything(),
                      "The boundary pieces whose surface points touch each other (any with the "
                      "other), a comma-separated list of pieces with a free displacement; empty: "
                      "every piece whose displacement is free.");
    prm.declare_entry(
      "Search distance",
      "1",
      Patterns::Double(0.),
      "In cells of the background grid as given ('Background grid/Cells'; on a refined grid "
      "its unrefined cells, at every level, as 'Time stepping/Largest increment'): a surface "
      "point and a segment of the surface closer than this at the start of a step are a pair "
      "of the step (the pairs, and the sparsity pattern with them, are fixed over the step). A "
      "point that passes through a segment it is not paired with is not seen in that step "
      "('Retake unseen passes').");
    prm.declare_entry(
      "Retake unseen passes",
      "true",
      Patterns::Bool(),
      "At the end of every step that the error control accepts the surface is searched again "
      "for points that lie behind a segment they were in front of at the start and that no "
      "pair of the step holds: they passed through the other face unseen. true: such a step is "
      "retaken with the step times 'Time stepping/Cut factor'. false: it is accepted, and the "
      "log's last lines count such steps and points (doc/method.md, \"Pairs, fixed over a "
      "step\").");
    prm.declare_entry("Minimum arc length",
                      "3",
                      Patterns::Double(0.),
                      "In cells of the background grid as given (as 'Search distance'): a point "
                      "never touches a segment whose ends lie closer than "
                      "this to it along the surface in the initial configuration (its own "
                      "segments and their neighbours; on a closed curve the shorter way round).");
    prm.declare_entry(
      "Separate faces",
      "true",
      Patterns::Bool(),
      "Where the points in the support of a displacement function form two or more parts of the "
      "material that are not connected there (the two faces of a closing crease, pore or slit, "
      "told apart by their neighbours in the initial configuration), each further part that "
      "holds surface points of 'Pieces' takes a copy of the function, an unknown of its own: the "
      "faces slide and separate, and only the contact term pushes them apart; a copy that holds "
      "a quarter of the function's weight or less is tied to its face's own functions "
      "(doc/method.md, \"Two faces on one grid\"). false: the faces share the grid's functions "
      "and stay tied about a cell apart, never touching.");
    prm.declare_entry(
      "Other face",
      "tangent planes",
      Patterns::Selection("segments|tangent planes"),
      "2D (plane strain and axisymmetric): what a point touches; 3D scenes take tangent planes "
      "only. segments: the segments of the "
      "current surface polylines, their normals turning with the iterate. tangent planes: the "
      "tangent plane of the nearest facing surface point, its normal that of the step's start "
      "(fixed over the step, the gap linear in the unknowns), as always in 3D (doc/method.md, "
      "\"The other face as tangent planes\").");
    prm.declare_entry("Largest depth",
                      "0.5",
                      Patterns::Double(0.),
                      "In cells of the background grid as given (as 'Search distance'): at the "
                      "start of a step a point up to this far behind the other face is still "
                      "its pair (a penetration the penalty left); farther behind it is taken for "
                      "the other face of a thin body. A Newton iterate that puts an active point "
                      "farther behind is no state the penalty leaves: the line search damps the "
                      "update as it damps one to J <= 1 (with 0.25 the closing notch of "
                      "doc/method.md stops at 0.57 tau_d, a point of a face 0.26 cells behind "
                      "the other once new copies let the faces go).");
    prm.leave_subsection();
  }


  void
  SelfContactSettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Self contact");
    const std::string name = prm.get("Method");
    method                 = name == "penalty"   ? Method::penalty
                             : name == "nitsche" ? Method::nitsche
                                                 : Method::none;
    penalty                = prm.get_double("Penalty");
    pieces                 = dealii::Utilities::split_string_list(prm.get("Pieces"), ',');
    search_distance        = prm.get_double("Search distance");
    minimum_arc_length     = prm.get_double("Minimum arc length");
    largest_depth          = prm.get_double("Largest depth");
    separate_faces         = prm.get_bool("Separate faces");
    retake_unseen_passes   = prm.get_bool("Retake unseen passes");
    tangent_planes         = prm.get("Other face") == "tangent planes";
    prm.leave_subsection();
    if (!enabled())
      return;
    const std::string section = "Contact/Self contact/";
    require(penalty > 0. && penalty <= largest_penalty,
            section + "Penalty",
            "must lie in (0, 1e8]: above, the linear solves keep no digit",
            "give gamma_s of e.g. 1000");
    require(search_distance > 0.,
            section + "Search distance",
            "must be positive: no pair would ever be found",
            "give e.g. 1 (one cell)");
    require(minimum_arc_length > 0.,
            section + "Minimum arc length",
            "must be positive: a point would touch its own segments",
            "give e.g. 3 (cells)");
  }


  std::string
  SelfContactSettings::notes() const
  {
    if (method != Method::nitsche || penalty >= 1000.)
      return "";
    std::ostringstream note;
    note << "  note: 'Contact/Self contact/Penalty' is " << penalty
         << " with 'Method = nitsche', whose stabilisation needs about 1000 (with 100 two "
            "pressed blocks do not converge past their third step; doc/method.md, \"By "
            "Nitsche's method\")\n";
    return note.str();
  }
} // namespace GelMPM

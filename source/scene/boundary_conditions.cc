#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/expression.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>

namespace GelMPM
{
  namespace
  {
    std::string
    variables(const int dim, const bool with_normal)
    {
      if (with_normal)
        return PointNormalExpression::variable_names(dim);
      return dim == 3 ? "x,y,z" : "x,y";
    }

    std::string
    number(const double x)
    {
      if (std::isnan(x))
        return "NaN";
      std::ostringstream text;
      text << x;
      return text.str();
    }

    const char *function_names[] = {"Displacement value",
                                    "Traction",
                                    "Chemical potential value",
                                    "Flux"};
  } // namespace


  template <int dim>
  void
  BoundaryPiece<dim>::declare_parameters(dealii::ParameterHandler &prm, const std::string &name)
  {
    using namespace dealii;
    prm.enter_subsection(name);
    prm.declare_entry("Selector",
                      "0",
                      Patterns::Anything(),
                      "Expression in the initial position and outward normal of a surface point (" +
                        variables(dim, true) +
                        "); the point belongs to this piece where it is nonzero, e.g. 'ny > 0.5' "
                        "for a top face, 'abs(x) < 1e-9' for a left face. For a body from "
                        "'Geometry/Mesh file' also 'boundary id <groups>': the points on the "
                        "boundary faces of these physical groups of the mesh, each a number (its "
                        "boundary id) or a name from the file's $PhysicalNames, separated by "
                        "commas, e.g. 'boundary id 3' or 'boundary id tip, 4'.");
    prm.declare_entry("Selector constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the selector, e.g. 'H=1, tol=1e-9'.");
    prm.declare_entry("Displacement",
                      "free",
                      Patterns::Selection("free|fixed|normal|tangential"),
                      "free: traction 'Traction'. fixed: u = u_bar. normal: u.N = u_bar.N (roller, "
                      "symmetry). tangential: u.T = u_bar.T (2D). u_bar is 'Displacement value', "
                      "the total displacement from the initial configuration; the constraint is "
                      "imposed weakly by symmetric Nitsche terms (see section Nitsche).");
    prm.declare_entry("Chemical potential",
                      "flux",
                      Patterns::Selection("flux|prescribed"),
                      "flux: inward solvent volume flux 'Flux' (0: impermeable). prescribed: "
                      "mu/(k_BT) = 'Chemical potential value', imposed weakly (Nitsche).");
    const unsigned int n_components[] = {dim, dim, 1, 1};
    for (unsigned int f = 0; f < 4; ++f)
      {
        prm.enter_subsection(function_names[f]);
        Functions::ParsedFunction<dim>::declare_parameters(prm, n_components[f]);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  template <int dim>
  void
  BoundaryPiece<dim>::parse_parameters(dealii::ParameterHandler &prm, const std::string &piece_name)
  {
    name                    = piece_name;
    const std::string where = "Boundary conditions/" + name;
    prm.enter_subsection(name);
    const std::string selector_text      = prm.get("Selector");
    const std::string selector_constants = prm.get("Selector constants");
    const std::string u_condition        = prm.get("Displacement");
    const std::string mu_condition       = prm.get("Chemical potential");

    displacement_condition = u_condition == "fixed"        ? DisplacementCondition::fixed
                             : u_condition == "normal"     ? DisplacementCondition::normal
                             : u_condition == "tangential" ? DisplacementCondition::tangential
                                                           : DisplacementCondition::free;
    chemical_condition =
      (mu_condition == "prescribed") ? ChemicalCondition::prescribed : ChemicalCondition::flux;

    const unsigned int                                       n_components[] = {dim, dim, 1, 1};
    std::unique_ptr<dealii::Functions::ParsedFunction<dim>> *targets[] =
      {&displacement_value_, &traction_, &chemical_potential_value_, &flux_};
    for (unsigned int f = 0; f < 4; ++f)
      {
        prm.enter_subsection(function_names[f]);
        *targets[f] = std::make_unique<dealii::Functions::ParsedFunction<dim>>(n_components[f]);
        try
          {
            parse_expression_constants(prm.get("Function constants"),
                                       prm.get("Variable names"),
                                       where + "/" + function_names[f] + "/Function constants");
          }
        catch (...)
          {
            prm.leave_subsection();
            prm.leave_subsection();
            throw;
          }
        try
          {
            const QuietCerr quiet;
            (*targets[f])->parse_parameters(prm);
            // Evaluate once: the parser compiles lazily.
            dealii::Vector<double> values(n_components[f]);
            (*targets[f])->vector_value(dealii::Point<dim>(), values);
          }
        catch (const dealii::ExceptionBase &e)
          {
            prm.leave_subsection();
            prm.leave_subsection();
            throw InputError(where + "/" + function_names[f],
                             "cannot be parsed: " + describe(e),
                             "give " + std::to_string(n_components[f]) + " expression(s) of x, y" +
                               (dim == 3 ? ", z" : "") +
                               ", t separated by ';' in 'Function expression'");
          }
        prm.leave_subsection();
      }
    prm.leave_subsection();

    // 'boundary id <groups>' selects by the physical groups of a mesh; which groups exist is
    // known only once the mesh is read (MaterialPointGenerator checks them).
    boundary_groups_.clear();
    const std::string keyword = "boundary id";
    if (const std::string trimmed = dealii::Utilities::trim(selector_text);
        trimmed.rfind(keyword, 0) == 0)
      {
        const std::string list = trimmed.substr(keyword.size());
        require(!list.empty() && std::isspace(static_cast<unsigned char>(list[0])),
                where + "/Selector",
                "'" + selector_text + "' is not 'boundary id <groups>'",
                "write e.g. 'boundary id 3' or 'boundary id tip, 4'");
        for (const auto &group : dealii::Utilities::split_string_list(list, ','))
          {
            require(!group.empty() && group.find_first_of(" \t\"") == std::string::npos,
                    where + "/Selector",
                    "'" + selector_text + "' has the group '" + group +
                      "', which is neither a number nor a name",
                    "separate the groups by commas, e.g. 'boundary id tip, 4'");
            boundary_groups_.push_back(group);
          }
        require(!boundary_groups_.empty(),
                where + "/Selector",
                "'" + selector_text + "' names no group",
                "write e.g. 'boundary id 3'");
        return;
      }

    const auto constants = parse_expression_constants(selector_constants,
                                                      variables(dim, true),
                                                      where + "/Selector constants");
    try
      {
        selector = std::make_unique<PointNormalExpression>(dim, selector_text, constants);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(where + "/Selector",
                         "'" + selector_text + "' cannot be parsed: " + e.what(),
                         "write an expression in " + variables(dim, true));
      }
  }


  template <int dim>
  bool
  BoundaryPiece<dim>::selects(const dealii::Point<dim>        &x,
                              const dealii::Tensor<1, dim>    &normal,
                              const dealii::types::boundary_id boundary_id,
                              const std::string               &group_name) const
  {
    if (!boundary_groups_.empty())
      {
        if (boundary_id == dealii::numbers::invalid_boundary_id)
          return false;
        const std::string id = std::to_string(boundary_id);
        for (const auto &group : boundary_groups_)
          if (group == id || (!group_name.empty() && group == group_name))
            return true;
        return false;
      }
    const double value = selector->value(&x[0], &normal[0]);
    if (!std::isfinite(value))
      throw InputError("Boundary conditions/" + name + "/Selector",
                       "is not a number (" + number(value) + ") at the surface point " +
                         format_point(x) + " with normal " + format_point(normal),
                       "write a condition that is 0 or 1 everywhere, e.g. 'ny > 0.5'");
    return value != 0.;
  }


  template <int dim>
  const std::vector<std::string> &
  BoundaryPiece<dim>::boundary_groups() const
  {
    return boundary_groups_;
  }


  template <int dim>
  bool
  BoundaryPiece<dim>::displacement_prescribed() const
  {
    return displacement_condition != DisplacementCondition::free;
  }


  template <int dim>
  bool
  BoundaryPiece<dim>::chemical_potential_prescribed() const
  {
    return chemical_condition == ChemicalCondition::prescribed;
  }


  template <int dim>
  const dealii::Function<dim> &
  BoundaryPiece<dim>::displacement_value() const
  {
    return *displacement_value_;
  }


  template <int dim>
  const dealii::Function<dim> &
  BoundaryPiece<dim>::traction() const
  {
    return *traction_;
  }


  template <int dim>
  const dealii::Function<dim> &
  BoundaryPiece<dim>::chemical_potential_value() const
  {
    return *chemical_potential_value_;
  }


  template <int dim>
  const dealii::Function<dim> &
  BoundaryPiece<dim>::flux() const
  {
    return *flux_;
  }


  template <int dim>
  void
  BoundaryPiece<dim>::set_time(const double t)
  {
    displacement_value_->set_time(t);
    traction_->set_time(t);
    chemical_potential_value_->set_time(t);
    flux_->set_time(t);
  }


  template <int dim>
  void
  BoundaryPiece<dim>::check_values(const std::vector<dealii::Point<dim>> &points,
                                   const std::vector<double>             &times,
                                   const double                           largest_mu)
  {
    const dealii::Functions::ParsedFunction<dim> *functions[] = {displacement_value_.get(),
                                                                 traction_.get(),
                                                                 chemical_potential_value_.get(),
                                                                 flux_.get()};
    for (unsigned int f = 0; f < 4; ++f)
      {
        dealii::Vector<double> values(functions[f]->n_components);
        for (const double t : times)
          {
            set_time(t);
            for (const auto &x : points)
              {
                functions[f]->vector_value(x, values);
                std::ostringstream where_when;
                where_when << " at x = " << format_point(x) << ", t = " << t;
                for (const double v : values)
                  require(std::isfinite(v),
                          "Boundary conditions/" + name + "/" + function_names[f],
                          "is not finite (" + number(v) + ")" + where_when.str(),
                          "give an expression that is finite on the piece for 0 <= t <= 'Time "
                          "stepping/End time' (guard divisions and logarithms)");
                if (f == 2 && chemical_potential_prescribed())
                  require(values[0] <= largest_mu,
                          "Boundary conditions/" + name + "/Chemical potential value",
                          "is " + number(values[0]) + where_when.str() +
                            ", above mu/(k_BT) = " + number(largest_mu) +
                            ", the largest at which the gel has a swollen equilibrium (it would "
                            "absorb solvent without bound)",
                          "prescribe mu/(k_BT) <= " + number(largest_mu) + " (0: pure solvent)");
              }
          }
      }
    set_time(0.);
  }


  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(dealii::ParameterHandler       &prm,
                                              const std::vector<std::string> &pieces)
  {
    require_new_subsection_names(prm,
                                 "Boundary conditions",
                                 pieces,
                                 "Boundary conditions/Pieces",
                                 "piece");
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : pieces)
      BoundaryPiece<dim>::declare_parameters(prm, name);
    prm.leave_subsection();
  }


  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(dealii::ParameterHandler       &prm,
                                            const std::vector<std::string> &pieces)
  {
    pieces_.clear();
    prm.enter_subsection("Boundary conditions");
    try
      {
        for (const auto &name : pieces)
          {
            pieces_.push_back(std::make_unique<BoundaryPiece<dim>>());
            pieces_.back()->parse_parameters(prm, name);
          }
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
  }


  template <int dim>
  unsigned int
  BoundaryConditions<dim>::n_pieces() const
  {
    return pieces_.size();
  }


  template <int dim>
  BoundaryPiece<dim> &
  BoundaryConditions<dim>::piece(const unsigned int i)
  {
    return *pieces_[i];
  }


  template <int dim>
  const BoundaryPiece<dim> &
  BoundaryConditions<dim>::piece(const unsigned int i) const
  {
    return *pieces_[i];
  }


  template <int dim>
  int
  BoundaryConditions<dim>::piece_of(const dealii::Point<dim>        &x,
                                    const dealii::Tensor<1, dim>    &normal,
                                    const dealii::types::boundary_id boundary_id,
                                    const std::string               &group_name) const
  {
    for (unsigned int i = 0; i < pieces_.size(); ++i)
      if (pieces_[i]->selects(x, normal, boundary_id, group_name))
        return i;
    return -1;
  }


  template <int dim>
  void
  BoundaryConditions<dim>::set_time(const double t)
  {
    for (auto &p : pieces_)
      p->set_time(t);
  }


  std::vector<unsigned int>
  piece_indices(const std::vector<std::string> &names,
                const std::vector<std::string> &pieces,
                const std::string              &entry)
  {
    std::vector<unsigned int> indices;
    for (const auto &name : names)
      {
        const auto it = std::find(pieces.begin(), pieces.end(), name);
        require(it != pieces.end(),
                entry,
                "names the piece '" + name + "' that is not in 'Boundary conditions/Pieces'",
                "use the declared pieces, separated by commas");
        const unsigned int index = it - pieces.begin();
        require(std::find(indices.begin(), indices.end(), index) == indices.end(),
                entry,
                "names the piece '" + name + "' twice",
                "name every piece once");
        indices.push_back(index);
      }
    return indices;
  }


  void
  check_section_names(const std::vector<std::string> &names,
                      const std::string              &entry,
                      const std::string              &what)
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      {
        require(!names[i].empty(),
                entry,
                "contains an empty name",
                "remove the doubled or trailing comma");
        require(names[i].find('/') == std::string::npos,
                entry,
                "contains the name '" + names[i] + "' with a '/'",
                "use names without '/'");
        require(std::find(names.begin(), names.begin() + i, names[i]) == names.begin() + i,
                entry,
                "names the " + what + " '" + names[i] + "' twice",
                "give every " + what + " a distinct name");
      }
  }


  template class BoundaryPiece<2>;
  template class BoundaryPiece<3>;
  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace GelMPM

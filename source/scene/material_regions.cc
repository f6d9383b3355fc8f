#include <gelmpm/core/format_point.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/scene/expression.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  namespace
  {
    /** The number in @p text, or @p fallback if it is empty; InputError naming @p entry. */
    double
    number_or(const std::string &text, const double fallback, const std::string &entry)
    {
      const std::string trimmed = dealii::Utilities::trim(text);
      if (trimmed.empty())
        return fallback;
      std::istringstream in(trimmed);
      double             value;
      in >> value;
      require(in && in.eof() && std::isfinite(value) &&
                (value == 0. || std::abs(value) >= std::numeric_limits<double>::min()),
              entry,
              "is '" + trimmed + "', not a finite normal number",
              "give a number, or leave it empty for the value of the section 'Material'");
      return value;
    }


    using NoConstants = std::map<std::string, double>;


    std::string
    text_of(const double x)
    {
      if (std::isnan(x))
        return "NaN";
      std::ostringstream out;
      out.precision(7);
      out << x;
      return out.str();
    }
  } // namespace


  template <int dim>
  void
  MaterialRegions<dim>::declare_parameters(dealii::ParameterHandler       &prm,
                                           const std::vector<std::string> &names)
  {
    using namespace dealii;
    // A region called like an entry of 'Material' (FloryRehnerGel, declared before) would merge
    // with it.
    require_new_subsection_names(prm, "Material", names, "Material/Regions", "region");
    prm.enter_subsection("Material");
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Selector",
                          "",
                          Patterns::Anything(),
                          "The region: an expression in the initial position x, y (, z), "
                          "nonzero inside the region (e.g. 'y > 0.5'). Either this or 'Mesh "
                          "group'.");
        prm.declare_entry("Mesh group",
                          "",
                          Patterns::Anything(),
                          "The region: the name of a physical group of dimension 2 (2D) or 3 "
                          "(3D) of 'Geometry/Mesh file'. Either this or 'Selector'.");
        prm.declare_entry("Shear modulus",
                          "",
                          Patterns::Anything(),
                          "G of the region's dry network; empty: from 'N nu' (G = N nu k_BT/nu, "
                          "k_BT/nu being the body's) or the section 'Material'.");
        prm.declare_entry("N nu",
                          "",
                          Patterns::Anything(),
                          "N nu of the region; empty: from 'Shear modulus' or the section "
                          "'Material'. G and N nu must give the body's k_BT/nu = G/(N nu) (one "
                          "solvent, one temperature).");
        prm.declare_entry("Flory-Huggins chi",
                          "",
                          Patterns::Anything(),
                          "chi of the region; empty: the section 'Material''s.");
        prm.declare_entry("Diffusivity",
                          "",
                          Patterns::Anything(),
                          "D of the region; empty: the section 'Material''s. The time unit "
                          "tau_d is built on the section 'Material''s D.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  template <int dim>
  void
  MaterialRegions<dim>::parse_parameters(dealii::ParameterHandler       &prm,
                                         const std::vector<std::string> &names,
                                         const FloryRehnerGel<dim>      &base)
  {
    gels = {base};
    regions.clear();
    prm.enter_subsection("Material");
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        regions.push_back(parse_selection(prm, name));
        gels.push_back(parse_gel(prm, name, base));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  template <int dim>
  typename MaterialRegions<dim>::Region
  MaterialRegions<dim>::parse_selection(dealii::ParameterHandler &prm, const std::string &name)
  {
    const std::string path = "Material/" + name + "/";
    Region            region;
    region.name          = name;
    region.selector_text = dealii::Utilities::trim(prm.get("Selector"));
    region.mesh_group    = dealii::Utilities::trim(prm.get("Mesh group"));
    require(region.selector_text.empty() != region.mesh_group.empty(),
            path + "Selector",
            region.selector_text.empty() ? "and 'Mesh group' are both empty: the region "
                                           "selects nothing"
                                         : "and 'Mesh group' are both given",
            "give one of them: an expression in x, y" + std::string(dim == 3 ? ", z" : "") +
              " or a physical group of the mesh");
    if (region.selector_text.empty())
      return region;
    // The parser of the boundary pieces' selectors, in the position alone: it evaluates the
    // expression once, so that an unknown name or a syntax error is found here, not at the
    // first material point.
    const std::string variables = PointNormalExpression::variable_names(dim, false);
    try
      {
        region.selector =
          std::make_unique<PointNormalExpression>(dim, region.selector_text, NoConstants{}, false);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(path + "Selector",
                         "'" + region.selector_text + "' cannot be parsed: " + e.what(),
                         "write an expression in " + variables + ", e.g. 'y > 0.5'");
      }
    return region;
  }


  template <int dim>
  FloryRehnerGel<dim>
  MaterialRegions<dim>::parse_gel(dealii::ParameterHandler  &prm,
                                  const std::string         &name,
                                  const FloryRehnerGel<dim> &base)
  {
    const std::string path       = "Material/" + name + "/";
    const double      kT_over_nu = base.kT_over_nu();
    const std::string G_text     = prm.get("Shear modulus");
    const std::string N_nu_text  = prm.get("N nu");
    double            G          = number_or(G_text, base.shear_modulus(), path + "Shear modulus");
    double            N_nu       = number_or(N_nu_text, base.N_nu(), path + "N nu");
    const double      chi =
      number_or(prm.get("Flory-Huggins chi"), base.chi(), path + "Flory-Huggins chi");
    const double D = number_or(prm.get("Diffusivity"), base.diffusivity(), path + "Diffusivity");
    require(G > 0., path + "Shear modulus", "must be positive", "give G > 0");
    require(N_nu > 0., path + "N nu", "must be positive", "give N nu > 0");
    require(D > 0., path + "Diffusivity", "must be positive", "give D > 0");
    require(chi >= 0.,
            path + "Flory-Huggins chi",
            "is negative (" + text_of(chi) + "), outside the physical range chi >= 0",
            "give 0 <= chi");
    // One solvent and one temperature: k_BT/nu is the body's.
    const bool G_given = !dealii::Utilities::trim(G_text).empty();
    const bool N_given = !dealii::Utilities::trim(N_nu_text).empty();
    if (G_given && !N_given)
      N_nu = G / kT_over_nu;
    else if (N_given && !G_given)
      G = N_nu * kT_over_nu;
    require(std::abs(G / N_nu - kT_over_nu) <= 1e-6 * kT_over_nu,
            path + "Shear modulus",
            "and 'N nu' give k_BT/nu = G/(N nu) = " + text_of(G / N_nu) +
              ", but the body's solvent has k_BT/nu = " + text_of(kT_over_nu) +
              " (section 'Material')",
            "give only one of the two (the other follows: G = " + text_of(kT_over_nu) + " N nu)");
    try
      {
        // Every region starts stress-free at the body's mu_0, at its own stretch.
        const double lambda_0 = FloryRehnerGel<dim>::lambda_0_from_mu_0(base.mu_0(), chi, N_nu);
        return FloryRehnerGel<dim>(G, chi, N_nu, D, lambda_0);
      }
    catch (const InputError &)
      {
        throw InputError(path + "Flory-Huggins chi",
                         "and 'N nu' give a gel without a stress-free swollen state at the "
                         "body's initial chemical potential mu_0/(k_BT) = " +
                           text_of(base.mu_0()),
                         "check the region's constants against the section 'Material''s "
                         "initial state");
      }
  }


  template <int dim>
  unsigned int
  MaterialRegions<dim>::size() const
  {
    return gels.size();
  }


  template <int dim>
  const FloryRehnerGel<dim> &
  MaterialRegions<dim>::operator[](const unsigned int region) const
  {
    return gels[region];
  }


  template <int dim>
  const std::string &
  MaterialRegions<dim>::name(const unsigned int region) const
  {
    return region == 0 ? base_name : regions[region - 1].name;
  }


  template <int dim>
  bool
  MaterialRegions<dim>::uses_mesh_groups() const
  {
    return std::any_of(regions.begin(), regions.end(), [](const Region &r) {
      return !r.mesh_group.empty();
    });
  }


  template <int dim>
  unsigned int
  MaterialRegions<dim>::region_of(const dealii::Point<dim> &X0, const std::string &group_name) const
  {
    unsigned int found = 0;
    for (unsigned int k = 0; k < regions.size(); ++k)
      {
        const auto &r  = regions[k];
        const bool  in = r.selector ? selector_value(r, X0) != 0.
                                    : (!group_name.empty() && group_name == r.mesh_group);
        if (!in)
          continue;
        if (found != 0)
          {
            std::ostringstream where;
            where << X0;
            throw InputError("Material/" + r.name + "/" + (r.selector ? "Selector" : "Mesh group"),
                             "overlaps the region '" + regions[found - 1].name + "' at (" +
                               where.str() + "): a point belongs to one region",
                             "make the regions' selectors exclude each other");
          }
        found = k + 1;
      }
    return found;
  }


  template <int dim>
  double
  MaterialRegions<dim>::selector_value(const Region &region, const dealii::Point<dim> &X0)
  {
    // NaN compares unequal to 0: it would put the point in the region.
    const double value = region.selector->value(&X0[0], nullptr);
    if (!std::isfinite(value))
      throw InputError("Material/" + region.name + "/Selector",
                       "is not a number (" + text_of(value) + ") at the initial position " +
                         format_point(X0),
                       "write a condition that is 0 or 1 everywhere, e.g. 'y > 0.5'");
    return value;
  }


  template <int dim>
  void
  MaterialRegions<dim>::check_populated(const std::vector<unsigned long> &counts) const
  {
    for (unsigned int k = 0; k < regions.size(); ++k)
      require(counts[k + 1] > 0,
              "Material/" + regions[k].name + "/" +
                (regions[k].selector ? "Selector" : "Mesh group"),
              "selects no material point of the body",
              regions[k].selector ? "check the expression against the body's initial position"
                                  : "check the group against the mesh's volume groups");
  }


  template <int dim>
  void
  MaterialRegions<dim>::check_mesh_groups(const std::vector<std::string> &volume_groups,
                                          const std::vector<std::string> &boundary_groups) const
  {
    for (const auto &r : regions)
      {
        if (r.mesh_group.empty())
          continue;
        const bool on_boundary =
          std::find(boundary_groups.begin(), boundary_groups.end(), r.mesh_group) !=
          boundary_groups.end();
        std::string known;
        for (const auto &g : volume_groups)
          known += (known.empty() ? "" : ", ") + g;
        require(std::find(volume_groups.begin(), volume_groups.end(), r.mesh_group) !=
                  volume_groups.end(),
                "Material/" + r.name + "/Mesh group",
                on_boundary ? "names '" + r.mesh_group +
                                "', a group of the mesh's boundary, not of its volume"
                            : "names '" + r.mesh_group +
                                "', which is not a physical group of the mesh's volume",
                known.empty() ? "give the mesh volume physical groups (Gmsh: Physical Surface "
                                "in 2D, Physical Volume in 3D) or use a 'Selector'"
                              : "use one of: " + known);
      }
  }


  template <int dim>
  double
  MaterialRegions<dim>::largest_swelling_chemical_potential(const bool axisymmetric) const
  {
    double mu = gels[0].largest_swelling_chemical_potential(axisymmetric);
    for (const auto &gel : gels)
      mu = std::min(mu, gel.largest_swelling_chemical_potential(axisymmetric));
    return mu;
  }


  template class MaterialRegions<2>;
  template class MaterialRegions<3>;
} // namespace GelMPM

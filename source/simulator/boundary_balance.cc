#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/boundary_balance.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  template <int dim>
  void
  BoundaryBalance<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Observables");
    prm.declare_entry(
      "Forces and fluxes",
      "",
      dealii::Patterns::Anything(),
      "Boundary piece names 'a, b, ...' or 'all': adds per piece P the columns P_force_x, "
      "P_force_y (, P_force_z), the force the piece exerts on the body (its traction, Nitsche "
      "and contact terms integrated; the reaction on a support or a punch is its negative; per "
      "unit thickness in 2D), P_inflow, the solvent volume entering through P per unit time, "
      "and P_solvent_in, the volume entered since the start; and solvent_volume, the body's "
      "solvent volume, with solvent_imbalance, the mass balance of the two (zero to the Newton "
      "tolerance). Empty: off.");
    prm.leave_subsection();
  }


  template <int dim>
  void
  BoundaryBalance<dim>::parse_parameters(dealii::ParameterHandler       &prm,
                                         const std::vector<std::string> &pieces)
  {
    prm.enter_subsection("Observables");
    const auto names = dealii::Utilities::split_string_list(prm.get("Forces and fluxes"), ',');
    prm.leave_subsection();
    piece_names = pieces;
    pieces_shown.clear();
    if (names.size() == 1 && names[0] == "all")
      {
        for (unsigned int i = 0; i < pieces.size(); ++i)
          pieces_shown.push_back(i);
        return;
      }
    require(std::find(names.begin(), names.end(), "all") == names.end(),
            "Observables/Forces and fluxes",
            "mixes 'all' with piece names",
            "write 'all' or a list of the declared pieces");
    pieces_shown = piece_indices(names, pieces, "Observables/Forces and fluxes");
  }


  template <int dim>
  bool
  BoundaryBalance<dim>::enabled() const
  {
    return !pieces_shown.empty();
  }


  template <int dim>
  std::vector<std::string>
  BoundaryBalance<dim>::columns() const
  {
    std::vector<std::string> c;
    for (const unsigned int i : pieces_shown)
      {
        for (unsigned int d = 0; d < dim; ++d)
          c.push_back(piece_names[i] + "_force_" + "xyz"[d]);
        c.push_back(piece_names[i] + "_inflow");
        c.push_back(piece_names[i] + "_solvent_in");
      }
    if (enabled())
      {
        c.push_back("solvent_volume");
        c.push_back("solvent_imbalance");
      }
    return c;
  }


  template <int dim>
  void
  BoundaryBalance<dim>::set_communicator(const MPI_Comm comm)
  {
    communicator = comm;
  }


  template <int dim>
  double
  BoundaryBalance<dim>::solvent_volume(const dealii::Particles::ParticleHandler<dim> &particles,
                                       const MaterialRegions<dim> &material) const
  {
    using Layout  = PropertyLayout<dim>;
    double volume = 0.;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) != PointKind::volume)
          continue;
        volume += props[Layout::measure_n] * (1. - 1. / volume_ratio_of(material, props));
      }
    return dealii::Utilities::MPI::sum(volume, communicator);
  }


  template <int dim>
  void
  BoundaryBalance<dim>::record_initial(const dealii::Particles::ParticleHandler<dim> &particles,
                                       const MaterialRegions<dim>                    &material,
                                       StatisticsFile                                &statistics)
  {
    if (!enabled())
      return;
    solvent_volume_0 = solvent_volume(particles, material);
    largest_change   = 0.;
    solvent_in.assign(piece_names.size(), 0.);
    for (const unsigned int i : pieces_shown)
      {
        for (unsigned int d = 0; d < dim; ++d)
          statistics.set(piece_names[i] + "_force_" + "xyz"[d], 0.);
        statistics.set(piece_names[i] + "_inflow", 0.);
        statistics.set(piece_names[i] + "_solvent_in", 0.);
      }
    statistics.set("solvent_volume", solvent_volume_0);
    statistics.set("solvent_imbalance", 0.);
  }


  template <int dim>
  void
  BoundaryBalance<dim>::record_step(
    const std::vector<typename MixedSystem<dim>::PieceBalance> &balances,
    const double                                                dt,
    const dealii::Particles::ParticleHandler<dim>              &particles,
    const MaterialRegions<dim>                                 &material,
    StatisticsFile                                             &statistics)
  {
    if (!enabled())
      return;
    double total_in = 0.;
    for (unsigned int i = 0; i < balances.size(); ++i)
      {
        solvent_in[i] += balances[i].solvent_in;
        total_in += solvent_in[i];
      }
    for (const unsigned int i : pieces_shown)
      {
        for (unsigned int d = 0; d < dim; ++d)
          statistics.set(piece_names[i] + "_force_" + "xyz"[d], balances[i].force[d]);
        statistics.set(piece_names[i] + "_inflow", balances[i].solvent_in / dt);
        statistics.set(piece_names[i] + "_solvent_in", solvent_in[i]);
      }
    const double volume = solvent_volume(particles, material);
    const double change = volume - solvent_volume_0;
    largest_change      = std::max(largest_change, std::abs(change));
    statistics.set("solvent_volume", volume);
    statistics.set("solvent_imbalance",
                   largest_change > 0. ? (change - total_in) / largest_change : 0.);
  }


  template class BoundaryBalance<2>;
  template class BoundaryBalance<3>;
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable_swelling_extent.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

namespace GelMPM
{
  template <int dim>
  void
  SwellingExtent<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Thickness pieces",
                      "",
                      dealii::Patterns::Anything(),
                      "Two boundary piece names 'first, second': adds the column "
                      "delta_h_over_h0 = h/h_0 - 1, with h the distance between the mean "
                      "positions of the two pieces' surface points along 'Thickness direction' "
                      "(h_0 in the initial configuration). Empty: off.");
    prm.declare_entry("Thickness direction",
                      "1",
                      dealii::Patterns::Integer(0, 2),
                      "Coordinate direction of the thickness (0: x, 1: y, 2: z).");
    prm.declare_entry("Radius piece",
                      "",
                      dealii::Patterns::Anything(),
                      "A boundary piece name (e.g. 'sphere'): adds the column radius_over_R0, the "
                      "mean distance of the piece's surface points from 'Radius centre' over its "
                      "value in the initial configuration (r/R_0 of a swelling sphere, disk or "
                      "cylinder). Empty: off.");
    prm.declare_entry("Radius centre",
                      "0, 0, 0",
                      dealii::Patterns::List(dealii::Patterns::Double(), 2, 3),
                      "With 'Radius piece': the centre the distances are measured from (its first "
                      "'Dimension' coordinates are used).");
  }


  template <int dim>
  std::unique_ptr<SwellingExtent<dim>>
  SwellingExtent<dim>::parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces)
  {
    auto extent                 = std::make_unique<SwellingExtent>();
    extent->thickness_direction = prm.get_integer("Thickness direction");
    require(extent->thickness_direction < dim,
            "Observables/Thickness direction",
            "exceeds the dimension",
            "give a direction below " + std::to_string(dim));
    extent->thickness_pieces =
      ObservedPieces::pair(dealii::Utilities::split_string_list(prm.get("Thickness pieces"), ','),
                           pieces,
                           "Observables/Thickness pieces",
                           "top, bottom");

    const std::string radius_name = dealii::Utilities::trim(prm.get("Radius piece"));
    if (!radius_name.empty())
      extent->radius_piece = ObservedPieces::index(radius_name, pieces, "Observables/Radius piece");
    const auto centre_text = dealii::Utilities::split_string_list(prm.get("Radius centre"), ',');
    for (unsigned int d = 0; d < dim && d < centre_text.size(); ++d)
      extent->radius_centre[d] = dealii::Utilities::string_to_double(centre_text[d]);

    if (extent->thickness_pieces[0] < 0 && extent->radius_piece < 0)
      return nullptr;
    return extent;
  }


  template <int dim>
  std::vector<std::string>
  SwellingExtent<dim>::columns() const
  {
    std::vector<std::string> c;
    if (thickness_pieces[0] >= 0)
      c.push_back("delta_h_over_h0");
    if (radius_piece >= 0)
      c.push_back("radius_over_R0");
    return c;
  }


  template <int dim>
  void
  SwellingExtent<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    if (thickness_pieces[0] >= 0)
      {
        const auto means =
          ObservedPieces::means(state.particles, thickness_pieces, this->communicator);
        const double h   = means[0][thickness_direction] - means[1][thickness_direction];
        const double h_0 = means[2][thickness_direction] - means[3][thickness_direction];
        statistics.set("delta_h_over_h0", h / h_0 - 1.);
      }
    if (radius_piece >= 0)
      statistics.set("radius_over_R0", radius_ratio(state.particles));
  }


  template <int dim>
  double
  SwellingExtent<dim>::radius_ratio(const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    using Layout = PropertyLayout<dim>;
    // Sums of the current and the initial distances.
    std::vector<double> sums(2, 0.);
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (kind_of(props) == PointKind::volume || piece_of(props) != radius_piece)
          continue;
        dealii::Point<dim> X0;
        for (unsigned int d = 0; d < dim; ++d)
          X0[d] = props[Layout::position_0 + d];
        sums[0] += position_of(particle.get_location(), props).distance(radius_centre);
        sums[1] += X0.distance(radius_centre);
      }
    dealii::Utilities::MPI::sum(sums, this->communicator, sums);
    return sums[0] / sums[1];
  }


  template class SwellingExtent<2>;
  template class SwellingExtent<3>;
} // namespace GelMPM

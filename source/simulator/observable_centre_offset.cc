#include <gelmpm/simulator/observable_centre_offset.h>

#include <deal.II/base/utilities.h>

namespace GelMPM
{
  template <int dim>
  void
  CentreOffset<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Centre offset pieces",
                      "",
                      dealii::Patterns::Anything(),
                      "Two boundary piece names 'first, second' (e.g. 'bottom, top' of a column): "
                      "adds the columns centre_offset_x, centre_offset_y (and centre_offset_z in "
                      "3D), the vector from the mean position of the first piece's surface points "
                      "to that of the second's minus its initial value, and centre_distance, its "
                      "length (paper Fig. 10a: the sideways separation of the ends of a buckling "
                      "column). Empty: off.");
  }


  template <int dim>
  std::unique_ptr<CentreOffset<dim>>
  CentreOffset<dim>::parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces)
  {
    auto offset = std::make_unique<CentreOffset>();
    offset->pieces =
      ObservedPieces::pair(dealii::Utilities::split_string_list(prm.get("Centre offset pieces"),
                                                                ','),
                           pieces,
                           "Observables/Centre offset pieces",
                           "bottom, top");
    if (offset->pieces[0] < 0)
      return nullptr;
    return offset;
  }


  template <int dim>
  std::vector<std::string>
  CentreOffset<dim>::columns() const
  {
    std::vector<std::string> c;
    for (unsigned int d = 0; d < dim; ++d)
      c.push_back(std::string("centre_offset_") + "xyz"[d]);
    c.push_back("centre_distance");
    return c;
  }


  template <int dim>
  void
  CentreOffset<dim>::evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const
  {
    const auto means = ObservedPieces::means(state.particles, pieces, this->communicator);
    const dealii::Tensor<1, dim> offset = (means[1] - means[0]) - (means[3] - means[2]);
    for (unsigned int d = 0; d < dim; ++d)
      statistics.set(std::string("centre_offset_") + "xyz"[d], offset[d]);
    statistics.set("centre_distance", offset.norm());
  }


  template class CentreOffset<2>;
  template class CentreOffset<3>;
} // namespace GelMPM

#include <gelmpm/core/input_error.h>
#include <gelmpm/scene/body.h>

#include <stdexcept>

namespace GelMPM
{
  template <int dim>
  bool
  Body<dim>::inside_boxes(const dealii::Point<dim> &p) const
  {
    return inside(p);
  }


  template <int dim>
  bool
  Body<dim>::has_own_volume_points() const
  {
    return false;
  }


  template <int dim>
  std::vector<typename Body<dim>::VolumeElement>
  Body<dim>::volume_elements(const unsigned int, const double) const
  {
    throw std::logic_error("this body's volume points are the sub-cell centres inside it");
  }


  template <int dim>
  void
  Body<dim>::check_volume_points(const unsigned long n_points,
                                 const bool,
                                 const unsigned long) const
  {
    require(n_points > 0,
            entry(),
            "places no volume point inside the background grid",
            "put the body inside 'Background grid'");
  }


  template class Body<2>;
  template class Body<3>;
} // namespace GelMPM

#ifndef gelmpm_simulator_observable_swelling_extent_h
#define gelmpm_simulator_observable_swelling_extent_h

#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <memory>

namespace GelMPM
{
  /**
   * @brief How far the body has swollen, from the surface points of its pieces:
   * - Thickness (column delta_h_over_h0): with "Thickness pieces = top, bottom" and direction d,
   *   h(t) is the mean coordinate x_d of the surface points of the first piece minus that of the
   *   second, h_0 the same in the initial configuration, and the column is h/h_0 - 1 (paper §4.1:
   *   Delta h / h_0).
   * - Radius (column radius_over_R0): with "Radius piece" and "Radius centre" c, the mean
   *   distance |x - c| of the piece's surface points over its initial value: the radius of a
   *   swelling sphere, disk or cylinder, r/R_0 (doc/axisymmetric.md).
   */
  template <int dim>
  class SwellingExtent : public Observable<dim>
  {
  public:
    /** Its entries, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered), @p pieces being the scene's piece names; none if off. */
    static std::unique_ptr<SwellingExtent>
    parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

  private:
    /** The mean distance of the radius piece's points from the centre over its initial one. */
    double
    radius_ratio(const dealii::Particles::ParticleHandler<dim> &particles) const;

    std::array<int, 2> thickness_pieces    = {{-1, -1}};
    unsigned int       thickness_direction = 1;
    int                radius_piece        = -1;
    dealii::Point<dim> radius_centre;
  };
} // namespace GelMPM

#endif

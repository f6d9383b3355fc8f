#ifndef gelmpm_simulator_observable_centre_offset_h
#define gelmpm_simulator_observable_centre_offset_h

#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <memory>

namespace GelMPM
{
  /**
   * @brief The sideways motion of one end of a body against the other (columns
   * centre_offset_x, _y, (_z), centre_distance): with "Centre offset pieces = bottom, top", the
   * vector between the mean positions of the two pieces' surface points minus its initial
   * value, and its length (paper §4.3, Fig. 10a: a buckling column).
   */
  template <int dim>
  class CentreOffset : public Observable<dim>
  {
  public:
    /** Its entry, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered), @p pieces being the scene's piece names; none if off. */
    static std::unique_ptr<CentreOffset>
    parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

  private:
    std::array<int, 2> pieces = {{-1, -1}};
  };
} // namespace GelMPM

#endif

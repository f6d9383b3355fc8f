#ifndef gelmpm_core_non_physical_state_h
#define gelmpm_core_non_physical_state_h

#include <stdexcept>
#include <string>

namespace GelMPM
{
  /**
   * @brief Thrown when a state leaves the physical range of the gel (J <= 1: less solvent than
   * none), where the mixing energy is undefined, or when a Newton iterate puts a point of the
   * self-contact deeper behind the surface than 'Largest depth'. The Newton solver's line search
   * damps such an update; a state that stays so fails the attempt and cuts the step.
   *
   * In core rather than next to the gel so that the solvers, which only catch it, and the
   * body-fitted peer need neither the material nor the material point assembly.
   */
  class NonPhysicalState : public std::runtime_error
  {
  public:
    explicit NonPhysicalState(const std::string &message)
      : std::runtime_error(message)
    {}
  };
} // namespace GelMPM

#endif

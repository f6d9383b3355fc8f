#ifndef GELMPM_REFERENCE_NUMERICAL_TOLERANCES_H
#define GELMPM_REFERENCE_NUMERICAL_TOLERANCES_H

namespace GelMPM
{
  /**
   * Tolerances shared by the finite-difference references (ConstrainedSwelling1D,
   * FreeSwellingSphere1D). The references are independent of the solvers module on purpose, so
   * they keep their own copy of its time tolerance.
   */
  namespace ReferenceTolerances
  {
    /** Relative tolerance of "the step reached its full size". */
    constexpr double relative_time_tolerance = 1e-12;

    /** How far above J = 1 (the mixing energy's domain) a damped Newton state must stay. */
    constexpr double above_dry_state = 1e-12;
  } // namespace ReferenceTolerances
} // namespace GelMPM

#endif

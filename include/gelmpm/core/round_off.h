#ifndef gelmpm_core_round_off_h
#define gelmpm_core_round_off_h

namespace GelMPM
{
  /**
   * Relative tolerance of "a position lies on an edge" and "two lengths are equal", in units of the
   * extent of the domain they belong to (a grid, an interval, a mesh). Points are moved by
   * increments that carry round-off, and a point that a body places exactly on an edge must count
   * as inside; 1e-12 stays far above double round-off after many steps and far below any
   * meaningful distance.
   */
  constexpr double relative_position_tolerance = 1e-12;
} // namespace GelMPM

#endif

#ifndef gelmpm_io_output_settings_h
#define gelmpm_io_output_settings_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace GelMPM
{
  /**
   * @brief The "Output" section: where results go, what is written, and how often.
   *
   * Everything here is off unless a scene asks for it, except the statistics table and the
   * parameter echo, which cost next to nothing.
   */
  struct OutputSettings
  {
    /** Directory for all results; created when the run starts (after all input is checked). */
    std::string directory = "output";
    /** Write material points (.vtu per output time, .pvd series). */
    bool write_particles = true;
    /**
     * Write the background grid (cell classification, volume points per cell, du and mu of the
     * last converged step; GridOutput) at the same times as the particles.
     */
    bool write_grid = false;
    /** Write output every this many converged steps (0: only the initial and final state). */
    unsigned int interval_steps = 1;
    /** Also write output whenever simulated time passes a multiple of this (0: off). */
    double interval_time = 0.;
    /**
     * Test mode: the log holds no timings, no version strings and no paths, so that it can be
     * compared with a stored reference (as ExaDG's IsTest).
     */
    bool test_mode = false;

    /** Declare the section "Output". */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the section "Output"; throws InputError on inconsistent values. */
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace GelMPM

#endif

#ifndef gelmpm_solvers_time_stepping_h
#define gelmpm_solvers_time_stepping_h

#include <deal.II/base/parameter_handler.h>

#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * Relative tolerance of "time t has reached time s" (a stop time, the end, the next output, the
   * end of a bisection bracket). Times are sums of many steps and carry their round-off: without
   * it a run would take a last step of ~1e-16 to reach a time it has already reached.
   */
  constexpr double relative_time_tolerance = 1e-12;


  /**
   * @brief The "Time stepping" section: adaptive implicit stepping as in the paper's §4.
   *
   * All times are in units of the diffusion time tau_d = L^2 / D, with L the scene's
   * "Characteristic length" and D the material's diffusivity (the paper's normalisation; e.g.
   * §4.1 uses L = h_0, the initial thickness). A failed Newton solve halves the step and retries
   * from the last converged state; convergence in fewer than "Growth below iterations" Newton
   * iterations multiplies the step by "Growth factor"; piecewise caps (paper eq. (64), (65))
   * bound it; steps are shortened to land exactly on the "Stop at times".
   */
  struct TimeStepping
  {
    double       characteristic_length = 1.;
    double       initial_step          = 1e-3;
    double       end_time              = 1.;
    double       minimum_step          = 1e-12;
    double       growth_factor         = 1.25;
    unsigned int growth_below          = 6;
    double       cut_factor            = 0.5;
    unsigned int maximum_steps         = 1000000;
    /** The default of 'Largest increment' (cells): doc/method.md, "Update after convergence". */
    static constexpr const char *default_largest_increment_text = "5";
    /** Largest displacement of a material point in one step, in cells of the u grid; 0: off. */
    double largest_increment = 5.;
    /** Whether 'Largest increment' is its default: it then bounds only the steps no error
     * estimate judges, and a model without a grid ignores it. */
    bool largest_increment_default = true;
    /** Largest predictor-corrector difference of a point's displacement in one step, in the
     * scene's length unit; 0: off. */
    double displacement_tolerance = 0.;
    /** Bound on the run's accumulated local error (units L and k_BT); 0: off. */
    double tolerance = 0.;
    /** Measure the local error by its largest value over the volume points (instead of the
     * root mean square): for errors confined to a boundary layer. */
    bool error_largest = false;
    /** 'Tolerance' applies to steps that begin before this time (tau_d); 0: the whole run. */
    double tolerance_until = 0.;
    /** 'Tolerance' applies until the first bracketed loss of stability. */
    bool tolerance_until_onset = false;
    /**
     * 'End at equilibrium': the run ends once the state's rate of change (the largest relative
     * change of a volume point's J or displacement in 'Characteristic length' per tau_d over an
     * accepted step) is below this on two consecutive steps after the last 'Stop at times';
     * 0: off.
     */
    double                                 end_at_equilibrium = 0.;
    std::vector<std::pair<double, double>> caps; // (until time, largest step), sorted
    std::vector<double>                    stop_times;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Throw InputError ('Time stepping/Tolerance') if the tolerance is below 1000 times
     * @p newton_tolerance ('Newton/Tolerance'): each step's solution is uncertain by about the
     * Newton tolerance, and the error estimate resolves no local error below it unless every
     * step is longer than a thousandth of the time elapsed.
     */
    void
    check_resolvable(const double newton_tolerance, const double smallest_newton_tolerance) const;

    /** Largest step allowed at time @p t by the caps (infinity beyond the last cap). */
    double
    cap(const double t) const;

    /**
     * The step to take from @p t given the step @p dt the controller proposes: capped, and
     * shortened to land on the next stop time or the end time.
     */
    double
    next_step(const double t, const double dt) const;
  };
} // namespace GelMPM

#endif

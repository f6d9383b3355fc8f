#include <gelmpm/core/input_error.h>
#include <gelmpm/solvers/time_stepping.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace GelMPM
{
  void
  TimeStepping::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Time stepping");
    prm.declare_entry("Characteristic length",
                      "1",
                      Patterns::Double(0.),
                      "L of the diffusion time tau_d = L^2/D that all times of the scene are "
                      "measured in (paper §4.1: the initial thickness h_0; §4.3: H/2).");
    prm.declare_entry("Initial step", "1e-3", Patterns::Double(0.), "First time step, in tau_d.");
    prm.declare_entry("End time", "1", Patterns::Double(0.), "End of the run, in tau_d.");
    prm.declare_entry(
      "End at equilibrium",
      "0",
      Patterns::Double(0.),
      "End the run at a steady state, before 'End time' (which stays the upper bound): once the "
      "state's rate of change stays below this on two consecutive accepted steps (so that one "
      "short step does not end the run), both beginning at or after the last 'Stop at times'. "
      "The rate of a step of dt (in tau_d) is max(largest |J_{n+1}/J_n - 1| over the volume "
      "points, largest |u_{n+1} - u_n| of a point / 'Characteristic length') / dt: the relative "
      "change of the volume ratio J, or the motion in units of L, per tau_d; it is dimensionless. "
      "Near a steady state the rate decays as exp(-t/tau), tau the body's slowest relaxation "
      "time, and the state is left short of its limit by at most about the tolerance times tau "
      "in tau_d, which can be long for a swollen gel: the free-swelling square of "
      "tests/simulator/free_swelling_scene.prm (tau about 85 tau_d) ended at 395 tau_d with "
      "J_mean 3.9e-3 short of its closed form at 1e-4, at 790 tau_d 3.9e-5 short at 1e-6. The "
      "end is said in the log, written as an 'equilibrium' row of events.csv where the run "
      "writes one, with the last output and checkpoint as at 'End "
      "time'. The criterion cannot know the boundary data's future: with a loading that starts "
      "late or pauses, put a 'Stop at times' at its last change. Material point scenes only; the "
      "body-fitted peer refuses it. 0: off.");
    prm.declare_entry("Minimum step",
                      "1e-12",
                      Patterns::Double(0.),
                      "When a failing step would be cut below this (in tau_d), the run stops "
                      "cleanly, keeping every result written so far (exit status 1).");
    prm.declare_entry("Growth factor",
                      "1.25",
                      Patterns::Double(1.),
                      "The step grows by this factor after a step that converged in fewer than "
                      "'Growth below iterations' Newton iterations (paper §4: 1.25).");
    prm.declare_entry("Growth below iterations",
                      "6",
                      Patterns::Integer(1),
                      "See 'Growth factor' (paper §4: 6).");
    prm.declare_entry("Cut factor",
                      "0.5",
                      Patterns::Double(0., 1.),
                      "A step whose Newton iteration fails is retried with the step times this "
                      "factor (paper §4: 1/2).");
    prm.declare_entry("Maximum steps",
                      "1000000",
                      Patterns::Integer(1),
                      "Stop (cleanly, exit status 1) after this many steps.");
    prm.declare_entry(
      "Largest increment",
      default_largest_increment_text,
      Patterns::Double(0.),
      "A converged step in which some material point moves farther than this, in "
      "cells of the displacement grid, is retaken with the step times 'Cut factor' "
      "(the material point method integrates on the points, so they should cross "
      "at most a few cells per step; a step far beyond converges to a wrong state: "
      "the free-swelling square in one step of 1000 tau_d, its points moving up to "
      "9.9 cells, ended at J_mean 8.805 against 9.432; near an instability it also "
      "keeps Newton on the branch it started from). At its default, 5, it bounds the "
      "steps that no error estimate judges ('Displacement tolerance', "
      "'Tolerance': every step of a scene without them, else the first, the one "
      "after a perturbation, one far longer than the last), below where the "
      "error appears and above what the scenes in prm/ move in such steps "
      "(doc/method.md, \"Update after convergence\"); a value given bounds every "
      "step. Material point scenes only; the body-fitted peer, which has no grid, "
      "ignores the default and refuses another value. 0: no limit.");
    prm.declare_entry(
      "Displacement tolerance",
      "0",
      Patterns::Double(0.),
      "Error control of the step: the largest distance, in the scene's length unit, between a material point's displacement in the step and its displacement in the last "
      "accepted step scaled by dt / dt_last (a predictor-corrector difference, about twice "
      "backward Euler's local error). A step above it is retaken shorter; the next step is "
      "the largest the estimate allows, dt * 0.9 sqrt(tolerance / difference), never more "
      "than the Newton rule's growth. A steady motion lets the steps grow; an accelerating "
      "one (the sway after a buckling onset) or a jump to another branch shortens them. "
      "Material point scenes only; the body-fitted peer ignores it. 0: off.");
    prm.declare_entry(
      "Tolerance",
      "0",
      Patterns::Double(0.),
      "Error control of the step by the accuracy asked for: the local error of each backward "
      "Euler step (estimated from the difference to the linear predictor, root mean square "
      "over the volume points) may be at most Tolerance * dt / (t + dt), in units of the "
      "'Characteristic length' for the displacement and of k_BT for the chemical potential: "
      "while the time grows by a factor e the run commits local errors of at most Tolerance "
      "(diffusion acts on the scale of the elapsed time, so early errors die out as fast as "
      "early steps are short). A step above it is retaken shorter; the next step is the one "
      "the estimate allows, with a safety factor 0.9, never more than the Newton rule's "
      "growth. The measured error against the reference follows it (doc/performance.md, "
      "'Error-controlled steps'). It does not act where a 'Step caps' interval applies (steps "
      "set by hand, e.g. over a loading ramp); combine it with 'Growth factor' = 2. "
      "At least 1000 times 'Newton/Tolerance' (each step's solution is uncertain by about that). "
      "A run continued with --resume may change it (and the other entries of this section "
      "that choose the steps ahead; doc/output.md), e.g. when it crawls; the log says so. "
      "Material point scenes only; the "
      "body-fitted peer ignores it. 0: off.");
    prm.declare_entry("Error norm",
                      "rms",
                      Patterns::Selection("rms|max"),
                      "How 'Tolerance' measures the local error over the volume points: 'rms', the "
                      "volume-weighted root mean square (errors spread over the body), or 'max', "
                      "the largest value (errors confined to a boundary layer, e.g. the diffusion "
                      "front that sets a buckling onset: doc/column_buckling.md).");
    prm.declare_entry("Tolerance until",
                      "0",
                      Patterns::Anything(),
                      "'Tolerance' applies to the steps that begin before this time (tau_d; 0: "
                      "the whole run), or, with 'onset', until the first bracketed loss of "
                      "stability (section Stability): the history that sets a buckling onset, "
                      "after which the motion's own control ('Displacement tolerance') and the "
                      "signature suffice (prm/column_buckling.prm).");
    prm.declare_entry("Step caps",
                      "",
                      Patterns::Anything(),
                      "Piecewise upper bounds of the step: 'until_1: cap_1, until_2: cap_2, ...' "
                      "(times in tau_d, increasing): for t <= until_1 the step is at most cap_1, "
                      "and so on; no cap after the last. Paper eq. (64): "
                      "'5: 0.0125, 20: 0.0625, 40: 0.125, 100: 0.625'.");
    prm.declare_entry("Stop at times",
                      "",
                      Patterns::List(Patterns::Double(0.)),
                      "Times (tau_d) the stepping lands on exactly, e.g. for profiles compared "
                      "with a reference; output is written at each of them. With 'Tolerance', "
                      "put one on each kink of a piecewise loading (min(t/T, 1) at T): a step "
                      "across a kink is retaken until it ends before it (doc/own_scenes.md, "
                      "section 12).");
    prm.leave_subsection();
  }


  void
  TimeStepping::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Time stepping");
    characteristic_length       = prm.get_double("Characteristic length");
    initial_step                = prm.get_double("Initial step");
    end_time                    = prm.get_double("End time");
    minimum_step                = prm.get_double("Minimum step");
    growth_factor               = prm.get_double("Growth factor");
    growth_below                = prm.get_integer("Growth below iterations");
    cut_factor                  = prm.get_double("Cut factor");
    maximum_steps               = prm.get_integer("Maximum steps");
    largest_increment           = prm.get_double("Largest increment");
    largest_increment_default   = prm.get("Largest increment") == default_largest_increment_text;
    displacement_tolerance      = prm.get_double("Displacement tolerance");
    tolerance                   = prm.get_double("Tolerance");
    end_at_equilibrium          = prm.get_double("End at equilibrium");
    error_largest               = prm.get("Error norm") == "max";
    const std::string until     = prm.get("Tolerance until");
    const std::string caps_text = prm.get("Step caps");
    const std::string stops     = prm.get("Stop at times");
    prm.leave_subsection();

    tolerance_until_onset = dealii::Utilities::trim(until) == "onset";
    if (!tolerance_until_onset)
      {
        char        *end   = nullptr;
        const double value = std::strtod(until.c_str(), &end);
        require(end != until.c_str() && dealii::Utilities::trim(end).empty() && value >= 0.,
                "Time stepping/Tolerance until",
                "is '" + until + "', neither a time nor 'onset'",
                "give a time in tau_d (0: the whole run) or 'onset'");
        tolerance_until = value;
      }

    require(characteristic_length > 0.,
            "Time stepping/Characteristic length",
            "must be positive",
            "give the length L of tau_d = L^2/D");
    require(initial_step > 0., "Time stepping/Initial step", "must be positive", "give dt_0 > 0");
    require(end_time > 0., "Time stepping/End time", "must be positive", "give t_final > 0");
    require(cut_factor > 0. && cut_factor < 1.,
            "Time stepping/Cut factor",
            "must lie strictly between 0 and 1",
            "use 0.5 as in the paper");
    require(tolerance < 1.,
            "Time stepping/Tolerance",
            "must be below 1 (it bounds local errors in units of L and k_BT)",
            "give e.g. 1e-3, or 0 to switch the error control off");
    require(minimum_step >= 1e-300,
            "Time stepping/Minimum step",
            "is below 1e-300, where the step arithmetic loses its precision",
            "give e.g. 1e-12 (tau_d)");
    require(minimum_step < initial_step,
            "Time stepping/Minimum step",
            "is not smaller than the initial step",
            "give a minimum step below 'Initial step'");

    caps.clear();
    for (const auto &item : dealii::Utilities::split_string_list(caps_text, ','))
      {
        const auto pair = dealii::Utilities::split_string_list(item, ':');
        require(pair.size() == 2,
                "Time stepping/Step caps",
                "has the item '" + item + "' that is not 'until: cap'",
                "write e.g. '5: 0.0125, 20: 0.0625'");
        double until = 0., value = 0.;
        try
          {
            until = dealii::Utilities::string_to_double(pair[0]);
            value = dealii::Utilities::string_to_double(pair[1]);
          }
        catch (...)
          {
            throw InputError("Time stepping/Step caps",
                             "has the item '" + item + "' with a non-number",
                             "write e.g. '5: 0.0125, 20: 0.0625'");
          }
        require(std::isfinite(until) && std::isfinite(value),
                "Time stepping/Step caps",
                "has the item '" + item + "' that is not finite",
                "write e.g. '5: 0.0125, 20: 0.0625'");
        require(value > 0.,
                "Time stepping/Step caps",
                "has the non-positive cap in '" + item + "'",
                "give caps > 0");
        require(value >= minimum_step,
                "Time stepping/Step caps",
                "has the cap in '" + item + "' below 'Minimum step' = " +
                  std::to_string(minimum_step) + " (the run would crawl there)",
                "give caps of at least the minimum step");
        require(caps.empty() || until > caps.back().first,
                "Time stepping/Step caps",
                "has times that do not increase",
                "list the items in increasing time");
        caps.emplace_back(until, value);
      }

    stop_times.clear();
    for (const auto &item : dealii::Utilities::split_string_list(stops, ','))
      {
        double t = 0.;
        try
          {
            t = dealii::Utilities::string_to_double(item);
          }
        catch (...)
          {
            throw InputError("Time stepping/Stop at times",
                             "has the item '" + item + "' that is not a number",
                             "write e.g. '0.1, 0.5, 1'");
          }
        require(std::isfinite(t) && t > 0.,
                "Time stepping/Stop at times",
                "has the item '" + item + "' that is not a positive, finite time",
                "write e.g. '0.1, 0.5, 1'");
        stop_times.push_back(t);
      }
    std::sort(stop_times.begin(), stop_times.end());
  }


  void
  TimeStepping::check_resolvable(const double newton_tolerance,
                                 const double smallest_newton_tolerance) const
  {
    // A local error below 1000 times the Newton tolerance needs steps of at least t / 1000: the
    // free-swelling test scene at 1e-8 against 1e-10 crept at steps of 1e-5 t (33,000 steps to
    // 0.1 tau_d); at 1e-300 every step was retaken twice and accepted as noise.
    if (!(tolerance > 0.) || tolerance >= 1000. * newton_tolerance)
      return;
    std::ostringstream problem, fix;
    problem << "is " << tolerance << ", below 1000 times 'Newton/Tolerance' ("
            << 1000. * newton_tolerance
            << "): each step's solution is uncertain by about the Newton tolerance, so the "
               "error estimate cannot resolve such a local error unless every step is longer "
               "than a thousandth of the time elapsed";
    fix << "give at least " << 1000. * newton_tolerance
        << " (e.g. 1e-3), or 0 for no error control; or lower 'Newton/Tolerance' (at least "
        << smallest_newton_tolerance << ")";
    throw InputError("Time stepping/Tolerance", problem.str(), fix.str());
  }


  double
  TimeStepping::cap(const double t) const
  {
    for (const auto &c : caps)
      if (t < c.first * (1. - relative_time_tolerance))
        return c.second;
    return std::numeric_limits<double>::infinity();
  }


  double
  TimeStepping::next_step(const double t, const double dt) const
  {
    double step = std::min(dt, cap(t));
    double next = end_time;
    for (const double s : stop_times)
      if (s > t * (1. + relative_time_tolerance) + 1e-300)
        {
          next = std::min(next, s);
          break;
        }
    // Land on the next stop exactly rather than leave a remainder of round-off size; but never
    // stretch a step by more than a thousandth (a step the error control shortened near a stop
    // would be stretched back to the same attempt over and over).
    if (t + step >= next - std::min(1e-10 * next, 1e-3 * step))
      step = next - t;
    return step;
  }
} // namespace GelMPM

// StepControl, the step policy shared by the material point simulator and the body-fitted peer,
// driven through scripted sequences of Newton outcomes and signatures; every decision is
// checked against the rule it implements (include/gelmpm/solvers/step_control.h):
// 1. growth by the growth factor after fast convergence, caps, landing on stop times and on the
//    end time, a stop-time step leaving the proposed step unchanged;
// 2. cuts after a failed attempt and the refusal below the minimum step;
// 3. bisection of a loss of stability to the tolerance, the bracket, the step-dependent case;
// 4. after an onset: the step from the bracket's width, the cap while unstable, and signature
// control (retake shorter while the
//    signature is unstable), then regained stability;
// 5. error control: a difference above the tolerance retakes the step by 0.9 sqrt(tol/e)
//    (clamped to [0.2, 0.9]), one below it bounds the next step by the same formula or by the
//    Newton growth, whichever is smaller; a difference that does not shrink with the step is
//    accepted as a jump; the tolerance 0 accepts everything;
// 6. 'Tolerance': the local error per unit relative time dt / (t + dt) against the tolerance:
//    retake and the bound on the next step by 0.9 tol dt / (e (t + dt)), the stricter of the
//    two rules when both are on;
// 7. 'End at equilibrium': the run is finished after two consecutive steps whose rate is below
//    the tolerance, not after one, not with a faster step between them, not for steps that
//    begin before the last stop time, never with the tolerance 0.
#include <gelmpm/solvers/step_control.h>

#include <cmath>
#include <iostream>

using GelMPM::StepControl;
using Verdict = StepControl::Verdict;

namespace
{
  bool
  close(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-12 * std::max(1., std::abs(b));
  }

  /** Judge the current attempt by its displacement difference @p d alone. */
  bool
  judge(StepControl &c, const double d)
  {
    return c.judge_error(c.error_excess(d, 0., c.attempt_size()));
  }


  /** Judge the current attempt by the excess @p factor of the tolerance rule. */
  bool
  judge_tolerance(StepControl &c, const double factor)
  {
    return c.judge_error(StepControl::ErrorExcess{factor, true});
  }


  GelMPM::TimeStepping
  settings()
  {
    GelMPM::TimeStepping s;
    s.initial_step  = 0.1;
    s.end_time      = 1.;
    s.minimum_step  = 1e-3;
    s.growth_factor = 1.25;
    s.growth_below  = 6;
    s.cut_factor    = 0.5;
    s.caps          = {{0.5, 0.15}};
    s.stop_times    = {0.3};
    return s;
  }
} // namespace

int
main()
{
  std::cout << std::boolalpha;
  {
    StepControl c(settings());
    bool        ok = close(c.attempt(), 0.1);
    c.accept(3); // fast: grows to 0.125
    ok = ok && close(c.attempt(), 0.125) && close(c.time(), 0.1);
    c.accept(8);                          // slow: stays
    ok = ok && close(c.attempt(), 0.075); // lands on the stop time 0.3
    c.accept(8);
    ok = ok && c.at_stop_time() && close(c.proposed_step(), 0.125);
    ok = ok && close(c.attempt(), 0.125);
    c.accept(3);
    ok = ok && close(c.attempt(), 0.15); // capped (0.15625 > 0.15) until t = 0.5
    std::cout << "growth, stop times and caps: " << ok << std::endl;
    c.accept(8);
    ok = close(c.time(), 0.575) && close(c.attempt(), 0.15);
    c.accept(3);
    ok = ok && close(c.attempt(), 0.1875);
    c.accept(3);
    ok = ok && close(c.attempt(), 1. - 0.9125) && !c.finished();
    c.accept(3);
    std::cout << "end time reached exactly: " << (ok && c.finished() && close(c.time(), 1.))
              << std::endl;
  }
  {
    StepControl c(settings());
    c.attempt();
    bool ok = c.cut_step() && close(c.attempt(), 0.05);
    for (unsigned int k = 0; k < 5; ++k)
      ok = ok && c.cut_step() && (c.attempt() > 0.);
    ok = ok && close(c.attempt_size(), 0.1 / 64.);
    std::cout << "cuts halve the step: " << ok << std::endl;
    std::cout << "a cut below the minimum step is refused: " << !c.cut_step() << std::endl;
  }
  {
    GelMPM::TimeStepping s = settings();
    s.caps.clear();
    s.stop_times.clear();
    StepControl c(s, 0.01);
    c.attempt();
    c.judge_signature(true);
    c.accept(8); // t = 0.1, stable
    c.attempt(); // to 0.2: unstable
    bool ok = c.judge_signature(false) == Verdict::retake && c.bracketing();
    // Bisection of (0.1, 0.2]: 0.15 stable, 0.175 unstable, 0.1625 stable, 0.16875 unstable by
    // a step narrower than the tolerance: the bracket (0.1625, 0.16875], onset.
    ok = ok && close(c.attempt(), 0.05) && c.judge_signature(true) == Verdict::accept;
    c.accept(3); // fast convergence, but a bisection step: the proposed step does not grow
    ok = ok && close(c.proposed_step(), 0.1);
    ok = ok && close(c.attempt(), 0.025) && c.judge_signature(false) == Verdict::retake;
    ok = ok && close(c.attempt(), 0.0125) && c.judge_signature(true) == Verdict::accept;
    c.accept(8);
    ok = ok && close(c.attempt(), 0.00625) && c.judge_signature(false) == Verdict::onset;
    ok = ok && close(c.bracket().t_stable, 0.1625) && close(c.bracket().t_unstable, 0.16875);
    c.accept(8);
    std::cout << "a loss of stability is bracketed to the tolerance: " << ok << std::endl;
    std::cout << "after the bracket the proposed step is the step before it: "
              << close(c.proposed_step(), 0.1) << std::endl;

    // With signature control (going through), the same sequence continues from the bracket's
    // width instead.
    StepControl g(s, 0.01, 0., true);
    g.attempt();
    g.judge_signature(true);
    g.accept(8);
    g.attempt();
    g.judge_signature(false);
    for (const bool stable : {true, false, true})
      {
        g.attempt();
        g.judge_signature(stable);
        if (stable)
          g.accept(3);
      }
    g.attempt();
    ok = g.judge_signature(false) == Verdict::onset;
    g.accept(3);
    std::cout << "with signature control the step after the onset is the bracket's width: "
              << (ok && close(g.proposed_step(), 0.00625)) << std::endl;
  }
  {
    GelMPM::TimeStepping s = settings();
    s.caps.clear();
    s.stop_times.clear();
    StepControl c(s, 0.06);
    c.attempt();
    c.judge_signature(false); // retake
    c.attempt();              // 0.05
    c.judge_signature(true);
    c.accept(8);
    c.attempt(); // 0.05 onto the unstable end, now stable
    std::cout << "a stable state at the unstable end ends the bracketing: "
              << (c.judge_signature(true) == Verdict::step_dependent && !c.bracketing())
              << std::endl;
  }
  {
    GelMPM::TimeStepping s = settings();
    s.caps.clear();
    s.stop_times.clear();
    StepControl c(s, 0., 0.02, true);
    c.attempt();
    bool ok = c.judge_signature(false) == Verdict::onset; // no bisection: onset at once
    c.accept(3);
    ok = ok && close(c.attempt(), 0.02); // capped while unstable
    ok = ok && c.judge_signature(false) == Verdict::shorten && close(c.proposed_step(), 0.01);
    ok = ok && close(c.attempt(), 0.01) && c.judge_signature(false) == Verdict::shorten;
    ok = ok && close(c.attempt(), 0.005) && c.judge_signature(true) == Verdict::regained;
    c.accept(3);
    ok = ok && c.stable() && close(c.attempt(), 0.00625);
    std::cout << "after an onset unstable attempts are shortened until stable: " << ok << std::endl;
  }

  {
    GelMPM::TimeStepping s = settings();
    s.caps.clear();
    s.stop_times.clear();
    s.displacement_tolerance = 0.01;
    StepControl c(s);
    c.attempt();                    // 0.1
    bool ok        = !judge(c, 1.); // 0.9 sqrt(0.01) = 0.09, clamped to 0.2
    ok             = ok && close(c.attempt(), 0.02);
    ok             = ok && !judge(c, 0.03); // shrank enough: 0.9 sqrt(1 / 3)
    ok             = ok && close(c.attempt(), 0.02 * 0.9 * std::sqrt(1. / 3.));
    const double h = c.attempt_size();
    ok = ok && judge(c, 0.0081) && !c.error_uncontrolled(); // 0.9 sqrt(0.01 / 0.0081) = 1
    c.accept(3);                                            // Newton would grow by 1.25
    ok = ok && close(c.time(), h) && close(c.attempt(), h);
    ok = ok && judge(c, 1e-6); // far below: Newton's growth limits
    c.accept(3);
    ok = ok && close(c.attempt(), h * 1.25);
    std::cout << "error control: retake, clamp, and the bound on the next step: " << ok
              << std::endl;

    StepControl jump(s);
    jump.attempt();
    ok = !judge(jump, 0.04) && close(jump.attempt(), 0.045);
    ok = ok && judge(jump, 0.039) && jump.error_uncontrolled(); // did not shrink: a jump
    std::cout << "a difference that does not shrink with the step is accepted as a jump: " << ok
              << std::endl;

    s.displacement_tolerance = 0.;
    StepControl off(s);
    off.attempt();
    std::cout << "the tolerance 0 accepts any difference: " << judge(off, 1e9) << std::endl;
  }

  {
    GelMPM::TimeStepping s = settings();
    s.caps.clear();
    s.stop_times.clear();
    s.tolerance = 1e-3;
    StepControl  c(s);
    const double dt = c.attempt(); // 0.1
    // e (t + dt) / (dt tol) = 2e-3 * 0.1 / (0.1 * 1e-3) = 2: retaken with 0.45 dt.
    bool ok = close(c.error_excess(0., 2e-3, dt).factor, 2.) && !judge_tolerance(c, 2.);
    ok      = ok && close(c.attempt(), 0.045);
    // (1e-3 10/9) 0.045 / (0.045 * 1e-3) = 10/9: still above, retaken with 0.81 of it.
    const double excess = c.error_excess(0., 1e-3 * 10. / 9., c.attempt_size()).factor;
    ok                  = ok && close(excess, 10. / 9.) && !judge_tolerance(c, excess) &&
         close(c.attempt(), 0.045 * 0.81);
    // Within: the next step is bounded by dt 0.9 / excess (below the Newton growth of 1.25).
    const double h = c.attempt_size();
    ok             = ok && judge_tolerance(c, 0.8);
    c.accept(3);
    ok = ok && close(c.time(), h) && close(c.attempt(), h * 0.9 / 0.8);
    // Later in the run the same error per step weighs less: (h + dt) / dt against 1.
    const double next = c.attempt_size();
    ok = ok && close(c.error_excess(0., 1e-4, next).factor, 1e-4 * (h + next) / (next * 1e-3));
    std::cout << "tolerance: retake and bound by 0.9 tol dt / (e (t + dt)): " << ok << std::endl;

    s.displacement_tolerance = 0.01;
    StepControl  both(s);
    const double dt2 = both.attempt();
    // sqrt(0.04 / 0.01) = 2 against 2e-4 / 1e-3 = 0.2: the displacement rule decides.
    ok = close(both.error_excess(0.04, 2e-4, dt2).factor, 2.) &&
         !both.error_excess(0.04, 2e-4, dt2).per_unit_time;
    ok = ok && close(both.error_excess(1e-4, 2e-3, dt2).factor, 2.) &&
         both.error_excess(1e-4, 2e-3, dt2).per_unit_time; // 0.1 against 2: the tolerance
    std::cout << "with both rules the stricter decides: " << ok << std::endl;

    GelMPM::TimeStepping capped   = s;
    capped.displacement_tolerance = 0.;
    capped.caps                   = {{0.5, 0.2}};
    StepControl by_hand(capped);
    std::cout << "no tolerance where a cap sets the steps: "
              << (by_hand.error_excess(0., 1., by_hand.attempt()).factor == 0.) << std::endl;

    // Noise: an excess per unit time that shrinks by less than the square root of the step
    // ratio is accepted, and the next step starts again from the first retaken attempt.
    s.displacement_tolerance = 0.;
    StepControl noise(s);
    noise.attempt(); // 0.1
    ok = !judge_tolerance(noise, 4.) && close(noise.attempt(), 0.0225);
    // 0.0225 / 0.1 = 0.225: an error would shrink to 4 sqrt(0.225) = 1.9 at least; 2.5 is noise.
    ok = ok && judge_tolerance(noise, 2.5) && noise.error_uncontrolled();
    noise.accept(3);
    ok = ok && close(noise.time(), 0.0225) && close(noise.attempt(), 0.1);
    std::cout << "integration noise is accepted and does not shrink the steps: " << ok << std::endl;

    // After cuts by more than StepControl::estimate_reach, the next step starts at most that
    // far above the accepted one: its error is then estimated, not taken unchecked.
    s.minimum_step = 1e-6;
    StepControl far(s);
    far.attempt();                                                         // 0.1
    ok = !judge_tolerance(far, 1000.) && close(far.attempt(), 0.02);       // clamped to 0.2
    ok = ok && !judge_tolerance(far, 200.) && close(far.attempt(), 0.004); // shrank: an error
    ok = ok && !judge_tolerance(far, 40.) && close(far.attempt(), 0.0008);
    ok = ok && judge_tolerance(far, 39.) && far.error_uncontrolled(); // 40 sqrt(0.2) = 17.9
    far.accept(3);
    ok = ok && close(far.attempt(), 0.008) &&
         StepControl::estimate_applies(far.attempt_size(), 0.0008) &&
         !StepControl::estimate_applies(0.1, 0.0008);
    std::cout << "after noise the next step stays within reach of the error estimate: " << ok
              << std::endl;

    // Noise accepted at t = 0.1, dt = 0.025 (a relative step 0.025 / 0.125 = 0.2): from
    // t = 0.125 a retake goes no shorter than 0.2 t / (1 - 0.2) = 0.03125, and an attempt of
    // that size is accepted as noise.
    StepControl fl(s);
    fl.attempt(); // 0.1
    ok = judge_tolerance(fl, 0.5);
    fl.accept(3);
    ok =
      ok && close(fl.attempt(), 0.125) && !judge_tolerance(fl, 10.) && close(fl.attempt(), 0.025);
    ok = ok && judge_tolerance(fl, 9.) && fl.error_uncontrolled(); // 10 sqrt(0.2) = 4.5
    fl.accept(3);
    ok = ok && close(fl.time(), 0.125) && close(fl.attempt(), 0.125) &&
         !judge_tolerance(fl, 100.) && close(fl.attempt(), 0.03125);
    ok = ok && judge_tolerance(fl, 100.) && fl.error_uncontrolled();
    fl.accept(3);
    // A retake that meets the tolerance keeps the floor (t / 4 here): the next attempt, 1.25
    // times that retake, lies below the floor at its own start and is accepted as noise.
    fl.attempt();
    ok = ok && !judge_tolerance(fl, 100.) && close(fl.attempt(), fl.time() / 4.);
    ok = ok && judge_tolerance(fl, 0.5) && !fl.error_uncontrolled();
    fl.accept(3);
    fl.attempt();
    ok = ok && judge_tolerance(fl, 100.) && fl.error_uncontrolled();
    fl.accept(3);
    // Once a first attempt meets the tolerance the floor is gone: a retake is 0.2 of it again.
    fl.attempt();
    ok = ok && judge_tolerance(fl, 0.5) && !fl.error_uncontrolled();
    fl.accept(3);
    const double after = fl.attempt();
    ok                 = ok && !judge_tolerance(fl, 4.5) && close(fl.attempt(), after * 0.2);
    std::cout << "noise sets a floor on the relative step until the estimate resolves the error: "
              << ok << std::endl;
  }
  {
    // 7. Stop time 0.3, tolerance 1e-3: steps 0.1, 0.1, 0.1 (landing on 0.3), then 0.1 each.
    auto s               = settings();
    s.caps               = {};
    s.growth_factor      = 1.;
    s.end_at_equilibrium = 1e-3;
    StepControl c(s);
    const auto  step = [&c](const double rate) {
      c.attempt();
      c.accept(8);
      return c.judge_equilibrium(rate);
    };
    // Before the last stop time calm steps do not count, nor does the step that lands on it.
    bool ok = !step(1e-4) && !step(1e-4) && !step(1e-4) && close(c.time(), 0.3);
    // One calm step, a faster one, one calm step: not yet.
    ok = ok && !step(1e-4) && !step(2e-3) && !step(1e-4) && !c.finished();
    // The second calm step in a row ends the run before the end time.
    ok = ok && step(5e-4) && c.at_equilibrium() && c.finished() && close(c.time(), 0.7) &&
         close(c.last_rate(), 5e-4);
    // Off: a rate of zero never ends the run.
    s.end_at_equilibrium = 0.;
    StepControl off(s);
    for (unsigned int i = 0; i < 8; ++i)
      {
        off.attempt();
        off.accept(8);
        ok = ok && !off.judge_equilibrium(0.);
      }
    ok = ok && !off.finished();
    std::cout << "equilibrium: two calm steps in a row after the last stop time end the run: " << ok
              << std::endl;
  }
  return 0;
}

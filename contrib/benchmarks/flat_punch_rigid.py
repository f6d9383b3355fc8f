#!/usr/bin/python3
"""The flat punch of paper §4.2 (prm/flat_punch.prm) against the same indentation by a rigid flat
punch (prm/flat_punch_rigid.prm): the force histories of the two (doc/flat_punch.md, "A rigid
punch").

  /usr/bin/python3 contrib/benchmarks/flat_punch_rigid.py [--gelmpm build/gelmpm]
      [--output output/flat_punch_rigid] [--method nitsche|penalty] [--plot FILE.png]
      [--set "Section/Entry=value" ...] [--reuse]

Prescribed: prm/flat_punch.prm as it is (the piece 'punch', the top for initial x <= 0.5, a roller
with u_y = ubar, u_x free, impermeable). Rigid: prm/flat_punch_rigid.prm, the same piece with a
free displacement, pressed by the obstacle 'indenter' (half-width H/4: a flat face of 0.2375H and
an edge rounded with 0.0125H, centred on the plane of symmetry x = 0.25 at the top, y = 1.25,
outward normal -y), moved by the same ramp; Nitsche's method with the prescribed piece's penalty
1000 and 'Active set factor' 0.01 (--method penalty: the penalty method instead). The punch cannot
pull: the two describe the same problem where the face is in full contact and the punched
points stay under it. Compared:
the force of the punch on the gel, -punch_force_y (prescribed) against indenter_force_y (rigid),
at the prescribed run's step times (the rigid run's force interpolated linearly in t during the
ramp, in log t after it). Extra --set overrides go to both runs (e.g. "Background grid/Cells=30,
30" for the coarse discretisation (iv)). Prints a Markdown table and the largest relative
difference; writes <output>/comparison.csv. Also the number of surface points in contact with the
rigid punch: more than the punched piece has once points of the free top come under its edge.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
RAMP = 3.125e-6

def run(gelmpm, scene, directory, overrides, reuse=False):
    if reuse and os.path.exists(os.path.join(directory, "statistics.csv")):
        with open(os.path.join(directory, "statistics.csv")) as f:
            return list(csv.DictReader(f))
    args = [gelmpm, os.path.join(ROOT, "prm", scene),
            "--set", "Output/Directory=" + directory, "--set", "Output/Write particles=false"]
    for o in overrides:
        args += ["--set", o]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(directory, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows


def interpolate(times, values, t):
    for k in range(1, len(times)):
        if times[k] >= t:
            t0, t1 = times[k - 1], times[k]
            if t0 >= RAMP and t0 > 0.:
                s = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0))
            else:
                s = (t - t0) / (t1 - t0)
            return values[k - 1] + s * (values[k] - values[k - 1])
    return values[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--gelmpm", default=os.path.join(ROOT, "build", "gelmpm"))
    parser.add_argument("--output", default=os.path.join(ROOT, "output", "flat_punch_rigid"))
    parser.add_argument("--method", default="nitsche", choices=["nitsche", "penalty"])
    parser.add_argument("--plot", help="also draw both histories into this PNG (matplotlib)")
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    parser.add_argument("--reuse", action="store_true",
                        help="take the runs already in --output instead of running them")
    a = parser.parse_args()
    os.makedirs(a.output, exist_ok=True)
    prescribed = run(a.gelmpm, "flat_punch.prm", os.path.join(a.output, "prescribed"), a.overrides,
                     a.reuse)
    rigid = run(a.gelmpm, "flat_punch_rigid.prm", os.path.join(a.output, "rigid"),
                a.overrides + ["Contact/Method=" + a.method], a.reuse)
    t_rigid = [float(r["t_over_tau_d"]) for r in rigid]
    f_rigid = [float(r["indenter_force_y"]) for r in rigid]
    # The surface points in contact with the punch: where more than the punched piece's, points
    # of the free top came under the rounded edge, which the prescribed roller never presses.
    n_contact = [float(r["contact_points"] or 0) for r in rigid]
    largest = 0.
    at = 0.
    lines = []
    for r in prescribed[1:]:
        t = float(r["t_over_tau_d"])
        if t > t_rigid[-1] * (1. + 1e-12):
            break
        f = -float(r["punch_force_y"])
        g = interpolate(t_rigid, f_rigid, t)
        # The rigid run's count at its last step not after t.
        points = n_contact[max(k for k in range(len(t_rigid)) if t_rigid[k] <= t * (1. + 1e-12))]
        if abs(g - f) / abs(f) > largest:
            largest, at = abs(g - f) / abs(f), t
        lines.append((t, f, g, (g - f) / f, points))
    with open(os.path.join(a.output, "comparison.csv"), "w") as out:
        out.write("t_over_tau_d,prescribed,rigid,relative_difference,rigid_contact_points\n")
        for line in lines:
            out.write("%.6g,%.8g,%.8g,%.3e,%d\n" % line)
    print("| t/τ_d | prescribed −punch_force_y | rigid indenter_force_y | difference | "
          "points in contact (rigid) |")
    print("|---|---|---|---|---|")
    shown = [line for line in lines if line[0] in (RAMP / 2, RAMP)] or lines[:1]
    for target in (RAMP / 2, RAMP, 1e-3, 0.1, 1., 10., 100., 1e9):
        best = min(lines, key=lambda l: abs(math.log(l[0]) - math.log(min(target, lines[-1][0]))))
        if best not in shown:
            shown.append(best)
    for t, f, g, d, points in sorted(shown):
        print("| %.4g | %.5f | %.5f | %+.3f%% | %d |" % (t, f, g, 100. * d, points))
    print("largest relative difference over %d steps: %.3f%% at t = %.4g tau_d"
          % (len(lines), 100. * largest, at))
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True,
                                          gridspec_kw={"height_ratios": [2, 1]})
        t = [line[0] for line in lines]
        top.semilogx(t, [line[1] for line in lines], "k-", label="prescribed u_y (roller)")
        top.semilogx(t_rigid[1:], f_rigid[1:], "C1--", label="rigid flat punch (Nitsche)")
        top.set_ylabel("punch force F / (G H)")
        top.legend()
        bottom.semilogx(t, [100. * line[3] for line in lines], "C0-")
        bottom.axhline(1., color="0.6", lw=0.8)
        bottom.axhline(-1., color="0.6", lw=0.8)
        bottom.set_ylabel("rigid - prescribed (%)")
        count = bottom.twinx()
        count.semilogx(t, [line[4] for line in lines], "C3:",
                       label="surface points in contact (rigid)")
        count.set_ylabel("points in contact", color="C3")
        count.legend(loc="upper left", fontsize=7)
        bottom.set_xlabel("t / tau_d")
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
    print("rigid run: %d steps; the largest contact radius %.4f H"
          % (len(rigid) - 1, max(float(r["indenter_contact_radius"]) for r in rigid)))
    return 0


if __name__ == "__main__":
    sys.exit(main())

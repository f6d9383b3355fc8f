#!/usr/bin/python3
"""The flat punch of paper §4.2 (prm/flat_punch.prm) with a rigid flat punch ('Contact/Obstacles',
Shape = flat punch) in place of the prescribed displacement of the punched piece: the force
histories of the two (doc/flat_punch.md, "A rigid punch").

  /usr/bin/python3 contrib/benchmarks/flat_punch_rigid.py [--gelmpm build/gelmpm]
      [--output output/flat_punch_rigid] [--method nitsche] [--set "Section/Entry=value" ...]

Prescribed: the scene as it is (the piece 'punch', the top for initial x <= 0.5, has u_y = ubar,
impermeable). Rigid: the same piece with a free displacement, pressed by the obstacle 'indenter'
(a flat face of half-width H/4 centred on the plane of symmetry x = 0.25 at the top, y = 1.25,
outward normal -y), moved by the same ramp; the contact by --method (Nitsche, the prescribed
piece's penalty 1000, or penalty). The punch cannot pull: the two describe the same problem where
the face is in full contact, which holds through the loading and the holding here. Compared:
the force of the punch on the gel, -punch_force_y (prescribed) against indenter_force_y (rigid),
at the prescribed run's step times (the rigid run's force interpolated linearly in t during the
ramp, in log t after it). Extra --set overrides go to both runs (e.g. "Background grid/Cells=30,
30" for the coarse discretisation (iv)). Prints a Markdown table and the largest relative
difference; writes <output>/comparison.csv.
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

RIGID = [
    "Boundary conditions/punch/Displacement=free",
    "Contact/Obstacles=indenter",
    "Contact/indenter/Shape=flat punch",
    "Contact/indenter/Center=0.25, 1.25",
    "Contact/indenter/Radius=0.25",
    "Contact/indenter/Normal=0, -1",
    "Contact/indenter/Motion/Function expression=0; -0.09 * min(t / 3.125e-6, 1)",
]


def run(gelmpm, directory, overrides):
    args = [gelmpm, os.path.join(ROOT, "prm", "flat_punch.prm"),
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
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    a = parser.parse_args()
    os.makedirs(a.output, exist_ok=True)
    prescribed = run(a.gelmpm, os.path.join(a.output, "prescribed"), a.overrides)
    rigid = run(a.gelmpm, os.path.join(a.output, "rigid"),
                a.overrides + RIGID + ["Contact/Method=" + a.method])
    t_rigid = [float(r["t_over_tau_d"]) for r in rigid]
    f_rigid = [float(r["indenter_force_y"]) for r in rigid]
    largest = 0.
    lines = []
    for r in prescribed[1:]:
        t = float(r["t_over_tau_d"])
        f = -float(r["punch_force_y"])
        g = interpolate(t_rigid, f_rigid, t)
        largest = max(largest, abs(g - f) / abs(f))
        lines.append((t, f, g, (g - f) / f))
    with open(os.path.join(a.output, "comparison.csv"), "w") as out:
        out.write("t_over_tau_d,prescribed,rigid,relative_difference\n")
        for line in lines:
            out.write("%.6g,%.8g,%.8g,%.3e\n" % line)
    print("| t/τ_d | prescribed −punch_force_y | rigid indenter_force_y | difference |")
    print("|---|---|---|---|")
    shown = [line for line in lines if line[0] in (RAMP / 2, RAMP)] or lines[:1]
    for target in (RAMP / 2, RAMP, 1e-3, 0.1, 1., 10., 100., 1e9):
        best = min(lines, key=lambda l: abs(math.log(l[0]) - math.log(min(target, lines[-1][0]))))
        if best not in shown:
            shown.append(best)
    for t, f, g, d in sorted(shown):
        print("| %.4g | %.5f | %.5f | %+.3f%% |" % (t, f, g, 100. * d))
    print("largest relative difference over %d steps: %.3f%%" % (len(lines), 100. * largest))
    print("rigid run: %d steps; the largest contact radius %.4f H"
          % (len(rigid) - 1, max(float(r["indenter_contact_radius"]) for r in rigid)))
    return 0


if __name__ == "__main__":
    sys.exit(main())

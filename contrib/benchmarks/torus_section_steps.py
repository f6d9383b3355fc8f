#!/usr/bin/python3
"""How many steps 'Time stepping/Tolerance' takes on a swelling torus, and what they buy: the
axisymmetric counterpart of prm/torus_swelling_3d.prm (its tube's meridian section, a disk of
radius 0.4 about r = 1 on the plane z = 0, on the same cells h = 0.1 with 3 x 3 points per cell,
Characteristic length 0.4) run with the bath and step settings of doc/own_scenes.md, section 12,
"The 3D torus", each against a reference of the same bath with small capped steps.

    /usr/bin/python3 contrib/benchmarks/torus_section_steps.py [--gelmpm build/gelmpm]
        [--output output/torus_section] [--tabulate-only]

Prints one Markdown row per run: steps (attempts), the median dt/t of the steps that begin
within 10-100 tau_d, and the
largest error of J_mean and of delta_h_over_h0 (the mean height of the surface's points above
z = 0) over t >= 1 tau_d, relative to the reference's change from t = 0 to the end (the time
discretisation's error: every run has the same grid and points). A run with
'Characteristic length = 1' is the same problem in other time units (t / 0.16). About 2 minutes
on one core; each run's directory is kept under the output directory, and --tabulate-only
prints the table from them again without running.
"""
import argparse
import bisect
import csv
import os
import subprocess
import sys

SCENE = """set Dimension = 2
subsection Output
  set Directory       = out
  set Write particles = false
  set Interval steps  = 0
end
subsection Background grid
  set Coordinate system = axisymmetric
  set Lower corner      = 0, -0.3
  set Upper corner      = 3.2, 1.1
  set Cells             = 32, 14
end
subsection Geometry
  set Level set = max(sqrt((x - 1)^2 + y^2) - 0.4, -y)
end
subsection Material points
  set Points per cell = 3
end
subsection Boundary conditions
  set Pieces = equator, surface
  subsection equator
    set Selector     = y < 1e-3 && ny < -0.99
    set Displacement = normal
  end
  subsection surface
    set Selector           = y > 1e-3 || ny > -0.99
    set Chemical potential = prescribed
    subsection Chemical potential value
      set Function constants  = mu0=-0.14597453
      set Function expression = mu0 * (1 - min(t / 4, 1))
    end
  end
end
subsection Time stepping
  set Characteristic length = 0.4
  set Initial step          = 1e-4
  set End time              = 1000
  set Tolerance             = 1e-2
  set Growth factor         = 2
end
subsection Observables
  set Volume ratio range  = true
  set Thickness pieces    = surface, equator
  set Thickness direction = 1
end
"""

BATH = "Boundary conditions/surface/Chemical potential value/Function expression"
KINKED = "mu0 * (1 - min(t / 4, 1))"
C1 = "mu0 * (t < 4 ? (1 - t / 4)^2 * (1 + t / 2) : 0)"
REFERENCE_CAPS = "4: 0.001, 10: 0.005, 100: 0.05, 1000: 0.5"


def with_length_1(bath):
    """The same bath, end time and first step in tau_d of L = 1 (0.16 of those of L = 0.4)."""
    return {BATH: bath.replace("t / 4", "t / 0.64").replace("t / 2", "t / 0.32")
            .replace("t < 4", "t < 0.64"),
            "Time stepping/Characteristic length": "1", "Time stepping/End time": "160",
            "Time stepping/Initial step": "1.6e-5"}


# name, reference, time scale to the reference's tau_d, the entries changed
RUNS = [
    ("ref_kinked", None, 1, {BATH: KINKED, "Time stepping/Tolerance": "0",
                             "Time stepping/Step caps": REFERENCE_CAPS}),
    ("ref_c1", None, 1, {BATH: C1, "Time stepping/Tolerance": "0",
                         "Time stepping/Step caps": REFERENCE_CAPS}),
    ("kinked 1e-2", "ref_kinked", 1, {BATH: KINKED}),
    ("kinked 1e-2, Stop at times = 4", "ref_kinked", 1,
     {BATH: KINKED, "Time stepping/Stop at times": "4"}),
    ("C1 1e-2", "ref_c1", 1, {BATH: C1}),
    ("kinked 3e-2", "ref_kinked", 1, {BATH: KINKED, "Time stepping/Tolerance": "3e-2"}),
    ("C1 3e-2", "ref_c1", 1, {BATH: C1, "Time stepping/Tolerance": "3e-2"}),
    ("kinked 1e-2, L = 1", "ref_kinked", 1 / 0.16, with_length_1(KINKED)),
    ("C1 1e-2, L = 1", "ref_c1", 1 / 0.16, with_length_1(C1)),
]
# Steps capped at a share of each interval's end from 10 tau_d on (no tolerance; before, as the
# reference's): dt/t from the share up to twice it (2.5 times over 40-100 tau_d).
for share in (2.5, 5, 10):
    caps = "4: 0.001, 10: 0.005, 20: %g, 40: %g, 100: %g, 1000: %g" % tuple(
        share / 100 * end for end in (20, 40, 100, 1000))
    RUNS.append(("kinked, caps %g %% of 20, 40, 100, 1000" % share, "ref_kinked", 1,
                 {BATH: KINKED, "Time stepping/Tolerance": "0", "Time stepping/Step caps": caps}))


def rows_of(directory):
    with open(os.path.join(directory, "statistics.csv")) as f:
        return [r for r in csv.DictReader(f) if r.get("n_active_cells")]


def directory_of(output, name):
    return os.path.join(output, name.replace(" ", "_").replace(",", "").replace("=", "")
                        .replace("%", "pc").replace("/", "_"))


def run(gelmpm, output, name, entries):
    directory = directory_of(output, name)
    scene = os.path.join(output, "torus_section.prm")
    command = [gelmpm, scene, "--set", "Output/Directory=" + directory]
    for key, value in entries.items():
        command += ["--set", "%s=%s" % (key, value)]
    environment = dict(os.environ, DEAL_II_NUM_THREADS="1")
    with open(directory + ".log", "w") as log:
        subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, env=environment, check=True)
    return rows_of(directory)


def worst_error(rows, reference, column, scale):
    """Largest |value - reference| over t >= 1 tau_d, over the reference's change."""
    times = [float(r["t_over_tau_d"]) for r in reference]
    values = [float(r[column]) for r in reference]
    change = abs(values[-1] - values[0])
    worst = 0.
    for r in rows:
        t = float(r["t_over_tau_d"]) * scale
        if t < 1 or t > times[-1]:
            continue
        i = min(max(bisect.bisect_left(times, t), 1), len(times) - 1)
        a = (t - times[i - 1]) / (times[i] - times[i - 1])
        worst = max(worst, abs(float(r[column]) - ((1 - a) * values[i - 1] + a * values[i])))
    return 100 * worst / change


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gelmpm", default="build/gelmpm")
    parser.add_argument("--output", default="output/torus_section")
    parser.add_argument("--tabulate-only", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "torus_section.prm"), "w") as f:
        f.write(SCENE)
    results = {}
    print("| run | steps (attempts) | median dt/t, 10-100 tau_d | J_mean error | delta_h_over_h0 error |")
    print("|---|---|---|---|---|")
    for name, reference, scale, entries in RUNS:
        rows = (rows_of(directory_of(args.output, name)) if args.tabulate_only else
                run(args.gelmpm, args.output, name, entries))
        results[name] = rows
        attempts = sum(int(r["attempts"]) for r in rows)
        rates = [float(r["dt"]) / float(r["t_over_tau_d"]) for r in rows[1:]
                 if 10 * (1 - 1e-9) <= (float(r["t_over_tau_d"]) - float(r["dt"])) * scale < 100]
        rates.sort()
        errors = ("%.2f %%" % worst_error(rows, results[reference], c, scale)
                  if reference else "(reference)" for c in ("J_mean", "delta_h_over_h0"))
        print("| %s | %d (%d) | %.2g %% | %s | %s |" % (
            name, len(rows) - 1, attempts, 100 * rates[len(rates) // 2], *errors))
        sys.stdout.flush()


if __name__ == "__main__":
    main()

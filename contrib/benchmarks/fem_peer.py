#!/usr/bin/python3
"""Paper §4.1 (constrained swelling to t = 1713 tau_d): the body-fitted finite-element peer
(gelmpm-fem-swelling) against the MPM (gelmpm prm/constrained_swelling.prm) at several
resolutions: wall time and error against the finite-difference reference (doc/fem_peer.md).

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  /usr/bin/python3 contrib/benchmarks/fem_peer.py [--build build] [--output output/fem_peer]

Per run: the whole process is timed (wall clock and CPU time user + system, median of --repeats runs for the finite-element
model and of --mpm-repeats for the MPM); steps and Newton iterations are read from its
statistics.csv; the error is that of contrib/plotting/constrained_swelling.py (agreement_data):
  max |Delta h - Delta h_ref| / Delta h_eq over the steps with t >= 0.01 tau_d (and, second
  column, over 0.01 <= t <= 100 tau_d, the stages capped by eq. (64)),
the reference (gelmpm-swelling-1d --samples 4000) interpolated at the step times (log-log).
Both methods use the initial step 8.75e-5, the caps of eq. (64) and the stop times of
prm/constrained_swelling.prm. The MPM writes no particle files here.

The 1-minute load average (/proc/loadavg) after each run is recorded (other jobs may share the
machine). Writes <output>/fem_peer.csv and <output>/fem_peer.md (the table of doc/fem_peer.md).
"""

import argparse
import os
import resource
import statistics as stats
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
from constrained_swelling import agreement_data, read_csv  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
STOPS = "0.001197,0.008589,0.1281,0.4531,1.953,4.453,16.06,1713"

# (label, directory name, options of gelmpm-fem-swelling)
FEM_RUNS = [
    ("1 x 8", "1x8", ["--set", "FE peer/Cells=1, 8"]),
    ("1 x 16", "1x16", ["--set", "FE peer/Cells=1, 16"]),
    ("1 x 32", "1x32", ["--set", "FE peer/Cells=1, 32"]),
    ("1 x 16, graded (g = 2)", "1x16g2", ["--set", "FE peer/Cells=1, 16", "--set", "FE peer/Grading=2"]),
]
# (label, --set overrides); the body is 0.2 x 1 h_0, the layer swells to 2.73 h_0.
MPM_RUNS = [
    ("20 x 120 over 0.5 x 3, 3 x 3 points",
     ["Background grid/Upper corner=0.5, 3", "Background grid/Cells=20, 120",
      "Material points/Points per cell=3"]),
    ("20 x 160 over 0.5 x 4, 6 x 6 points (paper)", []),
]


def load():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def timed(command, log_file):
    """Wall and CPU (user + system) seconds of the process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    with open(log_file, "w") as log:
        status = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT, cwd=ROOT)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if status != 0:
        sys.exit(f"fem_peer.py: {' '.join(command)} failed (status {status}); see {log_file}")
    return wall, cpu


def summarise(directory, reference, n_dofs_columns):
    data = agreement_data(directory, reference, profiles=False, note=lambda *a: None)
    table = read_csv(os.path.join(directory, "statistics.csv"))
    late = data["t_mpm"] >= 0.01
    capped = late & (data["t_mpm"] <= 100.0)
    n_dofs = sum(table[c][-1] for c in n_dofs_columns)
    return {
        "error": float(np.max(np.abs(data["error"][late]))),
        "error_capped": float(np.max(np.abs(data["error"][capped]))),
        "end_error": float(data["end_error"]),
        "steps": int(np.sum(table["t_over_tau_d"] > 0)),
        "newton": int(np.nansum(table["newton_iterations"])),
        "n_dofs": int(n_dofs),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--output", default="output/fem_peer")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--mpm-repeats", type=int, default=1)
    parser.add_argument("--no-mpm", action="store_true")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.output)
    os.makedirs(out, exist_ok=True)

    reference = os.path.join(out, "reference")
    if not os.path.isfile(os.path.join(reference, "reference_thickness.csv")):
        timed([os.path.join(build, "gelmpm-swelling-1d"), "--samples", "4000", "--output", reference],
              os.path.join(out, "reference.log"))

    rows = []
    for label, name, options in FEM_RUNS:
        directory = os.path.join(out, "fem_" + name)
        command = [os.path.join(build, "gelmpm-fem-swelling"),
                   os.path.join(ROOT, "prm", "constrained_swelling.prm")] + options + [
            "--set", "Time stepping/Stop at times=" + STOPS, "--quiet",
            "--set", "FE peer/Output directory=" + directory]
        times = [timed(command, directory + f".log{k}") for k in range(args.repeats)]
        walls, cpus = [w for w, _ in times], [c for _, c in times]
        row = {"method": "FE Q2-Q1", "resolution": label, "load": load(),
               "wall": stats.median(walls),
               "wall_min": min(walls), "wall_max": max(walls), "cpu": stats.median(cpus)}
        row.update(summarise(directory, reference, ["n_dofs"]))
        rows.append(row)
        print(row, flush=True)

    if not args.no_mpm:
        for label, overrides in MPM_RUNS:
            directory = os.path.join(out, "mpm_" + str(len(rows)))
            command = [os.path.join(build, "gelmpm"), "--set", "Output/Directory=" + directory,
                       "--set", "Output/Write particles=false"]
            for o in overrides:
                command += ["--set", o]
            command.append("prm/constrained_swelling.prm")
            times = [timed(command, directory + f".log{k}") for k in range(args.mpm_repeats)]
            walls, cpus = [w for w, _ in times], [c for _, c in times]
            row = {"method": "MPM Q2-Q2SD", "resolution": label, "load": load(),
                   "wall": stats.median(walls),
                   "wall_min": min(walls), "wall_max": max(walls), "cpu": stats.median(cpus)}
            row.update(summarise(directory, reference, ["n_dofs_u", "n_dofs_mu"]))
            rows.append(row)
            print(row, flush=True)

    keys = ["method", "resolution", "n_dofs", "steps", "newton", "wall", "wall_min", "wall_max",
            "cpu", "error", "error_capped", "end_error", "load"]
    with open(os.path.join(out, "fem_peer.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(f'"{r[k]}"' if isinstance(r[k], str) else f"{r[k]:.6g}" for k in keys)
                    + "\n")
    with open(os.path.join(out, "fem_peer.md"), "w") as f:
        f.write("| method | resolution | DoFs | steps | Newton iterations | wall time (s) | "
                "CPU time (s) | load | max error, t >= 0.01 tau_d | max error, 0.01 <= t <= 100 tau_d | "
                "error at 1713 tau_d |\n")
        f.write("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r['method']} | {r['resolution']} | {r['n_dofs']} | {r['steps']} | "
                    f"{r['newton']} | {r['wall']:.2f} | {r['cpu']:.2f} | {r['load']:.1f} | {100 * r['error']:.3f} % | "
                    f"{100 * r['error_capped']:.3f} % | "
                    f"{100 * r['end_error']:+.4f} % |\n")
    print("written:", os.path.join(out, "fem_peer.md"))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Speed against accuracy for the flat punch (paper §4.2): what each discretisation costs and how
smooth its chemical potential is in the undrained limit.

    /usr/bin/python3 contrib/benchmarks/flat_punch_sweep.py [--output DIR] [--end-time T]

Runs prm/flat_punch.prm for u-mu pairs, grid spacings and points per cell (listed in CONFIGURATIONS)
to --end-time (default 0.1 tau_d; --quick: four configurations to the end of the ramp), with 'Observables/Chemical potential oscillation' on and no
particle output, and records per run: wall time (whole process; median, min and max of --repeats
runs, default 3), peak memory (largest resident set of the repeats), steps, Newton iterations, unknowns,
and mu_oscillation at the end of the ramp (t_inc = 3.125e-6 tau_d, the accuracy measure of
doc/flat_punch.md: spurious pressure modes make it of order one) and at the end time. Writes
<DIR>/flat_punch_sweep.csv and <DIR>/flat_punch_sweep.png (oscillation at t_inc against wall time,
Pareto front marked). Prints an estimate before it starts (about 5 minutes on a 2-core machine with
3 repeats). The drained-limit error of these discretisations is measured against the body-fitted
finite-element reference in contrib/benchmarks/fem_peer_flat_punch.py (doc/fem_peer.md).
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
from gelmpm_files import read_csv  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SAME = "Discretisation/Chemical potential grid=same"
# (label, overrides, estimated seconds to 0.1 tau_d)
CONFIGURATIONS = [
    ("Q2-Q2 h=0.05", ["Background grid/Cells=30, 30", SAME], 6),
    ("Q3-Q2 h=0.05", ["Background grid/Cells=30, 30", SAME, "Discretisation/Displacement degree=3"],
     12),
    ("Q2-Q2SD h=0.05", ["Background grid/Cells=30, 30"], 4),
    ("Q2-Q2SD h=0.025 (paper)", [], 15),
    ("Q2-Q2SD h=0.025, 3x3 points", ["Material points/Points per cell=3"], 8),
    ("Q2-Q2SD h=0.025, 8x8 points", ["Material points/Points per cell=8"], 35),
    ("Q2-Q2SD h=0.05, 8x8 points", ["Background grid/Cells=30, 30",
                                     "Material points/Points per cell=8"], 10),
    ("Q2-Q2 h=0.025", ["Background grid/Cells=60, 60", SAME], 25),
    ("Q3-Q2 h=0.025", ["Background grid/Cells=60, 60", SAME,
                       "Discretisation/Displacement degree=3"], 60),
]


def value_at(statistics, column, t):
    """The column's value in the row whose time is closest to t."""
    times = statistics["t_over_tau_d"]
    row = min(range(len(times)), key=lambda i: abs(times[i] - t))
    return statistics[column][row]


def pareto(points):
    """Indices of the points not dominated in (time, error), both smaller-is-better."""
    front = []
    for i, (t_i, e_i) in enumerate(points):
        if not any((t_j <= t_i and e_j <= e_i) and (t_j, e_j) != (t_i, e_i)
                   for t_j, e_j in points):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="output/flat_punch_sweep")
    parser.add_argument("--end-time", type=float, default=0.1)
    parser.add_argument("--build", default=os.environ.get("GELMPM_BUILD_DIR", "build"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--quick", action="store_true",
                        help="the first four configurations, to the end of the ramp only (< 1 min)")
    args = parser.parse_args()
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    configurations = CONFIGURATIONS
    if args.quick:
        # The measure is taken at the end of the ramp: a run that stops there costs ~1/10.
        configurations = CONFIGURATIONS[:4]
        args.end_time = min(args.end_time, 3.125e-6)
    gelmpm = os.path.join(args.build, "gelmpm")
    scene = os.path.join(top, "prm", "flat_punch.prm")
    os.makedirs(args.output, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    estimate = args.repeats * sum(c[2] for c in configurations) * (0.1 if args.quick else 1.0)
    print(f"{len(configurations)} configurations x {args.repeats} runs to t = {args.end_time} tau_d,"
          f" about {estimate / 60:.1f} min")

    rows = []
    for label, overrides, _ in configurations:
        directory = os.path.join(args.output, label.replace(" ", "_").replace(",", "")
                                 .replace("(", "").replace(")", ""))
        command = [gelmpm, "--set", f"Output/Directory={directory}",
                   "--set", "Output/Write particles=false",
                   "--set", f"Time stepping/End time={args.end_time}",
                   "--set", "Observables/Chemical potential oscillation=true"]
        for entry in overrides:
            command += ["--set", entry]
        walls, peak_kb, load = [], 0, os.getloadavg()[0]
        for _ in range(args.repeats):
            start = time.time()
            with open(directory + ".log", "w") as log:
                process = subprocess.Popen(command + [scene], stdout=log,
                                           stderr=subprocess.STDOUT, env=env)
                # wait4: this process's own resource usage (peak resident set in kB).
                _, wait_status, usage = os.wait4(process.pid, 0)
                process.returncode = os.waitstatus_to_exitcode(wait_status)
            walls.append(time.time() - start)
            peak_kb = max(peak_kb, usage.ru_maxrss)
            status = process.returncode
            if status != 0:
                break
        seconds = statistics.median(walls)
        if status != 0:
            print(f"  {label}: exit status {status} (see {directory}.log); left out")
            continue
        s = read_csv(os.path.join(directory, "statistics.csv"))
        row = {"configuration": label, "wall_seconds": seconds, "wall_min": min(walls),
               "wall_max": max(walls), "repeats": len(walls), "peak_rss_mb": peak_kb / 1024.,
               "load": load,
               "steps": int(s["step"][-1]), "newton_iterations": int(sum(s["newton_iterations"][1:])),
               "n_dofs_u": int(s["n_dofs_u"][-1]), "n_dofs_mu": int(s["n_dofs_mu"][-1]),
               "oscillation_t_inc": value_at(s, "mu_oscillation", 3.125e-6),
               "oscillation_end": s["mu_oscillation"][-1]}
        rows.append(row)
        print(f"  {label:32s} {seconds:6.1f} s ({min(walls):.1f}-{max(walls):.1f}, load {load:.1f},"
              f" {peak_kb / 1024.:.0f} MB)  oscillation at t_inc "
              f"{row['oscillation_t_inc']:.3f}, at {args.end_time}: {row['oscillation_end']:.3f}")

    # The configuration names hold commas: the csv module quotes them.
    with open(os.path.join(args.output, "flat_punch_sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)

    points = [(r["wall_seconds"], r["oscillation_t_inc"]) for r in rows]
    front = pareto(points)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for i, r in enumerate(rows):
        ax.scatter(r["wall_seconds"], r["oscillation_t_inc"],
                   marker="*" if "paper" in r["configuration"] else "o", s=80,
                   color="C3" if i in front else "C0")
        ax.annotate(r["configuration"], (r["wall_seconds"], r["oscillation_t_inc"]), fontsize=7,
                    xytext=(4, 3), textcoords="offset points")
    ax.plot([points[i][0] for i in front], [points[i][1] for i in front], "C3--", lw=1,
            label="Pareto front")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"wall time to t = {args.end_time} τ_d (s)")
    ax.set_ylabel("μ oscillation at the end of the ramp")
    ax.set_title("flat punch (§4.2): smoothness of μ against cost")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, "flat_punch_sweep.png"), dpi=120)
    print("results:", os.path.join(args.output, "flat_punch_sweep.csv"), "and .png")


if __name__ == "__main__":
    main()

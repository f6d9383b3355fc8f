#!/usr/bin/python3
"""Speed against accuracy for the flat punch (paper §4.2): what each discretisation costs and how
smooth its chemical potential is in the undrained limit.

    /usr/bin/python3 contrib/benchmarks/flat_punch_sweep.py [--output DIR] [--end-time T]

Runs prm/flat_punch.prm for u-mu pairs, grid spacings and points per cell (listed in CONFIGURATIONS)
to --end-time (default 0.1 tau_d), with 'Observables/Chemical potential oscillation' on and no
particle output, and records per run: wall time (whole process), steps, Newton iterations, unknowns,
and mu_oscillation at the end of the ramp (t_inc = 3.125e-6 tau_d, the accuracy measure of
doc/flat_punch.md: spurious pressure modes make it of order one) and at the end time. Writes
<DIR>/flat_punch_sweep.csv and <DIR>/flat_punch_sweep.png (oscillation at t_inc against wall time,
Pareto front marked). Prints an estimate before it starts (about 4 minutes on a 2-core machine).
"""
import argparse
import os
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
    args = parser.parse_args()
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    gelmpm = os.path.join(args.build, "gelmpm")
    scene = os.path.join(top, "prm", "flat_punch.prm")
    os.makedirs(args.output, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print(f"{len(CONFIGURATIONS)} runs to t = {args.end_time} tau_d, about "
          f"{sum(c[2] for c in CONFIGURATIONS) / 60:.0f} min")

    rows = []
    for label, overrides, _ in CONFIGURATIONS:
        directory = os.path.join(args.output, label.replace(" ", "_").replace(",", "")
                                 .replace("(", "").replace(")", ""))
        command = [gelmpm, "--set", f"Output/Directory={directory}",
                   "--set", "Output/Write particles=false",
                   "--set", f"Time stepping/End time={args.end_time}",
                   "--set", "Observables/Chemical potential oscillation=true"]
        for entry in overrides:
            command += ["--set", entry]
        start = time.time()
        with open(directory + ".log", "w") as log:
            status = subprocess.call(command + [scene], stdout=log, stderr=subprocess.STDOUT,
                                     env=env)
        seconds = time.time() - start
        load = os.getloadavg()[0]
        if status != 0:
            print(f"  {label}: exit status {status} (see {directory}.log); left out")
            continue
        s = read_csv(os.path.join(directory, "statistics.csv"))
        row = {"configuration": label, "wall_seconds": seconds, "load": load,
               "steps": int(s["step"][-1]), "newton_iterations": int(sum(s["newton_iterations"][1:])),
               "n_dofs_u": int(s["n_dofs_u"][-1]), "n_dofs_mu": int(s["n_dofs_mu"][-1]),
               "oscillation_t_inc": value_at(s, "mu_oscillation", 3.125e-6),
               "oscillation_end": s["mu_oscillation"][-1]}
        rows.append(row)
        print(f"  {label:32s} {seconds:6.1f} s (load {load:.1f})  oscillation at t_inc "
              f"{row['oscillation_t_inc']:.3f}, at {args.end_time}: {row['oscillation_end']:.3f}")

    columns = list(rows[0].keys())
    with open(os.path.join(args.output, "flat_punch_sweep.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for row in rows:
            f.write(",".join(str(row[c]) for c in columns) + "\n")

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

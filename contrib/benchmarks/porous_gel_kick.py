#!/usr/bin/python3
"""The §4.4 lattice (prm/porous_gel.prm): how its pore ratios and event times depend on the kick
that leaves the symmetric branch, and on the criterion that finds the onset.

Runs the scene on h_u = R/18 (40 x 40 cells, the scene's 10 x 10 points per cell; the event
times agree with the scene's grid R/36 to 0.005 tau_d for the bifurcation and 0.05 tau_d for the
self-contact, doc/porous_gel.md "Three grids") to --end-time (default 200 tau_d, past the first
crease) with
  kick_1e-2, kick_1e-3, kick_1e-4   the drained onset, kicked by that many R along the critical
                                    mode of K_uu (the scene: 1e-2);
  no_kick                           the drained onset bracketed, no kick: the run leaves the
                                    symmetric branch on round-off alone;
  paper_detection                   the paper's detection: the signature of the full tangent K(dt)
                                    with the scene's steps (paper eq. (64)/(65)), kicked by 1e-2 R
                                    along the mode of the smallest Schur eigenvalue.
Per run: the bracketed onset, the first self_contact and crease events (events.csv), the pore
ratios at t = 20, 60, 120 tau_d and at the end (statistics.csv, pore_ratio_1..4), in tau_d and
in R^2/D (= 81 tau_d: tau_d = (R/9)^2/D, 'Characteristic length' = R/9).

  /usr/bin/python3 contrib/benchmarks/porous_gel_kick.py [--gelmpm build/gelmpm]
      [--output DIR] [--cells 40] [--end-time 200] [--only name,name]

Prints a Markdown table and writes it to <DIR>/kick.md.
"""
import argparse
import csv
import math
import os
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
R2_OVER_D = 81.0

RUNS = {
    "kick_1e-2": ["Stability/Perturbation amplitude=1e-2"],
    "kick_1e-3": ["Stability/Perturbation amplitude=1e-3"],
    "kick_1e-4": ["Stability/Perturbation amplitude=1e-4"],
    "no_kick": ["Stability/Perturbation amplitude=0"],
    "paper_detection": ["Stability/Onset criterion=tangent",
                        "Stability/Perturbation amplitude=1e-2"],
}


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def first_event(events, name):
    times = [float(e["t_over_tau_d"]) for e in events if e["event"] == name]
    return min(times) if times else math.nan


def ratios_at(stats, t):
    """pore_ratio_1..4 at the last step at or before t (NaN if the run did not get there)."""
    rows = [r for r in stats if float(r["t_over_tau_d"]) <= t * (1 + 1e-9)]
    if not rows or float(stats[-1]["t_over_tau_d"]) < t * (1 - 1e-9):
        return [math.nan] * 4
    return [float(rows[-1][f"pore_ratio_{k}"]) for k in range(1, 5)]


def run(a, name, extra):
    directory = os.path.join(a.output, name)
    args = [a.gelmpm, os.path.join(TOP, "prm", "porous_gel.prm"),
            "--set", f"Output/Directory={directory}",
            "--set", "Output/Write particles=false",
            "--set", f"Background grid/Cells={a.cells}, {a.cells}",
            "--set", f"Time stepping/End time={a.end_time}"]
    for entry in extra:
        args += ["--set", entry]
    start = time.time()
    with open(directory + ".log", "w") as log:
        status = subprocess.run(args, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.time() - start
    stats = read_csv(os.path.join(directory, "statistics.csv"))
    events = read_csv(os.path.join(directory, "events.csv"))
    brackets = read_csv(os.path.join(directory, "stability.csv"))
    return dict(name=name, status=status, wall=wall,
                t_end=float(stats[-1]["t_over_tau_d"]) if stats else math.nan,
                onset=float(brackets[0]["t_unstable"]) if brackets else math.nan,
                contact=first_event(events, "self_contact"),
                crease=first_event(events, "crease"),
                ratios={t: ratios_at(stats, t) for t in (20.0, 60.0, 120.0, a.end_time)})


def fmt(t):
    return "–" if math.isnan(t) else f"{t:.4g} ({t / R2_OVER_D:.3f})"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--gelmpm", default=os.path.join(TOP, "build", "gelmpm"))
    p.add_argument("--output", default="output/porous_gel_kick")
    p.add_argument("--cells", type=int, default=40)
    p.add_argument("--end-time", type=float, default=200.0)
    p.add_argument("--only", default="", help="comma-separated run names")
    a = p.parse_args()
    os.makedirs(a.output, exist_ok=True)
    names = [n for n in RUNS if not a.only or n in a.only.split(",")]
    results = []
    for name in names:
        r = run(a, name, RUNS[name])
        results.append(r)
        print(f"{name}: onset {r['onset']:.5g}, self-contact {r['contact']:.5g}, crease "
              f"{r['crease']:.5g}, reached {r['t_end']:.5g} tau_d, {r['wall']:.0f} s", flush=True)
    lines = ["| run | onset | self-contact | first crease | reached | wall |",
             "|---|---|---|---|---|---|"]
    for r in results:
        lines.append(f"| {r['name']} | {fmt(r['onset'])} | {fmt(r['contact'])} | "
                     f"{fmt(r['crease'])} | {r['t_end']:.4g} | {r['wall']:.0f} s |")
    lines += ["", "Times in tau_d (in brackets R^2/D). Pore ratios (holes 1-4):", "",
              "| run | " + " | ".join(f"t = {t:g}" for t in results[0]["ratios"]) + " |",
              "|---" * (1 + len(results[0]["ratios"])) + "|"]
    for r in results:
        lines.append(f"| {r['name']} | " + " | ".join(
            " / ".join("–" if math.isnan(v) else f"{v:.3f}" for v in vals)
            for vals in r["ratios"].values()) + " |")
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(a.output, "kick.md"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()

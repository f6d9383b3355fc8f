#!/usr/bin/python3
"""The drained onset of the §4.3 column (prm/column_buckling.prm) converged in h *and* dt, for
the MPM and the body-fitted FE peer (gelmpm-fem-column), with Richardson estimates.

The onset (the time at which K_uu first has a negative eigenvalue; doc/method.md) depends on the
history of mu before it, so it carries two errors: the grid's and the steps'. Every run here takes
uniform steps dt from t = 0 (MPM: 'Initial step' = dt, a cap of dt, 'Growth factor' = 1, no
stop times and no error control; FE: the same scene with 'Initial step' = the cap = dt), to 0.3 tau_d, and
brackets the onset to --bisection (default 1e-4 tau_d); the onset is the bracket's midpoint.

  /usr/bin/python3 contrib/benchmarks/column_onset_convergence.py [--model mpm|fem|both]
      [--mpm-h 0.1,0.05,0.025] [--fem-cells 8,16,32] [--steps 0.02,0.01,0.005]
      [--points 4] [--output DIR] [--build build]

Writes <DIR>/onsets.csv (model, h, points per cell, dt, unknowns, t_stable, t_unstable, wall) and
appends to it (runs already in it are not repeated, so a study can be extended), then prints per
model the table of onsets and the Richardson estimates:
  in dt at fixed h  t(dt) = t_0 + b dt^q, q from three steps (dt, dt/2, dt/4);
  in h at fixed dt  t(h) = t_0 + a h^p, p from three grids;
  the limit         the dt-extrapolated onsets of the grids extrapolated in h. Its uncertainty
                    is the change of the limit when the finest grid or the smallest step is left
                    out (the same extrapolation on the coarser data), a conservative bound when
                    the orders are in their asymptotic range.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
SCENE = os.path.join(TOP, "prm", "column_buckling.prm")
# Differences below this (tau_d) are at the resolution of the brackets (1e-4 wide by default).
RESOLUTION = 2e-4
FIELDS = ["model", "h", "points", "dt", "unknowns", "t_stable", "t_unstable", "wall"]
BRACKET = re.compile(r"loss of stability between t/tau_d = ([0-9.eE+-]+) (?:\(stable\) )?and "
                     r"([0-9.eE+-]+)")


def mpm_run(build, h, points, dt, bisection, directory):
    cells = (round(18 / h), round(10 / h))
    args = [os.path.join(build, "gelmpm"), os.path.join(TOP, "prm", "column_buckling.prm"),
            "--set", f"Output/Directory={directory}",
            "--set", "Output/Write particles=false",
            "--set", "Background grid/Upper corner=18, 10",
            "--set", f"Background grid/Cells={cells[0]}, {cells[1]}",
            "--set", f"Material points/Points per cell={points}",
            "--set", "Time stepping/End time=0.3",
            "--set", "Time stepping/Stop at times=",
            "--set", f"Time stepping/Initial step={dt}",
            "--set", f"Time stepping/Step caps=1: {dt}",
            "--set", "Time stepping/Growth factor=1",
            "--set", "Time stepping/Displacement tolerance=0",
            "--set", "Stability/Schur eigenvalues=1",
            "--set", "Stability/Perturbation amplitude=0",
            "--set", f"Stability/Bisection tolerance={bisection}",
            "--set", "Stability/End at onset=true"]
    return args


def fem_run(build, cells, dt, bisection):
    # The scene's gel, Newton and stability sections; uniform steps of dt without error control.
    return [os.path.join(build, "gelmpm-fem-column"), SCENE,
            "--set", f"FE peer/Cells={cells}",
            "--set", "Time stepping/End time=0.3",
            "--set", f"Time stepping/Initial step={dt}",
            "--set", f"Time stepping/Step caps=0.3: {dt}",
            "--set", "Time stepping/Stop at times=",
            "--set", "Time stepping/Tolerance=0",
            "--set", f"Stability/Bisection tolerance={bisection}",
            "--set", "Stability/Onset criterion=drained"]


def run_one(a, model, h, points, dt):
    name = f"{model}_h{h}_p{points}_dt{dt}"
    directory = os.path.join(a.output, name)
    os.makedirs(directory, exist_ok=True)
    if model == "mpm":
        args = mpm_run(a.build, h, points, dt, a.bisection, directory)
    else:
        args = fem_run(a.build, round(1 / h), dt, a.bisection)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    done = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          env=env, cwd=directory)
    wall = time.time() - start
    with open(directory + ".log", "w") as f:
        f.write(done.stdout)
    m = BRACKET.search(done.stdout)
    unknowns = 0
    if model == "fem":
        u = re.search(r"(\d+) DoFs", done.stdout)
        unknowns = int(u.group(1)) if u else 0
    else:
        stats = os.path.join(directory, "statistics.csv")
        if os.path.exists(stats):
            with open(stats) as f:
                row = ([r for r in csv.DictReader(f) if r["n_dofs_u"]] or [None])[-1]
            if row:
                unknowns = int(row["n_dofs_u"]) + int(row["n_dofs_mu"])
    return dict(model=model, h=h, points=points, dt=dt, unknowns=unknowns,
                t_stable=float(m.group(1)) if m else math.nan,
                t_unstable=float(m.group(2)) if m else math.nan, wall=round(wall, 1))


def onset(r):
    return 0.5 * (float(r["t_stable"]) + float(r["t_unstable"]))


def richardson(values, ratio=2.0):
    """(limit, order) from three values at parameters x, x/ratio, x/ratio^2 (coarsest first)."""
    a, b, c = values
    if (a - b) * (b - c) <= 0 or b == c:
        return math.nan, math.nan
    q = math.log((a - b) / (b - c)) / math.log(ratio)
    return c + (c - b) / (ratio**q - 1), q


def limit(table, hs, dts):
    """The dt-extrapolated onsets per h (at the three smallest steps), then extrapolated in h
    (three grids). Where a sequence has stopped changing (its differences at the bisection's
    resolution, or not monotone), its finest value is the limit."""
    per_h = []
    for h in hs:
        vals = [table.get((h, dt)) for dt in dts[-3:]]
        if len(dts) < 3 or None in vals:
            return math.nan
        extrapolated = richardson(vals)[0]
        per_h.append(vals[-1] if math.isnan(extrapolated) else extrapolated)
    if len(per_h) < 3:
        return per_h[-1] if len(per_h) == 2 and abs(per_h[-1] - per_h[-2]) < RESOLUTION \
            else math.nan
    extrapolated = richardson(per_h[-3:])[0]
    return per_h[-1] if math.isnan(extrapolated) else extrapolated


def separable_limit(table, hs, dts):
    """Where the finest grid has one step only: the h-limit at the smallest step that three
    grids share (that of the finest grid if it is one of them), plus the dt-correction (limit dt -> 0 minus the value at that step) of the
    finest grid that has three steps; its change from the next coarser grid is the
    uncertainty."""
    shared = [dt for dt in dts if sum((h, dt) in table for h in hs) >= 3]
    if not shared:
        return "Separable limit: too few runs."
    # The finest grid's sequence if it has one, else the smallest step.
    with_finest = [dt for dt in shared if (hs[-1], dt) in table]
    dt0 = (with_finest or shared)[-1]
    grids = [h for h in hs if (h, dt0) in table]
    h_limit = richardson([table[(h, dt0)] for h in grids[-3:]])[0]
    corrections = []
    for h in hs:
        vals = [table.get((h, dt)) for dt in dts[-3:]]
        if (h, dt0) in table and None not in vals and len(dts) >= 3:
            corrections.append(richardson(vals)[0] - table[(h, dt0)])
    if math.isnan(h_limit) or not corrections:
        return "Separable limit: too few runs."
    uncertainty = (abs(corrections[-1] - corrections[-2]) if len(corrections) > 1 else 0.) \
        + RESOLUTION
    return (f"Separable limit: h -> 0 at dt = {dt0:g} ({len(grids[-3:])} finest grids) "
            f"{h_limit:.5f}, plus the dt -> 0 correction of the finest grid with three steps "
            f"{corrections[-1]:+.5f}: {h_limit + corrections[-1]:.5f} +- {uncertainty:.5f} tau_d")


def report(rows, model, points):
    rows = [r for r in rows if r["model"] == model and int(r["points"]) == points
            and not math.isnan(float(r["t_stable"]))]
    if not rows:
        return ""
    hs = sorted({float(r["h"]) for r in rows}, reverse=True)
    dts = sorted({float(r["dt"]) for r in rows}, reverse=True)
    table = {(float(r["h"]), float(r["dt"])): onset(r) for r in rows}
    label = "MPM" if model == "mpm" else "FE peer"
    lines = [f"### {label}" + (f", {points} x {points} points per cell" if model == "mpm" else ""),
             "", "| h \\ dt | " + " | ".join(f"{dt:g}" for dt in dts) + " | dt -> 0 (order q) |",
             "|---" * (len(dts) + 2) + "|"]
    for h in hs:
        cells = [table.get((h, dt)) for dt in dts]
        ext = richardson(cells[-3:]) if len(cells) >= 3 and None not in cells[-3:] \
            else (math.nan, math.nan)
        lines.append(f"| {h:g} H | " + " | ".join("" if v is None else f"{v:.5f}" for v in cells)
                     + f" | {ext[0]:.5f} ({ext[1]:.2f}) |")
    per_dt = []
    for dt in dts:
        vals = [table.get((h, dt)) for h in hs[-3:]]
        per_dt.append(richardson(vals) if len(hs) >= 3 and None not in vals
                      else (math.nan, math.nan))
    lines.append("| h -> 0 (order p) | " + " | ".join(f"{v:.5f} ({p:.2f})" for v, p in per_dt)
                 + " | |")
    best = limit(table, hs, dts)
    spread = [abs(best - x) for x in (limit(table, hs[:-1], dts), limit(table, hs, dts[:-1]))
              if not math.isnan(x)]
    if spread:
        spread.append(RESOLUTION)
    lines += ["", f"Limit h, dt -> 0: {best:.5f} tau_d"
              + (f" +- {max(spread):.5f}" if spread else " (no uncertainty: too few runs)"), ""]
    if math.isnan(best):
        lines += [separable_limit(table, hs, dts), ""]
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--model", choices=["mpm", "fem", "both"], default="both")
    p.add_argument("--mpm-h", default="0.1,0.05,0.025")
    p.add_argument("--fem-cells", default="8,16,32")
    p.add_argument("--steps", default="0.02,0.01,0.005")
    p.add_argument("--points", type=int, default=4)
    p.add_argument("--bisection", type=float, default=1e-4)
    p.add_argument("--build", default=os.path.join(TOP, "build"))
    p.add_argument("--output", default="output/column_onset_convergence")
    a = p.parse_args()
    a.build = os.path.abspath(a.build)
    os.makedirs(a.output, exist_ok=True)
    path = os.path.join(a.output, "onsets.csv")
    rows = []
    if os.path.exists(path):
        with open(path) as f:
            rows = list(csv.DictReader(f))
    done = {(r["model"], float(r["h"]), int(r["points"]), float(r["dt"])) for r in rows}
    plan = []
    if a.model in ("mpm", "both"):
        plan += [("mpm", float(h), a.points) for h in a.mpm_h.split(",")]
    if a.model in ("fem", "both"):
        plan += [("fem", 1.0 / int(n), 0) for n in a.fem_cells.split(",")]
    for model, h, points in plan:
        for dt in [float(s) for s in a.steps.split(",")]:
            if (model, h, points, dt) in done:
                continue
            r = run_one(a, model, h, points, dt)
            rows.append(r)
            with open(path, "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=FIELDS)
                w.writeheader()
                w.writerows(rows)
            print(f"{model} h = {h:g} H, {points} points, dt = {dt:g}: bracket "
                  f"{r['t_stable']:.6f} - {r['t_unstable']:.6f} ({r['unknowns']} unknowns, "
                  f"{r['wall']} s)", flush=True)
    text = "\n".join(report(rows, m, pts) for m, pts in
                     sorted({(r["model"], int(r["points"])) for r in rows}))
    print(text)
    with open(os.path.join(a.output, "onsets.md"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Speed-accuracy benchmark of paper §4.1 (constrained swelling, prm/constrained_swelling.prm).

One command runs every sweep, measures the cost and the error against the finite-difference
reference of each run, and writes the tables and plots (doc/performance.md):

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  /usr/bin/python3 contrib/benchmarks/speed_accuracy.py            # full mode, 3 repeats per run
  /usr/bin/python3 contrib/benchmarks/speed_accuracy.py --quick    # < 10 min, see below

Each sweep varies one choice around the paper's setting (Q2-Q2SD on 20 x 160 u cells over
0.5 x 4 h_0, 6 x 6 points per cell, Table 1 penalties, the step caps of eq. (64), MUMPS (the default), t to 1713):
  grid       u cells 10 x 80, 20 x 160, 40 x 320 (mu grid: the coarse one, half of it); the body
             0.2 x 1 h_0 stays fixed, its edges lie on cell faces of both grids at every level.
             On 10 x 80 the body is 2 mu cells wide, which the extended B-splines refuse (the run
             stops, recorded as failed); '10x80 no ext.' reruns it with Extended B-splines = false
  degree     B-spline degree 2 and 3 of u and mu (Q2-Q2SD, Q3-Q3SD)
  points     material points per cell and direction 2, 3, 4, 6, 8
  step_caps  the caps of 'Time stepping/Step caps' times 0.25, 0.5, 1, 2, 4
  penalty    Nitsche gamma_u 1e3, 1e4 and gamma_mu 25, 250 (all four pairs)
  solver     'Linear solver/Solver' MUMPS (the default), KLU
The paper's setting is one level of every sweep; it is run once and shared by all sweeps.

Per run (one set of parameters): the whole gelmpm process is run --repeats times under
/usr/bin/time -v; wall time is the median (and min, max) of the repeats, peak memory is
'Maximum resident set size'; steps, Newton iterations (sum of statistics.csv), the TimerOutput
split and the number of material points come from the log; /proc/loadavg is read before each
repeat (other jobs share the machine). The errors are those of contrib/plotting/
constrained_swelling.py (its agreement_data(), shared):
  dh_error    max |Delta h - Delta h_ref| / Delta h_eq over t >= 0.01 tau_d
  eq_error    (Delta h - Delta h_eq) / Delta h_eq at t = 1713 (full mode only)
  mu_error    max |mu - mu_ref| / k_BT over volume points, max over the profile times >= 0.1281
  mu_error_first  the same at t = 0.001197 (the start-up boundary layer, not targeted)
Particles are written (only at the eight profile times and the end: ~0.2 % of the run time),
since mu_error needs them; --no-particles skips them (mu_error then empty). The particle files
of repeats after the first are deleted after the errors are taken.

--quick: fewer levels (grid 10x80, 20x160; degree 2, 3; points 2, 4, 6; caps x0.5, x1, x2;
penalty gamma_u 1e4 and gamma_mu 250 singly; MUMPS, KLU), 3 repeats as in full mode, and end time
0.4531 tau_d (the fourth profile time, about 70 of the 953 steps) instead of 1713, so there is no
eq_error; dh_error then covers 0.01 <= t <= 0.4531 only, where the start-up under the top
dominates it. Errors of quick runs are therefore not comparable with full runs.

Results (default output/speed_accuracy; output/speed_accuracy_quick with --quick):
  <sweep>.csv, all.csv        one row per (sweep, level); all.csv is every sweep
  tables.md                   the same as Markdown tables per sweep
  pareto.png                  dh_error, |eq_error| (or end error) and mu_error against wall time,
                              all runs, the Pareto front (non-dominated runs) as a line, the
                              paper's setting as a star
  sweeps.png                  wall time and dh_error per level of each sweep
  runs/<run>/r<k>/            the log, /usr/bin/time output, mpm/ directory of each repeat
  reference/                  gelmpm-swelling-1d --samples 4000 (computed once)
Finished runs are cached in runs/<run>/r<k>/result.json: rerunning the command only does what is
missing (e.g. more --repeats, or other --sweeps); --rerun ignores the cache.

Other options: --sweeps grid,points (a subset), --repeats N, --output DIR, --estimate (print the
run list and the estimate, run nothing), --tabulate-only (tables and plots of the cached runs
only, e.g. after an interrupted sweep), --paper-seconds S (the estimate's calibration; default
from a cached paper-setting run, else 45). Environment: GELMPM_BUILD_DIR (default build/); copy
the binaries elsewhere first if they may be rebuilt during the sweep.
Needs /usr/bin/python3 with numpy, matplotlib and VTK (Debian python3-numpy, python3-matplotlib,
python3-vtk9).
"""

import argparse
import csv
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

TOP = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
import constrained_swelling as cs  # noqa: E402  (agreement_data, read_cost)

import numpy as np  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCENE = os.path.join(TOP, "prm", "constrained_swelling.prm")
PAPER_CAPS = [(5, 0.0125), (20, 0.0625), (40, 0.125), (100, 0.625)]
PROFILE_TIMES = [0.001197, 0.008589, 0.1281, 0.4531, 1.953, 4.453, 16.06, 1713]
QUICK_END = 0.4531
PAPER_CELLS = (20, 160)
DOMAIN = (0.5, 4.0)
BODY = (0.2, 1.0)


def caps(scale):
    return ", ".join("%g: %g" % (t, c * scale) for t, c in PAPER_CAPS)


# level: (label, x value of the sweep, overrides {entry: value}); no overrides = the paper setting
def sweep_levels(quick):
    grid = [(10, 80), (20, 160)] + ([] if quick else [(40, 320)])
    degrees = [2, 3]
    points = [2, 4, 6] if quick else [2, 3, 4, 6, 8]
    scales = [0.5, 1, 2] if quick else [0.25, 0.5, 1, 2, 4]
    penalties = ([(1e3, 25), (1e4, 25), (1e3, 250)] if quick
                 else [(1e3, 25), (1e4, 25), (1e3, 250), (1e4, 250)])
    levels = {
        "grid": [("%dx%d" % c, DOMAIN[0] / c[0],
                  {} if c == PAPER_CELLS else {"Background grid/Cells": "%d, %d" % c})
                 for c in grid]
        # On 10 x 80 the mu grid (5 x 40) puts only 2 cells across the body's width, too few for
        # the extended B-splines (gelmpm stops with exit 1): that level is kept to show it, and
        # run again without the extension.
        + [("10x80 no ext.", DOMAIN[0] / 10, {"Background grid/Cells": "10, 80",
                                              "Discretisation/Extended B-splines": "false"})],
        "degree": [("Q%d-Q%dSD" % (p, p), p,
                    {} if p == 2 else {"Discretisation/Displacement degree": str(p),
                                       "Discretisation/Chemical potential degree": str(p)})
                   for p in degrees],
        "points": [("%dx%d" % (n, n), n, {} if n == 6 else {"Material points/Points per cell": str(n)})
                   for n in points],
        "step_caps": [("x%g" % s, s, {} if s == 1 else {"Time stepping/Step caps": caps(s)})
                      for s in scales],
        "penalty": [("gu=%g,gmu=%g" % (gu, gm), "%g/%g" % (gu, gm),
                     dict(([("Nitsche/Displacement penalty", "%g" % gu)] if gu != 1e3 else [])
                          + ([("Nitsche/Chemical potential penalty", "%g" % gm)] if gm != 25 else [])))
                    for gu, gm in penalties],
        "solver": [(s, s, {} if s == "MUMPS" else {"Linear solver/Solver": s}) for s in ["MUMPS", "KLU"]],
    }
    return levels


def run_key(sweep, label, overrides):
    if not overrides:
        return "paper"
    return re.sub(r"[^A-Za-z0-9.=_-]+", "_", "%s-%s" % (sweep, label))


def relative_cost(overrides, end_time):
    """Rough cost relative to the paper-setting run, for the estimate only."""
    cells = [int(v) for v in overrides.get("Background grid/Cells", "20, 160").split(",")]
    cell_ratio = cells[0] * cells[1] / (PAPER_CELLS[0] * PAPER_CELLS[1])
    n = int(overrides.get("Material points/Points per cell", "6"))
    p = int(overrides.get("Discretisation/Displacement degree", "2"))
    scale = 1.0
    if "Time stepping/Step caps" in overrides:
        scale = float(overrides["Time stepping/Step caps"].split(",")[0].split(":")[1]) / 0.0125
    per_step = (0.6 * cell_ratio * (n / 6.0) ** 2 * ((p + 1) / 3.0) ** 4
                + 0.4 * cell_ratio ** 1.2 * ((p + 1) / 3.0) ** 2)
    steps = scale ** -0.95
    if overrides.get("Linear solver/Solver") == "KLU":
        per_step *= 1.4
    if end_time < 1000:
        steps *= 0.08
    return per_step * steps


def body_check(overrides):
    cells = [int(v) for v in overrides.get("Background grid/Cells", "20, 160").split(",")]
    h = [DOMAIN[i] / cells[i] for i in range(2)]
    u_cells = [BODY[i] / h[i] for i in range(2)]
    mu_cells = [BODY[i] / (2 * h[i]) for i in range(2)]
    aligned = all(abs(c - round(c)) < 1e-9 for c in u_cells + mu_cells)
    return "%gx%g u cells, %gx%g mu cells, edges on cell faces: %s" % (
        u_cells[0], u_cells[1], mu_cells[0], mu_cells[1], "yes" if aligned else "NO")


def loadavg():
    try:
        return open("/proc/loadavg").read().split()[:3]
    except OSError:
        return ["nan"] * 3


def parse_time_v(path):
    text = open(path, errors="replace").read()
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)", text)
    seconds = float("nan")
    if wall:
        seconds = 0.0
        for part in wall.group(1).split(":"):
            seconds = 60 * seconds + float(part)
    return (int(rss.group(1)) / 1024.0 if rss else float("nan")), seconds


def errors_of(mpm_dir, reference_dir, particles):
    data = cs.agreement_data(mpm_dir, reference_dir, profiles=particles, note=lambda *_: None)
    t, err = data["t_mpm"], data["error"]
    result = {
        "t_end": float(t[-1]),
        "dh_error": float(abs(err[data["worst"]])),
        "dh_error_t": float(t[data["worst"]]),
        "end_error_vs_ref": float(err[-1]),
        "eq_error": float(data["end_error"]) if t[-1] >= 1000 else float("nan"),
        "mu_error": float("nan"), "mu_error_t": float("nan"), "mu_error_first": float("nan"),
    }
    late = [p for p in data["profiles"] if p["time"] >= 0.1281 * (1 - 1e-9)]
    if late:
        worst = max(late, key=lambda p: p["worst"])
        result["mu_error"], result["mu_error_t"] = float(worst["worst"]), float(worst["time"])
    first = [p for p in data["profiles"] if abs(p["time"] - PROFILE_TIMES[0]) < 1e-9]
    if first:
        result["mu_error_first"] = float(first[0]["worst"])
    return result


def run_once(gelmpm, run_dir, overrides, end_time, particles, reference_dir):
    os.makedirs(run_dir, exist_ok=True)
    mpm = os.path.join(run_dir, "mpm")
    sets = dict(overrides)
    sets["Output/Directory"] = mpm
    sets["Output/Write particles"] = "true" if particles else "false"
    if end_time < 1000:
        sets["Time stepping/End time"] = "%g" % end_time
        sets["Time stepping/Stop at times"] = ", ".join(
            "%g" % t for t in PROFILE_TIMES if t <= end_time * (1 + 1e-12))
    command = ["/usr/bin/time", "-v", gelmpm]
    for entry, value in sets.items():
        command += ["--set", "%s=%s" % (entry, value)]
    command.append(SCENE)
    load_before = loadavg()
    start = time.monotonic()
    with open(os.path.join(run_dir, "gelmpm.log"), "w") as log, \
            open(os.path.join(run_dir, "time.txt"), "w") as timing:
        status = subprocess.run(command, stdout=log, stderr=timing, cwd=TOP).returncode
    wall = time.monotonic() - start
    rss, wall_time_v = parse_time_v(os.path.join(run_dir, "time.txt"))
    cost = cs.read_cost(os.path.join(run_dir, "gelmpm.log"))
    result = {"command": " ".join("'%s'" % c if " " in c else c for c in command[2:]),
              "status": status, "wall": wall, "wall_time_v": wall_time_v, "max_rss_mb": rss,
              "loadavg_before": load_before, "loadavg_after": loadavg(),
              "steps": cost["steps"], "volume_points": cost["volume_points"],
              "surface_points": cost["surface_points"], "timer_total": cost["total"],
              "sections": {k: list(v) for k, v in cost["sections"].items()}}
    stats_file = os.path.join(mpm, "statistics.csv")
    if os.path.isfile(stats_file):
        stats = cs.read_csv(stats_file)
        keep = stats["t_over_tau_d"] > 0
        result["newton_iterations"] = int(np.nansum(stats["newton_iterations"][keep]))
        if not result["steps"]:
            result["steps"] = int(keep.sum())
    if status == 0:
        try:
            result.update(errors_of(mpm, reference_dir, particles))
        except SystemExit as problem:
            result["error_message"] = str(problem)
    json.dump(result, open(os.path.join(run_dir, "result.json"), "w"), indent=1)
    return result


def summarise(results):
    """One row from the repeats of one run."""
    ok = [r for r in results if r["status"] == 0] or results
    walls = [r["wall"] for r in ok]
    median = statistics.median(walls)
    typical = min(ok, key=lambda r: abs(r["wall"] - median))  # the repeat nearest the median
    first = ok[0]
    sections = typical.get("sections", {})
    n_points = first.get("volume_points", 0) + first.get("surface_points", 0)
    row = {
        "status": "ok" if all(r["status"] == 0 for r in results) else
        "exit %s" % ",".join(str(r["status"]) for r in results),
        "repeats": len(results),
        "wall_median_s": median, "wall_min_s": min(walls), "wall_max_s": max(walls),
        "walls_s": " ".join("%.1f" % w for w in walls),
        "max_rss_mb": max(r["max_rss_mb"] for r in ok),
        "steps": first.get("steps", 0), "newton_iterations": first.get("newton_iterations", 0),
        "volume_points": first.get("volume_points", 0),
        "surface_points": first.get("surface_points", 0),
        "loadavg_1min": " ".join(r["loadavg_before"][0] for r in results),
    }
    for name in ["assembly", "solve", "setup", "update", "output"]:
        calls, seconds = sections.get(name, (0, float("nan")))
        row["t_%s_s" % name] = seconds
        row["calls_%s" % name] = calls
    row["timer_total_s"] = typical.get("timer_total", float("nan"))
    if row["calls_assembly"] and n_points:
        row["us_per_point_assembly"] = 1e6 * row["t_assembly_s"] / row["calls_assembly"] / n_points
    else:
        row["us_per_point_assembly"] = float("nan")
    for name in ["t_end", "dh_error", "dh_error_t", "eq_error", "end_error_vs_ref", "mu_error",
                 "mu_error_t", "mu_error_first"]:
        row[name] = first.get(name, float("nan"))
    return row


COLUMNS = ["sweep", "level", "x", "run", "paper_setting", "overrides", "status", "repeats",
           "wall_median_s", "wall_min_s", "wall_max_s", "walls_s", "max_rss_mb", "steps",
           "newton_iterations", "calls_solve", "calls_assembly", "volume_points", "surface_points",
           "t_assembly_s", "t_solve_s", "t_setup_s", "t_update_s", "t_output_s", "timer_total_s",
           "us_per_point_assembly", "t_end", "dh_error", "dh_error_t", "eq_error",
           "end_error_vs_ref", "mu_error", "mu_error_t", "mu_error_first", "loadavg_1min", "body"]


def write_csv(path, rows):
    with open(path, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in row.items()})


def pct(value, digits=3):
    return "—" if value is None or (isinstance(value, float) and math.isnan(value)) else \
        ("%.*f %%" % (digits, 100 * value))


def sci(value):
    return "—" if isinstance(value, float) and math.isnan(value) else "%.2e" % value


def write_tables(path, rows, sweeps, header):
    lines = [header, ""]
    for sweep in sweeps:
        lines += ["### %s" % sweep, "",
                  "| level | wall median [s] (min–max, n) | peak RSS [MB] | steps | Newton its | "
                  "points | µs/point/assembly | solve share | Δh error | eq. error | "
                  "μ error (t ≥ 0.128) | μ error (t = 0.0012) | load (1 min) |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for row in [r for r in rows if r["sweep"] == sweep]:
            status = "" if row["status"] == "ok" else " **failed: %s**" % row["status"]
            share = row["t_solve_s"] / row["timer_total_s"] if row["timer_total_s"] else float("nan")
            lines.append("| %s%s%s | %.1f (%.1f–%.1f, %d) | %.0f | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s |" % (
                row["level"], " (paper)" if row["paper_setting"] else "", status,
                row["wall_median_s"], row["wall_min_s"], row["wall_max_s"], row["repeats"],
                row["max_rss_mb"], row["steps"], row["newton_iterations"],
                row["volume_points"] + row["surface_points"],
                "—" if math.isnan(row["us_per_point_assembly"]) else "%.2f" % row["us_per_point_assembly"],
                "—" if math.isnan(share) else "%.0f %%" % (100 * share),
                pct(row["dh_error"]), pct(row["eq_error"], 4), sci(row["mu_error"]),
                sci(row["mu_error_first"]), row["loadavg_1min"]))
        lines.append("")
    open(path, "w").write("\n".join(lines) + "\n")


def pareto(points):
    """Indices of the non-dominated (wall, error) pairs, by increasing wall time."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


MARKERS = {"grid": "s", "degree": "D", "points": "o", "step_caps": "^", "penalty": "v", "solver": "P"}
COLOURS = {"grid": "tab:blue", "degree": "tab:purple", "points": "tab:green",
           "step_caps": "tab:orange", "penalty": "tab:brown", "solver": "tab:gray"}


def plot_pareto(path, rows, title):
    metrics = [("dh_error", r"max $|\Delta h-\Delta h_{ref}|/\Delta h_{eq}$, $t\geq0.01\tau_d$", False)]
    if any(not math.isnan(r["eq_error"]) for r in rows):
        metrics.append(("eq_error", r"$|\Delta h-\Delta h_{eq}|/\Delta h_{eq}$ at $t=1713\,\tau_d$", True))
    else:
        metrics.append(("end_error_vs_ref", r"$|\Delta h-\Delta h_{ref}|/\Delta h_{eq}$ at the end", True))
    if any(not math.isnan(r["mu_error"]) for r in rows):
        metrics.append(("mu_error", r"max $|\mu-\mu_{ref}|/k_BT$, $t\geq0.128\,\tau_d$", True))
    figure, axes_list = plt.subplots(1, len(metrics), figsize=(5.6 * len(metrics), 4.8))
    unique = {}
    for row in rows:  # one point per run (the paper setting is in every sweep)
        if row["status"] == "ok":
            unique.setdefault(row["run"], row)
    runs = list(unique.values())
    for axes, (metric, label, absolute) in zip(np.atleast_1d(axes_list), metrics):
        values = [(r["wall_median_s"], abs(r[metric]) if absolute else r[metric]) for r in runs]
        valid = [i for i, v in enumerate(values) if not math.isnan(v[1]) and v[1] > 0]
        for sweep in MARKERS:
            chosen = [i for i in valid if runs[i]["sweep"] == sweep and not runs[i]["paper_setting"]]
            if chosen:
                axes.loglog([values[i][0] for i in chosen], [values[i][1] for i in chosen],
                            MARKERS[sweep], color=COLOURS[sweep], ms=6, mfc="none", label=sweep)
            for i in chosen:
                axes.annotate(runs[i]["level"], values[i], fontsize=6.5, xytext=(3, 3),
                              textcoords="offset points", color=COLOURS[sweep])
        front = [valid[j] for j in pareto([values[i] for i in valid])]
        axes.loglog([values[i][0] for i in front], [values[i][1] for i in front], "-",
                    color="black", lw=1, alpha=0.6, label="Pareto front", drawstyle="steps-post")
        axes.loglog([values[i][0] for i in front], [values[i][1] for i in front], "o",
                    color="black", ms=3)
        paper = [i for i in valid if runs[i]["paper_setting"]]
        if paper:
            axes.loglog([values[paper[0]][0]], [values[paper[0]][1]], "*", color="red", ms=15,
                        label="paper setting", zorder=5)
        axes.set_xlabel("wall time [s] (median of repeats)")
        axes.set_ylabel(label)
        axes.grid(True, which="both", alpha=0.25)
    np.atleast_1d(axes_list)[0].legend(fontsize=7, loc="best")
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path, dpi=130)
    plt.close(figure)


def plot_sweeps(path, rows, sweeps, title):
    figure, axes_list = plt.subplots(2, len(sweeps), figsize=(3.1 * len(sweeps), 5.6), squeeze=False)
    for column, sweep in enumerate(sweeps):
        chosen = [r for r in rows if r["sweep"] == sweep]
        labels = [r["level"] + ("" if r["status"] == "ok" else " (failed)") for r in chosen]
        x = np.arange(len(chosen))
        top, bottom = axes_list[0][column], axes_list[1][column]
        top.bar(x, [r["wall_median_s"] for r in chosen],
                color=["red" if r["paper_setting"] else COLOURS[sweep] for r in chosen])
        top.errorbar(x, [r["wall_median_s"] for r in chosen],
                     yerr=[[r["wall_median_s"] - r["wall_min_s"] for r in chosen],
                           [r["wall_max_s"] - r["wall_median_s"] for r in chosen]],
                     fmt="none", color="black", lw=0.8)
        top.set_title(sweep, fontsize=9)
        bottom.semilogy(x, [100 * r["dh_error"] for r in chosen], "o-", color=COLOURS[sweep])
        for i, r in enumerate(chosen):
            if r["paper_setting"]:
                bottom.semilogy([i], [100 * r["dh_error"]], "*", color="red", ms=12)
        for axes in (top, bottom):
            axes.set_xticks(x)
            axes.set_xticklabels(labels, rotation=45, ha="right", fontsize=7)
            axes.grid(True, alpha=0.25)
        if column == 0:
            top.set_ylabel("wall time [s]")
            bottom.set_ylabel(r"Δh error [% of $\Delta h_{eq}$]")
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(path, dpi=130)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(
        description="Speed-accuracy benchmark of paper §4.1 (see the top of this file).",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--quick", action="store_true",
                        help="fewer levels, end time %g tau_d (< 10 min)" % QUICK_END)
    parser.add_argument("--repeats", type=int, help="runs of each process (default 3)")
    parser.add_argument("--sweeps", default="grid,degree,points,step_caps,penalty,solver")
    parser.add_argument("--output", help="default output/speed_accuracy[_quick]")
    parser.add_argument("--no-particles", action="store_true",
                        help="Output/Write particles = false (no mu errors)")
    parser.add_argument("--rerun", action="store_true", help="ignore cached results")
    parser.add_argument("--estimate", action="store_true", help="print the plan, run nothing")
    parser.add_argument("--levels", help="only these level labels (comma-separated, e.g. x2,x4,8x8); "
                        "the paper setting is always included")
    parser.add_argument("--tabulate-only", action="store_true",
                        help="run nothing: tables and plots of the cached runs (levels without "
                             "a cached run are left out)")
    parser.add_argument("--paper-seconds", type=float,
                        help="wall time of one paper-setting run for the estimate")
    arguments = parser.parse_args()
    repeats = arguments.repeats or 3
    end_time = QUICK_END if arguments.quick else 1713.0
    out = os.path.abspath(arguments.output or os.path.join(
        TOP, "output", "speed_accuracy_quick" if arguments.quick else "speed_accuracy"))
    build = os.path.abspath(os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build")))
    gelmpm = os.path.join(build, "gelmpm")
    reference_tool = os.path.join(build, "gelmpm-swelling-1d")
    for binary in (gelmpm, reference_tool):
        if not os.access(binary, os.X_OK):
            sys.exit("speed_accuracy.py: %s missing (GELMPM_BUILD_DIR)" % binary)
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    os.makedirs(out, exist_ok=True)

    all_levels = sweep_levels(arguments.quick)
    if arguments.levels:
        wanted = set(arguments.levels.split(","))
        all_levels = {sweep: [level for level in levels if level[0] in wanted or not level[2]]
                      for sweep, levels in all_levels.items()}
    sweeps = [s for s in arguments.sweeps.split(",") if s]
    for sweep in sweeps:
        if sweep not in all_levels:
            sys.exit("speed_accuracy.py: unknown sweep %s (known: %s)" % (sweep, ", ".join(all_levels)))
    # Runs in order of first use; the paper setting first.
    runs = {}
    for sweep in sweeps:
        for label, _, overrides in all_levels[sweep]:
            runs.setdefault(run_key(sweep, label, overrides), (sweep, label, overrides))
    runs = dict(sorted(runs.items(), key=lambda item: item[0] != "paper"))

    def cached(key, k):
        path = os.path.join(out, "runs", key, "r%d" % k, "result.json")
        return None if arguments.rerun or not os.path.isfile(path) else json.load(open(path))

    paper_seconds = arguments.paper_seconds
    if paper_seconds is None:
        known = [cached("paper", k) for k in range(repeats)]
        known = [r["wall"] for r in known if r and r["status"] == 0]
        paper_seconds = statistics.median(known) if known else 45.0
    todo = [(key, k) for key in runs for k in range(repeats) if cached(key, k) is None]
    if arguments.tabulate_only:
        todo = []
    estimate = sum(relative_cost(runs[key][2], end_time) for key, _ in todo) * paper_seconds + 20
    mode = "quick" if arguments.quick else "full"
    print("speed_accuracy.py: %s mode, sweeps %s, %d distinct runs x %d repeat(s)%s, end time %g tau_d"
          % (mode, ",".join(sweeps), len(runs), repeats,
             " (quick mode: fewer levels, shortened end time)" if arguments.quick else "",
             end_time))
    print("  binary %s; results in %s" % (gelmpm, out))
    print("  %d of %d process runs to do (the rest cached); estimated %.0f min (a paper-setting run "
          "taken as %.0f s; load average now %s)"
          % (len(todo), len(runs) * repeats, estimate / 60, paper_seconds, " ".join(loadavg())))
    for key, (sweep, label, overrides) in runs.items():
        print("   %-28s %-55s ~%4.0f s%s" % (
            key, "; ".join("%s=%s" % kv for kv in overrides.items()) or "(paper setting)",
            relative_cost(overrides, end_time) * paper_seconds,
            "  [%s]" % body_check(overrides) if sweep == "grid" else ""))
    if arguments.estimate:
        return 0
    sys.stdout.flush()

    begin = time.monotonic()
    reference_dir = os.path.join(out, "reference")
    if not os.path.isfile(os.path.join(reference_dir, "reference_profiles.csv")):
        start = time.monotonic()
        with open(os.path.join(out, "reference.log"), "w") as log:
            subprocess.run([reference_tool, "--samples", "4000", "--output", reference_dir],
                           stdout=log, stderr=subprocess.STDOUT, check=True)
        print("  reference (gelmpm-swelling-1d --samples 4000): %.1f s" % (time.monotonic() - start))

    results = {}
    done = 0
    remaining = estimate - 20
    for key, (sweep, label, overrides) in runs.items():
        results[key] = []
        for k in range(repeats):
            result = cached(key, k)
            if result is None and arguments.tabulate_only:
                continue
            if result is None:
                done += 1
                guess = relative_cost(overrides, end_time) * paper_seconds
                print("  [%d/%d] %s repeat %d/%d (~%.0f s; load %s) ..."
                      % (done, len(todo), key, k + 1, repeats, guess, " ".join(loadavg())),
                      end=" ", flush=True)
                run_dir = os.path.join(out, "runs", key, "r%d" % k)
                if os.path.isdir(run_dir):
                    shutil.rmtree(run_dir)
                result = run_once(gelmpm, run_dir, overrides, end_time, not arguments.no_particles,
                                  reference_dir)
                remaining -= guess
                print("%s %.1f s, %d steps, dh_error %s, mu_error %s; elapsed %.1f min, ~%.0f min left"
                      % ("done" if result["status"] == 0 else "FAILED (exit %d)" % result["status"],
                         result["wall"], result.get("steps", 0), pct(result.get("dh_error", float("nan"))),
                         sci(result.get("mu_error", float("nan"))), (time.monotonic() - begin) / 60,
                         max(remaining, 0) / 60), flush=True)
                if k > 0:  # keep the particle files of the first repeat only
                    for name in os.listdir(os.path.join(run_dir, "mpm")) if os.path.isdir(
                            os.path.join(run_dir, "mpm")) else []:
                        if name.endswith(".vtu"):
                            os.remove(os.path.join(run_dir, "mpm", name))
            results[key].append(result)

    rows = []
    for sweep in sweeps:
        sweep_rows = []
        for label, x, overrides in all_levels[sweep]:
            key = run_key(sweep, label, overrides)
            if not results.get(key):
                continue
            row = {"sweep": sweep, "level": label, "x": x, "run": key,
                   "paper_setting": not overrides,
                   "overrides": "; ".join("%s=%s" % kv for kv in overrides.items()),
                   "body": body_check(overrides)}
            row.update(summarise(results[key]))
            sweep_rows.append(row)
        write_csv(os.path.join(out, "%s.csv" % sweep), sweep_rows)
        rows += sweep_rows
    write_csv(os.path.join(out, "all.csv"), rows)
    header = ("%s mode, end time %g tau_d, %d repeat(s) per run; errors against gelmpm-swelling-1d"
              % (mode, end_time, repeats))
    write_tables(os.path.join(out, "tables.md"), rows, sweeps, header)
    title = "§4.1 speed–accuracy (%s mode%s, median of %d runs, 2-core machine)" % (
        mode, ", end time %g τ_d" % end_time if arguments.quick else "", repeats)
    plot_pareto(os.path.join(out, "pareto.png"), rows, title)
    plot_sweeps(os.path.join(out, "sweeps.png"), rows, sweeps, title)
    print(open(os.path.join(out, "tables.md")).read())
    print("speed_accuracy.py: %s mode took %.1f min (%d process runs); results in %s "
          "(all.csv, <sweep>.csv, tables.md, pareto.png, sweeps.png)"
          % (mode, (time.monotonic() - begin) / 60, done, out))
    return 0


if __name__ == "__main__":
    sys.exit(main())

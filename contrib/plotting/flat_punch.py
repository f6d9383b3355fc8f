#!/usr/bin/python3
"""Paper §4.2 (flat punch indentation): Fig. 7b/7c, a Fig. 8-like panel and the comparison table
of the u–μ discretisations (doc/flat_punch.md).

Input: --study DIR, the directory of contrib/benchmarks/flat_punch.sh, holding one gelmpm output
directory per discretisation (statistics.csv with the column mu_oscillation, particles.pvd and the
particles-NNNNN.vtu it lists, parameters.prm):

  q2_q2/            (i)   Q2–Q2,          h_u = h_μ = 0.05H
  q3_q2/            (ii)  Q3–Q2,          h_u = h_μ = 0.05H
  q2_q2sd_fine/     (iii) Q2–Q2SD fine,   h_u = 0.025H, h_μ = 0.05H
  q2_q2sd_coarse/   (iv)  Q2–Q2SD coarse, h_u = 0.05H,  h_μ = 0.1H
  and, if present (flat_punch.sh --refined; only to t_inc):
  q2_q2_h0.025/     Q2–Q2,  h_u = h_μ = 0.025H
  q3_q2_h0.025/     Q3–Q2,  h_u = h_μ = 0.025H
  q2_q2sd_h0.0125/  Q2–Q2SD, h_u = 0.0125H, h_μ = 0.025H

and optionally runs.csv (run,label,end_time,exit_status,wall_seconds,load_average) written by the
driver. A missing run is left out with a warning. --run NAME=DIR[:LABEL] (repeatable) compares other
output directories instead (e.g. an extra run with another penalty).

Outputs (into --output DIR):
  fig7b_top_surface_t_inc.png     μ/k_BT along the top surface at the end of the ramp, t_inc
  fig7c_top_surface_t0.1.png      the same at t = 0.1 τ_d
  fig8_mu_volume_points.png       2 x 4 panel: μ/k_BT over the volume points (scatter at their
                                  current positions, one square per point) at the two times; one
                                  colour scale per row
  fig8_oscillation_map.png        the same layout, coloured by the local |second difference| of μ
                                  along the point's row over the range of μ (what mu_oscillation
                                  sums), log scale: where each pair oscillates
  fig7b_refinement.png            only with the refined runs: the top surface at t_inc on the
                                  paper's grids (h_μ = 0.05H) beside the next finer ones (h_μ = 0.025H)
  flat_punch_table.csv, .md       per run and time: see "Table" below

Table columns:
  mu_oscillation   the column of statistics.csv at that time (computed by gelmpm in double
                   precision): mean over rows of volume points (equal initial y, ordered by
                   initial x) of Σ|μ_{i+1} − 2μ_i + μ_{i−1}|, over the range of μ over the volume points
  row_median       the same per-row sums, median instead of mean (recomputed here from the .vtu,
                   single precision): insensitive to the few rows through the punch edge, where μ
                   is steep for every pair
  top_oscillation  the same sum along the ordered top-surface points, over the range of μ on the
                   top surface, leaving out the points within --edge-window of the punch edge
                   (X − X_left = 0.25H), where μ changes sign steeply for every pair
  volume_points, n_dofs_u, n_dofs_mu (statistics.csv), μ min and max over the volume points,
  wall time and load average of the run (runs.csv), t_end of the run, and max |μ|/k_BT over all
  points at t_end (drained limit; target below --drained-target, checked at t_end ≥ 1000 τ_d)

Definitions:
  - the times are the real times of particles.pvd (in τ_d); the data set nearest to each of
    --times (relative distance below 1e-3) is used, the last one for the drained limit;
  - top surface = surface points (kind > 0) of the pieces named by --top-pieces in the run's
    'Boundary conditions/Pieces' (default punch, top) whose normal_area points up, ordered by their
    initial x, X = x − displacement_x, drawn against X − X_left (X_left: the smallest initial x
    of all points, the left side of the gel), in H;
  - Fig. 8 colour scale per row: from the smallest to the largest μ over the volume points of the
    runs named by --colour-reference (default: all runs of the figure); values outside are clipped.

Typical use (contrib/benchmarks/flat_punch.sh runs all of it):

  /usr/bin/python3 contrib/plotting/flat_punch.py --study output/flat_punch_study \\
      --output output/flat_punch_study

Exit status: 0; 1 if a run of the driver that ended at t_end ≥ 1000 τ_d misses the drained-limit
target; 2 on missing input. Needs numpy, matplotlib and VTK's Python module (Debian:
python3-numpy python3-matplotlib python3-vtk9); run it with /usr/bin/python3.
"""

import argparse
import csv
import os
import re
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

from gelmpm_files import read_csv, read_pvd, read_vtu  # noqa: E402


# (directory name under --study, label)
RUNS = [
    ("q2_q2", "(i) Q2–Q2"),
    ("q3_q2", "(ii) Q3–Q2"),
    ("q2_q2sd_fine", "(iii) Q2–Q2SD fine"),
    ("q2_q2sd_coarse", "(iv) Q2–Q2SD coarse"),
]
REFINED = [
    ("q2_q2_h0.025", "Q2–Q2, h = 0.025H"),
    ("q3_q2_h0.025", "Q3–Q2, h = 0.025H"),
    ("q2_q2sd_h0.0125", "Q2–Q2SD, h_u = 0.0125H"),
]
COLOURS = {"q2_q2": "C0", "q3_q2": "C1", "q2_q2sd_fine": "C2", "q2_q2sd_coarse": "C3",
           "q2_q2_h0.025": "C0", "q3_q2_h0.025": "C1", "q2_q2sd_h0.0125": "C2"}
MARKERS = {"q2_q2": "o", "q3_q2": "s", "q2_q2sd_coarse": "^", "q2_q2_h0.025": "o",
           "q3_q2_h0.025": "s"}
PUNCH_EDGE = 0.25  # X - X_left of the punch edge, in H


# ------------------------------------------------------------------------------------------------
# Input

def fail(message):
    print(f"flat_punch.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_pieces(directory):
    """The names of 'Boundary conditions/Pieces' from parameters.prm (or original.prm)."""
    for name in ("parameters.prm", "original.prm"):
        path = os.path.join(directory, name)
        if os.path.isfile(path):
            match = re.search(r"^\s*set\s+Pieces\s*=\s*(.*)$", open(path, encoding="utf-8").read(),
                              re.MULTILINE)
            if match:
                return [piece.strip() for piece in match.group(1).split("#")[0].split(",")]
    return ["punch", "top", "rollers"]


def read_points(vtu):
    """Point fields of one particles-NNNNN.vtu."""
    position, fields = read_vtu(vtu)

    def field(name):
        if name not in fields:
            fail(f"{vtu} has no field {name}")
        return fields[name].astype(float)

    displacement = field("displacement")
    return {
        "x": position[:, 0],
        "y": position[:, 1],
        "X": position[:, 0] - displacement[:, 0],
        "Y": position[:, 1] - displacement[:, 1],
        "mu": field("mu_over_kT"),
        "kind": field("kind").astype(int),
        "piece": field("piece").astype(int),
        "normal": field("normal_area"),
    }


def read_runs_csv(study):
    """{run: {end_time, exit_status, wall_seconds, load_average}} from the driver's runs.csv."""
    path = os.path.join(study, "runs.csv") if study else ""
    if not path or not os.path.isfile(path):
        return {}
    runs = {}
    with open(path, newline="", encoding="utf-8") as stream:
        for row in csv.DictReader(stream):
            runs[row["run"]] = {"end_time": float(row["end_time"]),
                                "exit_status": int(row["exit_status"]),
                                "wall_seconds": float(row["wall_seconds"]),
                                "load_average": float(row.get("load_average") or "nan")}
    return runs


def nearest(series, time):
    """(time, path) of the data set nearest to @p time, or None if none is within 1e-3 relative."""
    times = np.array([t for t, _ in series])
    k = int(np.argmin(np.abs(times - time)))
    return series[k] if abs(times[k] - time) <= 1e-3 * abs(time) else None


def statistics_row(statistics, time):
    """Index of the statistics.csv row at @p time (relative distance below 1e-3), or None."""
    t = statistics["t_over_tau_d"]
    k = int(np.argmin(np.abs(t - time)))
    return k if abs(t[k] - time) <= 1e-3 * abs(time) else None


# ------------------------------------------------------------------------------------------------
# Analysis

def top_surface(points, top_pieces):
    """(X - X_left, μ/k_BT) of the top-surface points, ordered by initial x."""
    on_top = ((points["kind"] > 0) & np.isin(points["piece"], top_pieces)
              & (points["normal"][:, 1] > 0))
    order = np.argsort(points["X"][on_top])
    return points["X"][on_top][order] - points["X"].min(), points["mu"][on_top][order]


def row_second_differences(points):
    """Per volume point: |μ_{i+1} − 2μ_i + μ_{i−1}| along its row (equal initial y, ordered by
    initial x; 0 at the ends of a row) over the range of μ; and the per-row sums."""
    volume = points["kind"] == 0
    X, Y, mu = points["X"][volume], points["Y"][volume], points["mu"][volume]
    spread = mu.max() - mu.min()
    local = np.zeros_like(mu)
    sums = []
    rows = np.round(Y, 6)
    for row in np.unique(rows):
        index = np.flatnonzero(rows == row)
        index = index[np.argsort(X[index])]
        if len(index) < 3:
            continue
        second = np.abs(np.diff(mu[index], 2)) / spread
        local[index[1:-1]] = second
        sums.append(second.sum())
    return local, np.array(sums)


def top_oscillation(points, top_pieces, edge_window):
    """Σ|second differences| of μ along the top surface away from the punch edge, over the range
    of μ on the top surface."""
    x, mu = top_surface(points, top_pieces)
    if len(x) < 3:
        return float("nan")
    second = np.abs(np.diff(mu, 2))
    away = np.abs(x[1:-1] - PUNCH_EDGE) > edge_window
    return float(second[away].sum() / (mu.max() - mu.min()))


def format_time(t):
    return f"{t:.4g}"


def draw_top_surface(axis, runs, time, title):
    for run in runs:
        if time not in run["at"]:
            continue
        x, mu = top_surface(run["at"][time]["points"], run["top_pieces"])
        marker = MARKERS.get(run["name"])
        axis.plot(x, mu, color=COLOURS.get(run["name"]), marker=marker, markersize=3,
                  linewidth=1.2, markevery=max(1, len(x) // 100), label=run["label"])
    axis.axvline(PUNCH_EDGE, color="0.6", linewidth=0.8, linestyle=":")
    axis.axhline(0.0, color="0.6", linewidth=0.8)
    axis.set_xlabel("(X − X_left) / H along the top surface (punch: < 0.25)")
    axis.set_ylabel(r"$\mu/k_BT$")
    axis.set_title(title, fontsize=10)
    axis.legend(fontsize=8)
    axis.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))


def point_panel(fig, axes, data, times, colour_of, norm_of, colour_label, cmap, extend):
    """2 x n panel of the volume points coloured by colour_of(run, time, points)."""
    artists = []
    for row, time in enumerate(times):
        norm = norm_of(time)
        scatter = None
        for column, run in enumerate(data):
            axis = axes[row][column]
            axis.set_aspect("equal")
            axis.set_xlim(0.2, 1.3)
            axis.set_ylim(0.2, 1.35)
            axis.tick_params(labelsize=7)
            if time not in run["at"]:
                axis.set_title(f"{run['label']}\n(no output)", fontsize=9)
                continue
            points = run["at"][time]["points"]
            volume = points["kind"] == 0
            scatter = axis.scatter(points["x"][volume], points["y"][volume],
                                   c=colour_of(run, time, points), s=1.0, marker="s", linewidths=0,
                                   cmap=cmap, norm=norm, rasterized=True)
            artists.append((axis, scatter, run["spacing"]))
            axis.set_title(f"{run['label']}\n" + rf"$t/\tau_d$ = {format_time(run['at'][time]['t'])}",
                           fontsize=9)
        if scatter is not None:
            bar = fig.colorbar(scatter, ax=list(axes[row]), shrink=0.9, extend=extend)
            bar.set_label(colour_label)
            if extend != "neither":
                bar.formatter.set_powerlimits((-2, 2))
                bar.update_ticks()
    # One square per point: marker side = 1.4 x the initial point spacing (points move apart under
    # the punch), in display points.
    fig.canvas.draw()
    for axis, scatter, spacing in artists:
        width_points = axis.get_window_extent().width * 72.0 / fig.dpi
        side = 1.4 * spacing / (axis.get_xlim()[1] - axis.get_xlim()[0]) * width_points
        scatter.set_sizes([max(side, 0.3) ** 2])


# ------------------------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(
        description="Paper §4.2: Fig. 7b/7c, the Fig. 8-like panel and the table of the u-mu "
                    "discretisations of the flat punch.",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--study", help="directory of contrib/benchmarks/flat_punch.sh with the "
                                        "run directories " + ", ".join(n for n, _ in RUNS))
    parser.add_argument("--run", action="append", default=[], metavar="NAME=DIR[:LABEL]",
                        help="compare this output directory (repeatable; replaces --study's runs)")
    parser.add_argument("--output", default=".", help="directory for the PNGs and tables")
    parser.add_argument("--times", type=float, nargs=2, default=[3.125e-6, 0.1],
                        help="the two times (t/tau_d) of Fig. 7b/7c and the rows of Fig. 8")
    parser.add_argument("--top-pieces", default="punch,top",
                        help="boundary pieces that make the top surface")
    parser.add_argument("--edge-window", type=float, default=0.1,
                        help="top_oscillation leaves out the top-surface points this close (in H) "
                             "to the punch edge")
    parser.add_argument("--colour-reference", default="",
                        help="comma-separated run names whose mu range sets the colour scale of "
                             "Fig. 8 (empty: all runs of the figure)")
    parser.add_argument("--drained-target", type=float, default=1e-3,
                        help="target for max |mu|/kT at the end")
    parser.add_argument("--suffix", default="", help="appended to the PNG and table names")
    parser.add_argument("--dpi", type=int, default=150)
    arguments = parser.parse_args()
    os.makedirs(arguments.output, exist_ok=True)

    # ---- the runs ---------------------------------------------------------------------------
    runs, refined = [], []
    if arguments.run:
        for text in arguments.run:
            name, _, rest = text.partition("=")
            directory, _, label = rest.partition(":")
            runs.append((name, label or name, directory))
    elif arguments.study:
        for name, label in RUNS:
            directory = os.path.join(arguments.study, name)
            if os.path.isfile(os.path.join(directory, "particles.pvd")):
                runs.append((name, label, directory))
            else:
                print(f"flat_punch.py: warning: no {directory}/particles.pvd; {label} left out",
                      file=sys.stderr)
        for name, label in REFINED:
            directory = os.path.join(arguments.study, name)
            if os.path.isfile(os.path.join(directory, "particles.pvd")):
                refined.append((name, label, directory))
    else:
        fail("give --study DIR or --run NAME=DIR")
    if not runs:
        fail("no run to compare")
    driver = read_runs_csv(arguments.study)

    t_inc, t_later = arguments.times

    def load(name, label, directory):
        for required in ("particles.pvd", "statistics.csv"):
            if not os.path.isfile(os.path.join(directory, required)):
                fail(f"missing {directory}/{required}")
        series = read_pvd(directory)
        statistics = read_csv(os.path.join(directory, "statistics.csv"))
        if "mu_oscillation" not in statistics:
            fail(f"{directory}/statistics.csv has no mu_oscillation "
                 "(run with --set \"Observables/Chemical potential oscillation=true\")")
        pieces = read_pieces(directory)
        top_pieces = [pieces.index(p.strip()) for p in arguments.top_pieces.split(",")
                      if p.strip() in pieces]
        run = {"name": name, "label": label, "statistics": statistics, "top_pieces": top_pieces,
               "at": {}, "driver": driver.get(name)}
        for time in (t_inc, t_later):
            found = nearest(series, time)
            if found is not None:
                run["at"][time] = {"t": found[0], "points": read_points(found[1])}
            elif not (name in dict(REFINED) and time == t_later):
                print(f"flat_punch.py: warning: {directory}/particles.pvd has no data set at "
                      f"t = {time}", file=sys.stderr)
        run["end_time"], end_file = series[-1]
        run["end_points"] = read_points(end_file)
        # Initial point spacing: the smallest gap between initial x in one row of volume points.
        start = read_points(series[0][1])
        volume = start["kind"] == 0
        xs = np.unique(np.round(start["X"][volume], 6))
        run["spacing"] = float(np.min(np.diff(xs))) if len(xs) > 1 else 0.01
        return run

    data = [load(*run) for run in runs]
    data_refined = [load(*run) for run in refined]
    suffix = arguments.suffix

    def save(fig, name):
        fig.savefig(os.path.join(arguments.output, name + suffix + ".png"), dpi=arguments.dpi)
        plt.close(fig)

    # ---- Fig. 7b, 7c: μ along the top surface -----------------------------------------------
    for figure, time, what in (("fig7b_top_surface_t_inc", t_inc, "end of the ramp"),
                               ("fig7c_top_surface_t0.1", t_later, "relaxation")):
        fig, axis = plt.subplots(figsize=(6.4, 4.4))
        draw_top_surface(axis, data, time, rf"Top surface, $t/\tau_d$ = {format_time(time)} ({what})")
        fig.tight_layout()
        save(fig, figure)

    if data_refined:
        paper_grid = [run for run in data if run["name"] in ("q2_q2", "q3_q2", "q2_q2sd_fine")]
        fig, axes = plt.subplots(1, 2, figsize=(12.0, 4.4), sharey=True)
        draw_top_surface(axes[0], paper_grid, t_inc,
                         rf"paper's grids, $h_\mu$ = 0.05H, $t/\tau_d$ = {format_time(t_inc)}")
        draw_top_surface(axes[1], data_refined, t_inc,
                         rf"next finer grids, $h_\mu$ = 0.025H, $t/\tau_d$ = {format_time(t_inc)}")
        fig.tight_layout()
        save(fig, "fig7b_refinement")

    # ---- Fig. 8: μ over the volume points ---------------------------------------------------
    reference = [r.strip() for r in arguments.colour_reference.split(",") if r.strip()]
    times = (t_inc, t_later)

    def mu_norm(time):
        low, high = np.inf, -np.inf
        for run in data:
            if time in run["at"] and (not reference or run["name"] in reference):
                points = run["at"][time]["points"]
                mu = points["mu"][points["kind"] == 0]
                low, high = min(low, float(mu.min())), max(high, float(mu.max()))
        return matplotlib.colors.Normalize(vmin=low, vmax=high) if low < high else None

    figure_size = (3.1 * len(data) + 1.0, 6.6)
    fig, axes = plt.subplots(2, len(data), figsize=figure_size, squeeze=False,
                             constrained_layout=True)
    point_panel(fig, axes, data, times,
                lambda run, time, points: points["mu"][points["kind"] == 0], mu_norm,
                r"$\mu/k_BT$", "turbo", "both")
    save(fig, "fig8_mu_volume_points")

    fig, axes = plt.subplots(2, len(data), figsize=figure_size, squeeze=False,
                             constrained_layout=True)
    point_panel(fig, axes, data, times,
                lambda run, time, points: np.maximum(row_second_differences(points)[0], 1e-7),
                lambda time: LogNorm(vmin=1e-5, vmax=1e-1),
                r"$|\Delta^2_x \mu|$ / range of $\mu$ (along rows)", "viridis", "neither")
    save(fig, "fig8_oscillation_map")

    # ---- the table --------------------------------------------------------------------------
    columns = ["run", "label", "t_over_tau_d", "mu_oscillation", "row_median", "top_oscillation",
               "volume_points", "n_dofs_u", "n_dofs_mu", "mu_min", "mu_max", "wall_seconds",
               "load_average", "end_time", "max_abs_mu_end", "drained_target_met"]
    rows = []
    drained_missed = False
    for run in data + data_refined:
        statistics = run["statistics"]
        max_abs_end = float(np.abs(run["end_points"]["mu"]).max())
        driver_run = run["driver"]
        drained_checked = run["end_time"] >= 1000
        met = max_abs_end < arguments.drained_target
        if drained_checked and not met:
            drained_missed = True
        for time in times:
            at = run["at"].get(time)
            if at is None:
                continue
            k = statistics_row(statistics, time)
            points = at["points"]
            volume_mu = points["mu"][points["kind"] == 0]
            rows.append({
                "run": run["name"],
                "label": run["label"],
                "t_over_tau_d": time,
                "mu_oscillation": float(statistics["mu_oscillation"][k]) if k is not None else np.nan,
                "row_median": float(np.median(row_second_differences(points)[1])),
                "top_oscillation": top_oscillation(points, run["top_pieces"],
                                                   arguments.edge_window),
                "volume_points": int((points["kind"] == 0).sum()),
                "n_dofs_u": int(statistics["n_dofs_u"][k]) if k is not None else "",
                "n_dofs_mu": int(statistics["n_dofs_mu"][k]) if k is not None else "",
                "mu_min": float(volume_mu.min()),
                "mu_max": float(volume_mu.max()),
                "wall_seconds": driver_run["wall_seconds"] if driver_run else "",
                "load_average": driver_run["load_average"] if driver_run else "",
                "end_time": run["end_time"],
                "max_abs_mu_end": max_abs_end,
                "drained_target_met": ("yes" if met else "no") if drained_checked else "n/a",
            })

    with open(os.path.join(arguments.output, f"flat_punch_table{suffix}.csv"), "w", newline="",
              encoding="utf-8") as stream:
        writer = csv.DictWriter(stream, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow({key: (f"{value:.6g}" if isinstance(value, float) else value)
                             for key, value in row.items()})

    def cell(value, digits=3):
        if isinstance(value, float):
            return "–" if np.isnan(value) else f"{value:.{digits}g}"
        return str(value) if value != "" else "–"

    lines = [
        "| discretisation | t/τ_d | mu_oscillation | row median | top surface | volume points "
        "| n_dofs_u | n_dofs_mu | μ/k_BT min … max | wall time (load) | t_end/τ_d "
        f"| max \\|μ\\|/k_BT at t_end (< {arguments.drained_target:g}?) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        wall = (f"{row['wall_seconds']:.1f} s ({row['load_average']:.1f})"
                if row["wall_seconds"] != "" else "–")
        lines.append(
            f"| {row['label']} | {cell(row['t_over_tau_d'], 4)} | {cell(row['mu_oscillation'])} "
            f"| {cell(row['row_median'], 2)} | {cell(row['top_oscillation'], 2)} "
            f"| {row['volume_points']} | {row['n_dofs_u']} | {row['n_dofs_mu']} "
            f"| {cell(row['mu_min'], 2)} … {cell(row['mu_max'], 2)} | {wall} "
            f"| {cell(row['end_time'], 4)} | {cell(row['max_abs_mu_end'], 2)} "
            f"({row['drained_target_met']}) |")
    table = "\n".join(lines) + "\n"
    with open(os.path.join(arguments.output, f"flat_punch_table{suffix}.md"), "w",
              encoding="utf-8") as stream:
        stream.write(table)
    print(table, end="")
    print(f"flat_punch.py: wrote the PNGs and flat_punch_table{suffix}.csv/.md into "
          f"{arguments.output}")
    if drained_missed:
        print(f"flat_punch.py: max |mu|/kT at the end is not below {arguments.drained_target:g} "
              "for every run", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

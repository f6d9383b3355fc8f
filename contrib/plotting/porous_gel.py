#!/usr/bin/python3
"""Paper §4.4 (pattern transformation of a gel with a square lattice of holes): Fig. 11, 12a-c and
13 from gelmpm output directories of prm/porous_gel.prm (doc/porous_gel.md).

  /usr/bin/python3 contrib/plotting/porous_gel.py --run LABEL=DIR [--run LABEL=DIR ...]
                   [--snapshots DIR] [--times 0,9.8,50,...] --output DIR

Each --run is one output directory (statistics.csv with pore_ratio_k, pore_curvature_k,
mu_boundary; events.csv). The first run is the reference.

Outputs (into --output DIR):
  porous_gel_fig12a.png   the pores' extent ratios pore_ratio_1 ... _4 of the first run against
                          t/tau_d (logarithmic), the boundary mu on a second axis, the events
                          (bifurcation, self_contact, crease) marked
  porous_gel_fig12b.png   the largest surface curvature times R of pore 1 against t/tau_d, one
                          curve per run, crease events marked
  porous_gel_fig11.png    with --snapshots DIR: the material points of DIR's particles.pvd at
                          the output times nearest to --times, coloured by mu/k_BT, the cell
                          mirrored into a 3 x 3 array as the paper draws it
  porous_gel_fig12c.png   with --snapshots DIR: the surface points of pore 1 at the three output
                          times around its first crease
  porous_gel_fig13.png    the last data set of every run: the single cell, volume points (blue)
                          and surface points (red), one panel per run
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gelmpm_files import read_csv, read_pvd, read_vtu  # noqa: E402

CELL = 20.0 / 9.0  # the cell's side a in units of R


def read_events(directory):
    """[(event, t_over_tau_d, pore)] of events.csv (pore 0 for a bifurcation)."""
    path = os.path.join(directory, "events.csv")
    if not os.path.exists(path):
        return []
    events = []
    with open(path) as lines:
        next(lines)
        for line in lines:
            fields = line.strip().split(",")
            events.append((fields[0], float(fields[2]), int(fields[4]) if fields[4] else 0))
    return events


def mark_events(ax, events, kinds=("bifurcation", "self_contact", "crease")):
    styles = {"bifurcation": ("k", ":"), "self_contact": ("tab:green", "--"),
              "crease": ("tab:red", "-.")}
    seen = set()
    for name, t, _ in events:
        if name in kinds and (name, t) not in seen:
            colour, style = styles[name]
            ax.axvline(t, color=colour, linestyle=style, linewidth=0.8,
                       label=name if name not in {s[0] for s in seen} else None)
            seen.add((name, t))


def figure_12a(directory, output):
    data = read_csv(os.path.join(directory, "statistics.csv"))
    t = data["t_over_tau_d"]
    keep = t > 0
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for k in range(1, 5):
        ax.plot(t[keep], data[f"pore_ratio_{k}"][keep], label=f"pore {k}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("t / tau_d")
    ax.set_ylabel("pore extent along x / along y")
    mark_events(ax, read_events(directory))
    ax.legend(fontsize=7, loc="upper left")
    right = ax.twinx()
    right.plot(t[keep], data["mu_boundary"][keep], color="0.6", linewidth=0.8)
    right.set_ylabel("mu on the holes / k_BT (grey)")
    fig.tight_layout()
    fig.savefig(os.path.join(output, "porous_gel_fig12a.png"), dpi=150)
    plt.close(fig)


def figure_12b(runs, output):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for label, directory in runs:
        data = read_csv(os.path.join(directory, "statistics.csv"))
        t = data["t_over_tau_d"]
        keep = t > 0
        ax.plot(t[keep], data["pore_curvature_1"][keep], label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("t / tau_d")
    ax.set_ylabel("largest surface curvature x R, pore 1")
    mark_events(ax, read_events(runs[0][1]), kinds=("self_contact", "crease"))
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "porous_gel_fig12b.png"), dpi=150)
    plt.close(fig)


def mirrored(points, values):
    """The cell's points reflected into a 3 x 3 array of cells (the cell's edges are mirrors)."""
    xs, ys, vs = [], [], []
    for i in (-1, 0, 1):
        for j in (-1, 0, 1):
            x = points[:, 0] if i == 0 else (-points[:, 0] if i == -1 else 2 * CELL - points[:, 0])
            y = points[:, 1] if j == 0 else (-points[:, 1] if j == -1 else 2 * CELL - points[:, 1])
            xs.append(x)
            ys.append(y)
            vs.append(values)
    return np.concatenate(xs), np.concatenate(ys), np.concatenate(vs)


def nearest_data_sets(directory, times):
    data_sets = read_pvd(directory)
    chosen = []
    for t in times:
        best = min(data_sets, key=lambda d: abs(d[0] - t))
        if best not in chosen:
            chosen.append(best)
    return chosen


def figure_11(directory, times, output):
    chosen = nearest_data_sets(directory, times)
    columns = 4
    rows = (len(chosen) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.2 * columns, 3.2 * rows), squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, (t, path) in zip(axes.flat, chosen):
        points, arrays = read_vtu(path)
        volume = arrays["kind"] == 0
        x, y, mu = mirrored(points[volume], arrays["mu_over_kT"][volume])
        ax.scatter(x, y, c=mu, s=0.02, cmap="viridis", vmin=-0.146, vmax=0., rasterized=True)
        ax.set_aspect("equal")
        ax.set_xlim(-CELL, 2 * CELL)
        ax.set_ylim(-CELL, 2 * CELL)
        ax.set_title(f"t = {t:.4g} tau_d", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "porous_gel_fig11.png"), dpi=90)
    plt.close(fig)


def pore_polyline(path, pore):
    """(volume points, the surface points of pore 1 ... 4 in order along the boundary) of a .vtu."""
    points, arrays = read_vtu(path)
    initial = points - arrays["displacement"]
    centre = np.array([[0., 0.], [CELL, 0.], [0., CELL], [CELL, CELL]])[pore - 1]
    offset = initial[:, :2] - centre
    surface = (arrays["kind"] > 0) & (np.abs(np.linalg.norm(offset, axis=1) - 1.) < 1e-3)
    order = np.argsort(np.arctan2(offset[surface, 1], offset[surface, 0]))
    return points[arrays["kind"] == 0], points[surface][order]


def figure_12c(directory, output):
    creases = [t for name, t, pore in read_events(directory) if name == "crease" and pore == 1]
    if not creases:
        print("fig12c: no crease of pore 1 in events.csv; skipped")
        return
    data_sets = read_pvd(directory)
    index = min(range(len(data_sets)), key=lambda i: abs(data_sets[i][0] - creases[0]))
    chosen = data_sets[max(0, index - 1):index + 2]
    lines = [pore_polyline(path, 1) for _, path in chosen]
    # The window: around the sharpest turn of the polyline at the data set nearest the crease.
    line = lines[min(1, len(lines) - 1)][1]
    d = np.diff(line[:, :2], axis=0)
    turning = np.abs(np.arctan2(d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0],
                              (d[:-1] * d[1:]).sum(axis=1)))
    centre = line[1 + np.argmax(turning), :2]
    half = 0.3
    fig, axes = plt.subplots(1, len(chosen), figsize=(3.6 * len(chosen), 3.6), squeeze=False)
    for ax, (t, path), (volume_points, line) in zip(axes[0], chosen, lines):
        ax.scatter(volume_points[:, 0], volume_points[:, 1], s=0.5, c="tab:blue", rasterized=True)
        ax.plot(line[:, 0], line[:, 1], "-o", color="tab:red", markersize=2, linewidth=0.8)
        ax.set_aspect("equal")
        ax.set_xlim(centre[0] - half, centre[0] + half)
        ax.set_ylim(centre[1] - half, centre[1] + half)
        ax.set_title(f"pore 1, t = {t:.4g} tau_d", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "porous_gel_fig12c.png"), dpi=150)
    plt.close(fig)


def figure_13(runs, output):
    fig, axes = plt.subplots(1, len(runs), figsize=(4 * len(runs), 4), squeeze=False)
    for ax, (label, directory) in zip(axes[0], runs):
        t, path = read_pvd(directory)[-1]
        points, arrays = read_vtu(path)
        volume = arrays["kind"] == 0
        ax.scatter(points[volume, 0], points[volume, 1], s=0.02, c="tab:blue", rasterized=True)
        ax.scatter(points[~volume, 0], points[~volume, 1], s=1.5, c="tab:red")
        ax.set_aspect("equal")
        ax.set_xlim(0, CELL)
        ax.set_ylim(0, CELL)
        ax.set_title(f"{label}, t = {t:.4g} tau_d", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "porous_gel_fig13.png"), dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--run", action="append", required=True, help="LABEL=DIR")
    parser.add_argument("--snapshots", help="output directory whose particles.pvd Fig. 11 shows")
    parser.add_argument("--times", default="0,9.8,31,103,127,144,165,576.3",
                        help="t/tau_d of the Fig. 11 panels (nearest output times)")
    parser.add_argument("--output", required=True)
    arguments = parser.parse_args()
    runs = [tuple(run.rsplit("=", 1)) for run in arguments.run]
    os.makedirs(arguments.output, exist_ok=True)
    figure_12a(runs[0][1], arguments.output)
    figure_12b(runs, arguments.output)
    figure_13(runs, arguments.output)
    if arguments.snapshots:
        figure_11(arguments.snapshots, [float(t) for t in arguments.times.split(",")],
                  arguments.output)
        figure_12c(arguments.snapshots, arguments.output)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Paper §4.3 (swell-induced buckling of a gel column): Fig. 9, 10a and 10b from gelmpm output
directories of prm/column_buckling.prm (doc/column_buckling.md).

  /usr/bin/python3 contrib/plotting/column_buckling.py --run LABEL=DIR [--run LABEL=DIR ...]
                   [--snapshots DIR] [--times 0.2,0.3,...] --output DIR

Each --run is one output directory (statistics.csv with the columns centre_offset_x,
centre_distance and eig_1 ... eig_k, stability.csv if a loss of stability was bracketed).

Outputs (into --output DIR):
  fig10a_centre_distance.png  the separation of the centres of the top and bottom faces
                              (centre_distance; centre_offset_x thin, dashed) against t/tau_d, one
                              curve per run, the bracketed onset marked
  fig10b_schur_eigenvalues.png the Schur-complement eigenvalues eig_1 ... eig_k of the first run
                              against t/tau_d (symmetric log scale: they change sign)
  fig9_phi.png                with --snapshots DIR: the material points of DIR's particles.pvd at
                              the output times nearest to --times, coloured by the solvent volume
                              fraction phi, at their current positions, in panels of three
The time axes are logarithmic when the runs span more than two decades (the full run to
2154.4 tau_d), linear otherwise.
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


def onset(directory):
    """(t_stable, t_unstable) of the first bracketed loss of stability, or None."""
    path = os.path.join(directory, "stability.csv")
    if not os.path.exists(path):
        return None
    table = read_csv(path)
    if len(table.get("t_stable", [])) == 0:
        return None
    return table["t_stable"][0], table["t_unstable"][0]


def time_axis(ax, times):
    """Logarithmic from the first step on when the times span more than two decades."""
    positive = [t for t in times if t > 0.]
    if positive and max(positive) / min(positive) > 100.:
        ax.set_xscale("log")
        ax.set_xlim(min(positive), max(positive) * 1.2)


def figure_10a(runs, output):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    all_times = []
    for k, (label, directory) in enumerate(runs):
        s = read_csv(os.path.join(directory, "statistics.csv"))
        colour = "C%d" % k
        # Curves that nearly coincide (the amplitude study) stay visible: wide ones first.
        width = max(3.5 - 1.2 * k, 0.8)
        ax.plot(s["t_over_tau_d"], s["centre_distance"], color=colour, lw=width, label=label)
        ax.plot(s["t_over_tau_d"], s["centre_offset_x"], color="k", ls="--", lw=0.6)
        all_times.extend(s["t_over_tau_d"])
        bracket = onset(directory)
        if bracket is not None:
            ax.axvline(0.5 * (bracket[0] + bracket[1]), color=colour, ls=":", lw=0.8)
    ax.axvline(0.28, color="k", ls="-.", lw=0.8, label="paper: onset 0.28 $\\tau_d$")
    ax.set_xlabel("$t/\\tau_d$")
    time_axis(ax, all_times)
    ax.set_ylabel("centre distance / H  (dashed: offset in x)")
    ax.set_title("Fig. 10a: separation of the centres of top and bottom")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "fig10a_centre_distance.png"), dpi=150)


def figure_10b(label, directory, output):
    s = read_csv(os.path.join(directory, "statistics.csv"))
    columns = sorted((c for c in s if c.startswith("eig_")), key=lambda c: int(c[4:]))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for c in columns:
        ax.plot(s["t_over_tau_d"], s[c], marker=".", ms=3, lw=0.8, label=c)
    ax.set_yscale("symlog", linthresh=1e-7)
    ax.axhline(0., color="k", lw=0.5)
    bracket = onset(directory)
    if bracket is not None:
        ax.axvline(0.5 * (bracket[0] + bracket[1]), color="k", ls=":", lw=0.8, label="onset")
    time_axis(ax, s["t_over_tau_d"])
    ax.set_xlabel("$t/\\tau_d$")
    ax.set_ylabel("Schur-complement eigenvalues")
    ax.set_title("Fig. 10b: smallest eigenvalues of S (%s)" % label)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(output, "fig10b_schur_eigenvalues.png"), dpi=150)


def figure_9(directory, times, output):
    series = read_pvd(directory)
    chosen = []
    for t in times:
        nearest = min(series, key=lambda item: abs(item[0] - t))
        if nearest not in chosen:
            chosen.append(nearest)
    snapshots = [(t, read_vtu(path)) for t, path in chosen]
    x_all = np.concatenate([points[:, 0] for _, (points, _) in snapshots])
    y_all = np.concatenate([points[:, 1] for _, (points, _) in snapshots])
    x_range = (x_all.min() - 0.3, x_all.max() + 0.3)
    y_range = (y_all.min() - 0.3, y_all.max() + 0.3)
    columns = min(3, len(snapshots))
    rows = (len(snapshots) + columns - 1) // columns
    width = 2.2 * max((x_range[1] - x_range[0]) / (y_range[1] - y_range[0]), 0.4)
    fig, axes = plt.subplots(rows, columns, figsize=(width * columns + 1.0, 2.4 * rows + 0.4),
                             squeeze=False)
    scatter = None
    for ax, (t, (points, fields)) in zip(axes.flat, snapshots):
        volume = fields["kind"] == 0
        scatter = ax.scatter(points[volume, 0], points[volume, 1], c=fields["phi"][volume],
                             s=0.05, cmap="viridis", vmin=0.5, vmax=0.95, rasterized=True)
        ax.set_aspect("equal")
        ax.set_title("t = %.4g $\\tau_d$" % t, fontsize=9)
        ax.set_xlim(*x_range)
        ax.set_ylim(*y_range)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(snapshots):]:
        ax.axis("off")
    fig.colorbar(scatter, ax=axes.ravel().tolist(), shrink=0.8,
                 label="solvent volume fraction $\\phi$")
    fig.savefig(os.path.join(output, "fig9_phi.png"), dpi=150, bbox_inches="tight")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--run", action="append", required=True, help="LABEL=DIR")
    parser.add_argument("--snapshots", help="output directory whose particles.pvd Fig. 9 shows")
    parser.add_argument("--times", default="0.2,0.25,0.3,0.4,0.6",
                        help="comma-separated times (tau_d) for Fig. 9")
    parser.add_argument("--output", required=True)
    args = parser.parse_args()
    runs = [tuple(r.split("=", 1)) for r in args.run]
    os.makedirs(args.output, exist_ok=True)
    figure_10a(runs, args.output)
    figure_10b(runs[0][0], runs[0][1], args.output)
    if args.snapshots:
        figure_9(args.snapshots, [float(t) for t in args.times.split(",")], args.output)


if __name__ == "__main__":
    main()

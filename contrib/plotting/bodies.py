#!/usr/bin/python3
"""The material points of a run at a few times, coloured by mu/(k_BT): how a body from a level set
or a mesh (doc/material_points.md, "Bodies from a level set or a mesh") deforms.

Reads particles.pvd of an output directory and draws, side by side, the data sets nearest to the
given times (volume points small, surface points larger), on a common colour scale.

  /usr/bin/python3 contrib/plotting/bodies.py --run out/gripper_finger --times 0,10,25,100 \\
      --output doc/figures/bodies_gripper_finger.png

Needs numpy, matplotlib and VTK's Python module (Debian: python3-numpy python3-matplotlib
python3-vtk9). Use /usr/bin/python3, which sees Debian's packages.
"""

import argparse

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from gelmpm_files import read_pvd, read_vtu  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run", required=True, help="output directory of the run")
    parser.add_argument("--times", required=True, help="comma-separated times in tau_d")
    parser.add_argument("--output", required=True, help="the PNG to write")
    parser.add_argument("--title", default="", help="title above the panels")
    args = parser.parse_args()

    series = read_pvd(args.run)
    wanted = [float(t) for t in args.times.split(",")]
    chosen = [min(series, key=lambda item: abs(item[0] - t)) for t in wanted]
    data = [(time, *read_vtu(path)) for time, path in chosen]

    everything = np.vstack([points for _, points, _ in data])
    lower, upper = everything.min(axis=0), everything.max(axis=0)
    margin = 0.05 * (upper - lower).max()
    mu = np.concatenate([arrays["mu_over_kT"] for _, _, arrays in data])
    scale = (mu.min(), mu.max())

    figure, axes = plt.subplots(1, len(data), figsize=(3.2 * len(data), 4.2), squeeze=False)
    for axis, (time, points, arrays) in zip(axes[0], data):
        volume = arrays["kind"] == 0
        shown = axis.scatter(points[volume, 0], points[volume, 1], c=arrays["mu_over_kT"][volume],
                             s=1, vmin=scale[0], vmax=scale[1], cmap="viridis", linewidths=0)
        axis.scatter(points[~volume, 0], points[~volume, 1], c=arrays["mu_over_kT"][~volume],
                     s=4, vmin=scale[0], vmax=scale[1], cmap="viridis", edgecolors="k",
                     linewidths=0.2)
        axis.set_xlim(lower[0] - margin, upper[0] + margin)
        axis.set_ylim(lower[1] - margin, upper[1] + margin)
        axis.set_aspect("equal")
        axis.set_title(f"t = {time:.3g} $\\tau_d$")
    figure.colorbar(shown, ax=axes[0].tolist(), label="$\\mu/k_BT$", shrink=0.8)
    if args.title:
        figure.suptitle(args.title)
    figure.savefig(args.output, dpi=110, bbox_inches="tight")
    print(f"wrote {args.output}: {len(data)} data sets at t = "
          + ", ".join(f"{time:.4g}" for time, _, _ in data))


if __name__ == "__main__":
    main()

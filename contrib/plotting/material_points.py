#!/usr/bin/python3
"""Pictures of the material points and of the cell classification of a scene's initial state.

Reads what `gelmpm` writes with `Output/Write grid = true` (doc/output.md): the first data set
(t = 0) of particles.pvd and of grid.pvd in a run's output directory, and parameters.prm there.
Draws one PNG per run with three panels:

  (a) the displacement grid, cells coloured by their class in the u space (paper §3.5, Fig. 4b:
      interior light blue, boundary blue, outer white), the surface points on top;
  (b) the same for the chemical-potential space (its cells drawn on the u grid they cover);
  (c) a zoom window: u grid lines (thin), mu grid lines (thick), u cell classes, volume points
      (black dots) and surface points (coloured by their boundary piece).

and prints, and writes next to the PNG as <name>.md, the counts: volume and surface points (by
kind and by piece), u cells and mu cells by class.

Usage (one --run per scene; NAME is the PNG's name, DIR the output directory, and the optional
ZOOM = x0,x1,y0,y1 the window of panel (c), default: the lower-left corner of the body):

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  build/gelmpm --set "Output/Directory=out/column" --set "Output/Write grid=true" \\
               --set "Time stepping/End time=1e-9" prm/column_buckling.prm
  /usr/bin/python3 contrib/plotting/material_points.py --output doc/figures \\
      --run "column_buckling=out/column=0.9,1.6,0.9,1.4"

Needs numpy, matplotlib and VTK's Python module (Debian: python3-numpy python3-matplotlib
python3-vtk9). Use /usr/bin/python3, which sees Debian's packages.
"""

import argparse
import os
import re
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

from gelmpm_files import read_pvd, read_vtu as read_vtu_file  # noqa: E402

KIND_NAMES = ["interior", "boundary", "outer"]
KIND_COLOURS = ["#cfe3f7", "#4a90d9", "#ffffff"]  # paper Fig. 4b: light blue, blue, white
POINT_KIND_NAMES = ["volume", "Dirichlet-Dirichlet", "Dirichlet-Neumann", "Neumann-Dirichlet",
                    "Neumann-Neumann"]


# ------------------------------------------------------------------------------------------------
# Input

def first_data_set(directory, series):
    """Path and time of the first (t = 0) data set of <series>.pvd in the output directory."""
    time, path = read_pvd(directory, series)[0]
    return path, time


def read_vtu(file_name):
    """(points in the plane, point arrays, cells as lists of point ids) of a .vtu file."""
    points, arrays, cells = read_vtu_file(file_name, with_cells=True)
    return points[:, :2], arrays, cells


def parameter(directory, name, default):
    """Value of entry @p name in the run's parameters.prm (the parameters as used)."""
    path = os.path.join(directory, "parameters.prm")
    if os.path.isfile(path):
        with open(path) as f:
            for line in f:
                match = re.match(r"\s*set\s+" + re.escape(name) + r"\s*=\s*(.*?)\s*$", line)
                if match:
                    return match.group(1)
    return default


class Grid:
    """The background grid of grid-00000.vtu as structured arrays (row j, column i)."""

    def __init__(self, file_name):
        points, arrays, cells = read_vtu(file_name)
        # DataOut writes each cell's own points; per-cell fields are constant on them.
        first = cells[:, 0]
        corners = points[cells]  # (n_cells, 4, 2)
        self.lower = corners.min(axis=(0, 1))
        self.upper = corners.max(axis=(0, 1))
        size = corners.max(axis=1) - corners.min(axis=1)
        self.h = size[0]  # cell size per direction
        self.n = np.rint((self.upper - self.lower) / self.h).astype(int)
        centre = corners.mean(axis=1)
        index = np.floor((centre - self.lower) / self.h).astype(int)
        self.u_kind = np.full((self.n[1], self.n[0]), 2)
        self.mu_kind = np.full((self.n[1], self.n[0]), 2)
        self.points = np.zeros((self.n[1], self.n[0]), dtype=int)
        self.u_kind[index[:, 1], index[:, 0]] = np.rint(arrays["u_cell_kind"][first])
        self.mu_kind[index[:, 1], index[:, 0]] = np.rint(arrays["mu_cell_kind"][first])
        self.points[index[:, 1], index[:, 0]] = np.rint(arrays["n_volume_points"][first])

    def extent(self):
        return [self.lower[0], self.upper[0], self.lower[1], self.upper[1]]


# ------------------------------------------------------------------------------------------------
# Counts

def counts(grid, particles, mu_factor, piece_names=()):
    """The counts of the doc: points by kind and piece, cells by class in both spaces."""
    kind = np.rint(particles["kind"]).astype(int)
    piece = np.rint(particles["piece"]).astype(int)
    result = {
        "volume points": int(np.sum(kind == 0)),
        "surface points": int(np.sum(kind > 0)),
        "volume points counted on the grid": int(grid.points.sum()),
    }
    for k in range(1, 5):
        if np.any(kind == k):
            result[f"surface points {POINT_KIND_NAMES[k]}"] = int(np.sum(kind == k))
    for p in sorted(set(piece[kind > 0])):
        label = piece_names[p] if 0 <= p < len(piece_names) else "no piece"
        result[f"surface points: {label}"] = int(np.sum((kind > 0) & (piece == p)))
    for k, name in enumerate(KIND_NAMES):
        result[f"u cells {name}"] = int(np.sum(grid.u_kind == k))
    for k, name in enumerate(KIND_NAMES):
        result[f"mu cells {name}"] = int(np.sum(grid.mu_kind == k)) // mu_factor
    return result


# ------------------------------------------------------------------------------------------------
# Pictures

def draw_kinds(axes, grid, kinds, title):
    axes.imshow(kinds, origin="lower", extent=grid.extent(), cmap=ListedColormap(KIND_COLOURS),
                vmin=-0.5, vmax=2.5, interpolation="nearest")
    axes.add_patch(Rectangle(grid.lower, *(grid.upper - grid.lower), fill=False, lw=0.8))
    axes.set_title(title, fontsize=9)
    axes.set_aspect("equal")
    axes.tick_params(labelsize=7)


def draw_grid_lines(axes, grid, spacing, window, **style):
    """Lines of a grid with cell sizes @p spacing (per direction) inside @p window."""
    x0, x1, y0, y1 = window
    for x in np.arange(grid.lower[0], grid.upper[0] + 0.5 * spacing[0], spacing[0]):
        if x0 <= x <= x1:
            axes.plot([x, x], [y0, y1], **style)
    for y in np.arange(grid.lower[1], grid.upper[1] + 0.5 * spacing[1], spacing[1]):
        if y0 <= y <= y1:
            axes.plot([x0, x1], [y, y], **style)


def draw_points(axes, positions, kind, piece, piece_names, window, marker_size):
    """Volume points (black) and surface points (coloured by piece) inside @p window."""
    x0, x1, y0, y1 = window
    inside = ((positions[:, 0] >= x0) & (positions[:, 0] <= x1) & (positions[:, 1] >= y0)
              & (positions[:, 1] <= y1))
    volume = inside & (kind == 0)
    axes.plot(positions[volume, 0], positions[volume, 1], ".", color="k", ms=marker_size,
              mew=0, label="volume points")
    colours = plt.get_cmap("tab10")
    for p in sorted(set(piece[kind > 0])):
        selected = inside & (kind > 0) & (piece == p)
        label = piece_names[p] if 0 <= p < len(piece_names) else "no piece"
        axes.plot(positions[selected, 0], positions[selected, 1], "o", ms=1.6 * marker_size + 0.8,
                  mew=0, color=colours((p + 3) % 10), label=f"surface: {label}")
    axes.set_xlim(x0, x1)
    axes.set_ylim(y0, y1)


def legend(figure, axes):
    """One legend for the figure, below the panels: cell classes, then the points of @p axes."""
    handles = [Patch(fc=KIND_COLOURS[k], ec="0.5", label=f"{KIND_NAMES[k]} cell")
               for k in range(3)]
    handles += axes.get_legend_handles_labels()[0]
    figure.legend(handles=handles, fontsize=7, loc="lower center", ncol=len(handles),
                  markerscale=2, frameon=False)


def picture(name, directory, zoom, output):
    """The PNG and the counts of one run."""
    grid_file, grid_time = first_data_set(directory, "grid")
    particle_file, particle_time = first_data_set(directory, "particles")
    grid = Grid(grid_file)
    positions, particles, _ = read_vtu(particle_file)
    coarse = parameter(directory, "Chemical potential grid", "coarse") == "coarse"
    piece_names = [p.strip() for p in parameter(directory, "Pieces", "").split(",") if p.strip()]
    mu_factor = 4 if coarse else 1
    h_mu = 2 * grid.h if coarse else grid.h  # per direction
    kind = np.rint(particles["kind"]).astype(int)
    piece = np.rint(particles["piece"]).astype(int)

    if zoom is None:
        corner = positions[kind == 0].min(axis=0)
        zoom = [corner[0] - 3 * grid.h[0], corner[0] + 5 * grid.h[0],
                corner[1] - 3 * grid.h[1], corner[1] + 5 * grid.h[1]]
    # Volume points about a third of their spacing across, in typographic points.
    n_per_cell = max(1., np.sqrt(grid.points.max()))
    zoom_width = zoom[1] - zoom[0]
    marker_size = min(3., 0.35 * 4.2 * 72 * (grid.h[0] / n_per_cell) / zoom_width)

    figure, axes = plt.subplots(1, 3, figsize=(13, 4.6))
    a = axes[0]
    draw_kinds(a, grid, grid.u_kind,
               f"u cells ({grid.n[0]} x {grid.n[1]}, h_u = {grid.h[0]:.4g}), surface points")
    surface = positions[kind > 0]
    a.plot(surface[:, 0], surface[:, 1], ",", color="#d62728", rasterized=True)
    a.add_patch(Rectangle((zoom[0], zoom[2]), zoom[1] - zoom[0], zoom[3] - zoom[2], fill=False,
                          ec="k", lw=0.8, ls="--"))

    a = axes[1]
    draw_kinds(a, grid, grid.u_kind, "zoom (dashed box): u cells and points")
    draw_grid_lines(a, grid, grid.h, zoom, color="0.45", lw=0.4)
    draw_points(a, positions, kind, piece, piece_names, zoom, marker_size)
    legend(figure, a)

    a = axes[2]
    draw_kinds(a, grid, grid.mu_kind,
               f"zoom: mu cells ({grid.n[0] * grid.h[0] / h_mu[0]:.0f} x "
               f"{grid.n[1] * grid.h[1] / h_mu[1]:.0f}, h_mu = {h_mu[0]:.4g}) and points")
    draw_grid_lines(a, grid, h_mu, zoom, color="0.15", lw=0.6)
    draw_points(a, positions, kind, piece, piece_names, zoom, marker_size)

    c = counts(grid, particles, mu_factor, piece_names)
    figure.suptitle(f"{name}: {c['volume points']:,} volume and {c['surface points']:,} surface "
                    f"points; u cells {c['u cells interior']:,} interior, "
                    f"{c['u cells boundary']:,} boundary; mu cells {c['mu cells interior']:,} "
                    f"interior, {c['mu cells boundary']:,} boundary (t = {grid_time:g})",
                    fontsize=9)
    figure.tight_layout(rect=(0, 0.06, 1, 1))
    png = os.path.join(output, f"material_points_{name}.png")
    figure.savefig(png, dpi=130)
    plt.close(figure)

    lines = [f"| {key} | {value:,} |" for key, value in c.items()]
    with open(os.path.join(output, f"material_points_{name}.md"), "w") as f:
        f.write(f"Counts of `{name}` at t = {particle_time:g} (from {directory}):\n\n"
                "| quantity | count |\n|---|---|\n" + "\n".join(lines) + "\n")
    print(f"{png}:")
    for key, value in c.items():
        print(f"  {key}: {value}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", action="append", required=True,
                        help="NAME=DIR[=x0,x1,y0,y1]: a picture NAME from the output directory "
                             "DIR, with an optional zoom window")
    parser.add_argument("--output", default=".", help="directory for the PNG and .md files")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    for run in args.run:
        fields = run.split("=")
        if len(fields) not in (2, 3):
            sys.exit(f"material_points.py: --run '{run}' is not NAME=DIR[=x0,x1,y0,y1]")
        zoom = [float(v) for v in fields[2].split(",")] if len(fields) == 3 else None
        if zoom is not None and len(zoom) != 4:
            sys.exit(f"material_points.py: the zoom window of '{run}' needs x0,x1,y0,y1")
        picture(fields[0], fields[1], zoom, args.output)


if __name__ == "__main__":
    main()

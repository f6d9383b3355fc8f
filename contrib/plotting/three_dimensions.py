#!/usr/bin/python3
"""The 3D scenes against 2D, the 1D reference and the closed-form equilibrium (doc/three_dimensions.md).

Inputs (output directories of gelmpm runs; each optional, its part is skipped if not given):
  --prism DIR       prm/constrained_swelling_3d.prm
  --prism-2d DIR    prm/constrained_swelling.prm with the 3D scene's settings (3 points per cell,
                    Tolerance 1e-2, growth factor 2, no caps): same h, same time control
  --reference DIR   gelmpm-swelling-1d --samples 4000 output (reference_thickness.csv)
  --cube DIR        prm/free_swelling_cube.prm
  --column DIR      prm/column_buckling_3d.prm

Outputs: a markdown table of the agreement on stdout, and --figure FILE (three panels).

  /usr/bin/python3 contrib/plotting/three_dimensions.py --prism out/prism --prism-2d out/prism2d \\
      --reference out/reference --cube out/cube --column out/column \\
      --figure doc/figures/three_dimensions.png

Needs numpy and matplotlib (bash contrib/setup.sh --plotting); run with /usr/bin/python3.
"""

import argparse
import math
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gelmpm_files import read_csv  # noqa: E402
from constrained_swelling import agreement_data, log_log_interpolation  # noqa: E402

CHI, N_NU, LAMBDA_0 = 0.1, 7.299e-3, 1.2801


def free_swelling_stretch(chi=CHI, n_nu=N_NU):
    """λ_eq of the dry network at μ = 0, stress-free and isotropic (eq. (22)): bisection."""
    def mu(stretch):
        j = stretch ** 3
        return n_nu * (1.0 / stretch - 1.0 / j) + math.log1p(-1.0 / j) + 1.0 / j + chi / j ** 2

    low, high = 1.0 + 1e-12, 10.0
    for _ in range(200):
        middle = 0.5 * (low + high)
        if mu(middle) < 0.0:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def prism_part(args, axes, rows):
    prism = agreement_data(args.prism, args.reference, profiles=False, note=lambda *_: None)
    axes.loglog(prism["t_ref"], prism["dh_ref"], "k-", lw=1, label="1D reference")
    axes.loglog(prism["t_mpm"], prism["dh_mpm"], "o", ms=3, mfc="none", label="3D prism")
    late = prism["t_mpm"] >= 0.01
    rows.append(("§4.1 prism 3D: max |Δh − Δh_ref|/Δh_eq, t ≥ 0.01 τ_d",
                 f"{np.max(np.abs(prism['error'][late])) * 100:.3f} %"))
    rows.append(("§4.1 prism 3D: (Δh − Δh_eq)/Δh_eq at the end",
                 f"{prism['end_error'] * 100:.4f} %"))
    if args.prism_2d:
        flat = agreement_data(args.prism_2d, args.reference, profiles=False, note=lambda *_: None)
        axes.loglog(flat["t_mpm"], flat["dh_mpm"], "+", ms=5, label="2D, same settings")
        rows.append(("§4.1 2D, same settings: max |Δh − Δh_ref|/Δh_eq, t ≥ 0.01 τ_d",
                     f"{np.max(np.abs(flat['error'][flat['t_mpm'] >= 0.01])) * 100:.3f} %"))
        t = prism["t_mpm"]
        inside = (t >= flat["t_mpm"].min()) & (t <= flat["t_mpm"].max())
        flat_at = log_log_interpolation(t[inside], flat["t_mpm"], flat["dh_mpm"])
        same_steps = len(t) == len(flat["t_mpm"]) and np.allclose(t, flat["t_mpm"], rtol=1e-6)
        difference = np.abs(prism["dh_mpm"][inside] - flat_at) / prism["dh_eq"]
        rows.append(("§4.1 3D against 2D: max |Δh_3D − Δh_2D|/Δh_eq" +
                     (" (same step times)" if same_steps else " (2D interpolated)"),
                     f"{difference.max():.1e} Δh_eq"))
        rows.append(("§4.1 steps 3D / 2D", f"{len(t)} / {len(flat['t_mpm'])}"))
    axes.set_xlabel("t / τ_d")
    axes.set_ylabel("Δh / h_0")
    axes.set_title("§4.1 as a square prism")
    axes.legend(fontsize=8)


def cube_part(args, axes, rows):
    statistics = read_csv(os.path.join(args.cube, "statistics.csv"))
    t = statistics["t_over_tau_d"]
    side = 1.0 + statistics["delta_h_over_h0"]
    stretch = free_swelling_stretch()
    ratio, j_eq = stretch / LAMBDA_0, stretch ** 3
    axes.semilogx(t[t > 0], side[t > 0], "o-", ms=3, label="side / initial side")
    axes.semilogx(t[t > 0], statistics["J_max"][t > 0] / j_eq * ratio, ":",
                  label="J_max / J_eq × ratio")
    axes.semilogx(t[t > 0], statistics["J_min"][t > 0] / j_eq * ratio, "--",
                  label="J_min / J_eq × ratio")
    axes.axhline(ratio, color="k", lw=1, label=f"λ_eq/λ_0 = {ratio:.6f}")
    axes.set_xlabel("t / τ_d")
    axes.set_title("free-swelling cube")
    axes.legend(fontsize=8)
    rows.append(("cube: λ_eq (eq. (22) at μ = 0), λ_eq/λ_0, J_eq",
                 f"{stretch:.6f}, {ratio:.6f}, {j_eq:.5f}"))
    rows.append(("cube at the end (t = %g τ_d): side/initial side, relative error" % t[-1],
                 f"{side[-1]:.6f}, {(side[-1] - ratio) / ratio:.2e}"))
    rows.append(("cube at the end: J_min, J_mean, J_max relative to J_eq",
                 ", ".join(f"{(statistics[c][-1] - j_eq) / j_eq:.2e}"
                           for c in ("J_min", "J_mean", "J_max"))))


def column_part(args, axes, rows):
    statistics = read_csv(os.path.join(args.column, "statistics.csv"))
    t = statistics["t_over_tau_d"]
    axes.plot(t, statistics["centre_offset_x"], "o-", ms=3, label="sway x (top − bottom)")
    axes.plot(t, statistics["centre_offset_y"], "+-", ms=4, label="sway y")
    axes.set_xlabel("t / τ_d")
    axes.set_ylabel("centre offset / H")
    axes.set_title("3D column")
    axes.legend(fontsize=8)
    rows.append(("column: sway x, y at the end (t = %g τ_d)" % t[-1],
                 f"{statistics['centre_offset_x'][-1]:.4f} H, "
                 f"{statistics['centre_offset_y'][-1]:.2e} H"))
    if "n_neg_uu" in statistics:
        negative = np.nonzero(statistics["n_neg_uu"] > 0)[0]
        if len(negative):
            first = negative[0]
            rows.append(("column: K_uu indefinite from (last stable step, first unstable)",
                         f"{t[first - 1]:.4f} – {t[first]:.4f} τ_d"))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    for name in ("prism", "prism-2d", "reference", "cube", "column"):
        parser.add_argument("--" + name)
    parser.add_argument("--figure")
    args = parser.parse_args()
    if args.prism and not args.reference:
        sys.exit("three_dimensions.py: --prism needs --reference")
    parts = [(args.prism, prism_part), (args.cube, cube_part), (args.column, column_part)]
    parts = [(d, f) for d, f in parts if d]
    if not parts:
        sys.exit("three_dimensions.py: give at least one of --prism, --cube, --column")
    figure, axes = plt.subplots(1, len(parts), figsize=(5 * len(parts), 4), squeeze=False)
    rows = []
    for (directory, part), ax in zip(parts, axes[0]):
        part(args, ax, rows)
    print("| quantity | value |\n|---|---|")
    for name, value in rows:
        print(f"| {name} | {value} |")
    if args.figure:
        figure.tight_layout()
        figure.savefig(args.figure, dpi=120)


if __name__ == "__main__":
    main()

"""Bilayer actuator (prm/bilayer_actuator.prm) against Timoshenko's bimetal formula.

Runs gelmpm for three chi of the passive layer (mismatch strains 0.65%, 1.4%, 3.3% at the bath
mu = -0.04) on two grids (8 and 16 cells through the thickness), fits a circle to the lower
surface's profile at the end (surface_bottom-*.csv, least squares, Kasa), and compares the
curvature with bilayer_reference.py (Timoshenko, drained plane-strain moduli from the
Flory-Rehner law). Prints a Markdown table; with --plot writes doc/figures/bilayer_curvature.png.

With --peer, also the body-fitted peer (gelmpm-fem-bilayer: the same two layers, Taylor-Hood on
square cells, 4, 8 and 16 through the thickness, the same circle fit to its lower surface): its
curvature converged in h (Richardson's extrapolation of the three meshes, the order estimated from
them), and the MPM's curvature against it. Equal resolution: 8 and 16 cells through the thickness
in both (h = 0.025 and 0.0125).

  /usr/bin/python3 contrib/benchmarks/bilayer.py [--gelmpm build/gelmpm] [--plot]
      [--peer [--fem-bilayer build/gelmpm-fem-bilayer]]
"""
import argparse
import glob
import os
import subprocess
import tempfile
import time

import numpy as np

from bilayer_reference import timoshenko

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
MU_B = -0.04


def fitted_curvature(directory):
    f = sorted(glob.glob(os.path.join(directory, "surface_bottom-*.csv")))[-1]
    d = np.genfromtxt(f, delimiter=",", names=True)
    x, y = d["x"], d["y"]
    A = np.c_[2 * x, 2 * y, np.ones_like(x)]
    c = np.linalg.lstsq(A, x**2 + y**2, rcond=None)[0]
    return 1.0 / np.sqrt(c[2] + c[0]**2 + c[1]**2)


def run(gelmpm, chi, cells, directory):
    bath = f"{MU_B} * min(t, 1) - 0.1459745 * max(1 - t, 0)"
    args = [gelmpm, os.path.join(TOP, "prm", "bilayer_actuator.prm"),
            "--set", f"Output/Directory={directory}",
            "--set", "Output/Write particles=false",
            "--set", f"Material/passive/Flory-Huggins chi={chi}",
            "--set", f"Background grid/Cells={cells[0]}, {cells[1]}",
            "--set", f"Boundary conditions/bottom/Chemical potential value/Function expression={bath}",
            "--set", f"Boundary conditions/bath/Chemical potential value/Function expression={bath}"]
    start = time.time()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return fitted_curvature(directory), time.time() - start


def run_peer(fem_bilayer, chi, cells, directory):
    args = [fem_bilayer, os.path.join(TOP, "prm", "bilayer_actuator.prm"),
            "--set", f"Material/passive/Flory-Huggins chi={chi}",
            "--set", f"FE peer/Cells={cells}", "--set", f"FE peer/Bath={MU_B}",
            "--set", f"FE peer/Output directory={directory}", "--quiet"]
    start = time.time()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    d = np.genfromtxt(os.path.join(directory, "statistics.csv"), delimiter=",", names=True)
    # The same fit as the MPM's, to the peer's lower surface at the end.
    surface = np.genfromtxt(os.path.join(directory, "surface_bottom.csv"), delimiter=",", names=True)
    x, y = surface["x"], surface["y"]
    A = np.c_[2 * x, 2 * y, np.ones_like(x)]
    c = np.linalg.lstsq(A, x**2 + y**2, rcond=None)[0]
    return 1.0 / np.sqrt(c[2] + c[0]**2 + c[1]**2), d["curvature"][-1], time.time() - start


def richardson(k, refinement=2.0):
    """The limit and order from values on three meshes refined by @p refinement each time."""
    k1, k2, k3 = k
    if (k2 - k1) * (k3 - k2) <= 0 or abs(k3 - k2) >= abs(k2 - k1):
        return k3, float("nan")
    p = np.log(abs(k2 - k1) / abs(k3 - k2)) / np.log(refinement)
    return k3 + (k3 - k2) / (refinement**p - 1), p


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gelmpm", default=os.path.join(TOP, "build", "gelmpm"))
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--peer", action="store_true",
                        help="also the body-fitted peer's curvature, converged in h")
    parser.add_argument("--fem-bilayer", default=os.path.join(TOP, "build", "gelmpm-fem-bilayer"))
    options = parser.parse_args()
    grids = {"h = 0.025 (8 cells through the thickness)": (120, 56),
             "h = 0.0125 (16 cells)": (240, 112)}
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for chi in (0.15, 0.2, 0.3):
            kappa_t, eps = timoshenko(0.1, chi, MU_B)
            for name, cells in grids.items():
                kappa, seconds = run(options.gelmpm, chi, cells, os.path.join(scratch, f"{chi}-{cells[0]}"))
                rows.append((chi, eps, name, kappa, kappa_t, seconds))
    print("| chi (passive) | mismatch | grid | MPM curvature | Timoshenko | MPM / Timoshenko - 1 | wall |")
    print("|---|---|---|---|---|---|---|")
    for chi, eps, name, kappa, kappa_t, seconds in rows:
        print(f"| {chi} | {100 * eps:.2f}% | {name} | {kappa:.5f} | {kappa_t:.5f} | "
              f"{100 * (kappa / kappa_t - 1):+.2f}% | {seconds:.1f} s |")
    if options.peer:
        peer_cells = (4, 8, 16)
        peer = {}
        with tempfile.TemporaryDirectory() as scratch:
            for chi in (0.15, 0.2, 0.3):
                for n in peer_cells:
                    peer[chi, n] = run_peer(options.fem_bilayer, chi, n,
                                            os.path.join(scratch, f"fem-{chi}-{n}"))
        print()
        print("| chi (passive) | peer, 4 / 8 / 16 cells through the thickness | peer limit (order) "
              "| wall (4 / 8 / 16) | MPM, 8 cells | MPM / peer limit - 1 | MPM, 16 cells "
              "| MPM / peer limit - 1 | peer limit / Timoshenko - 1 |")
        print("|---|---|---|---|---|---|---|---|---|")
        for chi in (0.15, 0.2, 0.3):
            k = [peer[chi, n][0] for n in peer_cells]
            limit, order = richardson(k)
            mpm = [r[3] for r in rows if r[0] == chi]
            kappa_t = [r[4] for r in rows if r[0] == chi][0]
            print(f"| {chi} | {k[0]:.5f} / {k[1]:.5f} / {k[2]:.5f} | {limit:.5f} ({order:.2f}) | "
                  + " / ".join(f"{peer[chi, n][2]:.1f}" for n in peer_cells) + " s | "
                  f"{mpm[0]:.5f} | {100 * (mpm[0] / limit - 1):+.2f}% | "
                  f"{mpm[1]:.5f} | {100 * (mpm[1] / limit - 1):+.2f}% | "
                  f"{100 * (limit / kappa_t - 1):+.2f}% |")
        # The tool's own fit (about the centroid, 8 points per face) against this script's.
        worst = max(abs(v[1] / v[0] - 1) for v in peer.values())
        print(f"\n(gelmpm-fem-bilayer's own curvature and this script's fit agree to {worst:.1e})")
    if options.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 3.5))
        first = [r for r in rows if r[2] == next(iter(grids))]
        ax.plot([100 * r[1] for r in first], [r[4] for r in first], "k--",
                label="Timoshenko (drained plane-strain moduli)")
        for name in grids:
            sel = [r for r in rows if r[2] == name]
            ax.plot([100 * r[1] for r in sel], [r[3] for r in sel], "o", label="MPM, " + name)
            bx.plot([100 * r[1] for r in sel], [100 * (r[3] / r[4] - 1) for r in sel], "o-",
                    label="MPM, " + name)
        ax.set_xlabel("mismatch strain (%)")
        ax.set_ylabel("curvature (1/length)")
        ax.legend(fontsize=7)
        bx.axhline(0, color="k", lw=0.5)
        bx.set_xlabel("mismatch strain (%)")
        bx.set_ylabel("MPM / Timoshenko - 1 (%)")
        bx.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(TOP, "doc", "figures", "bilayer_curvature.png"), dpi=120)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The flat punch force F(t) (prm/flat_punch.prm, paper §4.2): the MPM's `punch_force_y` against
the body-fitted peer's (gelmpm-fem-flat-punch, the consistent reaction at the held punch DoFs),
at equal resolution and against the peer's mesh limit (doc/flat_punch.md, "The punch force").

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  /usr/bin/python3 contrib/benchmarks/punch_force.py [--build build] [--gelmpm build/gelmpm]
      [--output output/punch_force] [--depth 0.05] [--cells 20,40] [--limit-cells 16,32,64]

Both models: the gel [0, H]^2 (H = 1; the MPM places it at (H/4, H/4) in its grid), the punch over
its left quarter, the scene's ramp and stepping, to 2300 tau_d; the force is the punch's on the
gel per unit thickness in G H (the same domain, the same unit; negative while it pushes down).
MPM: discretisation (iv) (h_u = 0.05 H) and (iii) (h_u = 0.025 H, the scene's), equal in
resolution to the peer's 20 x 20 and 40 x 40 cells (--cells). The peer's mesh limit is
Richardson's extrapolation of three more meshes (--limit-cells; the order is estimated from them).
The depth is 0.05 H, where the peer completes on every mesh (at the scene's 0.09 H, 20 x 20 cells
stall in the drainage at t = 2.6 tau_d: doc/flat_punch.md). The histories are
compared at the MPM's step times (the peer's force interpolated linearly in log t after the ramp,
linearly in t during it). Prints Markdown tables; writes <output>/punch_force.csv.
"""
import argparse
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SCENE = os.path.join(ROOT, "prm", "flat_punch.prm")
T_INC = 3.125e-6
# The times of the table in doc/flat_punch.md (mid-ramp, end of the ramp, then held).
TIMES = [1.5625e-6, 3.125e-6, 1.97e-3, 0.162, 1.58, 14.8, 138.0, 2300.0]


def read(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def run(command, log):
    start = time.time()
    with open(log, "w") as f:
        subprocess.run(command, check=True, stdout=f, stderr=subprocess.STDOUT)
    return time.time() - start


def interpolate(t, T, F):
    """F(t) from the history (T, F), linear in t up to the end of the ramp, in log t after it."""
    T, F = np.asarray(T), np.asarray(F)
    if t <= T_INC * (1 + 1e-9):
        return np.interp(t, T, F)
    held = T >= T_INC * (1 - 1e-9)
    return np.interp(np.log(t), np.log(T[held]), F[held])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--gelmpm", default=None, help="the MPM executable (default <build>/gelmpm)")
    parser.add_argument("--output", default="output/punch_force")
    parser.add_argument("--depth", type=float, default=0.05)
    parser.add_argument("--cells", default="20,40")
    parser.add_argument("--limit-cells", default="16,32,64")
    args = parser.parse_args()
    gelmpm = args.gelmpm or os.path.join(args.build, "gelmpm")
    os.makedirs(args.output, exist_ok=True)
    depth_expr = f"0; -{args.depth} * min(t / 3.125e-6, 1)"

    histories, walls = {}, {}
    for name, grid in (("MPM (iv), h_u = 0.05 H", "30, 30"), ("MPM (iii), h_u = 0.025 H", "60, 60")):
        d = os.path.join(args.output, "mpm-" + grid.replace(", ", "x"))
        walls[name] = run([gelmpm, SCENE, "--set", f"Output/Directory={d}",
                           "--set", "Output/Write particles=false",
                           "--set", f"Background grid/Cells={grid}",
                           "--set", f"Boundary conditions/punch/Displacement value/Function expression={depth_expr}"],
                          d + ".log")
        s = read(os.path.join(d, "statistics.csv"))
        histories[name] = (s["t_over_tau_d"], s["punch_force_y"])
        print(f"{name}: {len(s)} rows, {walls[name]:.1f} s", flush=True)
    mpm_times = histories["MPM (iii), h_u = 0.025 H"][0]

    equal = [int(c) for c in args.cells.split(",")]
    cells = [int(c) for c in args.limit_cells.split(",")]
    fe = {}
    for n in sorted(set(equal + cells)):
        d = os.path.join(args.output, f"fem-{n}")
        name = f"FE {n} x {n}, h = {1 / n:.4g} H"
        walls[name] = run([os.path.join(args.build, "gelmpm-fem-flat-punch"), SCENE,
                           "--set", f"FE peer/Cells={n}", "--set", f"FE peer/Depth={args.depth}",
                           "--set", f"FE peer/Output directory={d}", "--quiet"], d + ".log")
        s = read(os.path.join(d, "statistics.csv"))
        histories[name] = (s["t_over_tau_d"][1:], s["punch_force_y"][1:])
        fe[n] = name
        print(f"{name}: {len(s) - 1} steps, {walls[name]:.1f} s", flush=True)

    # The peer's mesh limit at the table's times: Richardson on the three finest meshes.
    def fe_at(n, t):
        return interpolate(t, *histories[fe[n]])

    def limit(t):
        if len(cells) < 3:
            return np.nan, np.nan
        f1, f2, f3 = (fe_at(n, t) for n in cells[-3:])
        ratio = cells[-2] / cells[-3]
        if (f2 - f1) * (f3 - f2) <= 0 or abs(f3 - f2) >= abs(f2 - f1):
            return f3, np.nan  # not in the asymptotic range: the finest mesh
        p = np.log(abs(f2 - f1) / abs(f3 - f2)) / np.log(ratio)
        return f3 + (f3 - f2) / (ratio**p - 1), p

    names = list(histories)
    if len(cells) >= 3:
        print(f"\npeer limit: Richardson on {cells[-3:]} cells")
    header = "| t/τ_d | " + " | ".join(f"−F, {n}" for n in names) + " | −F, FE limit | order |"
    print("\n" + header)
    print("|" + "---|" * (len(names) + 3))
    rows = []
    for t in TIMES:
        values = [interpolate(t, *histories[n]) for n in names]
        lim, p = limit(t)
        rows.append([t] + values + [lim])
        print(f"| {t:.4g} | " + " | ".join(f"{-v:.5f}" for v in values) +
              f" | {-lim:.5f} | {p:.2f} |")

    # Differences over the whole history, at the MPM (iii) step times from mid-ramp on.
    print("\n| pair | max \\|ΔF\\|/\\|F\\| over the history | at t/τ_d | at F(0⁺) | at F(∞) |")
    print("|---|---|---|---|---|")
    ts = mpm_times[mpm_times >= 0.5 * T_INC - 1e-15]
    pairs = [("MPM (iv), h_u = 0.05 H", fe.get(20)), ("MPM (iii), h_u = 0.025 H", fe.get(40))]
    pairs += [(n, "limit") for n in names if n.startswith("MPM")]
    pairs += [(fe[n], "limit") for n in sorted(set(equal + cells))] if len(cells) >= 3 else []
    for a, b in pairs:
        if b is None:
            continue
        fa = np.array([interpolate(t, *histories[a]) for t in ts])
        fb = np.array([limit(t)[0] if b == "limit" else interpolate(t, *histories[b]) for t in ts])
        rel = np.abs(fa / fb - 1)
        k = int(np.argmax(rel))
        at = lambda t: 100 * (interpolate(t, *histories[a]) /
                              (limit(t)[0] if b == "limit" else interpolate(t, *histories[b])) - 1)
        print(f"| {a} / {'FE limit' if b == 'limit' else b} − 1 | {100 * rel[k]:.2f} % | "
              f"{ts[k]:.3g} | {at(T_INC):+.2f} % | {at(2300.0):+.2f} % |")
    print("\nwall times: " + ", ".join(f"{n} {w:.1f} s" for n, w in walls.items()))

    with open(os.path.join(args.output, "punch_force.csv"), "w") as f:
        f.write("t_over_tau_d," + ",".join(f'"{n}"' for n in names) + ",fe_limit\n")
        for r in rows:
            f.write(",".join(f"{v:.8g}" for v in r) + "\n")


if __name__ == "__main__":
    sys.exit(main())

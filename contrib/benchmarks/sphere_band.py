#!/usr/bin/env python3
"""The axisymmetric swelling sphere on a band that follows its surface, against uniform grids.

Runs prm/swelling_sphere.prm (a gel sphere of radius 0.5 in its meridian plane, its bath ramped
over 4 tau_d) to --end tau_d without particle output, alternating the variants --repeat times:
  coarse    the scene's grid (18 x 20 cells, h = 0.0625);
  fine      the uniform grid twice as fine (36 x 40 cells);
  band W    the scene's grid refined once within W of the current surface
            ('Background grid/Refinement band = W', marked anew every step), for each W of --bands;
  static    the scene's grid refined once in the fixed band |r - 0.5| <= 0.15 ('Refinement
            region'), unless --no-static;
and compares the radius with the spherical finite-volume reference gelmpm-swelling-sphere-1d
(--ramp 4). Prints and writes <output>/sphere_band.md: per variant the worst |r - r_ref| over the
steps with t >= 1 tau_d in units of the equilibrium change r_eq - R_0 (with its time), the time
reached, steps, unknowns u + mu (first -> last step), volume points at the end, and the median wall
time with its ratio to the fine grid's.

    python3 contrib/benchmarks/sphere_band.py [--output DIR] [--repeat N] [--end T]
        [--bands 0.1,0.15] [--tolerance 1e-3] [--no-static]

Environment: GELMPM_BUILD_DIR (default: build). Needs only Python's standard library.
"""
import argparse
import bisect
import os
import statistics
import subprocess
import sys
import time

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
from gelmpm_files import read_rows  # noqa: E402

EQUILIBRIUM = 1.834936045  # r_eq / R_0 of the scene's gel at mu = 0 (gelmpm-swelling-sphere-1d)


def reference(build, out, end):
    directory = os.path.join(out, "reference")
    if not os.path.exists(os.path.join(directory, "reference_radius.csv")):
        subprocess.run([os.path.join(build, "gelmpm-swelling-sphere-1d"), "--ramp", "4",
                        "--samples", "4000", "--times", f"1,{end:g}", "--output", directory],
                       check=True, stdout=subprocess.DEVNULL)
    rows = read_rows(os.path.join(directory, "reference_radius.csv"))
    t = [float(r["t_over_tau_d"]) for r in rows]
    r = [float(r["r_over_R0"]) for r in rows]

    def at(time_):
        i = min(max(bisect.bisect(t, time_), 1), len(t) - 1)
        w = (time_ - t[i - 1]) / (t[i] - t[i - 1])
        return r[i - 1] * (1 - w) + r[i] * w
    return at


def variants(bands, static):
    result = [("coarse", []), ("fine", ["Background grid/Cells=36, 40"])]
    for w in bands:
        result.append((f"band {w:g}", [f"Background grid/Refinement band={w:g}"]))
    if static:
        result.append(("static", ["Background grid/Refinement region="
                                  "abs(sqrt(x^2 + y^2) - 0.5) - 0.15"]))
    return result


def run(build, out, name, sets, end, tolerance):
    directory = os.path.join(out, name.replace(" ", "_"))
    command = [os.path.join(build, "gelmpm"), "--set", f"Output/Directory={directory}",
               "--set", "Output/Write particles=false", "--set", f"Time stepping/End time={end:g}",
               "--set", f"Time stepping/Tolerance={tolerance:g}", "--set", "Time stepping/Stop at times="]
    for s in sets:
        command += ["--set", s]
    command.append(os.path.join(TOP, "prm", "swelling_sphere.prm"))
    start = time.monotonic()
    with open(directory + ".log", "w") as log:
        status = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.monotonic() - start
    print(f"  {name}: exit {status}, {wall:.1f} s", flush=True)
    return directory, status, wall


def evaluate(directory, ref):
    rows = read_rows(os.path.join(directory, "statistics.csv"))
    worst, worst_t = 0., 0.
    for r in rows[1:]:
        t = float(r["t_over_tau_d"])
        error = abs(float(r["radius_over_R0"]) - ref(t)) / (EQUILIBRIUM - 1.)
        if t >= 1. and error > worst:
            worst, worst_t = error, t
    first, last = rows[1], rows[-1]
    return {"worst": worst, "worst_t": worst_t, "reached": float(last["t_over_tau_d"]),
            "steps": len(rows) - 1,
            "unknowns": (int(first["n_dofs_u"]) + int(first["n_dofs_mu"]),
                         int(last["n_dofs_u"]) + int(last["n_dofs_mu"])),
            "points": int(last["n_particles"])}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", default=os.path.join(TOP, "output", "sphere_band"))
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--end", type=float, default=20.)
    parser.add_argument("--bands", default="0.1,0.15")
    parser.add_argument("--tolerance", type=float, default=1e-3)
    parser.add_argument("--no-static", action="store_true")
    args = parser.parse_args()
    build = os.path.abspath(os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build")))
    os.makedirs(args.output, exist_ok=True)
    ref = reference(build, args.output, args.end)
    chosen = variants([float(w) for w in args.bands.split(",") if w], not args.no_static)
    walls = {name: [] for name, _ in chosen}
    results = {}
    for _ in range(args.repeat):
        for name, sets in chosen:
            directory, status, wall = run(build, args.output, name, sets, args.end, args.tolerance)
            walls[name].append(wall)
            results[name] = (directory, status)
    lines = [f"| grid | worst over t ≥ 1 τ_d | reached τ_d | steps | unknowns (first → last) "
             f"| points at the end | wall (median) | ratio to fine |", "|---|---|---|---|---|---|---|---|"]
    fine_wall = statistics.median(walls["fine"])
    for name, _ in chosen:
        directory, status = results[name]
        e = evaluate(directory, ref)
        wall = statistics.median(walls[name])
        stopped = "" if status == 0 else f" (exit {status})"
        lines.append(f"| {name} | {100 * e['worst']:.2f} % ({e['worst_t']:.3g}) | {e['reached']:.4g}"
                     f"{stopped} | {e['steps']} | {e['unknowns'][0]} → {e['unknowns'][1]} "
                     f"| {e['points']} | {wall:.1f} s | {wall / fine_wall:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(args.output, "sphere_band.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()

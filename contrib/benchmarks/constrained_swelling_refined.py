#!/usr/bin/env python3
"""Paper §4.1 on a locally refined grid against the uniform grids: accuracy and wall time.

Runs, alternating so that a change of the machine's load shows in both, --repeat times each:
  paper     prm/constrained_swelling.prm (20 x 160 cells, steps growing by 1.25);
  refined   prm/constrained_swelling_refined.prm (the cells of 0.9 <= y <= 1.2 halved once,
            steps growing by 1.08);
  band      the same scene with its box replaced by a band that follows the top
            ('Refinement band = 0.1', 'Refinement band pieces = top'), unless --no-band;
  front R   the same scene with its box replaced by refinement where the points' mu spans more
            than R ('Refinement mu range', marked anew every step), for each R of --ranges;
            refined --levels times; with --budgets B1,B2 also once per budget B of unknowns
            ('Refinement budget', the finest moving levels dropped at a step beyond it);
  jump J    the same scene with its box replaced by refinement where the slope of mu changes
            by more than J over a cell ('Refinement mu gradient jump'), for each J of --jumps,
            refined --levels times;
  material  the same scene with its box replaced by refinement round the material that starts
            at y >= 0.9 ('Refinement material region = 0.9 - y'), with --material;
  uniform   prm/constrained_swelling.prm on 40 x 320 cells with steps growing by 1.05 (the
            uniform grid that is as accurate, doc/constrained_swelling.md), unless --no-uniform;
each to the scene's end (1713 tau_d) without particle output, and compares Delta h with the
finite-difference reference gelmpm-swelling-1d (a step of mu at t = 0+). Prints and writes
<output>/refined.md: per variant the worst |Delta h / Delta h_ref - 1| over the steps with
t >= 1e-3 tau_d (with its time), Delta h at 1.197e-3 tau_d and at the end, steps, unknowns
(u + mu) at the first and the last step and the most at a step, and the median wall time with its ratio to the paper
setting's.

    python3 contrib/benchmarks/constrained_swelling_refined.py [--output DIR] [--repeat N]
        [--no-uniform] [--no-band] [--ranges 0.01,0.02] [--jumps 0.01,0.02] [--levels N]
        [--budgets B1,B2]
        [--material] [--end T]

Environment: GELMPM_BUILD_DIR (default: build). Needs only Python's standard library.
"""
import argparse
import bisect
import math
import os
import statistics
import subprocess
import sys
import time

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
from gelmpm_files import read_rows  # noqa: E402

VARIANTS = [
    ("paper", "constrained_swelling.prm", []),
    ("refined", "constrained_swelling_refined.prm", []),
    ("band", "constrained_swelling_refined.prm",
     ["Background grid/Refinement boxes=", "Background grid/Refinement band=0.1",
      "Background grid/Refinement band pieces=top"]),
    ("uniform", "constrained_swelling.prm",
     ["Background grid/Cells=40, 320", "Time stepping/Growth factor=1.05"]),
]


def reference(build, out, end):
    directory = os.path.join(out, "reference")
    if not os.path.exists(os.path.join(directory, "reference_thickness.csv")):
        subprocess.run([os.path.join(build, "gelmpm-swelling-1d"), "--samples", "4000", "--times",
                        f"0.001197,0.01,1,{end:g}", "--output", directory], check=True,
                       stdout=subprocess.DEVNULL)
    rows = read_rows(os.path.join(directory, "reference_thickness.csv"))
    t = [math.log(float(r["t_over_tau_d"])) for r in rows]
    d = [math.log(float(r["delta_h_over_h0"])) for r in rows]

    def at(time_):
        x = math.log(time_)
        i = min(max(bisect.bisect(t, x), 1), len(t) - 1)
        w = (x - t[i - 1]) / (t[i] - t[i - 1])
        return math.exp(d[i - 1] * (1 - w) + d[i] * w)
    return at


def run(build, out, name, scene, sets, end):
    directory = os.path.join(out, name.replace(",", "").replace(" ", "_"))
    command = [os.path.join(build, "gelmpm"), "--set", f"Output/Directory={directory}",
               "--set", "Output/Write particles=false", "--set", f"Time stepping/End time={end:g}"]
    for s in sets:
        command += ["--set", s]
    command.append(os.path.join(TOP, "prm", scene))
    start = time.monotonic()
    with open(directory + ".log", "w") as log:
        status = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.monotonic() - start
    print(f"  {name}: exit {status}, {wall:.1f} s", flush=True)
    return status, wall


def evaluate(out, name, ref):
    rows = read_rows(os.path.join(out, name.replace(",", "").replace(" ", "_"), "statistics.csv"))[1:]
    worst, worst_t, early = 0., 0., None
    for r in rows:
        t = float(r["t_over_tau_d"])
        ratio = float(r["delta_h_over_h0"]) / ref(t)
        if t >= 1e-3 and abs(ratio - 1) > abs(worst):
            worst, worst_t = ratio - 1, t
        if abs(t - 0.001197) < 1e-9:
            early = ratio
    last = rows[-1]
    return {"worst": worst, "worst_t": worst_t, "early": early,
            "end": float(last["delta_h_over_h0"]) / ref(float(last["t_over_tau_d"])),
            "steps": len(rows),
            "unknowns": (int(rows[0]["n_dofs_u"]) + int(rows[0]["n_dofs_mu"]),
                         int(last["n_dofs_u"]) + int(last["n_dofs_mu"])),
            "most": max(int(r["n_dofs_u"]) + int(r["n_dofs_mu"]) for r in rows)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", default=os.path.join(TOP, "output", "constrained_swelling_refined"))
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--no-uniform", action="store_true")
    parser.add_argument("--no-band", action="store_true")
    parser.add_argument("--ranges", default="", help="mu ranges of the 'front' variants")
    parser.add_argument("--jumps", default="", help="mu gradient jumps of the 'jump' variants")
    parser.add_argument("--levels", type=int, default=1, help="levels of the 'front' variants")
    parser.add_argument("--budgets", default="", help="budgets of unknowns of the 'front' variants")
    parser.add_argument("--material", action="store_true")
    parser.add_argument("--end", type=float, default=1713.)
    args = parser.parse_args()
    build = os.path.abspath(os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build")))
    os.makedirs(args.output, exist_ok=True)
    ref = reference(build, args.output, args.end)
    variants = [v for v in VARIANTS if not (args.no_uniform and v[0] == "uniform")
                and not (args.no_band and v[0] == "band")]
    for r in [float(x) for x in args.ranges.split(",") if x]:
        front = ["Background grid/Refinement boxes=", f"Background grid/Refinement mu range={r:g}",
                 f"Background grid/Refinement levels={args.levels}"]
        name = f"front {r:g}" + (f", {args.levels} levels" if args.levels > 1 else "")
        variants.append((name, "constrained_swelling_refined.prm", front))
        for b in [int(x) for x in args.budgets.split(",") if x]:
            variants.append((f"{name}, budget {b}", "constrained_swelling_refined.prm",
                             front + [f"Background grid/Refinement budget={b}"]))
    for j in [float(x) for x in args.jumps.split(",") if x]:
        variants.append((f"jump {j:g}" + (f", {args.levels} levels" if args.levels > 1 else ""),
                         "constrained_swelling_refined.prm",
                         ["Background grid/Refinement boxes=",
                          f"Background grid/Refinement mu gradient jump={j:g}",
                          f"Background grid/Refinement levels={args.levels}"]))
    if args.material:
        variants.append(("material", "constrained_swelling_refined.prm",
                         ["Background grid/Refinement boxes=",
                          "Background grid/Refinement material region=0.9 - y"]))
    walls = {v[0]: [] for v in variants}
    for k in range(args.repeat):
        for name, scene, sets in variants:
            status, wall = run(build, args.output, name, scene, sets, args.end)
            if status != 0:
                sys.exit(f"{name} failed with exit status {status}: see {args.output}/{name}.log")
            walls[name].append(wall)
    lines = ["| variant | worst over t ≥ 10⁻³ τ_d | Δh/Δh_ref at 1.197·10⁻³ | at the end | steps "
             "| unknowns (first → last, most) | wall (median) | ratio to paper |",
             "|---|---|---|---|---|---|---|---|"]
    paper_wall = statistics.median(walls["paper"])
    for name, _, _ in variants:
        e = evaluate(args.output, name, ref)
        wall = statistics.median(walls[name])
        lines.append(f"| {name} | {100 * e['worst']:+.2f} % ({e['worst_t']:.3g}) | {e['early']:.4f} "
                     f"| {e['end']:.5f} | {e['steps']} | {e['unknowns'][0]} → {e['unknowns'][1]}, {e['most']} "
                     f"| {wall:.1f} s | {wall / paper_wall:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(args.output, "refined.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()

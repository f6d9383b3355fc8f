#!/usr/bin/python3
"""Convergence of the finite-difference reference of paper §4.1 (gelmpm-swelling-1d) in space and time.

Runs build/gelmpm-swelling-1d (or --binary) for three sequences and tabulates Δh/h_0 at the chosen
times with the differences between consecutive levels and the observed order
p = log2(d_{k-1}/d_k) (each level halves the cell size and/or the relative step growth g - 1):

  space-time: n = 100 ... n_max cells with growth 1 + 0.64/n (as tests/reference/swelling_1d.cc)
  space:      n = 50 ... 800 cells, growth fixed at 1.0005 (time error the same at every level)
  time:       n = 400 cells, growth 1.16, 1.08, ..., 1.005 (space error the same at every level)

  /usr/bin/python3 contrib/benchmarks/swelling_1d_convergence.py --output out/reference_convergence

Writes convergence.md into --output (and prints it). Also reports the error of the default
settings of gelmpm-swelling-1d (800 cells, growth 1.01) against the finest space-time level.
"""

import argparse
import math
import os
import subprocess
import sys
import time


def run(binary, directory, cells, growth, times):
    """Δh/h_0 at each of @p times (12 digits from reference_thickness.csv) and the wall time."""
    os.makedirs(directory, exist_ok=True)
    start = time.time()
    subprocess.run([binary, "--cells", str(cells), "--growth", repr(growth),
                    "--times", ",".join(repr(t) for t in times), "--samples", "1",
                    "--output", directory],
                   check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - start
    values = {}
    with open(os.path.join(directory, "reference_thickness.csv"), encoding="utf-8") as csv:
        next(csv)
        for line in csv:
            t, dh = (float(x) for x in line.split(","))
            values[t] = dh
    return [values[min(values, key=lambda s: abs(s - t))] for t in times], seconds


def table(title, levels, results, times):
    lines = [f"**{title}**", "",
             "| cells | growth | " + " | ".join(
                 f"Δh/h_0 at t = {t:g} | difference | order" for t in times) + " | wall time |",
             "|---|---|" + "---|---|---|" * len(times) + "---|"]
    for k, ((cells, growth), (values, seconds)) in enumerate(zip(levels, results)):
        cells_text = [f"{cells}", f"{growth:.6g}"]
        for j in range(len(times)):
            difference = results[k][0][j] - results[k - 1][0][j] if k > 0 else None
            order = ""
            if k > 1:
                previous = results[k - 1][0][j] - results[k - 2][0][j]
                if difference != 0.0 and previous != 0.0:
                    order = f"{math.log2(abs(previous / difference)):.2f}"
            cells_text += [f"{values[j]:.10f}", "" if difference is None else f"{difference:.2e}", order]
        lines.append("| " + " | ".join(cells_text) + f" | {seconds:.2f} s |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser.add_argument("--binary", default=os.path.join(top, "build", "gelmpm-swelling-1d"))
    parser.add_argument("--output", default="output/reference_convergence")
    parser.add_argument("--times", default="0.1281,1.953,16.06",
                        help="comma-separated times at which Δh is compared")
    parser.add_argument("--max-cells", type=int, default=1600,
                        help="finest level of the space-time sequence (3200 takes about a minute)")
    arguments = parser.parse_args()
    times = [float(t) for t in arguments.times.split(",")]
    if not os.access(arguments.binary, os.X_OK):
        sys.exit(f"swelling_1d_convergence.py: {arguments.binary} not found; build first")

    sequences = []
    n, levels = 100, []
    while n <= arguments.max_cells:
        levels.append((n, 1.0 + 0.64 / n))
        n *= 2
    sequences.append(("Space and time together: n cells, step growth 1 + 0.64/n", levels))
    sequences.append(("Space: step growth fixed at 1.0005",
                      [(n, 1.0005) for n in (50, 100, 200, 400, 800)]))
    sequences.append(("Time: 400 cells",
                      [(400, g) for g in (1.16, 1.08, 1.04, 1.02, 1.01, 1.005)]))

    text = []
    finest = None
    for title, levels in sequences:
        results = []
        for cells, growth in levels:
            results.append(run(arguments.binary,
                               os.path.join(arguments.output, f"n{cells}_g{growth:.6g}"),
                               cells, growth, times))
        if finest is None:
            finest = results[-1][0]
        text.append(table(title, levels, results, times))

    default, seconds = run(arguments.binary, os.path.join(arguments.output, "default"), 800, 1.01, times)
    text.append("**Default settings (800 cells, growth 1.01) against the finest space-time level**\n\n"
                + "| t/τ_d | default | finest | difference |\n|---|---|---|---|\n"
                + "".join(f"| {t:g} | {d:.10f} | {f:.10f} | {d - f:.2e} |\n"
                          for t, d, f in zip(times, default, finest))
                + f"\n(default run to t = {max(times):g}: {seconds:.2f} s)\n")
    output = "\n".join(text)
    with open(os.path.join(arguments.output, "convergence.md"), "w", encoding="utf-8") as out:
        out.write(output)
    print(output)


if __name__ == "__main__":
    main()

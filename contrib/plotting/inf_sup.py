#!/usr/bin/env python3
"""Plot of the discrete inf-sup constant against the grid spacing (doc/inf_sup.md).

    /usr/bin/python3 contrib/plotting/inf_sup.py output/inf_sup_study/inf_sup.csv inf_sup.png

Reads the CSV written by contrib/benchmarks/inf_sup.sh; beta_h of each pair is normalised by its
value on the coarsest grid, so that the trend under refinement is what the plot shows.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="inf_sup.csv from contrib/benchmarks/inf_sup.sh")
    parser.add_argument("png", help="the plot to write")
    args = parser.parse_args()

    rows = list(csv.DictReader(open(args.csv)))
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for pair, marker in (("Q2-Q2", "s"), ("Q3-Q2", "^"), ("Q2-Q2SD", "o")):
        data = sorted((float(r["h"]), float(r["beta_h"])) for r in rows if r["pair"] == pair)
        if not data:
            continue
        h = [d[0] for d in data]
        beta = [d[1] / data[-1][1] for d in data]
        ax.loglog(h, beta, marker=marker, label=f"{pair} (coarsest: {data[-1][1]:.3g})")
    ax.set_xlabel("grid spacing $h_u / H$")
    ax.set_ylabel(r"$\beta_h / \beta_h(\mathrm{coarsest})$")
    ax.set_title("discrete inf-sup constant, undrained limit")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)


if __name__ == "__main__":
    main()

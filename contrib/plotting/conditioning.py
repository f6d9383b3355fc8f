#!/usr/bin/env python3
"""Plot of the condition numbers on cut cells with and without extended B-splines (doc/conditioning.md).

    cd build && ctest -R bspline/conditioning && cd ..
    /usr/bin/python3 contrib/plotting/conditioning.py \
        build/tests/bspline/conditioning.release/conditioning.csv doc/figures/conditioning.png

Reads the CSV the test bspline/conditioning writes beside its output. Values above 1e16 are at the
level of round-off (the smallest eigenvalue is below machine precision times the largest) and are
drawn hollow.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="conditioning.csv written by the test bspline/conditioning")
    parser.add_argument("png", help="the plot to write")
    args = parser.parse_args()

    rows = list(csv.DictReader(open(args.csv)))
    f = [float(r["fraction"]) for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    series = (("cond_mass_extended", "mass, extended", "C0", "o"),
              ("cond_mass_plain", "mass, plain", "C0", "x"),
              ("cond_laplace_nitsche_extended", "Laplace + Nitsche, extended", "C1", "o"),
              ("cond_laplace_nitsche_plain", "Laplace + Nitsche, plain", "C1", "x"))
    for key, label, colour, marker in series:
        values = [abs(float(r[key])) for r in rows]
        trusted = [(x, y) for x, y in zip(f, values) if y < 1e16]
        ax.loglog([x for x, _ in trusted], [y for _, y in trusted], marker=marker, color=colour,
                  linestyle="-" if "extended" in key else "--", label=label)
        rest = [(x, y) for x, y in zip(f, values) if y >= 1e16]
        if rest:
            ax.loglog([x for x, _ in rest], [y for _, y in rest], marker=marker, color=colour,
                      linestyle="none", markerfacecolor="none", alpha=0.5)
    ax.axhspan(1e16, 1e40, color="0.9", zorder=0)
    ax.set_ylim(1e1, 1e36)
    ax.invert_xaxis()
    ax.set_xlabel("material fraction f of the cut cells")
    ax.set_ylabel("condition number (2-norm)")
    ax.set_title("q = 2, cut cells, with and without extended B-splines")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Where the volume ratio J of the volume points spreads at the equilibrium of the torus eighth of
prm/torus_swelling_3d.prm (doc/own_scenes.md, section 12): reads the last particles file of an
output directory and prints the range of J relative to the closed form J_eq, over all volume
points and split by their initial depth below the tube's surface (in cells h) and by their
distance from the three planes of symmetry.

  /usr/bin/python3 contrib/benchmarks/torus_j_spread.py [--J-eq 12.95969] [--R 1] [--r 0.4]
      [--h 0.1] output/torus_swelling_3d
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphere_j_spread import particle_files, read_particles  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--J-eq", type=float, default=12.95969)
    parser.add_argument("--R", type=float, default=1.0)
    parser.add_argument("--r", type=float, default=0.4)
    parser.add_argument("--h", type=float, default=0.1)
    parser.add_argument("directory")
    a = parser.parse_args()
    data = read_particles(os.path.join(a.directory, particle_files(a.directory)[-1][1]))
    groups = {}
    for x, u, kind, J in zip(data["points"], data["displacement"], data["kind"], data["J"]):
        if round(kind) != 0:
            continue
        X = [x[d] - u[d] for d in range(3)]
        depth = (a.r - math.hypot(math.hypot(X[0], X[1]) - a.R, X[2])) / a.h
        near_plane = min(X) < a.h
        layer = ("outer cell layer (depth < 1 h)" if depth < 1 else
                 "1-2 h deep" if depth < 2 else "deeper than 2 h")
        for key in ("all", layer, "within h of a plane" if near_plane else "away from the planes"):
            groups.setdefault(key, []).append(J / a.J_eq - 1)
    print("| volume points | n | J/J_eq - 1 |")
    print("|---|---|---|")
    for key, values in groups.items():
        print(f"| {key} | {len(values)} | {100 * min(values):+.2f} % to {100 * max(values):+.2f} % |")


if __name__ == "__main__":
    main()

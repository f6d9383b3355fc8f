#!/usr/bin/python3
"""Where the volume ratio J of the material points spreads at the equilibrium of a freely swelling
body of revolution: prm/swelling_sphere.prm and its variants (doc/own_scenes.md, "The spread of J
at equilibrium"). Reads the last particles file of each output directory (written with
'Output/Write particles = true') and prints one Markdown row per directory: the range of J over
the volume points relative to the closed form J_eq, split into the points of the background cells
cut by the surface and those of the cells inside, the points that started more than two cells
below the surface (R_0 < R - 2h), the surface points, and the deviation of each volume point's J from the J of the affine map fitted by
least squares to the positions of its neighbours (X_0 -> x within 1.7 initial point spacings h/n,
times the point's own hoop stretch lambda_0 r / R_0): the part of the spread that varies from
point to point, which no smooth displacement field shows.

  /usr/bin/python3 contrib/benchmarks/sphere_j_spread.py [--J-eq 12.95969] [--radius 0.5]
      [--points-per-cell 5] output/swelling_sphere [...]
  /usr/bin/python3 contrib/benchmarks/sphere_j_spread.py --history output/swelling_sphere

--history prints, for every particles file of one run, the range of J and of J over the fitted J
minus 1 in the outermost layer R_0 > R - h and below it: when the point-to-point part of the
spread is made and whether it relaxes.

The sphere is centred at the origin of the meridian plane (x the radius, y the axis), or in 3D
(an eighth of a ball on its planes of symmetry, prm/free_swelling_sphere_3d.prm) at the origin,
the fit then a 3D affine map; the grid is read from the run's parameters.prm (uniform grids
only). Needs nothing beyond Python: it decodes
deal.II's zlib-compressed binary .vtu itself (no VTK).
"""
import argparse
import base64
import glob
import math
import os
import re
import struct
import sys
import zlib


def read_particles(file_name):
    """The arrays of a particles .vtu written by GelMPM: name -> list (tuples for vectors)."""
    text = open(file_name).read()
    arrays = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="(\w+)")?(?: NumberOfComponents="(\d+)")? '
               r'format="binary">\s*(.*?)\s*</DataArray>')
    for kind, name, components, data in re.findall(pattern, text, re.S):
        name = name or ("points" if "points" not in arrays else "unnamed")
        blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_length = 4 * ((4 * (3 + blocks) + 2) // 3)
        compressed, raw = base64.b64decode(data[header_length:]), b""
        while compressed:  # one zlib stream per block
            stream = zlib.decompressobj()
            raw += stream.decompress(compressed)
            compressed = stream.unused_data
        code = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B"}[kind]
        values = struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw)
        n = int(components or 1)
        arrays[name] = values if n == 1 else [values[i:i + n] for i in range(0, len(values), n)]
    return arrays


def dimension_of(directory):
    """2 or 3: the run's 'Dimension', from its parameters.prm."""
    for line in open(os.path.join(directory, "parameters.prm")):
        words = line.split()
        if words[:2] == ["set", "Dimension"]:
            return int(line.partition("=")[2])
    return 2


def grid_of(directory):
    """(lower corner, cell size) of the run's background grid, from its parameters.prm."""
    entries, section = {}, []
    for line in open(os.path.join(directory, "parameters.prm")):
        words = line.split()
        if words[:1] == ["subsection"]:
            section.append(" ".join(words[1:]))
        elif words[:1] == ["end"]:
            section.pop()
        elif words[:1] == ["set"] and section == ["Background grid"]:
            key, _, value = line.strip()[4:].partition("=")
            entries[key.strip()] = value
    lower, upper, cells = ([float(v) for v in entries[k].split(",")]
                           for k in ("Lower corner", "Upper corner", "Cells"))
    return lower, (upper[0] - lower[0]) / cells[0]


def points_of(file_name, dim=2):
    """The material points of a particles file: dicts of x, X_0, J and whether a volume point."""
    arrays = read_particles(file_name)
    points = []
    for x, u, J, kind in zip(arrays["points"], arrays["displacement"], arrays["J"],
                             arrays["kind"]):
        points.append({"x": tuple(x[:dim]), "X": tuple(x[d] - u[d] for d in range(dim)), "J": J,
                       "volume": round(kind) == 0})
    return points


def solve(M, n, m):
    """Gauss–Jordan elimination with partial pivoting of the n x (n + m) system @p M in place."""
    for c in range(n):
        pivot = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[pivot] = M[pivot], M[c]
        for r in range(n):
            if r != c:
                f = M[r][c] / M[c][c]
                M[r] = [M[r][k] - f * M[c][k] for k in range(n + m)]
    return [[M[r][n + k] / M[r][r] for k in range(m)] for r in range(n)]


def fitted_J_3d(volume, radius, lambda_0):
    """3D: J of the affine map X_0 -> x fitted to the volume points within @p radius of each
    point, times lambda_0^3 (from the dry state); None with fewer than ten."""
    key = lambda X: tuple(math.floor(c / radius) for c in X)
    buckets = {}
    for p in volume:
        buckets.setdefault(key(p["X"]), []).append(p)
    result = []
    for p in volume:
        i, j, k = key(p["X"])
        near = [q for a in (i - 1, i, i + 1) for b in (j - 1, j, j + 1) for c in (k - 1, k, k + 1)
                for q in buckets.get((a, b, c), []) if math.dist(q["X"], p["X"]) <= radius]
        if len(near) < 10:
            result.append(None)
            continue
        M = [[0.] * 7 for _ in range(4)]
        for q in near:
            v = (1.,) + tuple(q["X"][d] - p["X"][d] for d in range(3))
            for a in range(4):
                for b in range(4):
                    M[a][b] += v[a] * v[b]
                for d in range(3):
                    M[a][4 + d] += v[a] * q["x"][d]
        B = solve(M, 4, 3)[1:]  # B[e][d] = dx_d / dX_e
        result.append(lambda_0 ** 3 * (B[0][0] * (B[1][1] * B[2][2] - B[2][1] * B[1][2]) -
                                       B[1][0] * (B[0][1] * B[2][2] - B[2][1] * B[0][2]) +
                                       B[2][0] * (B[0][1] * B[1][2] - B[1][1] * B[0][2])))
    return result


def fitted_J(volume, radius, lambda_0):
    """J of the affine map X_0 -> x fitted to the volume points within @p radius of each point
    (in the initial configuration), times the point's hoop stretch; None with fewer than six."""
    buckets = {}
    for p in volume:
        buckets.setdefault((math.floor(p["X"][0] / radius), math.floor(p["X"][1] / radius)),
                           []).append(p)
    result = []
    for p in volume:
        i, j = math.floor(p["X"][0] / radius), math.floor(p["X"][1] / radius)
        near = [q for a in (i - 1, i, i + 1) for b in (j - 1, j, j + 1)
                for q in buckets.get((a, b), [])
                if math.dist(q["X"], p["X"]) <= radius]
        if len(near) < 6:
            result.append(None)
            continue
        # Normal equations of x = c + B (X - X_p).
        M = [[0.] * 5 for _ in range(3)]
        for q in near:
            v = (1., q["X"][0] - p["X"][0], q["X"][1] - p["X"][1])
            for a in range(3):
                for b in range(3):
                    M[a][b] += v[a] * v[b]
                M[a][3] += v[a] * q["x"][0]
                M[a][4] += v[a] * q["x"][1]
        B = solve(M, 3, 2)  # B[1 + e][d] = dx_d / dX_e
        in_plane = B[1][0] * B[2][1] - B[2][0] * B[1][1]
        result.append(in_plane * lambda_0 ** 3 * p["x"][0] / p["X"][0])
    return result


def spread(values, reference):
    """'min–max (−a/+b %)' of @p values about @p reference."""
    if not values:
        return "—"
    low, high = min(values), max(values)
    return "%.3f–%.3f (%+.2f/%+.2f %%)" % (low, high, 100 * (low / reference - 1),
                                           100 * (high / reference - 1))


def deviation(values):
    """'−a/+b %' of relative deviations @p values."""
    return "%+.2f/%+.2f %%" % (100 * min(values), 100 * max(values)) if values else "—"


def particle_files(directory):
    series = open(os.path.join(directory, "particles.pvd")).read()
    return re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', series)


def row(directory, args):
    (lower, h), files = grid_of(directory), particle_files(directory)
    dim = dimension_of(directory)
    points = points_of(os.path.join(directory, files[-1][1]), dim)
    volume = [p for p in points if p["volume"]]
    surface = [p["J"] for p in points if not p["volume"]]
    current_radius = max(math.hypot(*p["x"]) for p in points)

    def cut(p):
        index = [math.floor((p["x"][d] - lower[d]) / h) for d in range(dim)]
        corners = [[lower[d] + (index[d] + (c >> d & 1)) * h for d in range(dim)]
                   for c in range(2 ** dim)]
        return max(math.hypot(*c) for c in corners) > current_radius

    fits = (fitted_J(volume, 1.7 * h / args.points_per_cell, args.lambda_0) if dim == 2 else
            fitted_J_3d(volume, 1.7 * h / args.points_per_cell, args.lambda_0))
    local = [p["J"] / f - 1 for p, f in zip(volume, fits) if f]
    deep = [p["J"] for p in volume if args.radius - math.hypot(*p["X"]) > 2 * h]
    return "| %s | %s | %s | %s | %s | %s | %s |" % (
        os.path.basename(os.path.normpath(directory)), spread([p["J"] for p in volume], args.J_eq),
        spread([p["J"] for p in volume if cut(p)], args.J_eq),
        spread([p["J"] for p in volume if not cut(p)], args.J_eq), spread(deep, args.J_eq),
        spread(surface, args.J_eq), deviation(local))


def history(directory, args):
    h = grid_of(directory)[1]
    print("| t/τ_d | J of the volume points | J/J_fit − 1, R_0 > R − h | R_0 < R − h |")
    print("|---|---|---|---|")
    for time, name in particle_files(directory):
        volume = [p for p in points_of(os.path.join(directory, name)) if p["volume"]]
        fits = fitted_J(volume, 1.7 * h / args.points_per_cell, args.lambda_0)
        outer, inner = [], []
        for p, f in zip(volume, fits):
            if f:
                (outer if math.hypot(*p["X"]) > args.radius - h else inner).append(
                    p["J"] / f - 1)
        J = [p["J"] for p in volume]
        print("| %.4g | %.3f–%.3f | %s | %s |" % (float(time), min(J), max(J), deviation(outer),
                                                  deviation(inner)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directories", nargs="+")
    parser.add_argument("--J-eq", type=float, default=12.95969,
                        help="closed-form equilibrium J (gelmpm-reference: free swelling 3D: J)")
    parser.add_argument("--radius", type=float, default=0.5, help="initial radius R_0")
    parser.add_argument("--lambda-0", type=float, default=1.2801, help="initial stretch")
    parser.add_argument("--points-per-cell", type=int, default=5)
    parser.add_argument("--history", action="store_true")
    args = parser.parse_args()
    if args.history:
        history(args.directories[0], args)
        return
    print("| run | volume points | in cut cells | in the other cells | R_0 < "
          "R − 2h | surface points | J/J_fit − 1 |")
    print("|---|---|---|---|---|---|---|")
    for directory in args.directories:
        print(row(directory, args))


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Two blocks of one gel that swell across the gap between them until they press on each other.

The self-contact's check where nothing but the swelling closes the faces: two blocks of side
W = 0.5 (Table 1 gel, lambda_0 = 1.2801) on rollers at their outer ends (y = 0 and y = 2W + g,
or z in 3D) and at the planes of symmetry x = 0 (and y = 0 in 3D), a gap g between them (0.8,
3D 0.6), the bath (mu from mu_0 to 0 over --ramp tau_d) on every other side, the facing ones
included. Each block is run twice: the two blocks (self-contact, --method), and the lower one
alone against a rigid plane at the gap's middle (their plane of symmetry; the obstacles' penalty
contact), the reference for the transient.
The blocks swell into the gap, touch ('self_contact' event) and press on each other until
equilibrium, which is homogeneous: each block has F = diag(a, b, lambda_0) (3D: diag(a, a, b)),
b = lambda_0 (1 + g / 2W) fixed by the held ends and a from the free sides (P_aa = 0) at mu = 0.
The closed form of the held end's force, P_bb W / lambda_0^2 (3D: W^2 / lambda_0^2), the
obstacle block's drained one at mu = 0 (tests/simulator/obstacle_block.cc), is computed here by
bisection of the Flory-Rehner law, independently of GelMPM's code:

  P_ii F_ii = G (F_ii^2 - 1) + (G / N nu) J [ln(1 - 1/J) + 1/J + chi/J^2 - mu/kT].

Prints per run a table row: the steps, the time reached, the first touch, the held end's force
and the contact force at the end against the closed form, the contact length (area; the closed
form's W a / lambda_0, (W a / lambda_0)^2 in 3D) and the largest penetration. The defaults (h =
W/10, to 1500 tau_d) take about 12 s on two cores; doc/method.md, "Faces closed by swelling", has
the results.

    python3 contrib/benchmarks/swelling_closes_gap.py [--dimension 2|3] [--cells-per-block N]
        [--gap G] [--end T] [--ramp T] [--method penalty|nitsche] [--output DIR]
        [--set ENTRY=VALUE]...

Environment: GELMPM_BUILD_DIR (default: build). Needs only Python's standard library.
"""
import argparse
import math
import os
import subprocess
import sys

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gelmpm_files import read_rows  # noqa: E402
from bilayer_reference import LAMBDA_0, bisect  # noqa: E402
from bilayer_reference import stress_times_stretch as law  # noqa: E402

CHI = 0.1


def stress_times_stretch(s, J, mu):
    return law(s, J, mu, CHI)


W = 0.5
# The gap: wide enough that the blocks end compressed to 85 % of their free swelling in the
# pressed direction (plane strain 0.85 x 2.706, 3D 0.87 x 2.349); more, and their free sides
# crease (at 57 %, a gap of 0.2, the force fell by 1.3 % on h = W/10 and by 2.4 % on W/20 below
# the homogeneous state's).
GAP = {2: 0.8, 3: 0.6}


def closed_form(dim, gap):
    """(a, b, the held end's force, the contact area) at equilibrium in the bath mu = 0."""
    b = LAMBDA_0 * (1.0 + gap / (2.0 * W))
    J = (lambda a: a * b * LAMBDA_0) if dim == 2 else (lambda a: a * a * b)
    # J > 1 for the logarithm: a from just above that bound.
    low = (1.0 + 1e-12) / (b * LAMBDA_0) if dim == 2 else math.sqrt((1.0 + 1e-12) / b)
    a = bisect(lambda a: stress_times_stretch(a, J(a), 0.0), low, 10.0)
    P_bb = stress_times_stretch(b, J(a), 0.0) / b
    side = W ** (dim - 1)
    return a, b, P_bb * side / LAMBDA_0**2, (W * a / LAMBDA_0) ** (dim - 1)


def scene(dim, gap, cells_per_block, end, ramp, method, directory, half=False):
    h = W / cells_per_block
    top = 2 * W + gap
    # The free sides swell to W a / lambda_0: the grid reaches three cells beyond, with an even
    # count of cells.
    width = W * closed_form(dim, gap)[0] / LAMBDA_0
    reach = math.ceil((width + 3 * h) / (2 * h)) * 2 * h
    n_side = round(reach / h)
    n_top = round(top / h)
    if abs(n_top * h - top) > 1e-9 or n_top % 2:
        sys.exit("error: --cells-per-block %d and --gap %g put the held end (%g) off the grid's "
                 "even lines (h = %g)" % (cells_per_block, gap, top, h))
    axis = "z" if dim == 3 else "y"
    n = "nz" if dim == 3 else "ny"
    lateral = ", ".join(["%.17g" % reach] * (dim - 1))
    boxes = "; ".join("%s : %s" % (", ".join(["0"] * (dim - 1) + ["%.17g" % lo]),
                                     ", ".join(["%.17g" % W] * (dim - 1) + ["%.17g" % hi]))
                      for lo, hi in ((0.0, W), (W + gap, top))[:1 if half else 2])
    if half:
        # The lower block against a rigid plane at the gap's middle, the plane of symmetry of
        # the two blocks: the reference without self-contact.
        held = ""
        contact = f"""subsection Contact
  set Method    = penalty
  set Penalty   = 100
  set Obstacles = mid
  subsection mid
    set Shape  = plane
    set Center = {", ".join(["0"] * (dim - 1))}, {W + gap / 2}
    set Normal = {", ".join(["0"] * (dim - 1))}, -1
  end
end"""
    else:
        held = f"""  subsection top
    set Selector     = {{n}} > 0.5 && {{axis}} > {top - W / 2}
    set Displacement = normal
  end
"""
        contact = f"""subsection Contact
  subsection Self contact
    set Method          = {method}
    set Penalty         = {1000 if method == "nitsche" else 100}
    set Search distance = 3
  end
end"""
    symmetry = "  subsection left\n    set Selector     = nx < -0.5\n    set Displacement = normal\n  end\n"
    pieces = "left, "
    if dim == 3:
        symmetry += "  subsection back\n    set Selector     = ny < -0.5\n    set Displacement = normal\n  end\n"
        pieces += "back, "
    return f"""set Dimension = {dim}
subsection Output
  set Directory       = {directory}
  set Write particles = true
  set Interval steps  = 0
  set Interval time   = 0.5
end
subsection Background grid
  set Lower corner = {", ".join(["0"] * dim)}
  set Upper corner = {lateral}, {top!r}
  set Cells        = {", ".join([str(n_side)] * (dim - 1))}, {n_top}
end
subsection Geometry
  set Boxes = {boxes}
end
subsection Material points
  set Points per cell = 3
end
subsection Boundary conditions
  set Pieces = {pieces}bottom, {"" if half else "top, "}bath
{symmetry}  subsection bottom
    set Selector     = {n} < -0.5 && {axis} < {W / 2}
    set Displacement = normal
  end
{held.format(n=n, axis=axis)}  subsection bath
    set Selector           = nx > -0.5
    set Chemical potential = prescribed
    subsection Chemical potential value
      set Function expression = -0.1459745 * max(1 - t / {ramp}, 0)
    end
  end
end
{contact}
subsection Observables
  set Forces and fluxes = all
end
subsection Time stepping
  set Characteristic length = {W}
  set Initial step          = 1e-3
  set End time              = {end}
end
"""


def run(args, build, half):
    """One variant: (exit status, its statistics rows, its scene file)."""
    name = "%dd_%d_%s" % (args.dimension, args.cells_per_block, "half" if half else args.method)
    directory = os.path.join(args.output, name)
    path = directory + ".prm"
    with open(path, "w") as f:
        f.write(scene(args.dimension, args.gap, args.cells_per_block, args.end, args.ramp,
                      args.method, directory, half))
    command = [os.path.join(build, "gelmpm"), path]
    for entry in args.set:
        command += ["--set", entry]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        print(result.stderr[-1000:], end="")
    return result.returncode, read_rows(os.path.join(directory, "statistics.csv")), path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dimension", type=int, default=2, choices=(2, 3))
    parser.add_argument("--cells-per-block", type=int, default=10)
    parser.add_argument("--end", type=float, default=1500.0,
                        help="End time in tau_d (default 1500: equilibrium to 0.01 %%)")
    parser.add_argument("--ramp", type=float, default=0.1)
    parser.add_argument("--gap", type=float, help="the gap g (default: %s)" % GAP)
    parser.add_argument("--method", default="penalty", choices=("penalty", "nitsche"))
    parser.add_argument("--output", default="swelling_closes_gap")
    parser.add_argument("--set", action="append", default=[], help="a gelmpm --set entry")
    args = parser.parse_args()
    if args.gap is None:
        args.gap = GAP[args.dimension]
    build = os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build"))
    os.makedirs(args.output, exist_ok=True)
    a, b, force, area = closed_form(args.dimension, args.gap)
    measure = "length" if args.dimension == 2 else "area"
    axis = "z" if args.dimension == 3 else "y"
    print("closed form: a = %.6f, b = %.6f, the held end's force %.7g, contact %s %.6f"
          % (a, b, force, measure, area))
    print("| variant | exit | steps | reached (tau_d) | first touch (tau_d) | end's force "
          "(error) | contact force (error) | contact %s | largest penetration |" % measure)
    print("|---|---|---|---|---|---|---|---|---|")
    for half in (True, False):
        code, rows, path = run(args, build, half)
        last = rows[-1]
        # The half: its bottom carries the plane's force; the whole: the held top's.
        end_force = -float(last["bottom_force_" + axis]) if half else float(last["top_force_" + axis])
        points, contact, touched, depth = (
            ("contact_points", "mid_force_" + axis, "mid_contact_area", "contact_penetration")
            if half else ("self_contact_points", "self_contact_force", "self_contact_area",
                          "self_contact_penetration"))
        touch = next((r["t_over_tau_d"] for r in rows[1:] if r[points] and float(r[points]) > 0),
                     "none")
        contact_force = abs(float(last[contact] or 0))
        print("| %s | %d | %d | %.6g | %s | %.7g (%+.3f %%) | %.7g (%+.3f %%) | %s | %s |" % (
            "half against a plane" if half else "two blocks, " + args.method, code,
            len(rows) - 1, float(last["t_over_tau_d"]), touch, end_force,
            100 * (end_force - force) / abs(force), contact_force,
            100 * (contact_force - abs(force)) / abs(force), last.get(touched, "-"),
            last.get(depth, "-")))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A notch that closes as the gel swells: self-contact of its faces against a rigid plane.

A plane-strain block 2 x 1 (Table 1 gel, lambda_0 = 1.2801) on rollers at its bottom and outer
sides, with a vertical notch of width w = h/2 and depth 0.5 from the middle of its top; the bath
(mu from mu_0 to 0 over 0.1 tau_d) on the top and in the notch. The outer sides are held, so the
swelling halves close the notch from its mouth. Variants, each run to --end tau_d:
  half      the left half against a rigid plane at the notch's middle (an obstacle, penalty
            'Contact/Penalty'), rollers below the notch's root: the independent reference, since
            the scene is symmetric about that plane;
  tied      the whole block, self-contact of its surface, the faces sharing the grid's functions;
  separated the same with 'Separate faces = true' (doc/method.md, "Two faces on one grid");
with the self-contact's and the plane's penalty --penalty (default 100, the self-contact's
default), the whole block's self-contact by --method (penalty, or nitsche with the point's
traction; the half's plane keeps the penalty). Prints per variant the time reached, the first contact (the half's first contact
point; the whole block's 'self_contact' event) and the contact force (half: the plane's force;
whole: 'self_contact_force') at four times the half reached, and writes the scenes to --output.
Measured (doc/method.md, "The other face as tangent planes"): the half reaches 1 tau_d; separated,
the block reaches 1 tau_d (with 'Other face = segments' it stops at 0.124 tau_d); tied, its faces
never touching, it stops at 0.109 tau_d (with segments 1 tau_d).

    python3 contrib/benchmarks/closing_slit.py [--output DIR] [--end T] [--penalty P]
        [--line-search physical|merit|adaptive] [--method penalty|nitsche] [--set ENTRY=VALUE]

Environment: GELMPM_BUILD_DIR (default: build). Needs only Python's standard library.
"""
import argparse
import os
import re
import subprocess
import sys

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
from gelmpm_files import read_rows  # noqa: E402

# The 3D slab's thickness (--dimension 3): four cells of h = 0.0625.
THICKNESS = 0.25

# The block 0.25 < x < 2.25, 0.25 < y < 1.25 less the notch |x - 1.25| < w/2, y > 1.25 - d.
NOTCH = ("max(max(max(0.25 - x, x - {right}), max(0.25 - y, y - 1.25)), "
         "-max(abs(x - 1.25) - w / 2, 1.25 - d - y))")

SCENE = """set Dimension = 2
subsection Output
  set Directory       = {directory}
  set Write particles = true
  set Interval steps  = 0
  set Interval time   = 0.05
end
subsection Background grid
  set Lower corner = 0, 0
  set Upper corner = {upper}, 2.5
  set Cells        = {cells}, 40
end
subsection Geometry
  set Level set           = {level_set}
  set Level set constants = d=0.5, w=0.03125
end
subsection Material points
  set Points per cell = 3
end
subsection Boundary conditions
  set Pieces = bottom, left, {pieces}, bath
  subsection bottom
    set Selector     = ny < -0.9
    set Displacement = normal
  end
  subsection left
    set Selector     = nx < -0.9 && x < 0.5
    set Displacement = normal
  end
{side}
  subsection bath
    set Selector           = ny > 0.9 || (y > 0.74 && x > 0.5 && x < 2)
    set Chemical potential = prescribed
    subsection Chemical potential value
      set Function expression = -0.1459745 * max(1 - t / 0.1, 0)
    end
  end
end
{contact}
subsection Observables
  set Forces and fluxes = left
end
subsection Time stepping
  set Characteristic length  = 1
  set Initial step           = 1e-3
  set End time               = {end}
  set Displacement tolerance = 0.01
end
"""

RIGHT_SIDE = """  subsection right
    set Selector     = nx > 0.9 && x > 2
    set Displacement = normal
  end"""

MIRROR = """  subsection mirror
    set Selector     = nx > 0.9 && x > 1.249
    set Displacement = normal
  end"""

PLANE = """subsection Contact
  set Method    = penalty
  set Penalty   = {penalty}
  set Obstacles = mid
  subsection mid
    set Shape  = plane
    set Center = 1.25, 0
    set Normal = -1, 0
  end
end"""

SELF = """subsection Contact
  subsection Self contact
    set Method          = {method}
    set Penalty         = {penalty}
    set Search distance = 3
    set Separate faces  = {separate}
  end
end"""


ENDS = """  subsection ends
    set Selector     = abs(nz) > 0.9
    set Displacement = normal
  end
  subsection bath"""


def extruded(text):
    """The plane-strain scene as a 3D slab of THICKNESS (four cells) on rollers at its ends."""
    text = text.replace("set Dimension = 2", "set Dimension = 3")
    text = re.sub(r"(set Lower corner = [^\n]*)", r"\1, 0", text)
    text = re.sub(r"(set Upper corner = [^\n]*)", r"\1, %g" % THICKNESS, text)
    text = re.sub(r"(set Cells        = [^\n]*)", r"\1, 4", text)
    text = re.sub(r"set Level set           = (.*)",
                  lambda m: "set Level set           = max(%s, max(-z, z - %g))"
                  % (m.group(1), THICKNESS), text)
    text = re.sub(r"(set Pieces = [^\n]*), bath", r"\1, ends, bath", text)
    text = text.replace("  subsection bath", ENDS, 1)
    text = text.replace("set Center = 1.25, 0", "set Center = 1.25, 0, 0")
    return text.replace("set Normal = -1, 0", "set Normal = -1, 0, 0")


def scene(variant, out, end, penalty, line_search, method, dimension=2):
    directory = os.path.join(out, variant)
    if variant == "half":
        # The grid reaches a cell pair beyond the plane: mu lives on cells twice as large.
        text = SCENE.format(directory=directory, upper=1.375, cells=22,
                            level_set=NOTCH.format(right=1.25), pieces="mirror", side=MIRROR,
                            contact=PLANE.format(penalty=penalty), end=end)
    else:
        text = SCENE.format(directory=directory, upper=2.5, cells=40,
                            level_set=NOTCH.format(right=2.25), pieces="right", side=RIGHT_SIDE,
                            contact=SELF.format(penalty=penalty, method=method,
                                                separate=str(variant == "separated").lower()),
                            end=end)
    text += "subsection Newton\n  set Line search = %s\nend\n" % line_search
    if dimension == 3:
        text = extruded(text)
    path = os.path.join(out, variant + ".prm")
    with open(path, "w") as f:
        f.write(text)
    return path, directory


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="closing_slit")
    parser.add_argument("--end", type=float, default=1.0)
    parser.add_argument("--penalty", type=float, default=100.)
    parser.add_argument("--line-search", default="physical",
                        help="'Newton/Line search' of every variant (physical, merit, adaptive)")
    parser.add_argument("--method", default="penalty",
                        help="'Contact/Self contact/Method' of the whole block (penalty, nitsche)")
    parser.add_argument("--dimension", type=int, choices=(2, 3), default=2,
                        help="3: the scene as a slab four cells thick on rollers at its ends "
                        "(plane strain in 3D)")
    parser.add_argument("--variants", default="half,tied,separated",
                        help="comma-separated variants to run (the half is the reference)")
    parser.add_argument("--set", action="append", default=[], metavar="ENTRY=VALUE",
                        help="a further --set for every variant (repeatable), e.g. "
                        "'Contact/Self contact/Other face=segments'")
    args = parser.parse_args()
    build = os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build"))
    os.makedirs(args.output, exist_ok=True)
    results = {}
    variants = args.variants.split(",")
    for variant in variants:
        path, directory = scene(variant, args.output, args.end, args.penalty, args.line_search,
                                args.method, args.dimension)
        overrides = [arg for entry in args.set for arg in ("--set", entry)]
        run = subprocess.run([os.path.join(build, "gelmpm"), path] + overrides,
                             capture_output=True, text=True,
                             env=dict(os.environ, DEAL_II_NUM_THREADS="1"))
        rows = read_rows(os.path.join(directory, "statistics.csv"))
        force = "mid_force_x" if variant == "half" else "self_contact_force"
        points = "contact_points" if variant == "half" else "self_contact_points"
        touch = next((r["t_over_tau_d"] for r in rows[1:] if r[points] and float(r[points]) > 0),
                     None)
        results[variant] = (run.returncode, rows, force, touch)
    # The force at four times the half reached (without the half: the first variant run).
    half_rows = results.get("half", results[variants[0]])[1]
    print("| variant | exit | reached (tau_d) | first contact (tau_d) | force at t = "
          + ", ".join("%.3g" % float(half_rows[k]["t_over_tau_d"])
                      for k in range(max(len(half_rows) // 4, 1), len(half_rows), max(len(half_rows) // 4, 1)))
          + " |")
    print("|---|---|---|---|---|")
    for variant, (code, rows, force, touch) in results.items():
        times = [float(r["t_over_tau_d"]) for r in rows]
        values = []
        for k in range(max(len(half_rows) // 4, 1), len(half_rows), max(len(half_rows) // 4, 1)):
            t = float(half_rows[k]["t_over_tau_d"])
            # Linear in time between the variant's steps; "-" beyond what it reached.
            after = next((i for i in range(1, len(times)) if times[i] >= t), None)
            if after is None:
                values.append("-")
                continue
            f0, f1 = float(rows[after - 1][force] or 0), float(rows[after][force] or 0)
            share = (t - times[after - 1]) / (times[after] - times[after - 1])
            values.append("%.4g" % (f0 + share * (f1 - f0)))
        print("| %s | %d | %.4g | %s | %s |" % (variant, code, times[-1], touch or "none",
                                                ", ".join(values)))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Crease onset of the bonded film (prm/creasing_film.prm) on three grids and with two dips, set
against the creasing threshold of the literature.

Runs gelmpm on the scene with h = H/16, H/20 (the scene's grid) and H/32 and with dips of depth
0.02 H (the scene's) and 0.005 H, to --end-time (default 12 tau_d), profiles every 0.1 tau_d. Per
run it reads statistics.csv, events.csv and the profiles surface_top-*.csv and reports

  t_45       the first time the top's largest turning (angle between neighbouring surface
             segments, doc/statistics.md) reaches 45 degrees;
  t_fold     the first output time whose profile folds over (x decreases along the surface: the
             visible fold, what a look at the profile shows);
  t_crease   the first 'crease_top' event (two surface points more than 3 h apart along the
             surface come within h/2);
  s          at each of these times, the stretch of the top surface layer in the thickness
             direction relative to the initial state, s = h/H of a laterally constrained layer in
             equilibrium with the bath's mu at that time (closed form of the Flory-Rehner law,
             bilayer_reference.py, independent of the code). The layer is held at the initial
             lateral stretch lambda_0 in x and z, so s is also its ratio of principal stretches
             lambda_y / lambda_x, the measure of the creasing threshold of a neo-Hookean surface
             under plane-strain compression (Hong, Zhao & Suo, Appl. Phys. Lett. 95 (2009)
             111901: 2.4; Biot's linear surface instability: 3.38);
  J_max      the largest volume ratio (dry state to current) of the volume points before t_crease
             and over the whole run, against the plane-strain free-swelling value at mu = 0.

  /usr/bin/python3 contrib/benchmarks/creasing_film.py [--gelmpm build/gelmpm] [--output DIR]
      [--cells 16,20,32] [--dips 0.02,0.005] [--end-time 12] [--levels 0,1,2,3 --box BOX]
      [--band W] [--set ENTRY=VALUE ...]

--set passes further settings to every run, e.g. the self-contact of doc/method.md, "Two faces on
one grid": --set "Contact/Self contact/Method=penalty" --set "Contact/Self contact/Penalty=100"
--set "Contact/Self contact/Separate faces=true"; the table then gives the time at which the
flanks first touch (the 'self_contact' event).

With --levels, each grid is also run refined that many times in --box (default: round the dip
and the path of the top while the film swells), the finest spacing h/2^levels there; with
--band W instead within W of the top's current surface points ('Refinement band', marked anew
every step, so that the refined cells follow the top as it rises).

Prints a Markdown table (also <DIR>/onset.md) and writes <DIR>/onset.csv; with --plot the
profiles at t_crease to doc/figures/creasing_film_profiles.png.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import time

from bilayer_reference import LAMBDA_0, bisect, stress_times_stretch

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
MU_0 = -0.1459745
RAMP = 10.0
CHI = 0.1


def bath_mu(t):
    return MU_0 * max(1.0 - t / RAMP, 0.0)


def surface_layer_stretch(mu):
    """s with sigma_yy = 0 for F = diag(lambda_0, lambda_0 s, lambda_0) at the bath's mu."""
    return bisect(lambda s: stress_times_stretch(LAMBDA_0 * s, LAMBDA_0**3 * s, mu, CHI),
                  1.0 / LAMBDA_0 + 1e-9, 10.0)


def free_swelling_J(mu):
    """Plane strain free swelling from the initial state: F = diag(l0 a, l0 a, l0)."""
    a = bisect(lambda a: stress_times_stretch(LAMBDA_0 * a, LAMBDA_0**3 * a * a, mu, CHI),
               1.0 / LAMBDA_0 + 1e-9, 10.0)
    return LAMBDA_0**3 * a * a


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def profile_folds(path, h):
    """Whether the surface doubles back: two of its segments less than 4 h apart along it point
    in directions more than 150 degrees apart (the flanks of a closed groove; a crease need not
    overhang, its flanks meet symmetrically)."""
    rows = read_csv(path)
    x = [float(r["x"]) for r in rows]
    y = [float(r["y"]) for r in rows]
    segments = []  # (arc length at the segment's start, direction)
    s = 0.0
    for i in range(len(x) - 1):
        dx, dy = x[i + 1] - x[i], y[i + 1] - y[i]
        segments.append((s, math.atan2(dy, dx)))
        s += math.hypot(dx, dy)
    for i, (s_i, a_i) in enumerate(segments):
        for s_j, a_j in segments[i + 1:]:
            if s_j - s_i > 4 * h:
                break
            turn = abs((a_j - a_i + math.pi) % (2 * math.pi) - math.pi)
            if turn > math.radians(150.0):
                return True
    return False


def output_times(directory):
    """Output number -> time (tau_d) from particles.pvd, the list of the output times."""
    times = {}
    with open(os.path.join(directory, "particles.pvd")) as f:
        for m in re.finditer(r'timestep="([^"]+)"[^>]*file="particles-(\d+)', f.read()):
            times[int(m.group(2))] = float(m.group(1))
    return dict(sorted(times.items()))


def run(gelmpm, cells, dip, end_time, directory, reuse, levels=0, box="", band=0.0, extra=()):
    h = 1.0 / cells
    args = [gelmpm, os.path.join(TOP, "prm", "creasing_film.prm"),
            "--set", f"Output/Directory={directory}",
            "--set", "Output/Interval time=0.1",
            "--set", "Background grid/Upper corner=2.5, 4",
            "--set", f"Background grid/Cells={round(2.5 / h)}, {round(4 / h)}",
            "--set", f"Geometry/Level set constants=d={dip}, w=0.1",
            "--set", f"Time stepping/End time={end_time}",
            "--set", "Observables/Volume ratio range=true"]
    for setting in extra:
        args += ["--set", setting]
    if levels > 0 and band > 0:
        args += ["--set", f"Background grid/Refinement band={band}",
                 "--set", "Background grid/Refinement band pieces=top",
                 "--set", f"Background grid/Refinement levels={levels}"]
    elif levels > 0:
        args += ["--set", f"Background grid/Refinement boxes={box}",
                 "--set", f"Background grid/Refinement levels={levels}"]
    if reuse and os.path.exists(os.path.join(directory, "statistics.csv")):
        returncode = 0 if "reached t/tau_d" in open(directory + ".log").read() else 1
        wall_file = os.path.join(directory, "wall_seconds")
        wall = float(open(wall_file).read()) if os.path.exists(wall_file) else math.nan
    else:
        start = time.time()
        with open(directory + ".log", "w") as log:
            returncode = subprocess.run(args, stdout=log, stderr=subprocess.STDOUT).returncode
        wall = time.time() - start
        with open(os.path.join(directory, "wall_seconds"), "w") as f:
            f.write(f"{wall:.1f}\n")

    stats = read_csv(os.path.join(directory, "statistics.csv"))
    t = [float(r["t_over_tau_d"]) for r in stats]
    turning = [float(r["top_turning"]) for r in stats]
    J_max = [float(r["J_max"]) for r in stats]
    t_45 = next((ti for ti, a in zip(t, turning) if a >= 45.0), math.nan)
    events = [r for r in read_csv(os.path.join(directory, "events.csv"))
              if r["event"] == "crease_top"]
    t_crease = float(events[0]["t_over_tau_d"]) if events else math.nan
    touches = [r for r in read_csv(os.path.join(directory, "events.csv"))
               if r["event"] == "self_contact"]
    t_touch = float(touches[0]["t_over_tau_d"]) if touches else math.nan
    t_fold = math.nan
    for index, t_output in output_times(directory).items():
        if profile_folds(os.path.join(directory, f"surface_top-{index:05d}.csv"), h):
            t_fold = t_output
            break
    J_before = max((J for ti, J in zip(t, J_max) if not ti > t_crease), default=math.nan)
    return dict(cells=cells, levels=levels, dip=dip, t_end=t[-1], reached=returncode == 0,
                t_45=t_45, t_fold=t_fold, t_crease=t_crease, t_touch=t_touch,
                relief=float(stats[-1]["top_relief"]), folds=int(float(stats[-1]["top_folds"])),
                J_max_before=J_before, J_max=max(J_max), wall=wall)


def stretch_at(t):
    return surface_layer_stretch(bath_mu(t)) if not math.isnan(t) else math.nan


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--gelmpm", default=os.path.join(TOP, "build", "gelmpm"))
    parser.add_argument("--output", default="output/creasing_film_study")
    parser.add_argument("--cells", default="16,20,32", help="cells per H")
    parser.add_argument("--dips", default="0.02,0.005", help="dip depths in H")
    parser.add_argument("--end-time", type=float, default=12.0)
    parser.add_argument("--levels", default="0",
                        help="comma-separated refinement levels of --box on each grid (0: uniform)")
    parser.add_argument("--box", default="1.0, 1.0 : 1.5, 3.0",
                        help="the refined box, 'x0, y0 : x1, y1': round the dip and the path of "
                             "the top while the film swells (the top rises from y = 1.25 to 2.98)")
    parser.add_argument("--band", type=float, default=0.0,
                        help="with --levels: refine within this distance of the top's current "
                             "surface instead of --box")
    parser.add_argument("--set", action="append", default=[], metavar="ENTRY=VALUE",
                        help="a further --set for every run (repeatable), e.g. "
                             "'Contact/Self contact/Method=penalty'")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--reuse", action="store_true",
                        help="analyse the runs already in --output instead of running them")
    a = parser.parse_args()
    os.makedirs(a.output, exist_ok=True)

    results = []
    for dip in [float(d) for d in a.dips.split(",")]:
        for cells, levels in [(int(c), int(l)) for c in a.cells.split(",")
                              for l in a.levels.split(",")]:
            directory = os.path.join(a.output, f"h{cells}_d{dip}" +
                                     (f"_L{levels}" if levels > 0 else ""))
            r = run(a.gelmpm, cells, dip, a.end_time, directory, a.reuse, levels, a.box, a.band,
                    a.set)
            r["directory"] = directory
            results.append(r)
            print(f"h = H/{cells}, {levels} levels, dip {dip}: t_45 {r['t_45']:.3f}, fold {r['t_fold']:.2f}, "
                  f"crease {r['t_crease']:.3f}, J_max {r['J_max']:.2f}, "
                  f"end {r['t_end']:.3f}, {r['wall']:.0f} s", flush=True)

    J_free = free_swelling_J(0.0)
    lines = ["| h | levels | dip / H | t_45 (s) | visible fold (s) | first crease event (s) | "
             "J_max before / whole run | flanks touch (self_contact) | reached t/tau_d | "
             "relief, folds at the end | wall |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        lines.append(
            f"| H/{r['cells']} | {r['levels']} | {r['dip']} | {r['t_45']:.2f} ({stretch_at(r['t_45']):.3f}) | "
            f"{r['t_fold']:.1f} ({stretch_at(r['t_fold']):.3f}) | "
            f"{r['t_crease']:.2f} ({stretch_at(r['t_crease']):.3f}) | "
            f"{r['J_max_before']:.2f} / {r['J_max']:.2f} | {r['t_touch']:.2f} | {r['t_end']:.2f} | "
            f"{r['relief']:.3f}, {r['folds']} | {r['wall']:.0f} s |")
    lines.append("")
    lines.append(f"Times in tau_d; s in brackets. Plane-strain free swelling at mu = 0: "
                 f"J = {J_free:.3f}. s = 2.4 is reached at t = "
                 f"{bisect(lambda t: stretch_at(t) - 2.4, 0.0, RAMP):.3f} tau_d.")
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(a.output, "onset.md"), "w") as f:
        f.write(text + "\n")
    with open(os.path.join(a.output, "onset.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)

    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
        for ax, dip in zip(axes, sorted({r["dip"] for r in results}, reverse=True)):
            for r in [r for r in results if r["dip"] == dip]:
                if math.isnan(r["t_crease"]):
                    continue
                after = [(i, t) for i, t in output_times(r["directory"]).items()
                         if t >= r["t_crease"] - 1e-9]
                if not after:
                    continue
                index, t_out = after[0]
                path = os.path.join(r["directory"], f"surface_top-{index:05d}.csv")
                rows = read_csv(path)
                ax.plot([float(p["x"]) for p in rows], [float(p["y"]) for p in rows], ".-",
                        ms=2, lw=0.7, label=f"h = H/{r['cells']}, t = {t_out:.2f}")
            # The larger dip seeds the crease at the middle; a small one may not (the surface
            # creases where the discretisation seeds it): the whole width.
            ax.set_xlim((0.9, 1.6) if dip == max(r["dip"] for r in results) else (0.25, 2.25))
            ax.set_title(f"dip {dip} H", fontsize=10)
            ax.set_xlabel("x / H")
            ax.legend(fontsize=8)
        axes[0].set_ylabel("y / H")
        fig.suptitle("top surface at the first output after the first crease_top event",
                     fontsize=10)
        fig.tight_layout()
        fig.savefig(os.path.join(TOP, "doc", "figures", "creasing_film_profiles.png"), dpi=120)


if __name__ == "__main__":
    main()

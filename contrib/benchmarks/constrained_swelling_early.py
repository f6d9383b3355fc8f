#!/usr/bin/env python3
"""Paper §4.1, the first decade (t <= 0.02 tau_d): refinement study against the 1D reference.

Runs prm/constrained_swelling.prm to t = 0.02 tau_d (no particle output) with one or more changes
at a time -- the background grid (h_u, and h_mu = 2 h_u), the points per cell, the first step,
the step growth or error-controlled steps, the Nitsche penalty of mu, and a ramp of the top's mu
from mu_0 to 0 over t_inc (through the top's 'Chemical potential value' expression) -- one gelmpm
after the other, and compares Delta h with the finite-difference reference gelmpm-swelling-1d (a
step of mu at t = 0+; with --ramp also with the same ramp). Writes <output>/early.md (the Markdown
table) and early.csv; with --plot early.png; with --mechanism mechanism.md (five short runs with
the particles at every step: mu at the top, the undershoot ahead of the front).

    /usr/bin/python3 contrib/benchmarks/constrained_swelling_early.py [--output DIR] [--ramp]
        [--plot] [--mechanism] [--only NAME,...] [--skip-existing] [--tabulate-only] [--list]

The whole study (69 variants and the mechanism runs) took about 12 min of gelmpm wall time on a
loaded 2-core machine (doc/constrained_swelling.md, "Early times").

Columns: Delta h_MPM / Delta h_ref at the first step, at t = 1.197e-3 and 8.589e-3 tau_d; the
worst |Delta h_MPM / Delta h_ref - 1| over all steps with 1e-3 <= t <= 1e-2 (signed, with its
time); the least-squares log-log slope of Delta h_MPM over the steps in [1e-3, 1e-2] (reference
0.500); steps; wall time of the run (measured around the process); unknowns (u + mu) at the first
and the last step; material points. Environment: GELMPM_BUILD_DIR (default: build); NICE (default
5, the niceness of every run).
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

import numpy as np

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
T1, T2 = 0.001197, 0.008589
WINDOW = (1e-3, 1e-2)
LAMBDA_0, CHI, N_NU = 1.2801, 0.1, 7.299e-3


def mu_0():
    """mu/k_BT of the initial state (P_22 = 0 at lambda = 1), as in the reference."""
    J = LAMBDA_0 ** 3
    return N_NU * (LAMBDA_0 ** 2 - 1) / J + math.log(1 - 1 / J) + 1 / J + CHI / J ** 2


def grid(nx, ppc):
    return [f"Background grid/Cells={nx}, {8 * nx}", f"Material points/Points per cell={ppc}"]


def ramp(t_inc):
    base = "Boundary conditions/top/Chemical potential value/"
    return [base + f"Function constants=mu0={mu_0():.10g},tinc={t_inc:g}",
            base + "Function expression=mu0*max(0, 1 - t/tinc)"]


def gamma(g):
    return [f"Nitsche/Chemical potential penalty={g:g}"]


def dt0(dt):
    return [f"Time stepping/Initial step={dt:g}"]


def growth(g):
    return [f"Time stepping/Growth factor={g:g}"]


def tolerance(tol):
    # Error-controlled steps act only where no step cap applies; growth 2 (doc/performance.md).
    return ["Time stepping/Step caps=", f"Time stepping/Tolerance={tol:g}",
            "Time stepping/Growth factor=2"]


def variants():
    """(name, group, description, --set overrides, ramp time or None)."""
    v = []
    # h and points per cell (h_mu = 2 h_u; u cells nx x 8 nx).
    for nx in (20, 30, 40, 60, 80):
        for ppc in ((3, 4, 6) if nx in (20, 40) else (3, 6)):
            v.append((f"h{nx}_p{ppc}", "h, points", f"{nx} × {8 * nx}, {ppc} × {ppc}",
                      grid(nx, ppc), None))
    # First step (Delta t_0 = 8.75e-5 in the scene).
    for nx, ppc in ((20, 6), (40, 6), (80, 3)):
        for div in (4, 16):
            v.append((f"h{nx}_p{ppc}_dt{div}", "first step",
                      f"{nx} × {8 * nx}, {ppc} × {ppc}, Δt_0/{div}",
                      grid(nx, ppc) + dt0(8.75e-5 / div), None))
    # Later steps: growth factor of the step (1.25 in the scene), error-controlled steps.
    for nx, ppc, factors in ((20, 6, (1.1, 1.05)), (30, 6, (1.1,)), (40, 6, (1.1, 1.05)),
                             (60, 3, (1.1,)), (80, 3, (1.1, 1.05))):
        for g in factors:
            v.append((f"h{nx}_p{ppc}_growth{g:g}", "step growth",
                      f"{nx} × {8 * nx}, {ppc} × {ppc}, growth {g:g}", grid(nx, ppc) + growth(g),
                      None))
    for nx, ppc, tols in ((20, 6, (1e-3,)), (40, 6, (1e-3, 3e-4)), (80, 3, (1e-3,))):
        for tol in tols:
            v.append((f"h{nx}_p{ppc}_tol{tol:g}", "step growth",
                      f"{nx} × {8 * nx}, {ppc} × {ppc}, Tolerance = {tol:g} (growth 2, no caps)",
                      grid(nx, ppc) + tolerance(tol), None))
    # Nitsche penalty of mu.
    for nx, ppc, gammas in ((20, 6, (2, 5, 8, 10, 12, 15, 50, 100, 250, 1000)),
                            (40, 6, (5, 10, 100, 250)),
                            (80, 3, (5, 100))):
        for g in gammas:
            v.append((f"h{nx}_p{ppc}_g{g}", "γ_μ", f"{nx} × {8 * nx}, {ppc} × {ppc}, γ_μ = {g}",
                      grid(nx, ppc) + gamma(g), None))
    # Ramp of the top's mu from mu_0 to 0 over t_inc.
    for nx, ppc, t_incs in ((20, 6, (1e-4, 2e-4, 5e-4, 1e-3)),
                            (40, 6, (1e-4, 2e-4, 5e-4, 1e-3)),
                            (80, 3, (1e-4, 2e-4))):
        for t_inc in t_incs:
            v.append((f"h{nx}_p{ppc}_r{t_inc:g}", "ramp",
                      f"{nx} × {8 * nx}, {ppc} × {ppc}, ramp t_inc = {t_inc:g}",
                      grid(nx, ppc) + ramp(t_inc), t_inc))
    # Combinations.
    for nx, ppc, t_inc, div in ((40, 6, 1e-4, 4), (60, 3, 1e-4, 4), (80, 3, 1e-4, 4),
                                (60, 3, 2e-4, 1), (80, 3, 2e-4, 4)):
        sets = grid(nx, ppc) + ramp(t_inc) + (dt0(8.75e-5 / div) if div > 1 else [])
        v.append((f"h{nx}_p{ppc}_r{t_inc:g}" + (f"_dt{div}" if div > 1 else ""), "combination",
                  f"{nx} × {8 * nx}, {ppc} × {ppc}, ramp t_inc = {t_inc:g}"
                  + (f", Δt_0/{div}" if div > 1 else ""), sets, t_inc))
    # Grid, points and step growth together; the tuned penalty and the ramp that match at 1.2e-3.
    for nx, ppc, g, extra, label in (
            (30, 6, 1.05, [], ""), (40, 4, 1.1, [], ""), (40, 8, 1.1, [], ""),
            (60, 6, 1.1, [], ""), (80, 6, 1.1, [], ""),
            (40, 6, 1.1, gamma(10), ", γ_μ = 10"), (20, 6, 1.1, gamma(12), ", γ_μ = 12"),
            (20, 6, 1.25, ramp(4e-4), ", ramp t_inc = 0.0004")):
        name = f"h{nx}_p{ppc}_growth{g:g}" + "".join(
            "_" + x.split("=")[-1].replace(" ", "") for x in extra if "penalty" in x) + (
            "_r0.0004" if "ramp" in label else "")
        v.append((name, "combination", f"{nx} × {8 * nx}, {ppc} × {ppc}, growth {g:g}{label}",
                  grid(nx, ppc) + (growth(g) if g != 1.25 else []) + extra,
                  4e-4 if "ramp" in label else None))
    return v


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def reference_curve(directory):
    rows = read_csv(os.path.join(directory, "reference_thickness.csv"))
    t = np.array([float(r["t_over_tau_d"]) for r in rows])
    d = np.array([float(r["delta_h_over_h0"]) for r in rows])
    return lambda x: np.exp(np.interp(np.log(x), np.log(t), np.log(d)))


def run_reference(build, out, t_inc=None):
    directory = os.path.join(out, "reference" if t_inc is None else f"reference_ramp_{t_inc:g}")
    if os.path.exists(os.path.join(directory, "reference_thickness.csv")):
        return directory
    command = [os.path.join(build, "gelmpm-swelling-1d"), "--samples", "4000", "--times",
               "0.001197,0.008589,0.02", "--output", directory]
    if t_inc is not None:
        command += ["--ramp", f"{t_inc:g}"]
    print(" ".join(command), flush=True)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return directory


def run_variant(build, out, name, sets, nice):
    directory = os.path.join(out, name)
    command = (["nice", "-n", str(nice)] if nice else []) + [
        os.path.join(build, "gelmpm"),
        "--set", f"Output/Directory={directory}",
        "--set", "Output/Write particles=false",
        "--set", "Time stepping/End time=0.02",
        "--set", "Time stepping/Stop at times=0.001197, 0.008589, 0.02"]
    for s in sets:
        command += ["--set", s]
    command.append(os.path.join(TOP, "prm", "constrained_swelling.prm"))
    print(" ".join(f'"{c}"' if " " in c else c for c in command), flush=True)
    start = time.monotonic()
    with open(os.path.join(out, name + ".log"), "w") as log:
        status = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.monotonic() - start
    with open(os.path.join(directory if os.path.isdir(directory) else out, "wall.txt"), "w") as f:
        f.write(f"{wall:.3f} {status}\n")
    print(f"  {name}: exit {status}, {wall:.1f} s", flush=True)


def evaluate(out, name, reference, ramp_reference):
    directory = os.path.join(out, name)
    try:
        wall, status = open(os.path.join(directory, "wall.txt")).read().split()
        rows = read_csv(os.path.join(directory, "statistics.csv"))[1:]
    except (OSError, ValueError):
        return None
    result = {"wall": float(wall), "status": int(status)}
    if not rows or int(status) != 0:
        return result
    t = np.array([float(r["t_over_tau_d"]) for r in rows])
    d = np.array([float(r["delta_h_over_h0"]) for r in rows])
    ratio = d / reference(t)
    at = lambda s: ratio[np.argmin(abs(t - s))]
    w = (t >= WINDOW[0] * (1 - 1e-9)) & (t <= WINDOW[1] * (1 + 1e-9))
    worst = np.argmax(abs(ratio[w] - 1))
    dofs = lambda r: int(r["n_dofs_u"]) + int(r["n_dofs_mu"])
    result.update(first=ratio[0], t_first=t[0], r1=at(T1), r2=at(T2), worst=ratio[w][worst] - 1,
                  t_worst=t[w][worst], slope=np.polyfit(np.log(t[w]), np.log(d[w]), 1)[0],
                  steps=len(rows), dofs=(dofs(rows[0]), dofs(rows[-1])),
                  points=int(rows[-1]["n_particles"]), d1=d[np.argmin(abs(t - T1))])
    if ramp_reference is not None:
        rr = d / ramp_reference(t)
        result.update(ramp_r1=rr[np.argmin(abs(t - T1))], ramp_r2=rr[np.argmin(abs(t - T2))],
                      ramp_worst=max(abs(rr[w] - 1)))
    return result


def plot(out, reference, panels):
    """One panel per list of variant names: Delta h_MPM / Delta h_ref against t at every step."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    descriptions = {v[0]: v[2] for v in variants()}
    figure, axes = plt.subplots(2, 2, figsize=(11, 8.4), sharey=True)
    for ax, (title, names) in zip(axes.flat, panels):
        for name in names:
            path = os.path.join(out, name, "statistics.csv")
            if not os.path.exists(path):
                continue
            rows = read_csv(path)[1:]
            t = np.array([float(r["t_over_tau_d"]) for r in rows])
            d = np.array([float(r["delta_h_over_h0"]) for r in rows])
            ax.semilogx(t, d / reference(t), "o-", ms=3, lw=1, label=descriptions.get(name, name))
        ax.axhspan(0.99, 1.01, color="0.9")
        ax.axhline(1, color="k", lw=0.8)
        ax.axvspan(*WINDOW, color="y", alpha=0.1)
        ax.set_xlabel("t/τ_d")
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7)
    for ax in axes[:, 0]:
        ax.set_ylabel("Δh_MPM / Δh_ref")
    axes[0, 0].set_ylim(0.6, 1.3)
    figure.suptitle("§4.1 to 0.02 τ_d: Δh against the 1D reference at every step (grey band: ±1 %; "
                    "yellow: [1e-3, 1e-2] τ_d)", fontsize=10)
    figure.tight_layout()
    figure.savefig(os.path.join(out, "early.png"), dpi=110)


PANELS = [("grid and points (γ_μ = 25, growth 1.25)",
           ["h20_p6", "h30_p6", "h40_p6", "h60_p6", "h80_p6", "h80_p3"]),
          ("γ_μ on 20 × 160 and 80 × 640 (growth 1.25)",
           ["h20_p6_g5", "h20_p6_g10", "h20_p6_g12", "h20_p6", "h20_p6_g250", "h80_p3_g5",
            "h80_p3", "h80_p3_g100"]),
          ("ramp of the top's μ (against the step reference); γ_μ = 12",
           ["h20_p6_r0.0001", "h20_p6_growth1.25_r0.0004", "h20_p6_r0.001", "h20_p6_g12",
            "h40_p6_r0.0001", "h80_p3_r0.0001"]),
          ("step growth, grid and points together",
           ["h40_p6", "h40_p6_growth1.1", "h40_p6_growth1.05", "h40_p8_growth1.1",
            "h80_p6_growth1.1", "h40_p6_tol0.001", "h20_p6_growth1.05"])]


MECHANISM = [("m_h20_g5", 20, 6, 5), ("m_h20_g25", 20, 6, 25), ("m_h20_g250", 20, 6, 250),
             ("m_h80_g25", 80, 3, 25), ("m_h80_g5", 80, 3, 5)]


def mechanism(build, out, nice, run):
    """The first steps with the particles written at every step: mu at the top surface points,
    the undershoot of mu below mu_0 ahead of the front, the largest |mu - mu_ref| at the volume
    points, against sqrt(t)/h_mu. Returns a Markdown table."""
    sys.path.insert(0, os.path.join(TOP, "contrib", "plotting"))
    from gelmpm_files import read_pvd, read_vtu
    lines = ["| variant | t/τ_d | √t / h_μ | Δh/Δh_ref | μ at the top points (mean) | "
             "min μ − μ_0 (volume points) | max \\|μ − μ_ref\\| (at Y) |", "|" + "---|" * 7]
    for name, nx, ppc, g in MECHANISM:
        directory = os.path.join(out, name)
        if run:
            sets = grid(nx, ppc) + gamma(g) + ["Output/Interval steps=1"]
            command = (["nice", "-n", str(nice)] if nice else []) + [
                os.path.join(build, "gelmpm"), "--set", f"Output/Directory={directory}",
                "--set", "Time stepping/End time=0.001197",
                "--set", "Time stepping/Stop at times=0.001197"]
            for x in sets:
                command += ["--set", x]
            command.append(os.path.join(TOP, "prm", "constrained_swelling.prm"))
            print(" ".join(f'"{c}"' if " " in c else c for c in command), flush=True)
            with open(os.path.join(out, name + ".log"), "w") as log:
                subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, check=True)
        series = [(t, f) for t, f in read_pvd(directory) if t > 0]
        times = ",".join(f"{t:.10g}" for t, _ in series)
        ref_dir = os.path.join(out, name + "_reference")
        if run or not os.path.exists(ref_dir):
            subprocess.run([os.path.join(build, "gelmpm-swelling-1d"), "--times", times,
                            "--output", ref_dir], check=True, stdout=subprocess.DEVNULL)
        profiles = np.genfromtxt(os.path.join(ref_dir, "reference_profiles.csv"), delimiter=",",
                                 names=True)
        thickness = {round(float(r["t_over_tau_d"]), 12): float(r["delta_h_over_h0"])
                     for r in read_csv(os.path.join(directory, "statistics.csv"))}
        h_mu = 2 * 0.5 / nx
        for t, f in series:
            x, a = read_vtu(f)
            Y = x[:, 1] - a["displacement"][:, 1]
            mu, kind = a["mu_over_kT"].astype(float), a["kind"]
            top = (kind > 0) & (abs(Y - 1) < 1e-6)
            volume = kind == 0
            p = profiles[abs(profiles["t_over_tau_d"] - t) < 1e-9 * max(t, 1e-12)]
            mu_ref = np.interp(Y[volume], p["Y_over_h0"], p["mu_over_kT"])
            err = abs(mu[volume] - mu_ref)
            k = np.argmax(err)
            d_ref = reference_curve_cache(out)(t)
            d = min(thickness.items(), key=lambda kv: abs(kv[0] - t))[1]
            lines.append(f"| {nx} × {8 * nx}, {ppc} × {ppc}, γ_μ = {g} | {t:.3g} | "
                         f"{math.sqrt(t) / h_mu:.2f} | {d / d_ref:.3f} | {mu[top].mean():+.4f} | "
                         f"{mu[volume].min() - mu_0():+.4f} | {err[k]:.4f} ({Y[volume][k]:.3f}) |")
    return "\n".join(lines) + "\n"


_reference_cache = {}


def reference_curve_cache(out):
    if out not in _reference_cache:
        _reference_cache[out] = reference_curve(os.path.join(out, "reference"))
    return _reference_cache[out]


def table(out, rows, with_ramp):
    header = ["variant", "first step: Δh/Δh_ref", "Δh/Δh_ref at 1.197e-3", "at 8.589e-3",
              "worst Δh/Δh_ref − 1 in [1e-3, 1e-2] (at t)", "slope 1e-3–1e-2", "steps",
              "wall [s]", "unknowns (first → last step)", "points"]
    if with_ramp:
        header += ["against the ramped reference: at 1.197e-3, 8.589e-3, worst"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    group = None
    for name, grp, description, _, t_inc in rows:
        r = evaluate_cache[name]
        if grp != group:
            lines.append(f"| **{grp}** |" + " |" * (len(header) - 1))
            group = grp
        if r is None:
            cells = [description, "not run"] + [""] * (len(header) - 2)
        elif "r1" not in r:
            cells = [description, f"**failed: exit {r['status']}**"] + [""] * (len(header) - 2)
            cells[7] = f"{r['wall']:.1f}"
        else:
            cells = [description, f"{r['first']:.3f} (t = {r['t_first']:.3g})", f"{r['r1']:.4f}",
                     f"{r['r2']:.4f}", f"{100 * r['worst']:+.2f} % ({r['t_worst']:.3g})",
                     f"{r['slope']:.3f}", str(r["steps"]), f"{r['wall']:.1f}",
                     f"{r['dofs'][0]} → {r['dofs'][1]}", str(r["points"])]
            if with_ramp:
                cells.append(f"{r['ramp_r1']:.4f}, {r['ramp_r2']:.4f}, {100 * r['ramp_worst']:.2f} %"
                             if "ramp_r1" in r else "")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


evaluate_cache = {}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("--output", default=os.path.join(TOP, "output", "constrained_swelling_early"))
    parser.add_argument("--only", default="", help="comma-separated variant names")
    parser.add_argument("--tabulate-only", action="store_true", help="no runs, tables from --output")
    parser.add_argument("--ramp", action="store_true",
                        help="also compare the ramp variants with the reference under the same ramp "
                             "(gelmpm-swelling-1d --ramp)")
    parser.add_argument("--list", action="store_true", help="list the variants and exit")
    parser.add_argument("--plot", action="store_true",
                        help="also write early.png (Delta h_MPM / Delta h_ref of chosen variants)")
    parser.add_argument("--mechanism", action="store_true",
                        help="also the first steps with the particles at every step (mu at the "
                             "top, undershoot ahead of the front): mechanism.md")
    parser.add_argument("--skip-existing", action="store_true",
                        help="do not run a variant whose directory holds a finished run")
    args = parser.parse_args()
    build = os.environ.get("GELMPM_BUILD_DIR", os.path.join(TOP, "build"))
    nice = int(os.environ.get("NICE", "5"))
    out = os.path.abspath(args.output)
    os.makedirs(out, exist_ok=True)
    todo = variants()
    if args.list:
        for name, grp, description, sets, _ in todo:
            print(f"{name:24s} {grp:12s} {description}")
        return 0
    if args.only:
        keep = set(args.only.split(","))
        todo = [v for v in todo if v[0] in keep]
    reference = reference_curve(run_reference(build, out))
    ramp_references = {}
    if args.ramp:
        for t_inc in sorted({v[4] for v in todo if v[4] is not None}):
            ramp_references[t_inc] = reference_curve(run_reference(build, out, t_inc))
    if not args.tabulate_only:
        for name, _, _, sets, _ in todo:
            if args.skip_existing and os.path.exists(os.path.join(out, name, "wall.txt")):
                continue
            run_variant(build, out, name, sets, nice)
    for name, _, _, _, t_inc in todo:
        evaluate_cache[name] = evaluate(out, name, reference, ramp_references.get(t_inc))
    markdown = table(out, todo, args.ramp)
    if args.plot:
        plot(out, reference, PANELS)
    if args.mechanism:
        with open(os.path.join(out, "mechanism.md"), "w") as f:
            f.write(mechanism(build, out, nice, not args.tabulate_only))
        print(open(os.path.join(out, "mechanism.md")).read())
    with open(os.path.join(out, "early.md"), "w") as f:
        f.write(markdown)
    with open(os.path.join(out, "early.csv"), "w") as f:
        keys = ["first", "t_first", "r1", "r2", "worst", "t_worst", "slope", "steps", "wall",
                "points", "ramp_r1", "ramp_r2", "ramp_worst"]
        f.write("name,group,description," + ",".join(keys) + ",dofs_first,dofs_last\n")
        for name, grp, description, _, _ in todo:
            r = evaluate_cache[name] or {}
            f.write(f'{name},"{grp}","{description}",'
                    + ",".join(str(r.get(k, "")) for k in keys)
                    + "," + ",".join(str(x) for x in r.get("dofs", ("", ""))) + "\n")
    print(markdown)
    print(f"tables: {out}/early.md, early.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main())

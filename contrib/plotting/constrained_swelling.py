#!/usr/bin/python3
"""Paper §4.1 (constrained swelling): Fig. 6b and 6c, and the measured MPM-versus-reference agreement.

Inputs:
  --mpm DIR        output directory of `gelmpm prm/constrained_swelling.prm` (statistics.csv,
                   particles.pvd and the particles-NNNNN.vtu it lists)
  --reference DIR  output directory of `gelmpm-swelling-1d` (reference_thickness.csv,
                   reference_profiles.csv)
  --log FILE       optional: the gelmpm log (stdout); adds the cost of the run (steps, Newton
                   iterations, TimerOutput split, µs per material point per assembly)

Outputs (into --output DIR):
  fig6b_thickness.png     log-log Δh/h_0 against t/τ_d: MPM, finite-difference reference, √t slope
  fig6c_chemical_potential.png   μ/k_BT against Y at the profile times: MPM volume points, reference
  agreement_diagnostics.png      where MPM and reference differ: Δh error against t, μ error against Y
  agreement.csv, agreement.md    the measured agreement and the targets
  thickness.md                   Δh of MPM and reference at the profile times
  cost.md                        only with --log

Typical use (contrib/benchmarks/constrained_swelling.sh runs all of it):

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  build/gelmpm --set "Output/Directory=out/mpm" prm/constrained_swelling.prm | tee out/gelmpm.log
  build/gelmpm-swelling-1d --samples 4000 --output out/reference
  /usr/bin/python3 contrib/plotting/constrained_swelling.py \\
      --mpm out/mpm --reference out/reference --log out/gelmpm.log --output out

Needs numpy, matplotlib and VTK's Python module (Debian: python3-numpy python3-matplotlib
python3-vtk9; `bash contrib/setup.sh --plotting`). Use /usr/bin/python3, which sees Debian's packages.

Definitions (doc/constrained_swelling.md):
  - Y is the initial (pre-swelling) height of a point, Y = y - displacement_y, in h_0;
  - the reference Δh is interpolated at the MPM step times (linear in log t, log Δh);
  - Δh_eq = λ(μ = 0) - 1 is computed here from the closed-form μ(λ) at P_22 = 0;
  - slopes are least-squares fits of log Δh against log t over the MPM steps in a window;
  - μ errors are over volume points (kind 0), the reference linearly interpolated at each Y.
"""

import argparse
import math
import os
import re
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from gelmpm_files import read_csv, read_pvd, read_vtu  # noqa: E402


# ------------------------------------------------------------------------------------------------
# Input

def read_points(vtu):
    """Point fields of one particles-NNNNN.vtu: Y (initial height), mu_over_kT, kind."""
    position, fields = read_vtu(vtu)
    return {
        "Y": position[:, 1] - fields["displacement"][:, 1].astype(float),
        "mu": fields["mu_over_kT"].astype(float),
        "kind": fields["kind"].astype(int),
    }


def read_cost(log_file):
    """Steps, TimerOutput rows {section: (calls, seconds)} and total wall time from a gelmpm log."""
    text = open(log_file, encoding="utf-8", errors="replace").read()
    sections = {}
    for name, calls, seconds in re.findall(r"^\|\s*([a-z][\w ]*?)\s*\|\s*(\d+)\s*\|\s*([\d.e+-]+)s\s*\|",
                                           text, re.MULTILINE):
        sections[name] = (int(calls), float(seconds))
    total = re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+-]+)s", text)
    points = re.search(r"material points: (\d+) volume, (\d+) surface", text)
    steps = re.search(r"reached t/tau_d = \S+ in (\d+) steps", text)
    return {
        "sections": sections,
        "total": float(total.group(1)) if total else float("nan"),
        "volume_points": int(points.group(1)) if points else 0,
        "surface_points": int(points.group(2)) if points else 0,
        "steps": int(steps.group(1)) if steps else 0,
    }


# ------------------------------------------------------------------------------------------------
# Analysis

def equilibrium_thickness_change(chi, n_nu, lambda_0, mu_top=0.0):
    """Δh_eq/h_0 = λ - 1 with μ(λ) = mu_top, μ/kT = Nν(F22²-1)/J + ln(1-1/J) + 1/J + χ/J² at P_22 = 0,
    F22 = λ_0 λ, J = λ_0³ λ (include/gelmpm/reference/constrained_swelling_1d.h). Bisection."""
    def mu(stretch):
        j = lambda_0 ** 3 * stretch
        f22 = lambda_0 * stretch
        return n_nu * (f22 * f22 - 1.0) / j + math.log(1.0 - 1.0 / j) + 1.0 / j + chi / j ** 2

    low, high = 1.0, 2.0
    while mu(high) < mu_top:
        high *= 2.0
    for _ in range(200):
        middle = 0.5 * (low + high)
        if mu(middle) < mu_top:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high) - 1.0


def log_log_interpolation(t, t_table, value_table):
    return np.exp(np.interp(np.log(t), np.log(t_table), np.log(value_table)))


def slope(t, dh, window):
    inside = (t >= window[0]) & (t <= window[1]) & (dh > 0)
    if inside.sum() < 2:
        return float("nan"), int(inside.sum())
    return float(np.polyfit(np.log(t[inside]), np.log(dh[inside]), 1)[0]), int(inside.sum())


def binned_means(y, values, bins):
    """Means of @p values over @p bins equal bins of Y in [0, 1]; bins = 0: over the points that
    share one Y (to 1e-6), i.e. one row of volume points each."""
    if bins > 0:
        edges = np.linspace(0.0, 1.0, bins + 1)
        index = np.clip(np.digitize(y, edges) - 1, 0, bins - 1)
    else:
        _, index = np.unique(np.round(y, 6), return_inverse=True)
    centres = np.bincount(index, weights=y) / np.maximum(np.bincount(index), 1)
    means = np.bincount(index, weights=values) / np.maximum(np.bincount(index), 1)
    used = np.bincount(index) > 0
    return centres[used], means[used]


# ------------------------------------------------------------------------------------------------
# The comparison (shared)

def agreement_data(mpm_dir, reference_dir, chi=0.1, n_nu=7.299e-3, lambda_0=1.2801,
                   profiles=True, note=print):
    """The MPM-versus-reference comparison that the agreement table and Fig. 6b/6c are made of;
    shared with contrib/benchmarks/speed_accuracy.py. Returns a dict with
      t_mpm, dh_mpm, newton        per step with t > 0 (statistics.csv)
      t_ref, dh_ref                reference thickness curve (sorted)
      dh_ref_at_mpm                reference interpolated at the MPM step times
      dh_eq                        closed-form equilibrium Δh/h_0
      error                        (Δh_MPM − Δh_ref)/Δh_eq per step
      worst                        index of max |error| over t ≥ 0.01 τ_d
      end_error                    (Δh_MPM − Δh_eq)/Δh_eq at the last step
      profiles                     per particles-*.vtu at a reference profile time (if @p profiles):
                                   time, y, mu, difference, y_ref, mu_ref, worst, worst_y, rms, top_mu
    Exits (SystemExit) on missing or inconsistent input."""
    statistics = read_csv(os.path.join(mpm_dir, "statistics.csv"))
    if "delta_h_over_h0" not in statistics:
        sys.exit("constrained_swelling.py: statistics.csv has no delta_h_over_h0 "
                 "(Observables/Thickness pieces)")
    t_all = statistics["t_over_tau_d"]
    keep = t_all > 0.0
    t_mpm, dh_mpm = t_all[keep], statistics["delta_h_over_h0"][keep]
    newton = statistics["newton_iterations"][keep]

    thickness = read_csv(os.path.join(reference_dir, "reference_thickness.csv"))
    t_ref, dh_ref = thickness["t_over_tau_d"], thickness["delta_h_over_h0"]
    order = np.argsort(t_ref)
    t_ref, dh_ref = t_ref[order], dh_ref[order]
    if t_mpm.min() < t_ref.min() or t_mpm.max() > t_ref.max() * (1 + 1e-12):
        sys.exit("constrained_swelling.py: the reference does not cover the MPM times "
                 f"[{t_mpm.min():g}, {t_mpm.max():g}]")
    dh_ref_at_mpm = log_log_interpolation(np.minimum(t_mpm, t_ref.max()), t_ref, dh_ref)

    dh_eq = equilibrium_thickness_change(chi, n_nu, lambda_0)
    error = (dh_mpm - dh_ref_at_mpm) / dh_eq
    late = t_mpm >= 0.01
    worst = int(np.argmax(np.abs(error) * late))
    end_error = (dh_mpm[-1] - dh_eq) / dh_eq

    mpm_profiles = []
    if profiles:
        reference_profiles = read_csv(os.path.join(reference_dir, "reference_profiles.csv"))
        profile_times = np.unique(reference_profiles["t_over_tau_d"])
        series = [(time, path) for time, path in read_pvd(mpm_dir) if time > 0.0]
        for time, path in series:
            match = np.abs(profile_times - time) <= 1e-9 * max(1.0, time)
            if not match.any():
                note(f"constrained_swelling.py: no reference profile at t = {time:g}; skipped")
                continue
            on = reference_profiles["t_over_tau_d"] == profile_times[match][0]
            y_ref, mu_ref = reference_profiles["Y_over_h0"][on], reference_profiles["mu_over_kT"][on]
            order = np.argsort(y_ref)
            y_ref, mu_ref = y_ref[order], mu_ref[order]
            points = read_points(path)
            volume = points["kind"] == 0
            y, mu = points["Y"][volume], points["mu"][volume]
            difference = mu - np.interp(y, y_ref, mu_ref)
            worst_point = np.argmax(np.abs(difference))
            top = points["kind"] != 0
            top = top & (points["Y"] > 1.0 - 1e-6)
            mpm_profiles.append({
                "time": time, "y": y, "mu": mu, "difference": difference, "y_ref": y_ref,
                "mu_ref": mu_ref, "worst": abs(difference[worst_point]), "worst_y": y[worst_point],
                "rms": float(np.sqrt(np.mean(difference ** 2))),
                "top_mu": points["mu"][top].mean() if top.any() else float("nan"),
            })
    return {"t_mpm": t_mpm, "dh_mpm": dh_mpm, "newton": newton, "t_ref": t_ref, "dh_ref": dh_ref,
            "dh_ref_at_mpm": dh_ref_at_mpm, "dh_eq": dh_eq, "error": error, "worst": worst,
            "end_error": end_error, "profiles": mpm_profiles}


# ------------------------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(
        description="Paper §4.1: Fig. 6b/6c and the measured MPM-versus-reference agreement.",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--mpm", required=True, help="gelmpm output directory")
    parser.add_argument("--reference", required=True, help="gelmpm-swelling-1d output directory")
    parser.add_argument("--output", default=".", help="directory for the PNGs and tables")
    parser.add_argument("--log", help="gelmpm log (stdout) for the cost table")
    parser.add_argument("--chi", type=float, default=0.1, help="Flory-Huggins chi")
    parser.add_argument("--N-nu", dest="n_nu", type=float, default=7.299e-3, help="N nu")
    parser.add_argument("--lambda-0", dest="lambda_0", type=float, default=1.2801,
                        help="initial isotropic stretch")
    parser.add_argument("--bins", type=int, default=0,
                        help="Fig. 6c: MPM volume points as means over this many equal bins of Y "
                             "(0: one mean per row of points with the same Y)")
    parser.add_argument("--every", type=int, default=3,
                        help="Fig. 6c: draw every this many-th mean (rows are dense)")
    parser.add_argument("--dpi", type=int, default=150)
    arguments = parser.parse_args()
    os.makedirs(arguments.output, exist_ok=True)

    # ---- thickness --------------------------------------------------------------------------
    data = agreement_data(arguments.mpm, arguments.reference, arguments.chi, arguments.n_nu,
                          arguments.lambda_0)
    t_mpm, dh_mpm, newton = data["t_mpm"], data["dh_mpm"], data["newton"]
    t_ref, dh_ref, dh_ref_at_mpm = data["t_ref"], data["dh_ref"], data["dh_ref_at_mpm"]
    dh_eq, error, worst = data["dh_eq"], data["error"], data["worst"]

    rows = []  # (quantity, where, measured, target, met)
    rows.append(("max |Δh_MPM − Δh_ref| / Δh_eq", "t ≥ 0.01 τ_d (worst at t = %.4g τ_d)" % t_mpm[worst],
                 "%.3f %%" % (100 * abs(error[worst])), "≤ 2 %", abs(error[worst]) <= 0.02))
    end_error = data["end_error"]
    rows.append(("(Δh_MPM − Δh_eq) / Δh_eq at the end",
                 "t = %.4g τ_d; Δh_MPM/h_0 = %.6f, Δh_eq/h_0 = %.6f" % (t_mpm[-1], dh_mpm[-1], dh_eq),
                 "%+.4f %%" % (100 * end_error), "≤ 0.5 %", abs(end_error) <= 0.005))
    reference_end = dh_ref[-1]
    # The windows are 0.001-0.1 and 0.01-1; the two decades below are shown for diagnosis.
    for window, targeted in [((1e-3, 1e-1), True), ((1e-2, 1.0), True),
                             ((1e-3, 1e-2), False), ((1e-2, 1e-1), False)]:
        s, n = slope(t_mpm, dh_mpm, window)
        s_ref, _ = slope(t_ref, dh_ref, window)
        rows.append(("log–log slope of Δh_MPM", "%g ≤ t/τ_d ≤ %g (%d steps; reference %.3f)"
                     % (window[0], window[1], n, s_ref),
                     "%.3f" % s + ("" if targeted or abs(s - 0.5) <= 0.05 else " (outside 0.5 ± 0.05)"),
                     "0.5 ± 0.05" if targeted else "(diagnostic)",
                     abs(s - 0.5) <= 0.05 if targeted else None))

    # ---- profiles ---------------------------------------------------------------------------
    mpm_profiles = data["profiles"]
    for entry in mpm_profiles:
        time = entry["time"]
        targeted = time >= 0.1281 * (1 - 1e-9)
        rows.append(("max |μ_MPM − μ_ref| / k_BT over volume points",
                     "t = %g τ_d (worst at Y = %.4f; rms %.2g; top surface points μ = %.2g)"
                     % (time, entry["worst_y"], entry["rms"], entry["top_mu"]),
                     "%.2e" % entry["worst"],
                     "≤ 0.02" if targeted else "(not targeted)",
                     (entry["worst"] <= 0.02) if targeted else None))

    # ---- tables -----------------------------------------------------------------------------
    def verdict(met):
        return "—" if met is None else ("yes" if met else "NO")

    with open(os.path.join(arguments.output, "agreement.csv"), "w", encoding="utf-8") as out:
        out.write("quantity,where,measured,target,met\n")
        for quantity, where, measured, target, met in rows:
            out.write('"%s","%s","%s","%s",%s\n' % (quantity, where, measured, target, verdict(met)))
    with open(os.path.join(arguments.output, "agreement.md"), "w", encoding="utf-8") as out:
        out.write("| quantity | where | measured | target | met |\n|---|---|---|---|---|\n")
        for quantity, where, measured, target, met in rows:
            cells = [text.replace("|", "\\|") for text in (quantity, where, measured, target)]
            out.write("| " + " | ".join(cells + [verdict(met)]) + " |\n")
    with open(os.path.join(arguments.output, "thickness.md"), "w", encoding="utf-8") as out:
        out.write("| t/τ_d | Δh_MPM/h_0 | Δh_ref/h_0 | (Δh_MPM − Δh_ref)/Δh_eq | Δh_MPM/Δh_ref − 1 |\n"
                  "|---|---|---|---|---|\n")
        for entry in mpm_profiles:
            i = np.argmin(np.abs(t_mpm - entry["time"]))
            out.write("| %g | %.6f | %.6f | %+.3f %% | %+.2f %% |\n"
                      % (t_mpm[i], dh_mpm[i], dh_ref_at_mpm[i], 100 * error[i],
                         100 * (dh_mpm[i] / dh_ref_at_mpm[i] - 1)))
    print("Δh at the profile times:")
    print(open(os.path.join(arguments.output, "thickness.md"), encoding="utf-8").read())
    print("Agreement of MPM (%s) with the reference (%s); Δh_eq/h_0 = %.6f (closed form), "
          "reference at t = %g: %.6f" % (arguments.mpm, arguments.reference, dh_eq, t_ref[-1],
                                         reference_end))
    print(open(os.path.join(arguments.output, "agreement.md"), encoding="utf-8").read())

    # ---- cost -------------------------------------------------------------------------------
    if arguments.log:
        cost = read_cost(arguments.log)
        sections = cost["sections"]
        n_points = cost["volume_points"] + cost["surface_points"]
        lines = ["| quantity | value |", "|---|---|",
                 "| steps | %d |" % len(t_mpm),
                 "| Newton iterations (linear solves) | %d (%.2f per step; %d to %d) |"
                 % (newton.sum(), newton.mean(), newton.min(), newton.max()),
                 "| material points | %d volume + %d surface |"
                 % (cost["volume_points"], cost["surface_points"]),
                 "| wall time (TimerOutput total) | %.0f s |" % cost["total"]]
        for name, (calls, seconds) in sections.items():
            lines.append("| %s | %.3g s in %d calls (%.0f %%) |"
                         % (name, seconds, calls, 100 * seconds / cost["total"]))
        if "assembly" in sections and n_points:
            calls, seconds = sections["assembly"]
            lines.append("| assembly per material point per assembly | %.2f µs |"
                         % (1e6 * seconds / calls / n_points))
        with open(os.path.join(arguments.output, "cost.md"), "w", encoding="utf-8") as out:
            out.write("\n".join(lines) + "\n")
        print("Cost of the run (%s):\n%s\n" % (arguments.log, "\n".join(lines)))

    # ---- Fig. 6b ----------------------------------------------------------------------------
    figure, axes = plt.subplots(figsize=(6.4, 4.8))
    shown = (t_ref >= 0.5 * t_mpm.min()) & (t_ref <= t_mpm.max())
    axes.loglog(t_ref[shown], dh_ref[shown], "-", color="black", lw=1.5,
                label="finite-difference reference")
    # About 12 markers per decade, so that the dense late steps do not hide the line.
    picks = np.unique(np.searchsorted(t_mpm, np.logspace(np.log10(t_mpm.min()),
                                                         np.log10(t_mpm.max()), 150)))
    picks = picks[picks < len(t_mpm)]
    axes.loglog(t_mpm[picks], dh_mpm[picks], "o", mfc="none", color="tab:red", ms=4.5,
                label="MPM (Q2–Q2SD, %d steps)" % len(t_mpm))
    anchor = 1e-3
    c = log_log_interpolation(anchor, t_ref, dh_ref) / math.sqrt(anchor)
    t_line = np.logspace(math.log10(t_mpm.min()), 1.0, 50)
    axes.loglog(t_line, 1.6 * c * np.sqrt(t_line), "--", color="tab:blue", lw=1.2,
                label=r"$\propto\sqrt{t}$ (slope 1/2)")
    axes.axhline(dh_eq, color="gray", lw=0.8, ls=":", label=r"$\Delta h_{eq}/h_0 = %.4f$" % dh_eq)
    for entry in mpm_profiles:
        axes.axvline(entry["time"], color="gray", lw=0.4, alpha=0.5)
    axes.set_xlabel(r"$t/\tau_d$")
    axes.set_ylabel(r"$\Delta h / h_0$")
    axes.set_title("Constrained swelling (§4.1, Fig. 6b)")
    axes.legend(loc="lower right", fontsize=9)
    axes.grid(True, which="major", alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(arguments.output, "fig6b_thickness.png"), dpi=arguments.dpi)
    plt.close(figure)

    # ---- Fig. 6c ----------------------------------------------------------------------------
    figure, axes = plt.subplots(figsize=(6.4, 4.8))
    colours = plt.cm.viridis(np.linspace(0.0, 0.92, max(1, len(mpm_profiles))))
    for colour, entry in zip(colours, mpm_profiles):
        y, mu = binned_means(entry["y"], entry["mu"], arguments.bins)
        axes.plot(y[::max(1, arguments.every)], mu[::max(1, arguments.every)], "o", color=colour,
                  ms=2.5, alpha=0.8, label=r"$t/\tau_d = %g$" % entry["time"])
    for entry in mpm_profiles:
        axes.plot(entry["y_ref"], entry["mu_ref"], "-", color="black", lw=0.8)
    axes.plot([], [], "-", color="black", lw=0.8, label="reference")
    axes.set_xlabel(r"$Y/h_0$ (initial configuration)")
    axes.set_ylabel(r"$\mu / k_B T$")
    axes.set_xlim(0.0, 1.0)
    axes.set_title("Chemical potential (§4.1, Fig. 6c)\ndots: MPM volume points ("
                   + ("means over %d bins of Y" % arguments.bins if arguments.bins > 0
                      else "row means") + "); lines: finite-difference reference", fontsize=10)
    axes.legend(fontsize=8, loc="lower left")
    axes.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(arguments.output, "fig6c_chemical_potential.png"), dpi=arguments.dpi)
    plt.close(figure)

    # ---- diagnostics ------------------------------------------------------------------------
    figure, (left, right) = plt.subplots(1, 2, figsize=(11.5, 4.4))
    left.semilogx(t_mpm, 100 * error, "-", color="tab:red", lw=1)
    left.axhline(0.0, color="black", lw=0.6)
    left.axvspan(t_mpm.min(), 0.01, color="gray", alpha=0.15, label=r"$t < 0.01\,\tau_d$ (not targeted)")
    left.set_xlabel(r"$t/\tau_d$")
    left.set_ylabel(r"$(\Delta h_{MPM} - \Delta h_{ref})/\Delta h_{eq}$  [%]")
    left.set_title("Thickness change: MPM minus reference", fontsize=10)
    left.legend(fontsize=8)
    left.grid(True, alpha=0.3)
    for colour, entry in zip(colours, mpm_profiles):
        right.semilogy(entry["y"], np.maximum(np.abs(entry["difference"]), 1e-10), ".", color=colour,
                       ms=1.5, label=r"$t/\tau_d = %g$" % entry["time"])
    right.axhline(0.02, color="black", lw=0.8, ls="--", label=r"0.02 $k_BT$")
    right.set_xlabel(r"$Y/h_0$ (initial configuration)")
    right.set_ylabel(r"$|\mu_{MPM} - \mu_{ref}| / k_B T$ (volume points)")
    right.set_title("Chemical potential: MPM minus reference", fontsize=10)
    right.set_xlim(0.0, 1.0)
    right.legend(fontsize=7, loc="lower right", markerscale=5, ncol=2)
    right.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(arguments.output, "agreement_diagnostics.png"), dpi=arguments.dpi)
    plt.close(figure)

    print("Figures and tables: " + ", ".join(
        os.path.join(arguments.output, name) for name in
        ["fig6b_thickness.png", "fig6c_chemical_potential.png", "agreement_diagnostics.png",
         "agreement.md", "agreement.csv", "thickness.md"] + (["cost.md"] if arguments.log else [])))
    return 0 if all(met is not False for *_, met in rows) else 1


if __name__ == "__main__":
    sys.exit(main())

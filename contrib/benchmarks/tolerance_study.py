#!/usr/bin/python3
"""Error-controlled time steps ('Time stepping/Tolerance') against the paper's step rules.

    /usr/bin/python3 contrib/benchmarks/tolerance_study.py [--scenes swelling,punch]
        [--output DIR] [--estimate] [--tabulate-only]

Runs, once each (one repeat: wall times are indicative; the step and iteration counts are exact):

swelling   prm/constrained_swelling.prm (paper §4.1) to 1713 tau_d
           - with 'Tolerance' = 1e-1 ... 1e-4 (no step caps, growth factor 2);
           - with the paper's caps of eq. (64) times 4, 2, 1, 0.5 (growth 1.25, the scene as is);
           error: max |Delta h - Delta h_ref| / Delta h_eq over t >= 0.01 tau_d against the
           finite-difference reference gelmpm-swelling-1d --samples 4000 (the metric of
           doc/performance.md, agreement_data() of contrib/plotting/constrained_swelling.py), and
           the mu error over the volume points at the Fig. 6c times >= 0.1281 tau_d.
punch      prm/flat_punch.prm (paper §4.2) on 30 x 30 cells (h_u = 0.05 H, the 'draft' level of
           doc/performance.md), to 2300 tau_d, with 'Observables/Volume ratio range' on
           - with 'Tolerance' = 1e-1 ... 1e-5 (the scene's ramp caps kept, growth factor 2);
           - with the scene's own stepping (growth factor 1.25 after the ramp) and growth factors
             1.1 and 1.05;
           error: the time-discretisation error of the drainage, max over the steps of
           |J_mean(t) - J_ref(t)| / |J_mean(0) - J_mean(end)|, against the same discretisation run
           with steps growing by a factor 1.0025 (no tolerance; about 8,000 steps; J_ref
           interpolated linearly in log t). The spatial error is the same in every run and does
           not enter (a step of any length leaves a converged state unchanged, doc/method.md).

Writes <DIR>/tolerance_study.csv, tables.md and tolerance_study.png (error against tolerance,
error against wall time). Runs are cached in <DIR>/runs/<name>/result.json.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "plotting"))
import speed_accuracy as sa  # noqa: E402  (errors_of, caps, parse_time_v, loadavg)
from gelmpm_files import read_csv  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TOLERANCES = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
PUNCH_TOLERANCES = TOLERANCES + [1e-5]
PUNCH_REFERENCE_GROWTH = 1.0025
PUNCH_REFERENCE = "punch-growth%g" % PUNCH_REFERENCE_GROWTH
TOLERANCE_STEPPING = {"Time stepping/Growth factor": "2"}
PUNCH = os.path.join(sa.TOP, "prm", "flat_punch.prm")
PUNCH_GRID = {"Background grid/Cells": "30, 30", "Observables/Volume ratio range": "true",
              "Output/Write particles": "false"}


def runs_of(scene):
    """(name, kind, x, overrides) of every run of a scene; kind 'tolerance' or 'rule'."""
    runs = []
    if scene == "swelling":
        for tol in TOLERANCES:
            runs.append(("swelling-tol%g" % tol, "tolerance", tol,
                         dict(TOLERANCE_STEPPING, **{"Time stepping/Tolerance": "%g" % tol,
                                                     "Time stepping/Step caps": ""})))
        for scale in [4, 2, 1, 0.5]:
            runs.append(("swelling-caps-x%g" % scale, "rule", scale,
                         {} if scale == 1 else {"Time stepping/Step caps": sa.caps(scale)}))
    else:
        runs.append((PUNCH_REFERENCE, "reference", PUNCH_REFERENCE_GROWTH,
                     dict(PUNCH_GRID, **{"Time stepping/Growth factor": "%g" % PUNCH_REFERENCE_GROWTH})))
        for tol in PUNCH_TOLERANCES:
            runs.append(("punch-tol%g" % tol, "tolerance", tol,
                         dict(PUNCH_GRID, **TOLERANCE_STEPPING,
                              **{"Time stepping/Tolerance": "%g" % tol})))
        for growth in [1.25, 1.1, 1.05]:
            runs.append(("punch-growth%g" % growth, "rule", growth,
                         dict(PUNCH_GRID, **{"Time stepping/Growth factor": "%g" % growth})))
    return runs


def run(gelmpm, scene_file, run_dir, overrides):
    """Run gelmpm once under /usr/bin/time -v; the cost figures."""
    os.makedirs(run_dir, exist_ok=True)
    out = os.path.join(run_dir, "mpm")
    command = ["/usr/bin/time", "-v", gelmpm, "--set", "Output/Directory=" + out]
    for entry, value in overrides.items():
        command += ["--set", "%s=%s" % (entry, value)]
    command.append(scene_file)
    load = sa.loadavg()
    start = time.monotonic()
    with open(os.path.join(run_dir, "gelmpm.log"), "w") as log, \
            open(os.path.join(run_dir, "time.txt"), "w") as timing:
        status = subprocess.run(command, stdout=log, stderr=timing, cwd=sa.TOP).returncode
    wall = time.monotonic() - start
    rss, _ = sa.parse_time_v(os.path.join(run_dir, "time.txt"))
    result = {"command": " ".join("'%s'" % c if " " in c else c for c in command[2:]),
              "status": status, "wall": wall, "max_rss_mb": rss, "loadavg_before": load}
    stats_file = os.path.join(out, "statistics.csv")
    if os.path.isfile(stats_file):
        stats = read_csv(stats_file)
        later = stats["t_over_tau_d"] > 0
        result["steps"] = int(later.sum())
        result["newton_iterations"] = int(np.nansum(stats["newton_iterations"][later]))
        result["attempts"] = int(np.nansum(stats["attempts"][later]))
    return result


def drainage_error(run_dir, reference_dir):
    """max |J_mean - J_ref| / |J_mean(0) - J_mean(end)| over the steps after t = 0."""
    stats = read_csv(os.path.join(run_dir, "mpm", "statistics.csv"))
    ref = read_csv(os.path.join(reference_dir, "mpm", "statistics.csv"))
    t_ref, j_ref = ref["t_over_tau_d"][1:], ref["J_mean"][1:]
    t, j = stats["t_over_tau_d"][1:], stats["J_mean"][1:]
    reference_at = np.interp(np.log(t), np.log(t_ref), j_ref)
    change = abs(ref["J_mean"][0] - ref["J_mean"][-1])
    errors = np.abs(j - reference_at) / change
    worst = int(np.argmax(errors))
    return {"error": float(errors[worst]), "error_t": float(t[worst])}


def write_tables(path, rows):
    with open(path, "w") as table:
        for scene, title in [("swelling", "§4.1 (20 x 160 cells, to 1713 tau_d)"),
                             ("punch", "flat punch (30 x 30 cells, to 2300 tau_d)")]:
            mine = [r for r in rows if r["scene"] == scene]
            if not mine:
                continue
            table.write("#### %s\n\n" % title)
            table.write("| run | steps | attempts | Newton | wall | peak memory | error |%s\n"
                        % (" μ error |" if scene == "swelling" else ""))
            table.write("|---|---:|---:|---:|---:|---:|---:|%s\n"
                        % ("---:|" if scene == "swelling" else ""))
            for r in mine:
                table.write("| %s | %s | %s | %s | %.1f s | %.0f MB | %.3g %% |%s\n" % (
                    r["label"], r.get("steps", ""), r.get("attempts", ""),
                    r.get("newton_iterations", ""), r["wall"], r["max_rss_mb"],
                    100 * r.get("error", float("nan")),
                    (" %.2g |" % r.get("mu_error", float("nan"))) if scene == "swelling" else ""))
            table.write("\n")


def plot(path, rows):
    scenes = [s for s in ["swelling", "punch"] if any(r["scene"] == s for r in rows)]
    figure, axes = plt.subplots(len(scenes), 2, figsize=(10, 4 * len(scenes)), squeeze=False)
    for row, scene in enumerate(scenes):
        mine = [r for r in rows if r["scene"] == scene and np.isfinite(r.get("error", np.nan))]
        tol = [r for r in mine if r["kind"] == "tolerance"]
        rule = [r for r in mine if r["kind"] == "rule"]
        name = "§4.1, Δh error" if scene == "swelling" else "flat punch, drainage error"
        ax = axes[row][0]
        x = np.array([r["x"] for r in tol])
        ax.loglog(x, [r["error"] for r in tol], "o-", label="measured")
        ax.loglog(x, x, "k--", lw=0.8, label="error = Tolerance")
        ax.set_xlabel("Time stepping/Tolerance")
        ax.set_ylabel("error")
        ax.set_title(name + " against the tolerance")
        ax.legend()
        ax = axes[row][1]
        ax.loglog([r["wall"] for r in tol], [r["error"] for r in tol], "o-", label="Tolerance")
        for r in tol:
            ax.annotate("%g" % r["x"], (r["wall"], r["error"]), fontsize=7,
                        textcoords="offset points", xytext=(3, 3))
        ax.loglog([r["wall"] for r in rule], [r["error"] for r in rule], "s-",
                  label="caps × k" if scene == "swelling" else "growth factor")
        for r in rule:
            ax.annotate(r["label"].split("-", 1)[1], (r["wall"], r["error"]), fontsize=7,
                        textcoords="offset points", xytext=(3, -9))
        ax.set_xlabel("wall time (s), one run each")
        ax.set_ylabel("error")
        ax.set_title(name + " against cost")
        ax.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", default="swelling,punch")
    parser.add_argument("--output", default=os.path.join(sa.TOP, "output", "tolerance_study"))
    parser.add_argument("--estimate", action="store_true", help="print the plan, run nothing")
    parser.add_argument("--tabulate-only", action="store_true")
    arguments = parser.parse_args()
    build = os.path.abspath(os.environ.get("GELMPM_BUILD_DIR", os.path.join(sa.TOP, "build")))
    gelmpm = os.path.join(build, "gelmpm")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    out = os.path.abspath(arguments.output)
    os.makedirs(out, exist_ok=True)
    scenes = arguments.scenes.split(",")
    plan = [(scene,) + r for scene in scenes for r in runs_of(scene)]
    # The reference of the punch first: every punch error needs it.
    plan.sort(key=lambda p: p[2] != "reference")
    print("tolerance_study.py: %d runs (one each), binary %s, results in %s; on an idle 2-core "
          "machine about 9 min (the tightest tolerances take longest); load average now %s"
          % (len(plan), gelmpm, out, " ".join(sa.loadavg())))
    if arguments.estimate:
        for p in plan:
            print("  %-24s %s" % (p[1], p[4]))
        return 0
    reference_1d = os.path.join(out, "reference-1d")
    if "swelling" in scenes and not os.path.isfile(
            os.path.join(reference_1d, "reference_profiles.csv")) and not arguments.tabulate_only:
        subprocess.run([os.path.join(build, "gelmpm-swelling-1d"), "--samples", "4000",
                        "--output", reference_1d], stdout=subprocess.DEVNULL, check=True)
    rows = []
    for scene, name, kind, x, overrides in plan:
        run_dir = os.path.join(out, "runs", name)
        cache = os.path.join(run_dir, "result.json")
        if os.path.isfile(cache):
            result = json.load(open(cache))
        elif arguments.tabulate_only:
            continue
        else:
            scene_file = sa.SCENE if scene == "swelling" else PUNCH
            result = run(gelmpm, scene_file, run_dir, overrides)
            json.dump(result, open(cache, "w"), indent=1)
        if result["status"] == 0:
            if scene == "swelling":
                errors = sa.errors_of(os.path.join(run_dir, "mpm"), reference_1d, True)
                result["error"], result["mu_error"] = errors["dh_error"], errors["mu_error"]
            elif kind != "reference":
                result.update(drainage_error(run_dir, os.path.join(out, "runs", PUNCH_REFERENCE)))
        result.update(scene=scene, label=name, kind=kind, x=x)
        rows.append(result)
        print("  %-24s status %d  %6.1f s  steps %5s  error %s" % (
            name, result["status"], result["wall"], result.get("steps", "?"),
            "%.3g" % result["error"] if "error" in result else "-"), flush=True)
    with open(os.path.join(out, "tolerance_study.csv"), "w", newline="") as f:
        keys = ["scene", "label", "kind", "x", "status", "steps", "attempts", "newton_iterations",
                "wall", "max_rss_mb", "error", "mu_error"]
        writer = csv.DictWriter(f, keys, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    write_tables(os.path.join(out, "tables.md"), rows)
    plot(os.path.join(out, "tolerance_study.png"), rows)
    print("tolerance_study.py: wrote %s/tolerance_study.csv, tables.md, tolerance_study.png" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

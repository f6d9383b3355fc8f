#!/usr/bin/python3
"""Paper §4.2 (flat punch, prm/flat_punch.prm): the body-fitted finite-element peer
(gelmpm-fem-flat-punch) against the MPM, at equal accuracy and as the indentation deepens
(doc/fem_peer.md).

  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  /usr/bin/python3 contrib/benchmarks/fem_peer_flat_punch.py [--build build] [--output DIR]

Part 1, accuracy against cost: the scene with the punch pushed to --depth (default 0.05 H, where the
FE model converges on every mesh; at the scene's 0.09 H it stops on meshes of 32 x 32 cells and
finer, part 2), ramped over t_inc = 3.125e-6 tau_d and held to 2300 tau_d. Per run the whole process is timed (median of --repeats runs; wall and CPU time).
The accuracy measure is the settlement of the free top surface (x > punch edge), u_y along the top
of the initial configuration, at the end of the ramp (undrained limit) and at 2300 tau_d (drained
limit), against the finest FE mesh (--reference-cells, default 64 x 64):
  error = max over the free top |u_y - u_y,ref| / depth   (and the root mean square over the points)
FE: top_profile-NN.csv of gelmpm-fem-flat-punch (9 points per face); MPM: the surface points of the
piece 'top' in particles.pvd, u_y from the field 'displacement', the initial x from the position
minus the displacement, shifted by the grid offset H/4. The reference is interpolated linearly.

Part 2, the deepening indentation: the same scene with the punch pushed to depths --depths at the
same speed (0.09 H per 3.125e-6 tau_d, i.e. the ramp time grows with the depth and every ramp
step moves the punch by 0.009 H), then held to --depth-end-time. Recorded per run: whether it
reached the end, the punch displacement and time of the last converged step, why it stopped (the
last failure message of the log; a run still going after --depth-time-limit seconds, default 120,
is stopped and recorded with the step size it had reached), and the extremes of the deformation there (FE: smallest det F and
largest ratio of principal stretches at the Gauss points, relative to the initial configuration;
MPM: smallest volume ratio J from the dry state over the volume points).

A third measure of part 1 is global: the volume lost by 2300 tau_d (solvent squeezed out under the
punch), Delta V / V_0 (FE: int det F_n dV_0; MPM: the V_0-weighted mean volume ratio J_mean of
'Observables/Volume ratio range' over its initial value), against the reference mesh's value.

Writes <DIR>/accuracy.csv, accuracy.md, depth.csv, depth.md and profiles.png (the top surface of
every run at both times). Takes about 15 minutes on a 2-core machine; the runs are printed as they
finish. --skip-accuracy / --skip-depth run one part only; --quick runs a small part 1 (FE 8 x 8 and
16 x 16 against 32 x 32, MPM (iv); about 1 minute).
"""

import argparse
import os
import statistics as stats
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "plotting"))
from fem_peer import load, timed  # noqa: E402
from gelmpm_files import read_csv, read_pvd, read_vtu  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SCENE = os.path.join(ROOT, "prm", "flat_punch.prm")
T_INC = 3.125e-6
END = 2300.0
SCENE_DEPTH = 0.09  # the scene's depth and ramp: the punch speed of part 2
OFFSET = 0.25  # the gel's lower-left corner in the MPM's grid
PUNCH_EDGE = 0.25
SAME = "Discretisation/Chemical potential grid=same"
# (label, directory, --set overrides of prm/flat_punch.prm)
MPM_RUNS = [
    ("(iv) Q2-Q2SD h=0.05", "iv", ["Background grid/Cells=30, 30"]),
    ("(iii) Q2-Q2SD h=0.025 (paper)", "iii", []),
    ("(i) Q2-Q2 h=0.05", "i", ["Background grid/Cells=30, 30", SAME]),
]
FEM_CELLS = [8, 16, 32]


def fem_profiles(directory):
    """{time: (X, u_y)} of the top surface of a gelmpm-fem-flat-punch run."""
    index = read_csv(os.path.join(directory, "profiles.csv"))
    out = {}
    for i, t in zip(index["index"], index["t_over_tau_d"]):
        profile = read_csv(os.path.join(directory, "top_profile-%02d.csv" % int(i)))
        out[float(t)] = (profile["X"], profile["u_y"])
    return out


def mpm_profile(directory, t):
    """(X, u_y) of the free top surface points (piece 1, 'top') in the particle output nearest t."""
    series = read_pvd(directory)
    time, path = min(series, key=lambda item: abs(np.log(max(item[0], 1e-30) / t)))
    if abs(time - t) > 1e-6 * t:
        sys.exit(f"fem_peer_flat_punch.py: no particle output at t = {t} in {directory}")
    points, arrays = read_vtu(path)
    top = arrays["piece"] == 1
    u = arrays["displacement"][top]
    X = points[top, 0] - u[:, 0] - OFFSET
    order = np.argsort(X)
    return X[order], u[order, 1].astype(float)


def at(profiles, t):
    time = min(profiles, key=lambda s: abs(np.log(max(s, 1e-30) / t)))
    if abs(time - t) > 1e-6 * t:
        sys.exit(f"fem_peer_flat_punch.py: no FE profile at t = {t}")
    return profiles[time]


def errors(X, u_y, reference, depth):
    """max and root mean square of |u_y - u_y,ref| / depth over the free top."""
    X_ref, u_ref = reference
    free = X > PUNCH_EDGE + 1e-9
    difference = np.abs(u_y[free] - np.interp(X[free], X_ref, u_ref)) / depth
    return float(np.max(difference)), float(np.sqrt(np.mean(difference ** 2)))


def last_failure(log_file):
    """The last 'failed (...)' reason in a log, or ''."""
    reason = ""
    with open(log_file, errors="replace") as f:
        for line in f:
            if "failed (" in line:
                reason = line.split("failed (", 1)[1].rsplit(")", 1)[0]
    return reason


TIMED_OUT = -1000


def run_status(command, log_file, time_limit):
    """Exit status of the run, or TIMED_OUT if it was stopped after time_limit seconds."""
    import subprocess
    with open(log_file, "w") as log:
        try:
            return subprocess.call(command, stdout=log, stderr=subprocess.STDOUT, cwd=ROOT,
                                   timeout=time_limit)
        except subprocess.TimeoutExpired:
            return TIMED_OUT


def accuracy(args, build, out):
    rows, curves = [], []
    reference_cells = args.reference_cells
    fem = [(n, "fem_%d" % n) for n in sorted(set(FEM_CELLS + [reference_cells]))]
    for n, name in fem:
        directory = os.path.join(out, name)
        command = [os.path.join(build, "gelmpm-fem-flat-punch"), SCENE,
                   "--set", "FE peer/Cells=%d" % n, "--set", "FE peer/Depth=%r" % args.depth,
                   "--set", "FE peer/Output directory=" + directory, "--quiet"]
        repeats = args.repeats if n != reference_cells else 1
        times = [timed(command, directory + ".log%d" % k) for k in range(repeats)]
        statistics = read_csv(os.path.join(directory, "statistics.csv"))
        rows.append({"method": "FE Q2-Q1", "resolution": "%d x %d cells" % (n, n),
                     "volume_change": float(statistics["relative_volume_change"][-1]),
                     "dir": directory, "fem": True, "n_dofs": int(statistics["n_dofs"][-1]),
                     "steps": int(np.sum(statistics["t_over_tau_d"] > 0)),
                     "newton": int(np.nansum(statistics["newton_iterations"])),
                     "wall": stats.median([w for w, _ in times]),
                     "wall_min": min(w for w, _ in times), "wall_max": max(w for w, _ in times),
                     "cpu": stats.median([c for _, c in times]), "repeats": repeats,
                     "load": load()})
        print(rows[-1]["method"], rows[-1]["resolution"], "%.2f s" % rows[-1]["wall"], flush=True)
    for label, name, overrides in MPM_RUNS:
        directory = os.path.join(out, "mpm_" + name)
        command = [os.path.join(build, "gelmpm"), "--set", "Output/Directory=" + directory,
                   "--set", "Boundary conditions/punch/Displacement value/Function expression="
                   "0; -%r * min(t / %r, 1)" % (args.depth, T_INC),
                   "--set", "Observables/Volume ratio range=true"]
        for o in overrides:
            command += ["--set", o]
        command.append(SCENE)
        times = [timed(command, directory + ".log%d" % k) for k in range(args.repeats)]
        statistics = read_csv(os.path.join(directory, "statistics.csv"))
        rows.append({"method": "MPM", "resolution": label, "dir": directory, "fem": False,
                     # J_mean is V_0-weighted: its ratio to the initial one is V_n / V_0.
                     "volume_change": float(statistics["J_mean"][-1] / statistics["J_mean"][0] - 1),
                     "n_dofs": int(statistics["n_dofs_u"][-1] + statistics["n_dofs_mu"][-1]),
                     "steps": int(np.sum(statistics["t_over_tau_d"] > 0)),
                     "newton": int(np.nansum(statistics["newton_iterations"])),
                     "wall": stats.median([w for w, _ in times]),
                     "wall_min": min(w for w, _ in times), "wall_max": max(w for w, _ in times),
                     "cpu": stats.median([c for _, c in times]), "repeats": args.repeats,
                     "load": load()})
        print(rows[-1]["method"], rows[-1]["resolution"], "%.2f s" % rows[-1]["wall"], flush=True)

    reference = fem_profiles(os.path.join(out, "fem_%d" % reference_cells))
    reference_volume_change = [r for r in rows if r["fem"] and
                               r["resolution"].startswith("%d x" % reference_cells)][0]["volume_change"]
    for row in rows:
        row["volume_error"] = (row["volume_change"] - reference_volume_change) / abs(
            reference_volume_change)
        for key, t in (("undrained", T_INC), ("drained", END)):
            if row["fem"]:
                X, u_y = at(fem_profiles(row["dir"]), t)
            else:
                X, u_y = mpm_profile(row["dir"], t)
            row[key + "_max"], row[key + "_rms"] = errors(X, u_y, at(reference, t), args.depth)
            curves.append((row["method"] + " " + row["resolution"], key, X, u_y))

    keys = ["method", "resolution", "n_dofs", "steps", "newton", "wall", "wall_min", "wall_max",
            "cpu", "repeats", "load", "undrained_max", "undrained_rms", "drained_max", "drained_rms",
            "volume_change", "volume_error"]
    with open(os.path.join(out, "accuracy.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join('"%s"' % r[k] if isinstance(r[k], str) else "%.6g" % r[k]
                             for k in keys) + "\n")
    with open(os.path.join(out, "accuracy.md"), "w") as f:
        f.write("| method | resolution | DoFs | steps | Newton iterations | wall time (s), median "
                "(min–max) | CPU time (s) | load | top surface error at t_inc, max / rms | "
                "at 2300 τ_d, max / rms | ΔV/V at 2300 τ_d (error) |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            reference_row = r["fem"] and r["resolution"].startswith("%d x" % reference_cells)
            f.write("| %s | %s | %d | %d | %d | %.2f (%.2f–%.2f) | %.2f | %.1f | %s | %s | %s |\n" % (
                r["method"], r["resolution"] + (" (reference)" if reference_row else ""),
                r["n_dofs"], r["steps"], r["newton"], r["wall"], r["wall_min"], r["wall_max"],
                r["cpu"], r["load"],
                "—" if reference_row else "%.2f %% / %.2f %%" % (100 * r["undrained_max"],
                                                                 100 * r["undrained_rms"]),
                "—" if reference_row else "%.2f %% / %.2f %%" % (100 * r["drained_max"],
                                                                 100 * r["drained_rms"]),
                "%.4f %%" % (100 * r["volume_change"]) + (
                    "" if reference_row else " (%+.2f %%)" % (100 * r["volume_error"]))))
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, key, title in ((axes[0], "undrained", "end of the ramp, t = 3.125e-6 τ_d"),
                           (axes[1], "drained", "t = 2300 τ_d")):
        for label, k, X, u_y in curves:
            if k == key:
                ax.plot(X, u_y / args.depth, ".-" if "MPM" in label else "-", ms=2, lw=1, label=label)
        ax.set_title(title)
        ax.set_xlabel("initial x / H")
        ax.axvline(PUNCH_EDGE, color="0.6", lw=0.8)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("u_y / depth on the top surface")
    axes[1].legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(os.path.join(out, "profiles.png"), dpi=130)
    return rows


def depth_sweep(args, build, out):
    rows = []
    depths = [float(d) for d in args.depths.split(",")]
    configurations = [("FE Q2-Q1 %d x %d" % (n, n), "fem", n) for n in args.depth_fem_cells] + [
        ("MPM " + label, "mpm", overrides) for label, name, overrides in MPM_RUNS[:2]]
    for depth in depths:
        ramp = T_INC * depth / SCENE_DEPTH
        for label, kind, setting in configurations:
            name = "%s_%s_%g" % (kind, label.split()[-1] if kind == "fem" else label.split()[1],
                                 depth)
            directory = os.path.join(out, "depth", name.replace("(", "").replace(")", ""))
            if kind == "fem":
                command = [os.path.join(build, "gelmpm-fem-flat-punch"), SCENE,
                           "--set", "FE peer/Cells=%d" % setting,
                           "--set", "FE peer/Depth=%r" % depth,
                           "--set", "FE peer/Ramp time=%r" % ramp,
                           "--set", "Time stepping/Step caps=%r: 3.125e-7" % ramp,
                           "--set", "Time stepping/Stop at times=%r, 0.1" % ramp,
                           "--set", "Time stepping/End time=%r" % args.depth_end_time,
                           "--set", "FE peer/Output directory=" + directory, "--quiet"]
            else:
                command = [os.path.join(build, "gelmpm"), "--set", "Output/Directory=" + directory,
                           "--set", "Output/Write particles=false",
                           "--set", "Observables/Volume ratio range=true",
                           "--set", "Boundary conditions/punch/Displacement value/Function "
                           "expression=0; -%r * min(t / %r, 1)" % (depth, ramp),
                           "--set", "Time stepping/Step caps=%r: 3.125e-7" % ramp,
                           "--set", "Time stepping/Stop at times=%r, 0.1" % ramp,
                           "--set", "Time stepping/End time=%r" % args.depth_end_time]
                for o in setting:
                    command += ["--set", o]
                command.append(SCENE)
            os.makedirs(os.path.dirname(directory), exist_ok=True)
            status = run_status(command, directory + ".log", args.depth_time_limit)
            statistics = read_csv(os.path.join(directory, "statistics.csv"))
            t_last = float(statistics["t_over_tau_d"][-1])
            row = {"depth": depth, "method": label, "status": status,
                   "completed": status == 0, "t_reached": t_last,
                   "depth_reached": depth * min(t_last / ramp, 1.0),
                   "failure": "" if status == 0 else
                   ("stopped by the time limit of %g s; the steps had fallen to %.2g tau_d%s" % (
                       args.depth_time_limit, float(statistics["dt"][-1]),
                       " (last failure: %s)" % last_failure(directory + ".log")
                       if last_failure(directory + ".log") else "")
                    if status == TIMED_OUT else last_failure(directory + ".log"))}
            if kind == "fem":
                row["min_det_F"] = float(statistics["min_det_F"][-1])
                row["max_stretch_ratio"] = float(statistics["max_stretch_ratio"][-1])
                row["J_min"] = float("nan")
            else:
                row["min_det_F"] = row["max_stretch_ratio"] = float("nan")
                row["J_min"] = float(np.nanmin(statistics["J_min"]))
            rows.append(row)
            print("depth %.3g %-32s %s at t = %.4g (depth %.4g) %s" % (
                depth, label, "completed" if row["completed"] else "STOPPED", t_last,
                row["depth_reached"], row["failure"][:90]), flush=True)
    keys = ["depth", "method", "status", "t_reached", "depth_reached", "min_det_F",
            "max_stretch_ratio", "J_min", "failure"]
    with open(os.path.join(out, "depth.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join('"%s"' % r[k].replace('"', "'") if isinstance(r[k], str)
                             else "%.6g" % r[k] for k in keys) + "\n")
    with open(os.path.join(out, "depth.md"), "w") as f:
        f.write("| depth / H | method | reached | punch displacement reached / H | t reached / τ_d | "
                "min det F (FE) | max stretch ratio (FE) | min J over the run (MPM) | why it "
                "stopped |\n|---:|---|---|---:|---:|---:|---:|---:|---|\n")
        for r in rows:
            f.write("| %g | %s | %s | %.4g | %.4g | %s | %s | %s | %s |\n" % (
                r["depth"], r["method"], "end" if r["completed"] else "stopped",
                r["depth_reached"], r["t_reached"],
                "" if np.isnan(r["min_det_F"]) else "%.3g" % r["min_det_F"],
                "" if np.isnan(r["max_stretch_ratio"]) else "%.3g" % r["max_stretch_ratio"],
                "" if np.isnan(r["J_min"]) else "%.4g" % r["J_min"], r["failure"]))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--output", default="output/fem_peer_flat_punch")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--reference-cells", type=int, default=64)
    parser.add_argument("--depth", type=float, default=0.05)
    parser.add_argument("--depths", default="0.05,0.07,0.09,0.15,0.2,0.25,0.3")
    parser.add_argument("--depth-end-time", type=float, default=END)
    parser.add_argument("--depth-time-limit", type=float, default=120.0,
                        help="seconds after which a run of part 2 is stopped and recorded as such")
    parser.add_argument("--depth-fem-cells", default="16,32",
                        help="FE meshes of part 2 (64 x 64 cells at 0.05 H took over 7 minutes: "
                        "in the drainage its steps fell to 1e-6 tau_d)")
    parser.add_argument("--skip-accuracy", action="store_true")
    parser.add_argument("--skip-depth", action="store_true")
    parser.add_argument("--quick", action="store_true",
                        help="part 1 only, FE 8 x 8 and 16 x 16 against 32 x 32, MPM (iv) (~1 min)")
    args = parser.parse_args()
    args.depth_fem_cells = [int(n) for n in args.depth_fem_cells.split(",")]
    if args.quick:
        global FEM_CELLS, MPM_RUNS
        FEM_CELLS, MPM_RUNS = [8, 16], MPM_RUNS[:1]
        args.reference_cells = min(args.reference_cells, 32)
        args.skip_depth = True
    build = os.path.abspath(args.build)
    out = os.path.abspath(args.output)
    os.makedirs(out, exist_ok=True)
    if not args.skip_accuracy:
        accuracy(args, build, out)
        print("written:", os.path.join(out, "accuracy.md"))
    if not args.skip_depth:
        depth_sweep(args, build, out)
        print("written:", os.path.join(out, "depth.md"))


if __name__ == "__main__":
    main()

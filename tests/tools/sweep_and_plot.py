#!/usr/bin/python3
"""gelmpm-sweep on a tiny sweep and gelmpm-plot's numbers (doc/own_scenes.md, "Plots and sweeps").

Arguments: the build directory (with the links gelmpm-sweep and gelmpm-plot), gelmpm, the source
directory. Checked:
- a zipped sweep of the short §4.1 scene (tests/scenes/constrained_swelling_short.prm to 5e-4 tau_d)
  over the bath's mu = -0.1, -0.05, 0 and a bad End time (-1) in the third run: exit status 1,
  the failed run recorded as failed with gelmpm's exit status 2, the others run; sweep.csv has one
  row per run in order, with each swept value as given and as in the run's parameters.prm, and
  each collected value equal to the cell gelmpm wrote into that run's statistics.csv (last row, the
  row nearest a time, the largest); the swelling delta_h_over_h0 grows with the bath's mu (0.0024,
  0.0056, 0.0099 measured: far apart);
- --skip-done runs again only the failed run;
- the order of a product (--dry-run), and gelmpm-sweep's bad input (exit status 2);
- gelmpm-plot --data: the history of a sweep's runs (every row of statistics.csv, labelled by the
  swept value), a surface profile, and the relaxation g of a synthetic indentation run against its
  closed form exp(-(t - t_0)/T) (the obstacle's force chosen, not the larger force of a piece);
  its errors (a missing column, a directory that is no output directory) with exit status 2;
- drawing a PNG only where matplotlib is installed (contrib/setup.sh --plotting); else said.
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

build, gelmpm, source = (os.path.abspath(a) for a in sys.argv[1:4])
sweep_tool = os.path.join(build, "gelmpm-sweep")
plot_tool = os.path.join(build, "gelmpm-plot")
scene = os.path.join(source, "tests", "scenes", "constrained_swelling_short.prm")
MU = "Boundary conditions/top/Chemical potential value/Function expression"
failures = []


def check(name, condition, detail=""):
    print(("ok   " if condition else "FAIL ") + name + ("" if condition else f": {detail}"))
    if not condition:
        failures.append(name)


def run(command):
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return done.returncode, done.stdout


def rows(file_name):
    with open(file_name, newline="") as stream:
        return list(csv.DictReader(stream))


work = tempfile.mkdtemp(prefix="gelmpm_tools_")
os.chdir(work)

# A zipped sweep of four runs, the third with bad input.
sweep = [sweep_tool, scene, "--gelmpm", gelmpm, "--output", "sweep", "--zip",
         "--vary", f"{MU}=-0.1, -0.05, 0, 0",
         "--vary", "Time stepping/End time=5e-4, 5e-4, -1, 5e-4",
         "--set", "Stability/Inertia=false", "--set", "Observables/Surface pieces=top",
         "--collect", "delta_h_over_h0,delta_h_over_h0@2e-4,max:top_relief,events"]
status, output = run(sweep)
print(output)
check("sweep: exit status 1 with a failed run", status == 1, f"exit status {status}")
check("sweep: progress n of N and the failed run named",
      "[4/4]" in output and "FAILED: bad input (exit status 2)" in output
      and "1 run failed: 3" in output, output[-500:])
table = rows(os.path.join("sweep", "sweep.csv"))
check("sweep.csv: one row per run, in order", [r["run"] for r in table] == ["1", "2", "3", "4"],
      [r["run"] for r in table])
check("sweep.csv: status and exit status per run",
      [(r["status"], r["exit_status"]) for r in table]
      == [("ok", "0"), ("ok", "0"), ("failed", "2"), ("ok", "0")], table)
check("sweep.csv: the swept values as given",
      [r[MU] for r in table] == ["-0.1", "-0.05", "0", "0"], [r.get(MU) for r in table])
for r in table:
    directory = os.path.join("sweep", r["directory"])
    if r["exit_status"] != "0" or not os.path.isfile(os.path.join(directory, "statistics.csv")):
        continue
    statistics = rows(os.path.join(directory, "statistics.csv"))
    with open(os.path.join(directory, "parameters.prm")) as f:
        parameters = [" ".join(line.split()) for line in f]
    check(f"run {r['run']}: its parameters.prm has the swept mu",
          f"set Function expression = {r[MU]}" in parameters)
    check(f"run {r['run']}: t_end and steps from statistics.csv",
          r["t_end"] == statistics[-1]["t_over_tau_d"] == "0.0005"
          and r["steps"] == statistics[-1]["step"], (r["t_end"], r["steps"]))
    check(f"run {r['run']}: delta_h_over_h0 as written in statistics.csv",
          r["delta_h_over_h0"] == statistics[-1]["delta_h_over_h0"],
          (r["delta_h_over_h0"], statistics[-1]["delta_h_over_h0"]))
    nearest = min(statistics, key=lambda s: abs(float(s["t_over_tau_d"]) - 2e-4))
    check(f"run {r['run']}: delta_h_over_h0@2e-4 from the row nearest 2e-4",
          r["delta_h_over_h0@2e-4"] == nearest["delta_h_over_h0"])
    check(f"run {r['run']}: max:top_relief",
          float(r["max:top_relief"]) == max(float(s["top_relief"]) for s in statistics))
    check(f"run {r['run']}: no events", r["events"] == "", r["events"])
swelling = [float(table[k]["delta_h_over_h0"]) for k in (0, 1, 3)]
check("delta_h_over_h0 grows with the bath's mu", swelling[0] < swelling[1] < swelling[2], swelling)

# --skip-done: only the failed run again.
kept = os.path.getmtime(os.path.join("sweep", table[0]["directory"], "statistics.csv"))
status, output = run(sweep + ["--skip-done"])
check("--skip-done: the three runs done before are kept, the failed one runs again",
      output.count("done before (--skip-done)") == 3 and status == 1
      and os.path.getmtime(os.path.join("sweep", table[0]["directory"], "statistics.csv")) == kept,
      output[-400:])

# A product, in order (the first --vary changes slowest), without running.
status, output = run([sweep_tool, scene, "--gelmpm", gelmpm, "--dry-run", "--vary", "A/b=1,2",
                      "--vary", "C/d=x|y, z|w"])
commands = [line for line in output.splitlines() if line.startswith("[")]
expected = [("1", "x"), ("1", "y, z"), ("1", "w"), ("2", "x"), ("2", "y, z"), ("2", "w")]
check("--dry-run: a product of 2 x 3, the first --vary slowest",
      status == 0 and len(commands) == 6
      and all(f"A/b={a}" in c and f"C/d={d}" in c for c, (a, d) in zip(commands, expected)),
      output)
for name, arguments, text in [
        ("an entry without a value", ["--vary", "Time stepping/End time"], "Section/Entry=value"),
        ("zipped lists of unequal length", ["--zip", "--vary", "A/b=1,2", "--vary", "C/d=1"],
         "same length"),
        ("the output directory varied", ["--vary", "Output/Directory=a,b"], "Output/Directory")]:
    status, output = run([sweep_tool, scene, "--gelmpm", gelmpm, "--dry-run"] + arguments)
    check(f"sweep bad input, {name}: exit status 2 naming it", status == 2 and text in output,
          f"{status}: {output}")

# gelmpm-plot: the sweep's histories as numbers.
status, output = run([plot_tool, "sweep", "--y", "delta_h_over_h0", "--data", "history.csv"])
data = rows("history.csv") if status == 0 else []
labels = sorted({d["label"] for d in data})
check("plot --data: the runs of the sweep, labelled by the swept values",
      status == 0 and labels == ["Function expression=-0.05", "Function expression=-0.1",
                                 "Function expression=0"], f"{status} {output} {labels}")
first = rows(os.path.join("sweep", table[0]["directory"], "statistics.csv"))
mine = [d for d in data if d["label"] == "Function expression=-0.1"]
check("plot --data: every row of statistics.csv",
      [(float(d["x"]), float(d["y"])) for d in mine]
      == [(float(s["t_over_tau_d"]), float(s["delta_h_over_h0"])) for s in first])
status, output = run([plot_tool, os.path.join("sweep", table[0]["directory"]), "--surface", "top",
                      "--outputs=-1", "--data", "surface.csv"])
profiles = sorted(f for f in os.listdir(os.path.join("sweep", table[0]["directory"]))
                  if f.startswith("surface_top-"))
last = rows(os.path.join("sweep", table[0]["directory"], profiles[-1]))
check("plot --data: the last surface profile",
      status == 0 and [(float(d["x"]), float(d["y"])) for d in rows("surface.csv")]
      == [(float(p["x"]), float(p["y"])) for p in last], output)
status, output = run([plot_tool, "sweep", "--y", "delta_h_over_h", "--data", "x.csv"])
check("plot: a missing column is named, exit status 2",
      status == 2 and "no column 'delta_h_over_h'" in output and "delta_h_over_h0" in output, output)
status, output = run([plot_tool, work, "--y", "step", "--data", "x.csv"])
check("plot: a directory that is no output directory, exit status 2",
      status == 2 and "is not a GelMPM output directory" in output, output)

# The relaxation of a synthetic indentation: ramp to t_0 = 0.01, then F = F_inf + (F_0 - F_inf)
# exp(-(t - t_0)/T); a piece's force larger than the indenter's must not be taken.
os.makedirs("indentation")
t_0, T, F_0, F_inf = 0.01, 2.0, 3.0, 2.0
times = [0.0, 0.005, t_0] + [t_0 + 0.01 * 1.4 ** k for k in range(30)]
with open(os.path.join("indentation", "statistics.csv"), "w") as f:
    f.write("step,time,t_over_tau_d,top_force_y,indenter_force_y,indenter_contact_radius\n")
    for k, t in enumerate(times):
        force = F_0 * t / t_0 if t <= t_0 else F_inf + (F_0 - F_inf) * math.exp(-(t - t_0) / T)
        f.write(f"{k},{t!r},{t!r},{-10 * force!r},{force!r},0.1\n")
status, output = run([plot_tool, "indentation", "--relaxation", "--data", "g.csv",
                      "--final-force", str(F_inf)])
g = rows("g.csv") if status == 0 else []
error = max((abs(float(d["y"]) - math.exp(-float(d["x"]) / T)) for d in g), default=math.inf)
check("plot --relaxation: g = exp(-(t - t_0)/T) of the indenter's force after the ramp",
      status == 0 and len(g) == 30 and "indenter_force_y: F(0+) = 3 at t/tau_d = 0.01" in output
      and error < 1e-12,
      f"{status} {output} rows {len(g)} error {error}")
status, output = run([plot_tool, "indentation", "--relaxation", "--load-end", "0.005",
                      "--data", "g.csv"])
g = rows("g.csv") if status == 0 else []
check("plot --relaxation --load-end: F(0+) from that row, F(inf) the last row's",
      status == 0 and float(g[0]["x"]) == 0.005 and float(g[-1]["y"]) == 0.0, output)

# Drawing, where matplotlib is installed.
try:
    __import__("matplotlib")
    status, output = run([plot_tool, "sweep", "--y", "delta_h_over_h0", "--events", "--log", "xy",
                          "-o", "history.png"])
    check("plot: a PNG drawn", status == 0 and os.path.getsize("history.png") > 1000, output)
except ImportError:
    print("skipped: drawing a PNG (no matplotlib; bash contrib/setup.sh --plotting installs it)")

if failures:
    print(f"{len(failures)} checks failed; the files are in {work}")
    sys.exit(1)
shutil.rmtree(work)
print("all checks passed")

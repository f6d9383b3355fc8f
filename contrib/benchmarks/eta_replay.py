"""Replays the time-to-end estimate of the step lines (include/gelmpm/solvers/run_progress.h)
on finished runs' statistics.csv (t_over_tau_d, dt, wall_time) with other rules for the dt/t
ahead, and prints for each rule the mean |ln(estimate/actual)| over the reads at 10%, 25%, 50% and
75% of each run's wall time (doc/output.md, "Run feedback: the log").

  /usr/bin/python3 contrib/benchmarks/eta_replay.py run1 run2 ...   (output directories)
"""
import csv
import math
import os
import re
import statistics
import sys

RELATIVE = 1e-9


def settings(directory):
    entries = {}
    section = []
    for line in open(os.path.join(directory, "parameters.prm")):
        line = line.split("#")[0].strip()
        if line.startswith("subsection"):
            section.append(line.split(None, 1)[1])
        elif line == "end":
            section.pop()
        elif line.startswith("set") and section == ["Time stepping"]:
            key, value = re.match(r"set\s+(.+?)\s*=\s*(.*)", line).groups()
            entries[key] = value.strip()
    caps = [tuple(map(float, part.split(":"))) for part in entries["Step caps"].split(",")
            if part.strip()]
    return dict(end=float(entries["End time"]), growth=float(entries["Growth factor"]), caps=caps,
                tolerance=float(entries["Tolerance"]) > 0
                or float(entries.get("Displacement tolerance", 0)) > 0)


def cap_and_its_end(s, run):
    for time, cap in run["caps"]:
        if s < time * (1 - RELATIVE):
            return cap, min(time, run["end"])
    return math.inf, run["end"]


def remaining_steps(run, t, dt, rate):
    """RunProgress::remaining_steps(): growth by the factor, then steps of rate * t, then caps."""
    end = run["end"] * (1 - RELATIVE)
    s, h, steps = t, dt, 0.0
    for _ in range(100000):
        if s >= end or dt <= 0:
            break
        cap, b = cap_and_its_end(s, run)
        if run["growth"] > 1 and h * run["growth"] < min(rate * s, cap):
            h *= run["growth"]
            s += h
            steps += 1
            continue
        if rate * s < cap:
            s_c = min(b, cap / rate)
            if s_c > s * (1 + RELATIVE):
                steps += math.log(s_c / s) / math.log1p(rate)
                h, s = rate * s_c, s_c
                continue
        step = cap if math.isfinite(cap) else h
        steps += (b - s) / step
        h, s = step, b
    return max(steps, 1.0) if t < end else 0.0


RULES = {
    "largest of the last 20 (kept)": lambda rates: max(rates[-20:]),
    "median of the last 20": lambda rates: statistics.median(rates[-20:]),
    "mean of the last 20": lambda rates: statistics.mean(rates[-20:]),
    "largest of the last 50": lambda rates: max(rates[-50:]),
    "the last step's": lambda rates: rates[-1],
}


def log_errors(directory, rule):
    run = settings(directory)
    rows = [(float(r["t_over_tau_d"]), float(r["dt"]), float(r["wall_time"]))
            for r in csv.DictReader(open(os.path.join(directory, "statistics.csv")))]
    total = rows[-1][2]
    reads = [0.1, 0.25, 0.5, 0.75]
    per_step, rates, errors = -1.0, [], []
    for (t_prev, _, w_prev), (t, dt, w) in zip(rows, rows[1:]):
        cost = w - w_prev
        per_step = cost if per_step < 0 else 0.75 * per_step + 0.25 * cost
        rates.append(dt / t)
        rate = min(rule(rates), run["growth"] - 1) if run["tolerance"] else math.inf
        while reads and w >= reads[0] * total:
            reads.pop(0)
            if total > w:
                errors.append(math.log(per_step * remaining_steps(run, t, dt, rate) / (total - w)))
    return errors


def main():
    for name, rule in RULES.items():
        errors = [e for d in sys.argv[1:] for e in log_errors(d, rule)]
        print(f"{name:32s} reads {len(errors):3d}  mean |ln(estimate/actual)| "
              f"{statistics.mean(map(abs, errors)):.2f}  worst ratio {math.exp(max(map(abs, errors))):.1f}")


if __name__ == "__main__":
    main()

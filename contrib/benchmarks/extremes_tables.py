#!/usr/bin/env python3
"""The tables of doc/extremes.md from the runs of contrib/benchmarks/extremes.sh.

    /usr/bin/python3 contrib/benchmarks/extremes_tables.py <directory of extremes.sh>

Reads <directory>/runs.csv, <run>/statistics.csv and <run>.log; writes <directory>/extremes.md
(and prints it): the three tables in the columns of doc/extremes.md, the skew-symmetric runs, and
the figures the prose of doc/extremes.md quotes. Column meanings (doc/statistics.md):
  Newton its. (max)   largest newton_iterations of a converged step;
  Newton its.         newton_iterations summed over the converged steps (the log's count, which adds
                      the iterations of failed attempts, is listed under the tables);
  signature stable    every converged step has (n_pos, n_neg, n_zero) = (n_dofs_u, n_dofs_mu, 0);
  u_bc_error          largest over the converged steps; mu_bc_error: last step and largest;
  cond_1(K)           condition_number of the last converged step;
  mu oscillation      mu_oscillation of the last converged step;
  Delta h/h_0         delta_h_over_h0 at the end, for runs that reached it.
"""
import csv
import math
import os
import re
import sys

PUNCH_DT = ["1e-4", "1e-6", "1e-8", "1e-10"]
GAMMA_U = ["1", "10", "100", "1e3", "1e4", "1e5", "1e6"]
GAMMA_MU = ["0.01", "0.1", "1", "10", "25", "100", "1e3", "1e4", "1e5", "1e6"]
SKEW_U = ["1", "10", "100", "1e3"]
SKEW_MU = ["0.1", "1"]
END_TIME = 0.1


class Run:
    """One run: its exit status, its statistics rows (row 0: initial state) and its log."""

    def __init__(self, directory, name, status):
        self.name, self.status = name, status
        self.rows = []
        path = os.path.join(directory, name, "statistics.csv")
        if os.path.exists(path):
            with open(path) as f:
                for row in csv.DictReader(f):
                    self.rows.append({k: (float(v) if v not in ("", None) else None)
                                      for k, v in row.items()})
        log = open(os.path.join(directory, name + ".log")).read()
        match = re.search(r"^gelmpm: (\d+) Newton iterations", log, re.M)
        self.log_newton = int(match.group(1)) if match else None
        self.steps_rows = self.rows[1:]

    def column(self, key):
        return [r[key] for r in self.steps_rows if r.get(key) is not None]

    @property
    def reached(self):
        return self.rows[-1]["t_over_tau_d"] if self.rows else 0.

    @property
    def steps(self):
        return int(self.rows[-1]["step"]) if self.rows else 0

    @property
    def completed(self):
        return self.status == 0

    def stable_at(self, r):
        return (r["n_pos"] == r["n_dofs_u"] and r["n_neg"] == r["n_dofs_mu"] and r["n_zero"] == 0)

    def stable(self):
        return all(self.stable_at(r) for r in self.steps_rows)

    def first_unstable(self):
        for r in self.steps_rows:
            if not self.stable_at(r):
                return r
        return None


def exponent(x, digits=2):
    """1.6e-4 (no zero padding of the exponent, no '+')."""
    if x == 0:
        return "0"
    mantissa, power = ("%.*e" % (digits - 1, x)).split("e")
    return "%se%d" % (mantissa, int(power))


def short(x, digits=2):
    """Fixed notation from 0.01 up to 1000, else exponent notation."""
    return ("%.*g" % (digits, x)) if 0.01 <= abs(x) < 1000 else exponent(x, digits)


def signed(x, digits=5):
    text = "%.*f" % (digits, x)
    return text.replace("-", "\u2212")


def yes(flag):
    return "yes" if flag else "no"


def label(gamma, table1):
    return gamma + (" (Table 1)" if gamma == table1 else "")


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "output/extremes_study"
    status = {}
    with open(os.path.join(directory, "runs.csv")) as f:
        for row in csv.DictReader(f):
            status[row["run"]] = int(row["exit_status"])
    runs = {name: Run(directory, name, s) for name, s in status.items()}

    def symmetric(gu, gm):
        # Table 1's run (gamma_u = 1e3, gamma_mu = 25) is in both tables; it is run once.
        return runs["symmetric_gu%s_gm%s" % (gu, gm)]

    lines = []
    out = lines.append
    notes = []

    # Undrained limit.
    out("| Δt/τ_d | Q2–Q2SD: Newton its. (max) | signature stable | μ oscillation "
        "| Q2–Q2: Newton its. (max) | signature stable | μ oscillation |")
    out("|---|---|---|---|---|---|---|")
    for dt in PUNCH_DT:
        cells = [dt]
        for pair in ("q2q2sd", "q2q2"):
            run = runs["punch_%s_dt%s" % (pair, dt)]
            newton = "%d" % max(run.column("newton_iterations")) if run.steps_rows else "—"
            if not run.completed:
                newton += " (stopped at t/τ_d = %s)" % exponent(run.reached, 3)
            oscillation = run.column("mu_oscillation")
            cells += [newton, yes(run.stable()) if run.steps_rows else "—",
                      "%#.4g" % oscillation[-1] if oscillation else "—"]
            notes.append("%s: %d steps to t/τ_d = %s, exit %d, largest attempts per step %d, "
                         "log Newton iterations %s" % (run.name, run.steps, exponent(run.reached, 3),
                                                      run.status, max(run.column("attempts") or [0]),
                                                      run.log_newton))
        out("| " + " | ".join(cells) + " |")
    sd = [runs["punch_q2q2sd_dt%s" % dt].column("mu_oscillation")[-1] for dt in PUNCH_DT]
    notes.append("Q2–Q2SD μ oscillation: largest/smallest over Δt − 1 = %.2f %%; "
                 "1e-10 against 1e-6: %.3f %%" % (100 * (max(sd) / min(sd) - 1),
                                                   100 * (sd[3] / sd[1] - 1)))
    out("")

    def nitsche_cells(run):
        reached = ("%g" % END_TIME if run.completed
                   else "%s (stopped)" % short(run.reached))
        u_error = run.column("u_bc_error")
        condition = run.column("condition_number")
        delta_h = run.column("delta_h_over_h0")
        return {
            "reached": reached,
            "steps": "%d" % run.steps,
            "newton": "%d" % sum(run.column("newton_iterations")),
            "stable": yes(run.stable()) if "n_pos" in (run.rows[0] if run.rows else {}) else "—",
            "u_bc": exponent(max(u_error)) if u_error else "—",
            "cond": exponent(condition[-1]) if condition else "—",
            "delta_h": signed(delta_h[-1]) if run.completed and delta_h else "—",
        }

    def nitsche_notes(run):
        first = run.first_unstable() if "n_pos" in run.rows[0] else None
        text = ("%s: exit %d, t/τ_d = %s, log Newton iterations %s, largest attempts %d"
                % (run.name, run.status, "%.4g" % run.reached, run.log_newton,
                   max(run.column("attempts") or [0])))
        if first is not None:
            last = run.steps_rows[-1]
            text += ("; first unstable step %d (t/τ_d = %.3g): n_neg − n_dofs_mu = %d, n_zero = %d; "
                     "at the last step n_neg − n_dofs_mu = %d"
                     % (first["step"], first["t_over_tau_d"], first["n_neg"] - first["n_dofs_mu"],
                        first["n_zero"], last["n_neg"] - last["n_dofs_mu"]))
        if "mu_bc_error" in run.rows[0]:
            mu_error = run.column("mu_bc_error")
            if mu_error:
                text += "; largest mu_bc_error at step %d" % (1 + mu_error.index(max(mu_error)))
        return text

    # Displacement penalty.
    out("| γ_u | reached t/τ_d | steps | Newton its. | signature stable at every step "
        "| u_bc_error | cond₁(K) | Δh/h_0 |")
    out("|---|---|---|---|---|---|---|---|")
    for gamma in GAMMA_U:
        run = symmetric(gamma, "25")
        c = nitsche_cells(run)
        out("| %s | %s | %s | %s | %s | %s | %s | %s |"
            % (label(gamma, "1e3"), c["reached"], c["steps"], c["newton"], c["stable"], c["u_bc"],
               c["cond"], c["delta_h"]))
        notes.append(nitsche_notes(run))
    out("")

    # Chemical-potential penalty.
    out("| γ_μ | reached t/τ_d | steps | Newton its. | signature stable at every step "
        "| mu_bc_error, last | largest | cond₁(K) | Δh/h_0 |")
    out("|---|---|---|---|---|---|---|---|---|")
    for gamma in GAMMA_MU:
        run = symmetric("1e3", gamma)
        c = nitsche_cells(run)
        mu_error = run.column("mu_bc_error")
        out("| %s | %s | %s | %s | %s | %s | %s | %s | %s |"
            % (label(gamma, "25"), c["reached"], c["steps"], c["newton"], c["stable"],
               short(mu_error[-1]) if mu_error else "—", short(max(mu_error)) if mu_error else "—",
               c["cond"], c["delta_h"]))
        if gamma != "25":
            notes.append(nitsche_notes(run))
    out("")

    # Skew-symmetric variant.
    out("Skew-symmetric variant (no stability analysis):")
    out("")
    out("| γ_u | γ_μ | reached t/τ_d | steps | Newton its. | u_bc_error | mu_bc_error, last "
        "| Δh/h_0 |")
    out("|---|---|---|---|---|---|---|---|")
    skew = [("skew_gu%s_gm25" % g, g, "25") for g in SKEW_U]
    skew += [("skew_gu1e3_gm%s" % g, "1e3", g) for g in SKEW_MU]
    for name, gu, gm in skew:
        run = runs[name]
        c = nitsche_cells(run)
        mu_error = run.column("mu_bc_error")
        out("| %s | %s | %s | %s | %s | %s | %s | %s |"
            % (gu, gm, c["reached"], c["steps"], c["newton"], c["u_bc"],
               exponent(mu_error[-1]) if mu_error else "—", c["delta_h"]))
        notes.append(nitsche_notes(run))
    out("")

    # Figures for the prose.
    stable_runs = [symmetric(g, "25") for g in GAMMA_U] + [symmetric("1e3", g) for g in GAMMA_MU]
    stable_runs = [r for r in stable_runs if r.completed and r.stable()]
    delta = [r.column("delta_h_over_h0")[-1] for r in stable_runs]
    if delta:
        notes.append("Δh/h_0 over the completed symmetric runs stable at every step (%d): "
                     "%.6f … %.6f, spread %.1e"
                     % (len(delta), min(delta), max(delta), max(delta) - min(delta)))
    skew_delta = [runs[n].column("delta_h_over_h0")[-1] for n, _, _ in skew if runs[n].completed]
    if skew_delta:
        notes.append("Δh/h_0 of the completed skew-symmetric runs: %.6f … %.6f"
                     % (min(skew_delta), max(skew_delta)))
    out("Figures quoted in the prose:")
    out("")
    for note in notes:
        out("- " + note)

    text = "\n".join(lines) + "\n"
    with open(os.path.join(directory, "extremes.md"), "w") as f:
        f.write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()

#!/usr/bin/env bash
# The paper's four benchmarks at paper resolution with the paper's settings, one after the other:
# §4.1 (prm/constrained_swelling.prm), §4.2 (iii) (prm/flat_punch.prm, Q2-Q2SD fine), §4.3
# (prm/column_buckling.prm, stability analysis at every step) and §4.4 (prm/porous_gel.prm, with
# it). Writes one table (scene, wall time, steps, Newton iterations, peak memory, key result
# against the paper) to <output>/paper_suite.md and, with --update-doc, into doc/performance.md
# between the markers "paper suite: begin" and "paper suite: end".
#
#   bash contrib/benchmarks/paper_suite.sh [--update-doc] [output directory]
#        (default directory: output/paper_suite)
#
# Run it on an otherwise idle machine (the table records the load average before each run).
# Needs the build (bash contrib/setup.sh) and /usr/bin/time (Debian package 'time').
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "${top}/contrib/benchmarks/doc_driver.sh"
doc_driver_arguments paper_suite "$@"
echo "paper_suite.sh: about 13-18 minutes on a 2-core machine (measured 12.4-18.1); results in ${out}"

run_case() {
  local name="$1" scene="$2"
  shift 2
  echo "  ${name}: started $(date +%H:%M:%S), load average $(cut -d' ' -f1 /proc/loadavg)"
  cut -d' ' -f1 /proc/loadavg > "${out}/${name}.load"
  set +e
  /usr/bin/time -f "%e %M" -o "${out}/${name}.time" "${build_dir}/gelmpm" "${top}/prm/${scene}" \
    --set "Output/Directory=${out}/${name}" "$@" > "${out}/${name}.log" 2>&1
  echo $? > "${out}/${name}.status"
  set -e
  echo "  ${name}: exit $(cat "${out}/${name}.status"), $(cut -d' ' -f1 "${out}/${name}.time") s"
}

run_case s4.1_constrained_swelling constrained_swelling.prm
run_case s4.2_flat_punch_iii flat_punch.prm --set "Observables/Chemical potential oscillation=true"
run_case s4.3_column_buckling column_buckling.prm
run_case s4.4_porous_gel porous_gel.prm

/usr/bin/python3 - "${out}" "${top}/doc/performance.md" "${update_doc}" <<'PYTHON'
import csv, os, sys

out, doc, update = sys.argv[1], sys.argv[2], sys.argv[3] == "1"


def rows(name):
    with open(os.path.join(out, name, "statistics.csv")) as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text else float("nan")


def events(name, kind):
    path = os.path.join(out, name, "events.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [r for r in csv.DictReader(f) if r["event"] == kind]


def key_result(name, table):
    if name.startswith("s4.1"):
        final = number(table[-1]["delta_h_over_h0"])
        return f"Δh/h_0 at 1713 τ_d {final:.6f}, equilibrium 1.7272214 ({100 * (final / 1.7272214 - 1):+.3f} %)"
    if name.startswith("s4.2"):
        largest = max(number(r["mu_oscillation"]) for r in table[1:])
        return f"largest μ oscillation measure {largest:.3g} (spurious modes: of order one; the paper: smooth for Q2–Q2SD)"
    if name.startswith("s4.3"):
        onset = events(name, "bifurcation")
        t = f"{number(onset[0]['t_over_tau_d']):.4f} τ_d" if onset else "none"
        return f"onset {t} (paper 0.28 τ_d); centre offset at the end {number(table[-1]['centre_distance']):.2f} H"
    bifurcation = events(name, "bifurcation")
    contact = events(name, "self_contact")
    crease = events(name, "crease")
    parts = []
    if bifurcation:
        parts.append(f"bifurcation at μ = {number(bifurcation[0]['mu_boundary']):.4f} k_BT (paper −0.13)")
    if contact:
        parts.append(f"self-contact {number(contact[0]['t_over_tau_d']) / 81:.3f} R²/D (paper 2)")
    if crease:
        parts.append(f"first crease {number(crease[0]['t_over_tau_d']) / 81:.3f} R²/D (paper 3)")
    return "; ".join(parts) or "no events"


lines = ["| scene | exit | wall / s | load before | steps | Newton iterations | peak memory / MB | key result against the paper |",
         "|---|---|---|---|---|---|---|---|"]
total = 0.
for name in ["s4.1_constrained_swelling", "s4.2_flat_punch_iii", "s4.3_column_buckling", "s4.4_porous_gel"]:
    wall, memory = open(os.path.join(out, name + ".time")).read().split()[-2:]
    status = open(os.path.join(out, name + ".status")).read().strip()
    load = open(os.path.join(out, name + ".load")).read().strip()
    total += float(wall)
    try:
        table = rows(name)
        steps = len(table) - 1
        newton = sum(int(r["newton_iterations"]) for r in table[1:])
        result = key_result(name, table)
    except (OSError, KeyError, ValueError, IndexError) as error:
        steps, newton, result = "–", "–", f"no result ({error})"
    lines.append(f"| {name} | {status} | {float(wall):.0f} | {load} | {steps} | {newton} | {int(memory) / 1024:.0f} | {result} |")
lines.append(f"\nTotal wall time: {total:.0f} s ({total / 60:.1f} min).")
table_text = "\n".join(lines) + "\n"
open(os.path.join(out, "paper_suite.md"), "w").write(table_text)
print(table_text)
if update:
    text = open(doc).read()
    begin, end = "<!-- paper suite: begin -->", "<!-- paper suite: end -->"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        open(doc, "w").write(head + begin + "\n" + table_text + end + tail)
        print(f"updated {doc}")
    else:
        print(f"{doc} has no '{begin}' ... '{end}' markers; table not inserted")
PYTHON

#!/usr/bin/python3
"""gelmpm-sweep: runs a scene for each value (or combination of values) of some entries, one run
after another, each in its own output directory, and collects a table of what they ended with.

    gelmpm-sweep scene.prm --vary "Section/Entry=V1,V2,..." [--vary ...] [--zip] [--separator TEXT]
        [--set "Section/Entry=V" ...] [--collect SPEC,...] [--output DIR] [--gelmpm PATH]
        [--launcher "mpirun -n 2"] [--skip-done] [--dry-run]

(`build/gelmpm-sweep` is a link to this file; `/usr/bin/python3 contrib/plotting/gelmpm_sweep.py`
runs it as well.)

--vary ENTRY=LIST  an entry of the scene (as for gelmpm --set) and its values, separated by commas,
                   or by '|' when the list holds a '|' (for values with commas of their own:
                   --vary "Background grid/Cells=20, 80 | 40, 160"), or by --separator TEXT
                   (for values with both, e.g. selectors with '||'). Several --vary: every
                   combination (their product; the first --vary changes slowest), or with --zip
                   the first values together, then the second ones, ... (lists of equal length).
--set ENTRY=VALUE  an override that every run gets (before the varied ones).
--collect SPEC     columns of the table besides the fixed ones (below), comma-separated or repeated:
                     COLUMN        the last row's value of a statistics.csv column, as gelmpm wrote it
                     COLUMN@T      its value in the row nearest t/tau_d = T
                     max:COLUMN, min:COLUMN   its largest or smallest value over the run
                     event:NAME    t/tau_d of the first NAME event of events.csv (empty: none)
                     events        every event, as name@t/tau_d; ...
                   Default: the last values of the statistics columns that are observables (all but
                   the step's bookkeeping: step, times, dt, Newton counts, residuals, unknowns, cells,
                   points, wall time).
--output DIR       where the runs go (default sweep_<scene name>): DIR/NN_<values>/ holds a run's
                   files and its log (log.txt); DIR/sweep.csv the table.
--launcher CMD     a prefix of each run's command (e.g. "mpirun -n 2").
--skip-done        leave out the runs whose directory holds a log of the same command that ended
                   with exit status 0 (a sweep stopped part-way goes on where it stopped).
--dry-run          print the runs' commands and stop.

Progress: one line as each run starts (n of N, its values, its directory) and one as it ends (its
exit status, wall time, how far it got, the sweep's elapsed time and an estimate of the rest); a
failed run's last message. The table (sweep.csv) has per run: run, directory, one column per varied
entry, status (ok or failed), exit_status, wall_seconds, steps and t_end (the last row of
statistics.csv: how far a failed run got), then the --collect columns. It is printed at the end and
written after every run. A failed run is recorded and the sweep goes on; the exit status is 0 when
every run succeeded, 1 when any failed (or a --collect column was in no run's statistics.csv), 2
for bad input to gelmpm-sweep, 130 when stopped by Ctrl-C. gelmpm-plot DIR plots the sweep's runs.

Needs only Python 3.
"""
import argparse
import csv
import itertools
import math
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from gelmpm_files import number, read_rows  # noqa: E402

# Columns of statistics.csv that describe the step, not the state (left out of the default table).
BOOKKEEPING = {"step", "time", "t_over_tau_d", "dt", "newton_iterations", "attempts", "residual_u",
               "residual_mu", "n_dofs_u", "n_dofs_mu", "n_active_cells", "n_particles", "wall_time"}
# gelmpm's exit statuses (gelmpm --help).
OUTCOMES = {1: "the run failed", 2: "bad input", 130: "stopped by SIGINT", 143: "stopped by SIGTERM"}


def outcome_of(status):
    """What a non-zero exit status of gelmpm says (negative: killed by that signal)."""
    if status < 0:
        try:
            return f"killed by {signal.Signals(-status).name}"
        except ValueError:
            return f"killed by signal {-status}"
    return OUTCOMES.get(status, "the run failed")


LOG_HEAD = "# gelmpm-sweep command: "
LOG_TAIL = "# gelmpm-sweep exit status: "


class SweepError(Exception):
    """Bad input to gelmpm-sweep (exit status 2)."""


class Terminated(Exception):
    """gelmpm-sweep received SIGTERM."""


def on_sigterm(signal_number, frame):
    raise Terminated()


def split_values(text, separator=None):
    """The values of a --vary list: separated by @p separator, else by '|' if the list holds one,
    else by commas."""
    separator = separator or ("|" if "|" in text else ",")
    values = [value.strip() for value in text.split(separator)]
    if not all(values):
        raise SweepError(f"an empty value in '{text}' (values are separated by "
                         f"'{separator}')")
    return values


def parse_entry(text, option):
    """(entry, value) of 'Section/Entry=value'."""
    if "=" not in text:
        raise SweepError(f"{option} '{text}': give 'Section/Entry=value', as for gelmpm --set")
    entry, value = text.split("=", 1)
    entry = entry.strip()
    if entry.lower() == "output/directory":
        raise SweepError(f"{option} '{text}': gelmpm-sweep sets each run's 'Output/Directory' "
                         "(--output names the sweep's directory)")
    return entry, value


def combinations(varied, zipped):
    """[[(entry, value), ...] per run] of the --vary lists: their product, or with @p zipped the
    i-th values together."""
    if zipped:
        lengths = {len(values) for _, values in varied}
        if len(lengths) > 1:
            raise SweepError("--zip needs lists of the same length; they have "
                             + ", ".join(f"{len(v)} ({e})" for e, v in varied))
        return [[(entry, values[i]) for entry, values in varied] for i in range(lengths.pop())]
    return [list(zip([e for e, _ in varied], choice))
            for choice in itertools.product(*[values for _, values in varied])]


def slug(assignments):
    """A directory name for one run's values: the last part of each entry's name and its value,
    letters, digits, '.', '+' and '-' kept."""
    parts = []
    for entry, value in assignments:
        name = entry.split("/")[-1]
        parts.append(re.sub(r"[^A-Za-z0-9.+-]+", "-", f"{name}={value}".replace("=", "_")).strip("-"))
    return "_".join(parts)[:80].strip("-_") or "run"


def find_gelmpm(requested):
    """gelmpm: --gelmpm, else beside this command (build/gelmpm-sweep links here), else
    $GELMPM_BUILD_DIR/gelmpm, build/gelmpm of the source tree, or the one on PATH."""
    if requested:
        if not (os.path.isfile(requested) and os.access(requested, os.X_OK)):
            raise SweepError(f"--gelmpm '{requested}' is not an executable file")
        return os.path.abspath(requested)
    here = os.path.dirname(os.path.abspath(sys.argv[0]))
    source_tree = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..")
    for directory in (here, os.environ.get("GELMPM_BUILD_DIR", ""),
                      os.path.join(source_tree, "build")):
        candidate = os.path.join(directory, "gelmpm")
        if directory and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    found = shutil.which("gelmpm")
    if not found:
        raise SweepError("found no gelmpm (beside gelmpm-sweep, in $GELMPM_BUILD_DIR, build/ or "
                         "on PATH): give --gelmpm build/gelmpm")
    return found


def parse_collect(specs):
    """The --collect specifications, checked: [(spec, kind, column, time)]."""
    parsed = []
    for text in specs:
        for spec in (s.strip() for s in text.split(",")):
            if not spec:
                continue
            if spec == "events":
                parsed.append((spec, "events", None, None))
            elif spec.startswith("event:"):
                parsed.append((spec, "event", spec[6:], None))
            elif spec.startswith(("max:", "min:")):
                parsed.append((spec, spec[:3], spec[4:], None))
            elif "@" in spec:
                column, at = spec.split("@", 1)
                if math.isnan(number(at)):
                    raise SweepError(f"--collect '{spec}': the time after '@' is no number")
                parsed.append((spec, "at", column, number(at)))
            else:
                parsed.append((spec, "last", spec, None))
    return parsed


def statistics_rows(directory):
    path = os.path.join(directory, "statistics.csv")
    return read_rows(path) if os.path.isfile(path) else []


def events_rows(directory):
    path = os.path.join(directory, "events.csv")
    return read_rows(path) if os.path.isfile(path) else []


def last_value(rows, column):
    """The last non-empty cell of a column, as written (the initial row may leave some empty)."""
    for row in reversed(rows):
        if row.get(column):
            return row[column]
    return ""


def collected_value(spec, rows, events):
    """One --collect cell of a run; None if its column is not in statistics.csv."""
    _, kind, column, at = spec
    if kind == "events":
        return "; ".join(f"{e.get('event')}@{e.get('t_over_tau_d')}" for e in events)
    if kind == "event":
        first = next((e for e in events if e.get("event") == column), None)
        return first.get("t_over_tau_d", "") if first else ""
    if not rows:
        return ""
    if column not in rows[0]:
        return None
    if kind == "last":
        return last_value(rows, column)
    if kind == "at":
        row = min(rows, key=lambda r: abs(number(r.get("t_over_tau_d")) - at))
        return row[column]
    values = [number(r[column]) for r in rows if not math.isnan(number(r[column]))]
    if not values:
        return ""
    return repr(max(values) if kind == "max" else min(values))


def default_collect(rows):
    """The observables of a statistics.csv: its columns but the bookkeeping ones."""
    return [(name, "last", name, None) for name in (rows[0] if rows else {})
            if name not in BOOKKEEPING]


def last_message(log_file):
    """How a run ended, from its log: the first line beginning with 'gelmpm:' after its last step
    line ('gelmpm: error: ...', 'gelmpm: the run stopped: ...', 'gelmpm: SIGINT received ...')."""
    try:
        with open(log_file, errors="replace") as log:
            lines = [line.strip() for line in log]
    except OSError:
        return ""
    steps = [k for k, line in enumerate(lines) if line.startswith("step ")]
    after = lines[steps[-1] + 1:] if steps else lines
    return next((line for line in after if line.startswith("gelmpm:")), "")


def finished_before(log_file, command_text):
    """Whether @p log_file is the log of this command run to exit status 0 by gelmpm-sweep, and
    its wall seconds."""
    try:
        with open(log_file, errors="replace") as log:
            lines = log.read().splitlines()
    except OSError:
        return False, None
    if len(lines) < 2 or lines[0] != LOG_HEAD + command_text or not lines[-1].startswith(LOG_TAIL):
        return False, None
    status, _, seconds = lines[-1][len(LOG_TAIL):].partition(" after ")
    return status.strip() == "0", number(seconds.split()[0] if seconds else "")


def run_one(command, directory, environment):
    """Runs gelmpm into @p directory with its log in directory/log.txt: (exit status, seconds,
    whether the sweep was told to stop meanwhile)."""
    os.makedirs(directory, exist_ok=True)
    log_file = os.path.join(directory, "log.txt")
    start, stop = time.time(), False
    with open(log_file, "w") as log:
        log.write(LOG_HEAD + shlex.join(command) + "\n")
        log.flush()
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=environment)
        try:
            status = process.wait()
        except (KeyboardInterrupt, Terminated) as signal_received:
            # Ctrl-C reaches gelmpm too (a second SIGINT would end it at once); a SIGTERM sent to
            # the sweep alone is passed on. Either way gelmpm ends after its step.
            if isinstance(signal_received, Terminated):
                process.terminate()
            status, stop = process.wait(), True
        seconds = time.time() - start
        log.write(f"{LOG_TAIL}{status} after {seconds:.1f} s\n")
    # gelmpm stopped by a signal (Ctrl-C in the terminal): the sweep stops as well.
    return status, seconds, stop or status in (130, 143)


def format_seconds(seconds):
    if seconds < 60:
        return f"{seconds:.1f} s"
    if seconds < 3600:
        return f"{int(seconds // 60)} min {int(seconds % 60)} s"
    return f"{int(seconds // 3600)} h {int(seconds % 3600 // 60)} min"


def write_table(file_name, header, rows):
    temporary = file_name + ".tmp"
    with open(temporary, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(header)
        writer.writerows([[row.get(name, "") for name in header] for row in rows])
    os.replace(temporary, file_name)


def print_table(header, rows):
    def shown(value):
        x = number(value)
        return value if math.isnan(x) or not re.search(r"[.eE]", str(value)) else f"{x:.6g}"
    # The varied entries by the last part of their names (sweep.csv has them whole).
    cells = [[name.split("/")[-1] for name in header]] + [[shown(row.get(name, "")) for name in header]
                                           for row in rows]
    widths = [max(len(str(line[k])) for line in cells) for k in range(len(header))]
    for line in cells:
        print("  ".join(str(cell).ljust(width) for cell, width in zip(line, widths)).rstrip())


def parse(argv):
    parser = argparse.ArgumentParser(
        prog="gelmpm-sweep", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("scene")
    parser.add_argument("--vary", action="append", default=[], metavar="ENTRY=LIST")
    parser.add_argument("--zip", action="store_true")
    parser.add_argument("--separator", metavar="TEXT")
    parser.add_argument("--set", action="append", default=[], metavar="ENTRY=VALUE")
    parser.add_argument("--collect", action="append", default=[], metavar="SPEC")
    parser.add_argument("--output", metavar="DIR")
    parser.add_argument("--gelmpm", metavar="PATH")
    parser.add_argument("--launcher", default="", metavar="CMD")
    parser.add_argument("--skip-done", action="store_true")
    parser.add_argument("--dry-run", action="store_true")
    return parser.parse_args(argv)


def plan(args):
    """The runs: [(name, assignments, command)] and the sweep's directory."""
    if not os.path.isfile(args.scene):
        raise SweepError(f"no scene file '{args.scene}'")
    if not args.vary:
        raise SweepError("nothing to vary: give --vary \"Section/Entry=V1,V2,...\"")
    varied = []
    for text in args.vary:
        entry, values = parse_entry(text, "--vary")
        if entry in [e for e, _ in varied]:
            raise SweepError(f"--vary names '{entry}' twice")
        varied.append((entry, split_values(values, args.separator)))
    fixed = [parse_entry(text, "--set") for text in args.set]
    output = os.path.abspath(args.output or "sweep_" + os.path.splitext(
        os.path.basename(args.scene))[0])
    gelmpm = shlex.split(args.launcher) + [find_gelmpm(args.gelmpm)]
    runs = []
    all_runs = combinations(varied, args.zip)
    digits = len(str(len(all_runs)))
    for k, assignments in enumerate(all_runs, start=1):
        name = f"{k:0{digits}d}_{slug(assignments)}"
        command = list(gelmpm)
        for entry, value in [("Output/Directory", os.path.join(output, name))] + fixed + assignments:
            command += ["--set", f"{entry}={value}"]
        runs.append((name, assignments, command + [os.path.abspath(args.scene)]))
    return runs, output, varied


def main(argv=None):
    args = parse(argv)
    try:
        runs, output, varied = plan(args)
        collect = parse_collect(args.collect)
    except SweepError as error:
        print(f"gelmpm-sweep: error: {error}", file=sys.stderr)
        return 2
    n = len(runs)
    how = "one list" if len(varied) == 1 else ("zipped lists" if args.zip else "product of "
                                               + " x ".join(str(len(v)) for _, v in varied))
    print(f"gelmpm-sweep: {n} run{'s' if n > 1 else ''} of {args.scene} ({how}) into {output}")
    if args.dry_run:
        for k, (name, _, command) in enumerate(runs, start=1):
            print(f"[{k}/{n}] {shlex.join(command)}")
        return 0
    os.makedirs(output, exist_ok=True)
    environment = dict(os.environ)
    if os.geteuid() == 0:  # Open MPI refuses to start as root unless told
        environment.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        environment.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")

    table, failed, missing, interrupted = [], [], {}, False
    header = ["run", "directory"] + [entry for entry, _ in varied] + \
        ["status", "exit_status", "wall_seconds", "steps", "t_end"]
    specs = collect
    start, run_seconds = time.time(), []
    for k, (name, assignments, command) in enumerate(runs, start=1):
        directory = os.path.join(output, name)
        values = ", ".join(f"{entry}={value}" for entry, value in assignments)
        print(f"[{k}/{n}] {values}  ->  {os.path.relpath(directory)}", flush=True)
        done, seconds = (finished_before(os.path.join(directory, "log.txt"), shlex.join(command))
                         if args.skip_done else (False, None))
        if done:
            status = 0
            print(f"[{k}/{n}] done before (--skip-done): kept", flush=True)
        else:
            status, seconds, interrupted = run_one(command, directory, environment)
            run_seconds.append(seconds)
        rows, events = statistics_rows(directory), events_rows(directory)
        if not specs and rows:
            specs = default_collect(rows)
        record = {"run": k, "directory": name, "status": "ok" if status == 0 else "failed",
                  "exit_status": status, "wall_seconds": f"{seconds:.1f}",
                  "steps": last_value(rows, "step"), "t_end": last_value(rows, "t_over_tau_d")}
        record.update({entry: value for entry, value in assignments})
        for spec in specs:
            value = collected_value(spec, rows, events)
            if value is None:
                missing.setdefault(spec[0], []).append(k)
                value = ""
            record[spec[0]] = value
        table.append(record)
        full_header = header + [spec[0] for spec in specs]
        write_table(os.path.join(output, "sweep.csv"), full_header, table)

        elapsed = time.time() - start
        remaining = n - k
        mean = sum(s for s in run_seconds if not math.isnan(s)) / max(len(run_seconds), 1)
        estimate = f", ~{format_seconds(mean * remaining)} to go" if remaining and run_seconds else ""
        outcome = "ok" if status == 0 else "FAILED: " + outcome_of(status)
        reached = f"; t/tau_d = {record['t_end']} after {record['steps']} steps" if rows else ""
        print(f"[{k}/{n}] {outcome} (exit status {status}) in {format_seconds(seconds)}{reached};"
              f" elapsed {format_seconds(elapsed)}{estimate}", flush=True)
        if status != 0:
            failed.append(k)
            message = last_message(os.path.join(directory, "log.txt"))
            if message:
                print(f"        {message[:300]}", flush=True)
            print(f"        log: {os.path.relpath(os.path.join(directory, 'log.txt'))}", flush=True)
        if interrupted:
            print(f"gelmpm-sweep: stopped by a signal during run {k} of {n}", flush=True)
            break

    print()
    print_table(header + [spec[0] for spec in specs], table)
    print(f"\ngelmpm-sweep: table {os.path.relpath(os.path.join(output, 'sweep.csv'))}; "
          f"{len(table) - len(failed)} of {n} runs ok in {format_seconds(time.time() - start)}")
    status = 0
    if failed:
        print(f"gelmpm-sweep: {len(failed)} run{'s' if len(failed) > 1 else ''} failed: "
              + ", ".join(str(k) for k in failed), file=sys.stderr)
        status = 1
    never = [spec for spec, ks in missing.items()
             if len(ks) == sum(1 for r in table if r["steps"] != "")]
    for spec in never:
        print(f"gelmpm-sweep: --collect '{spec}': no run's statistics.csv has that column "
              "(gelmpm-plot DIR --list lists them)", file=sys.stderr)
        status = 1
    if interrupted:
        return table[-1]["exit_status"] if table[-1]["exit_status"] in (130, 143) else 130
    return status


if __name__ == "__main__":
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    signal.signal(signal.SIGTERM, on_sigterm)
    try:
        sys.exit(main())
    except (KeyboardInterrupt, Terminated):
        print("gelmpm-sweep: stopped by a signal", file=sys.stderr)
        sys.exit(130)

#!/usr/bin/python3
"""gelmpm-plot: plots of GelMPM output directories, one run or several on one figure.

    gelmpm-plot DIR [DIR ...] --list
    gelmpm-plot DIR [DIR ...] --y COLUMN [--y COLUMN ...] [--x COLUMN] [--events] [--log x|y|xy]
    gelmpm-plot DIR [DIR ...] --relaxation [COLUMN] [--load-end T] [--final-force F]
                [--time-scale T [--fit sphere|flat]]
    gelmpm-plot DIR [DIR ...] --surface PIECE [--outputs 0,5,-1|all] [--profile-x x] [--profile-y y]
    common: [-o FILE.png|.pdf|.svg] [--data FILE.csv] [--label TEXT ...] [--title TEXT]
            [--xlabel TEXT] [--ylabel TEXT]
            [--with FILE:XCOLUMN:YCOLUMN[:LABEL] ...]

(`build/gelmpm-plot` is a link to this file; `/usr/bin/python3 contrib/plotting/gelmpm_plot.py`
runs it as well.) Each DIR is a run's 'Output/Directory' (it holds statistics.csv), or the output
directory of gelmpm-sweep (it holds sweep.csv): its runs, each labelled by its swept values.

--list           the columns of each run's statistics.csv with their final values, its events and
                 its surface profiles.
--y COLUMN       a history: the statistics.csv column against --x (default t_over_tau_d, the time
                 in tau_d); several --y draw several curves. --events marks the rows of events.csv
                 (dashed lines at their times, or on each curve at the nearest row when --x is not
                 a time).
--relaxation     the normalised relaxation g = (F(t) - F(inf)) / (F(0+) - F(inf)) of a force
                 column (doc/indentation.md): default the largest force component of an obstacle
                 (a column <obstacle>_force_* beside <obstacle>_contact_radius). F(0+) is the force
                 at the end of the loading: the row nearest --load-end T (tau_d), by default the
                 row of the largest |F| (the end of a ramp-and-hold loading); F(inf) is the last
                 row's force or --final-force. Drawn against t - t_0 (log scale), divided by
                 --time-scale (e.g. a^2/c, doc/indentation.md: tau = c t / a^2); --fit adds
                 Hu et al.'s fit of linear poroelasticity for a sphere or a flat punch.
--surface PIECE  the profiles surface_PIECE-NNNNN.csv (Observables/Surface pieces, 2D): --profile-y
                 against --profile-x (default y against x, equal axes), at the output numbers of
                 --outputs (default: at most six, the first and the last among them), labelled with
                 their time when particles.pvd lists it.
--with           a curve from any CSV file with a header row (e.g. the finite-difference reference
                 of gelmpm-swelling-1d) on the same axes.
-o FILE          the figure (PNG, PDF or SVG by the extension; default: <what>.png here).
--data FILE      the plotted numbers as CSV (run, label, x, y); with --data and without -o no figure
                 is drawn (and matplotlib is not needed).

Needs Python 3; drawing also needs matplotlib (Debian: python3-matplotlib; `bash contrib/setup.sh
--plotting`). Exit status 0, or 2 with one message naming the missing column, file or directory.
"""
import argparse
import csv
import difflib
import math
import os
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from gelmpm_files import (number, output_directory_problem, output_times, read_columns,  # noqa: E402
                          read_rows, surface_pieces, surface_profiles)

TIME_COLUMNS = ("t_over_tau_d", "time")
AXIS_NAMES = {"t_over_tau_d": "t/τ_d", "time": "t", "s_0": "s_0 (arc length, initial)",
              "x": "x", "y": "y", "mu": "μ/k_BT", "delta_h_over_h0": "Δh/h_0"}


class PlotError(Exception):
    """Bad input: one message naming what is missing and how to find what is there."""


def fail(message):
    print(f"gelmpm-plot: error: {message}", file=sys.stderr)
    sys.exit(2)


class Run:
    """One output directory: its statistics.csv (columns of floats), events.csv rows and label."""

    def __init__(self, directory, label):
        problem = output_directory_problem(directory)
        if problem:
            raise PlotError(problem)
        self.directory = directory
        self.label = label
        self.statistics = read_columns(os.path.join(directory, "statistics.csv"))
        events = os.path.join(directory, "events.csv")
        self.events = read_rows(events) if os.path.isfile(events) else []

    def column(self, name):
        """A column of statistics.csv; a missing one is an error naming the closest columns."""
        if name not in self.statistics:
            close = difflib.get_close_matches(name, list(self.statistics), n=3, cutoff=0.5)
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            raise PlotError(f"{os.path.join(self.directory, 'statistics.csv')} has no column "
                            f"'{name}'{hint}; `gelmpm-plot {self.directory} --list` lists its columns")
        return self.statistics[name]

    def event_times(self, column="t_over_tau_d"):
        """[(event, time)] of events.csv, the time in its column @p column (t_over_tau_d or time)."""
        return [(row.get("event", "?"), number(row.get(column))) for row in self.events]


def sweep_runs(directory):
    """[(run directory, label)] of a gelmpm-sweep output directory (its sweep.csv), labelled by
    the swept values; None if @p directory holds no sweep.csv."""
    table = os.path.join(directory, "sweep.csv")
    if not os.path.isfile(table):
        return None
    rows = read_rows(table)
    if not rows:
        return []
    # The swept entries are the columns between 'directory' and 'status' (gelmpm_sweep.py); a
    # label names those that differ among the runs with output.
    names = list(rows[0])
    swept = names[names.index("directory") + 1: names.index("status")]
    rows = [row for row in rows
            if output_directory_problem(os.path.join(directory, row["directory"])) is None]
    differing = [name for name in swept if len({row[name] for row in rows}) > 1]
    return [(os.path.join(directory, row["directory"]),
             ", ".join(f"{name.split('/')[-1]}={row[name]}" for name in differing) or row["run"])
            for row in rows]


def load_runs(directories, labels):
    """The runs of the directories given (a sweep's directory: all its runs with output)."""
    entries = []
    for directory in directories:
        from_sweep = None if os.path.isfile(os.path.join(directory, "statistics.csv")) \
            else sweep_runs(directory)
        if from_sweep is None:
            entries.append((directory, os.path.basename(os.path.normpath(directory))))
        elif not from_sweep:
            raise PlotError(f"the sweep '{directory}' has no run with output yet")
        else:
            entries.extend(from_sweep)
    if labels:
        if len(labels) != len(entries):
            raise PlotError(f"{len(labels)} --label for {len(entries)} runs: give one per run")
        entries = [(directory, label) for (directory, _), label in zip(entries, labels)]
    return [Run(directory, label) for directory, label in entries]


def finite_pairs(xs, ys):
    """The (x, y) pairs where both are numbers (a column left empty in some rows: NaN)."""
    pairs = [(x, y) for x, y in zip(xs, ys) if not (math.isnan(x) or math.isnan(y))]
    return [p[0] for p in pairs], [p[1] for p in pairs]


def history(run, x, y):
    """(xs, ys) of a statistics column against another."""
    return finite_pairs(run.column(x), run.column(y))


def obstacle_force_column(run):
    """The force column of the run's obstacle: of the columns <obstacle>_force_x/_y/_z beside an
    <obstacle>_contact_radius (boundary pieces have forces but no contact radius), the one with
    the largest final magnitude."""
    columns = run.statistics
    candidates = []
    for name in columns:
        if name.endswith("_contact_radius"):
            obstacle = name[: -len("_contact_radius")]
            for axis in "xyz":
                force = f"{obstacle}_force_{axis}"
                if force in columns:
                    values = [v for v in columns[force] if not math.isnan(v)]
                    candidates.append((abs(values[-1]) if values else 0.0, force))
    if not candidates:
        raise PlotError(f"{run.directory}/statistics.csv has no obstacle force (a column "
                        "<obstacle>_force_y beside <obstacle>_contact_radius, written with "
                        "'Contact/Obstacles'); name the force column: --relaxation COLUMN")
    return max(candidates)[1]


def force_relaxation(times, forces, load_end=None, final_force=None):
    """The normalised relaxation of a force held after a loading (doc/indentation.md):
    g = (F(t) - F(inf)) / (F(0+) - F(inf)) for the rows from the end of the loading on.

    F(0+) is the force in the row nearest @p load_end (by default the row of the largest |F|,
    the end of a ramp-and-hold loading), F(inf) @p final_force or the last row's force.
    Returns dict(t_load, F0, Finf, t: [t - t_load], F: [F], g: [g]) from that row on."""
    times, forces = finite_pairs(times, forces)
    if len(times) < 2:
        raise PlotError("the force column has fewer than two values")
    if load_end is None:
        start = max(range(len(forces)), key=lambda i: abs(forces[i]))
    else:
        start = min(range(len(times)), key=lambda i: abs(times[i] - load_end))
    f0 = forces[start]
    f_inf = forces[-1] if final_force is None else final_force
    if f0 == f_inf:
        raise PlotError(f"F(0+) = F(inf) = {f0:g}: nothing relaxes (is --load-end the end of the "
                        "loading, and did the run go on after it?)")
    return dict(t_load=times[start], F0=f0, Finf=f_inf,
                t=[t - times[start] for t in times[start:]], F=forces[start:],
                g=[(f - f_inf) / (f0 - f_inf) for f in forces[start:]])


def poroelastic_relaxation_fit(shape, tau):
    """Hu, Zhao, Vlassak & Suo's fits of the normalised relaxation g(tau), tau = c t / a^2, of an
    impermeable indenter on a linear poroelastic half-space (Appl. Phys. Lett. 96, 121904, 2010;
    doc/indentation.md): 'sphere' or 'flat' (a flat-ended cylinder)."""
    if shape == "sphere":
        return 0.491 * math.exp(-0.908 * math.sqrt(tau)) + 0.509 * math.exp(-1.679 * tau)
    return 1.304 * math.exp(-math.sqrt(tau)) - 0.304 * math.exp(-0.254 * tau)


def chosen_outputs(numbers, request):
    """The output numbers to draw: 'all', a list such as '0,5,-1' (negative: from the end), or by
    default at most six spread evenly, the first and the last among them."""
    if not numbers:
        return []
    if request == "all":
        return numbers
    if request:
        chosen = []
        for text in request.split(","):
            k = int(text)
            if k < 0:
                if -k > len(numbers):
                    raise PlotError(f"--outputs {k}: there are {len(numbers)} outputs")
                k = numbers[k]
            if k not in numbers:
                raise PlotError(f"--outputs: there is no output {k} (there are {numbers[0]} to "
                                f"{numbers[-1]})")
            chosen.append(k)
        return chosen
    if len(numbers) <= 6:
        return numbers
    return sorted({numbers[round(i * (len(numbers) - 1) / 5)] for i in range(6)})


def surface_series(run, piece, x, y, request):
    """[(label, xs, ys)] of the piece's profiles at the chosen outputs."""
    profiles = dict(surface_profiles(run.directory, piece))
    if not profiles:
        pieces = surface_pieces(run.directory)
        raise PlotError(f"{run.directory} has no surface profiles of '{piece}' "
                        + (f"(it has: {', '.join(pieces)})" if pieces else
                           "(none at all: run with 'Observables/Surface pieces', 2D)"))
    times = output_times(run.directory)
    series = []
    for k in chosen_outputs(sorted(profiles), request):
        columns = read_columns(profiles[k])
        for name in (x, y):
            if name not in columns:
                raise PlotError(f"{profiles[k]} has no column '{name}' (it has: "
                                f"{', '.join(columns)})")
        label = f"t/τ_d = {times[k]:.4g}" if k in times else f"output {k}"
        series.append((label, *finite_pairs(columns[x], columns[y])))
    return series


def extra_curve(spec):
    """(label, xs, ys) of --with FILE:XCOLUMN:YCOLUMN[:LABEL]."""
    parts = spec.split(":")
    if len(parts) < 3:
        raise PlotError(f"--with '{spec}': give FILE:XCOLUMN:YCOLUMN[:LABEL]")
    file_name, x, y = parts[0], parts[1], parts[2]
    label = ":".join(parts[3:]) or os.path.basename(file_name)
    if not os.path.isfile(file_name):
        raise PlotError(f"--with: no file '{file_name}'")
    columns = read_columns(file_name)
    for name in (x, y):
        if name not in columns:
            raise PlotError(f"--with: {file_name} has no column '{name}' (it has: "
                            f"{', '.join(columns)})")
    return (label, *finite_pairs(columns[x], columns[y]))


def listing(run):
    """The text of --list for one run."""
    columns = run.statistics
    n_rows = max((len(v) for v in columns.values()), default=0)
    lines = [f"{run.directory}: statistics.csv, {n_rows} rows, {len(columns)} columns "
             "(final value; '(empty)' where the last row leaves it empty)"]
    for name, values in columns.items():
        last = values[-1] if values else math.nan
        lines.append(f"  {name:32s} {'(empty)' if math.isnan(last) else format(last, '.10g')}")
    events = run.event_times()
    if events:
        lines.append(f"  events.csv: {len(events)} events: "
                     + ", ".join(f"{name} at {t:.6g}" for name, t in events))
    elif os.path.isfile(os.path.join(run.directory, "events.csv")):
        lines.append("  events.csv: no events")
    for piece in surface_pieces(run.directory):
        lines.append(f"  surface_{piece}-*.csv: {len(surface_profiles(run.directory, piece))} "
                     "profiles (columns s_0, x, y, mu)")
    return "\n".join(lines)


def axis_name(column):
    return AXIS_NAMES.get(column, column)


def collect(args, runs):
    """What to draw: a dict with the curves [(run, label, xs, ys)], the event marks, the axes'
    names and scales."""
    plot = dict(curves=[], marks=[], vlines=[], logx="x" in args.log, logy="y" in args.log,
                equal=False, title=args.title, legend=False)
    if args.events:
        for run in runs:
            if not os.path.isfile(os.path.join(run.directory, "events.csv")):
                print(f"gelmpm-plot: note: {run.directory} has no events.csv (a run writes one with "
                      "'Stability/Inertia', 'Observables/Pore piece' or 'Surface pieces')",
                      file=sys.stderr)
    if args.relaxation is not None:
        for run in runs:
            name = obstacle_force_column(run) if args.relaxation == "auto" else args.relaxation
            r = force_relaxation(run.column("t_over_tau_d"), run.column(name), args.load_end,
                                 args.final_force)
            scale = args.time_scale or 1.0
            print(f"gelmpm-plot: {run.directory}: {name}: F(0+) = {r['F0']:.6g} at t/tau_d = "
                  f"{r['t_load']:.6g}, F(inf) = {r['Finf']:.6g}, F(0+)/F(inf) = "
                  f"{r['F0'] / r['Finf'] if r['Finf'] else math.inf:.4f}")
            keep = [(t / scale, g) for t, g in zip(r["t"], r["g"]) if t > 0]
            plot["curves"].append((run, run.label, [p[0] for p in keep], [p[1] for p in keep]))
            if args.events:
                plot["vlines"] += [((t - r["t_load"]) / scale, name_, run)
                                   for name_, t in run.event_times() if t > r["t_load"]]
        plot.update(xlabel=f"(t − t_0)/{args.time_scale:g} τ_d" if args.time_scale else
                    "t − t_0 (τ_d)", ylabel="g = (F − F(∞))/(F(0⁺) − F(∞))", logx=True,
                    legend=True, default_name="relaxation")
        if args.fit:
            xs = [p[0] for curve in plot["curves"] for p in zip(curve[2], curve[3])]
            low, high = min(xs), max(xs)
            tau = [low * (high / low) ** (i / 199) for i in range(200)]
            plot["curves"].append((None, f"Hu et al. 2010, {args.fit} (linear poroelasticity)",
                                   tau, [poroelastic_relaxation_fit(args.fit, t) for t in tau]))
    elif args.surface:
        for run in runs:
            for label, xs, ys in surface_series(run, args.surface, args.profile_x, args.profile_y,
                                                args.outputs):
                plot["curves"].append((run, f"{run.label}: {label}" if len(runs) > 1 else label,
                                       xs, ys))
        plot.update(xlabel=axis_name(args.profile_x), ylabel=axis_name(args.profile_y),
                    equal=(args.profile_x, args.profile_y) == ("x", "y"), legend=True,
                    default_name=f"surface_{args.surface}")
    else:
        ys = [name for value in args.y for name in value.split(",") if name]
        if not ys:
            raise PlotError("say what to plot: --y COLUMN (a history), --relaxation or --surface "
                            "PIECE; --list lists the columns")
        for run in runs:
            for y in ys:
                xs_, ys_ = history(run, args.x, y)
                label = run.label if len(ys) == 1 else (y if len(runs) == 1 else f"{run.label}: {y}")
                plot["curves"].append((run, label, xs_, ys_))
            if args.events and args.x in TIME_COLUMNS:  # events.csv has both time columns
                plot["vlines"] += [(t, name, run) for name, t in run.event_times(args.x)]
            elif args.events:  # on each curve, at the row nearest the event
                times = run.column("t_over_tau_d")
                for name, t in run.event_times():
                    i = min(range(len(times)), key=lambda k: abs(times[k] - t))
                    for y in ys:
                        plot["marks"].append((run.column(args.x)[i], run.column(y)[i], name, run))
        plot.update(xlabel=axis_name(args.x), ylabel=", ".join(axis_name(y) for y in ys),
                    legend=len(plot["curves"]) > 1, default_name="_".join(ys))
    for spec in args.with_:
        label, xs, ys = extra_curve(spec)
        plot["curves"].append((None, label, xs, ys))
        plot["legend"] = True
    return plot


def write_data(plot, file_name):
    with open(file_name, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["run", "label", "x", "y"])
        for run, label, xs, ys in plot["curves"]:
            for x, y in zip(xs, ys):
                writer.writerow([run.directory if run else "", label, repr(x), repr(y)])
        for x, name, run in plot["vlines"]:
            writer.writerow([run.directory, f"event {name}", repr(x), ""])
        for x, y, name, run in plot["marks"]:
            writer.writerow([run.directory, f"event {name}", repr(x), repr(y)])


def draw(plot, args, file_name):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        fail("drawing needs matplotlib (Debian: python3-matplotlib; bash contrib/setup.sh "
             "--plotting); --data FILE.csv writes the numbers without drawing")
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    colours = {}
    for run, label, xs, ys in plot["curves"]:
        # A log axis leaves out the values it cannot show (the initial row's t = 0).
        kept = [(x, y) for x, y in zip(xs, ys)
                if not (plot["logx"] and x <= 0) and not (plot["logy"] and y <= 0)]
        xs, ys = [p[0] for p in kept], [p[1] for p in kept]
        style = dict(marker=".", markersize=3, linewidth=1.2) if run else dict(color="k", linestyle="--")
        line, = ax.plot(xs, ys, label=label, **style)
        if run is not None and run not in colours:
            colours[run] = line.get_color()
    seen = set()
    for x, name, run in plot["vlines"]:
        ax.axvline(x, color=colours.get(run, "grey"), linestyle=":", linewidth=1)
        if (name, run) not in seen:
            ax.annotate(name, (x, 1.0), xycoords=("data", "axes fraction"), rotation=90,
                        va="top", ha="right", fontsize=7, color=colours.get(run, "grey"))
            seen.add((name, run))
    for x, y, name, run in plot["marks"]:
        ax.plot([x], [y], marker="v", color=colours.get(run, "grey"), markersize=7)
        ax.annotate(name, (x, y), xytext=(3, 5), textcoords="offset points", fontsize=7)
    if plot["logx"]:
        ax.set_xscale("log")
    if plot["logy"]:
        ax.set_yscale("log")
    if plot["equal"]:
        ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(args.xlabel or plot["xlabel"])
    ax.set_ylabel(args.ylabel or plot["ylabel"])
    if plot["title"]:
        ax.set_title(plot["title"])
    ax.grid(True, which="both", alpha=0.3)
    if plot["legend"]:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(file_name, dpi=150)
    plt.close(fig)


def parse(argv):
    parser = argparse.ArgumentParser(
        prog="gelmpm-plot", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("directories", nargs="+", metavar="DIR")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--y", action="append", default=[], metavar="COLUMN")
    parser.add_argument("--x", default="t_over_tau_d", metavar="COLUMN")
    parser.add_argument("--events", action="store_true")
    parser.add_argument("--log", default="", choices=["x", "y", "xy"])
    parser.add_argument("--relaxation", nargs="?", const="auto", metavar="COLUMN")
    parser.add_argument("--load-end", type=float, metavar="T")
    parser.add_argument("--final-force", type=float, metavar="F")
    parser.add_argument("--time-scale", type=float, metavar="T")
    parser.add_argument("--fit", choices=["sphere", "flat"])
    parser.add_argument("--surface", metavar="PIECE")
    parser.add_argument("--outputs", default="", metavar="LIST")
    parser.add_argument("--profile-x", default="x", metavar="COLUMN")
    parser.add_argument("--profile-y", default="y", metavar="COLUMN")
    parser.add_argument("--with", dest="with_", action="append", default=[],
                        metavar="FILE:XCOLUMN:YCOLUMN[:LABEL]")
    parser.add_argument("--label", action="append", default=[])
    parser.add_argument("--title", default="")
    parser.add_argument("--xlabel", default="")
    parser.add_argument("--ylabel", default="")
    parser.add_argument("-o", "--output", metavar="FILE")
    parser.add_argument("--data", metavar="FILE.csv")
    args = parser.parse_args(argv)
    if args.relaxation is not None and args.surface:
        parser.error("--relaxation and --surface draw different figures: give one")
    if args.time_scale is not None and not args.time_scale > 0:
        parser.error("--time-scale must be positive")
    if args.fit and (args.relaxation is None or args.time_scale is None):
        parser.error("--fit draws g(tau) with tau = c t / a^2: give it with --relaxation and "
                     "--time-scale a^2/c (doc/indentation.md)")
    return args


def main(argv=None):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `gelmpm-plot DIR --list | head` ends quietly
    args = parse(argv)
    try:
        runs = load_runs(args.directories, args.label)
        if args.list:
            print("\n\n".join(listing(run) for run in runs))
            return 0
        plot = collect(args, runs)
        if not any(xs for _, _, xs, _ in plot["curves"]):
            raise PlotError("nothing to draw: the columns chosen have no values")
        if args.data:
            write_data(plot, args.data)
            print(f"gelmpm-plot: wrote {args.data}")
        if args.output or not args.data:
            output = args.output or plot["default_name"] + ".png"
            draw(plot, args, output)
            print(f"gelmpm-plot: wrote {output}")
    except PlotError as error:
        fail(str(error))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""heliostand report: charts and a one-page summary of finished stand runs (run by `heliostand report`).

    python3 heliostand_report.py RUN_DIR [RUN_DIR ...] [--out DIR] [--label NAME ...]

One run folder: PNG charts over stand age (stems/ha, basal area, Dg/Hg/top height, standing volume and total
production, CAI and MAI, mortality by cause; thinnings marked), diameter distributions before and after each
thinning and in the last output year, and report.md embedding them with a summary table; into RUN_DIR/report
unless --out says otherwise. Several run folders: every run on the same axes (legend = folder name or --label)
and a comparison table; --out is then required.

Everything is read before anything is written, and the report is drawn into a temporary folder next to the
destination that replaces it only when complete, so a failure leaves no half-written report. An existing
destination is replaced only when it is empty or an earlier report (it holds the marker file).

Exit status: 0 done, 1 failure (matplotlib missing, a chart could not be drawn), 2 bad input (the message names
the file, and the line and column where it applies). Needs Debian's python3-matplotlib (Agg backend, no display).
"""
import argparse
import os
import shutil
import sys

sys.dont_write_bytecode = True  # it runs from the source tree: leave no __pycache__ there
from run_data import RunInputError, read_run  # noqa: E402 (after the line above)

REPORT_MARKER = ".heliostand-report"


class UsageError(Exception):
    """A command line or output folder the report refuses (exit status 2)."""


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="heliostand report", description=__doc__.split("\n")[0])
    parser.add_argument("run_dirs", nargs="+", metavar="RUN_DIR", help="run folder written by heliostand grow")
    parser.add_argument("--out", help="report folder (default RUN_DIR/report; required with several runs)")
    parser.add_argument("--label", action="append", default=[],
                        help="legend name of a run, once per run in the order of the folders")
    return parser.parse_args(argv)


def run_labels(arguments):
    """Legend names: --label per run, else each folder's name; they must tell the runs apart."""
    if arguments.label and len(arguments.label) != len(arguments.run_dirs):
        raise UsageError("%d --label for %d run folders: give one per run, or none"
                         % (len(arguments.label), len(arguments.run_dirs)))
    labels = arguments.label or [os.path.basename(os.path.normpath(os.path.abspath(d)))
                                 for d in arguments.run_dirs]
    from charts import slug  # file names of per-run charts are built from the labels
    slugs = [slug(label) for label in labels]
    for index, label in enumerate(labels):
        if slugs.index(slugs[index]) != index:
            raise UsageError("two runs named '%s' in the charts: tell them apart with --label NAME per run" % label)
    return labels


def output_folder(arguments):
    if arguments.out:
        return os.path.abspath(arguments.out)
    if len(arguments.run_dirs) > 1:
        raise UsageError("comparing %d runs: say where the report goes with --out DIR" % len(arguments.run_dirs))
    return os.path.abspath(os.path.join(arguments.run_dirs[0], "report"))


def check_replaceable(folder):
    """An existing folder is replaced only when it is empty or an earlier report: never someone's files."""
    if not os.path.exists(folder):
        return
    if not os.path.isdir(folder):
        raise UsageError("%s: exists and is not a folder; choose another --out" % folder)
    if os.listdir(folder) and not os.path.exists(os.path.join(folder, REPORT_MARKER)):
        raise UsageError("%s: exists and is not an earlier heliostand report (no %s); choose another --out or "
                         "empty it" % (folder, REPORT_MARKER))


def load_matplotlib():
    import charts
    try:
        charts.load_pyplot()
    except ImportError as e:
        sys.stderr.write(
            "error: heliostand report draws its charts with matplotlib, which %s cannot import (%s). Install it "
            "with `apt-get install python3-matplotlib`; where several python3 are installed, set HELIOSTAND_PYTHON "
            "to the one that has it (Debian's is /usr/bin/python3).\n" % (sys.executable, e))
        return False
    return True


def draw_report(runs, folder):
    """Charts, report.md and the marker into `folder`; returns the number of PNGs."""
    import charts
    import summary
    over_age, final_chart, thinning_charts = charts.draw_all(runs, folder)
    summary.write_report(os.path.join(folder, "report.md"), runs, over_age, final_chart, thinning_charts)
    with open(os.path.join(folder, REPORT_MARKER), "w", encoding="utf-8") as f:
        f.write("Written by heliostand report; the next report into this folder replaces it.\n")
    return len(over_age) + 1 + len(thinning_charts)


def write_complete(runs, destination):
    """Draw into a temporary sibling folder, then swap it in: a failure leaves the destination as it was."""
    parent, name = os.path.split(destination)
    os.makedirs(parent, exist_ok=True)
    temporary = os.path.join(parent, ".%s.tmp-%d" % (name, os.getpid()))
    previous = os.path.join(parent, ".%s.old-%d" % (name, os.getpid()))
    os.makedirs(temporary)
    try:
        charts_drawn = draw_report(runs, temporary)
        if os.path.exists(destination):
            os.rename(destination, previous)
        os.rename(temporary, destination)
    finally:
        shutil.rmtree(temporary, ignore_errors=True)
        shutil.rmtree(previous, ignore_errors=True)
    return charts_drawn


def main(argv):
    arguments = parse_arguments(argv)
    try:
        labels = run_labels(arguments)
        destination = output_folder(arguments)
        if not load_matplotlib():
            return 1
        runs = [read_run(folder, label) for folder, label in zip(arguments.run_dirs, labels)]
        check_replaceable(destination)
    except (RunInputError, UsageError) as e:
        sys.stderr.write("error: %s\n" % e)
        return 2
    charts_drawn = write_complete(runs, destination)
    print("report: %s (%d charts)" % (os.path.join(destination, "report.md"), charts_drawn))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except OSError as e:
        sys.stderr.write("error: %s\n" % e)
        sys.exit(1)

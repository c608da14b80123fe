#!/usr/bin/env python3
"""CTest driver for `heliostand report` (tests/scripts/report.cmake).

    report_test.py made HELIOSTAND REPORT_DIR THINNING_CHARTS -- REPORT_ARGS...
        runs `HELIOSTAND report REPORT_ARGS...`, requires exit status 0, then checks REPORT_DIR as `check` does.
    report_test.py check REPORT_DIR THINNING_CHARTS
        every chart the report promises is a PNG that shows something, report.md embeds each of them, and no
        other PNG lies there. THINNING_CHARTS = how many before/after-thinning distributions the runs call for.
    report_test.py refused HELIOSTAND STATUS TEXT NO_FOLDER [NAME=VALUE ...] -- REPORT_ARGS...
        runs `HELIOSTAND report REPORT_ARGS...` with the environment additions, requires exit status STATUS,
        TEXT on stderr, and that NO_FOLDER (where the report would have gone) was not created, nor any
        temporary folder beside it.
    report_test.py blank-fails REPORT_DIR CHART THINNING_CHARTS
        the check itself can fail: copies REPORT_DIR to REPORT_DIR-blank, paints CHART one colour and passes only
        when `check` then names CHART as blank.
    report_test.py spoil RUN_DIR COPY FILE LINE COLUMN TEXT
        copies RUN_DIR's tables to COPY with one field of FILE (line LINE, column named COLUMN) set to TEXT;
        LINE 1 renames the column itself: bad input for `refused`.

A PNG "shows something" when it decodes and has at least MIN_COLOURS distinct colours with no single colour
covering more than MAX_SHARE of the pixels (the thresholds validation/paraview/check_png.py uses for renders):
an empty file, a one-colour image or a nearly empty canvas fails.
"""
import csv
import fnmatch
import glob
import os
import re
import shutil
import subprocess
import sys

import numpy

MIN_COLOURS = 16
MAX_SHARE = 0.98
# The charts every report has, whatever the runs (src/report/charts.py).
ALWAYS = ("stems_per_ha.png", "basal_area.png", "diameter_and_height.png", "volume_and_production.png",
          "increments.png", "mortality_by_cause.png", "diameter_distribution_final.png")
THINNING_CHART = "diameter_distribution_*age_*.png"


def png_problem(path):
    """Why the PNG at `path` is not a picture of something, or None."""
    import matplotlib.image
    try:
        pixels = matplotlib.image.imread(path)
    except (OSError, ValueError, SyntaxError) as e:
        return "%s: cannot be read as a PNG (%s)" % (path, e)
    if pixels.ndim != 3 or pixels.shape[0] == 0 or pixels.shape[1] == 0:
        return "%s: not a colour image (shape %s)" % (path, pixels.shape)
    colours, counts = numpy.unique((pixels * 255).round().astype(numpy.uint8).reshape(-1, pixels.shape[2]),
                                   axis=0, return_counts=True)
    share = counts.max() / counts.sum()
    if len(colours) < MIN_COLOURS:
        return "%s: blank, only %d distinct colours (need %d)" % (path, len(colours), MIN_COLOURS)
    if share > MAX_SHARE:
        return "%s: blank, one colour covers %.1f%% of the image" % (path, 100 * share)
    print("%s: %dx%d, %d colours, background %.1f%%" % (path, pixels.shape[1], pixels.shape[0], len(colours),
                                                         100 * share))
    return None


def report_problems(folder, thinning_charts):
    markdown = os.path.join(folder, "report.md")
    if not os.path.isfile(markdown):
        return ["%s: missing" % markdown]
    with open(markdown, encoding="utf-8") as f:
        embedded = set(re.findall(r"!\[[^\]]*\]\(([^)]+)\)", f.read()))
    present = {os.path.basename(p) for p in glob.glob(os.path.join(folder, "*.png"))}
    thinning = {name for name in present if fnmatch.fnmatch(name, THINNING_CHART)}
    problems = ["%s: missing" % os.path.join(folder, name) for name in ALWAYS if name not in present]
    if len(thinning) != thinning_charts:
        problems.append("%s: %d before/after-thinning charts (%s), expected %d"
                        % (folder, len(thinning), ", ".join(sorted(thinning)), thinning_charts))
    problems += ["report.md does not embed %s" % name for name in sorted(present - embedded)]
    problems += ["report.md embeds %s, which is not there" % name for name in sorted(embedded - present)]
    problems += [p for p in (png_problem(os.path.join(folder, name)) for name in sorted(present)) if p]
    return problems


def run_report(heliostand, arguments, extra_environment=()):
    environment = dict(os.environ)
    environment.update(item.split("=", 1) for item in extra_environment)
    print("$ %s report %s" % (heliostand, " ".join(arguments)), flush=True)
    return subprocess.run([heliostand, "report"] + arguments, env=environment, capture_output=True, text=True)


def split_at_dashes(arguments):
    if "--" not in arguments:
        sys.exit("usage: see the docstring of %s" % __file__)
    at = arguments.index("--")
    return arguments[:at], arguments[at + 1:]


def made(arguments):
    (heliostand, folder, thinning_charts), report_arguments = split_at_dashes(arguments)
    result = run_report(heliostand, report_arguments)
    sys.stdout.write(result.stdout + result.stderr)
    if result.returncode != 0:
        return ["heliostand report exited with status %d" % result.returncode]
    return report_problems(folder, int(thinning_charts))


def refused(arguments):
    (heliostand, status, text, no_folder, *environment), report_arguments = split_at_dashes(arguments)
    result = run_report(heliostand, report_arguments, environment)
    sys.stdout.write(result.stdout + result.stderr)
    problems = []
    if result.returncode != int(status):
        problems.append("exit status %d, expected %s" % (result.returncode, status))
    if text not in result.stderr:
        problems.append("stderr does not say '%s'" % text)
    parent, name = os.path.split(os.path.normpath(no_folder))
    left = [no_folder] if os.path.exists(no_folder) else []
    left += glob.glob(os.path.join(parent, ".%s.tmp-*" % name))
    problems += ["%s: written although the report was refused" % path for path in left]
    return problems


def blank_fails(arguments):
    folder, chart, thinning_charts = arguments
    import matplotlib.image
    copy = folder.rstrip("/") + "-blank"
    shutil.rmtree(copy, ignore_errors=True)
    shutil.copytree(folder, copy)
    height, width = matplotlib.image.imread(os.path.join(folder, chart)).shape[:2]
    matplotlib.image.imsave(os.path.join(copy, chart), numpy.ones((height, width, 3)))
    problems = report_problems(copy, int(thinning_charts))
    for problem in problems:
        print("the check says: %s" % problem)
    if any(problem.startswith(os.path.join(copy, chart) + ": blank") for problem in problems):
        return []
    return ["the check passed %s painted one colour" % os.path.join(copy, chart)]


def spoil(arguments):
    run, copy, name, line, column, text = arguments
    shutil.rmtree(copy, ignore_errors=True)
    os.makedirs(copy)
    for table in ("stand_table.csv", "trees.csv", "events.csv"):
        shutil.copy(os.path.join(run, table), copy)
    with open(os.path.join(copy, name), newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    rows[int(line) - 1][rows[0].index(column)] = text
    with open(os.path.join(copy, name), "w", newline="", encoding="utf-8") as f:
        csv.writer(f, lineterminator="\n").writerows(rows)
    return []


def main(arguments):
    modes = {"made": made, "refused": refused, "blank-fails": blank_fails, "spoil": spoil,
             "check": lambda a: report_problems(a[0], int(a[1]))}
    if not arguments or arguments[0] not in modes:
        sys.stderr.write(__doc__)
        return 2
    problems = modes[arguments[0]](arguments[1:])
    for problem in problems:
        sys.stderr.write("error: %s\n" % problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""Every run of issue 16's goal hectare on two cores, summarised (issue 16: under 10 minutes and 8 GiB).

The hectare (validation/bench/stands/hectare_60_years.toml, `heliostand bench stand ... --tables T`) has been grown
on 2-core machines many times, in quick hours and slow ones, on machines started anew, with main's code and with
variants measured beside it. Whether it meets its 10 minutes depends on the hour and the machine, so the verdict is a
count and a median over runs, not one run. The runs are rows of validation/bench/hectare_runs.csv, one a run, in the
order they ran:

    date, time_utc        when the run started (UTC; time empty where its section did not record it)
    machine_started       when the machine it ran on was started ("YYYY-MM-DD HH:MM" UTC), empty where not recorded
    code                  the commit the binary was built from
    variant               empty for that commit's own code; otherwise what was changed or set for the run
    kernels               which generation of the light kernels it ran (the floor and ceil of 2026-12-02 changed
                          every later run's time by 0.89-0.94, so the verdict counts runs of one generation)
    same_tables           "yes" if it grew the stand, tree and event tables of every hectare since 2026-11-28
                          byte for byte; "no" for a variant whose answer differs (left out of the summary)
    wall_s, peak_mib      GNU time's wall seconds and maximum resident set (MiB)
    section               the section of docs/performance.md that has the run, its command and its context

The summary is two Markdown tables: the runs of each kernel generation (how many, how many under the 10 minutes, the
median, the quickest and slowest, the peak memory) and, for the latest generation, the same machine by machine.

The goal tables at the front of docs/performance.md quote the summary's figures in their own words (the median, the
counts, the ranges); --check also asks that each of those quotations (QUOTATIONS below) read as the runs give it, so
that a run added to the file fails until the goal tables say so too. A doc whose goal tables word a figure otherwise
fails as well: the message gives the sentence to write.

    validation/bench/hectare_runs.py                       print the summary
    validation/bench/hectare_runs.py --write docs/performance.md
                                                           put it between the doc's two marker lines
    validation/bench/hectare_runs.py --check docs/performance.md
                                                           exit 1 if the doc's lines differ from it, or a quotation
                                                           of it in the goal tables does (CTest runs this)

A row that cannot be read (a field missing or malformed, a run out of order, a section the doc does not have) is an
error naming the file, line and field: exit 2, and nothing is written.
"""
import argparse
import csv
import datetime
import difflib
import math
import pathlib
import re
import statistics
import sys

HERE = pathlib.Path(__file__).resolve().parent
GOAL_SECONDS = 600.0  # issue 16: the hectare's 60 years in under 10 minutes
BEGIN = "<!-- validation/bench/hectare_runs.py writes the lines below from validation/bench/hectare_runs.csv -->"
END = "<!-- end of validation/bench/hectare_runs.py's lines -->"
COLUMNS = ["date", "time_utc", "machine_started", "code", "variant", "kernels", "same_tables", "wall_s", "peak_mib",
           "section"]
HEADING = re.compile(r"^#{1,6}\s+(.+?)\s*$")
FORMS = {"%Y": "YYYY", "%m": "MM", "%d": "DD", "%H": "HH", "%M": "MM"}  # strptime's codes as a reader writes them


class BadInput(Exception):
    """A runs file or a doc that cannot be read as one: its message names the file and line."""


class BadRow(Exception):
    """A field of a row that cannot be what its column holds: (field, reason)."""


def parse_date(text, what):
    try:
        return datetime.datetime.strptime(text, what)
    except ValueError:
        form = re.sub("%[YmdHM]", lambda m: FORMS[m.group()], what)
        raise BadRow(f"'{text}' is not of the form {form}") from None


def positive(text, kind, unit):
    try:
        value = kind(text)
    except ValueError:
        raise BadRow(f"'{text}' is not a number of {unit}") from None
    if not (value > 0 and math.isfinite(value)):
        raise BadRow(f"{text} {unit} is not a positive, finite amount")
    return value


def commit(text):
    if not re.fullmatch(r"[0-9a-f]{7,40}", text):
        raise BadRow(f"'{text}' is not a commit (7 to 40 hexadecimal digits)")
    return text


def not_empty(text):
    if not text.strip():
        raise BadRow("empty")
    return text


def machine_start(text):
    if text:
        parse_date(text, "%Y-%m-%d %H:%M")
    return text


def yes_or_no(text):
    if text not in ("yes", "no"):
        raise BadRow(f"'{text}' is neither yes nor no")
    return text == "yes"


def read_run(row, doc, headings):
    """One row as a run; raises BadRow(field, reason) for the first field that cannot be one."""
    def field(name, check):
        if row.get(name) is None:
            raise BadRow(name, "missing (the row has too few fields)")
        try:
            return check(row[name])
        except BadRow as reason:
            raise BadRow(name, str(reason)) from None

    def section(text):
        if not any(h == text or h.startswith(text + " (") for h in headings):
            raise BadRow(f"{doc} has no section \"{text}\"")
        return text

    return {
        "date": field("date", lambda t: parse_date(t, "%Y-%m-%d")),
        "time": field("time_utc", lambda t: parse_date(t, "%H:%M").time() if t else None),
        "machine_started": field("machine_started", machine_start),
        "code": field("code", commit),
        "kernels": field("kernels", not_empty),
        "same_tables": field("same_tables", yes_or_no),
        "wall_s": field("wall_s", lambda t: positive(t, float, "seconds")),
        "peak_mib": field("peak_mib", lambda t: positive(t, int, "MiB")),
        "section": field("section", section),
    }


def read_runs(path, doc):
    headings = [m.group(1) for line in doc.read_text(encoding="utf-8").splitlines() if (m := HEADING.match(line))]
    runs, last = [], None
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != COLUMNS:
            raise BadInput(f"{path}:1: the header must be {','.join(COLUMNS)}, not {','.join(reader.fieldnames or [])}")
        for row in reader:
            line = reader.line_num
            try:
                if None in row:
                    raise BadRow("section", "followed by more fields than the header has (a value with a comma "
                                 "needs quotes)")
                run = read_run(row, doc, headings)
            except BadRow as error:
                field, reason = error.args
                raise BadInput(f"{path}:{line}: field '{field}': {reason}") from None
            when = (run["date"], run["time"] or datetime.time.min)
            if last is not None and when < last:
                raise BadInput(f"{path}:{line}: field 'time_utc': the run is earlier than the row before it (rows "
                                 "are in the order the runs started)")
            last = when
            runs.append(run)
    if not runs:
        raise BadInput(f"{path}: no runs")
    return runs


def seconds(value):
    """One decimal, or two where a median of an even count needs them (659.1, 600.05)."""
    text = f"{value:.2f}"
    return text[:-1] if text.endswith("0") else text


def spaced(number):
    """Thousands apart by a space, as the docs write them (4 613 MiB)."""
    whole, point, fraction = str(number).partition(".")
    return f"{int(whole):,}".replace(",", " ") + point + fraction


def figures_of(runs):
    """The figures of a group of runs as the docs write them: how many, how many under the line, the median (and
    its share of the line), the quickest and slowest, the lowest and highest peak."""
    walls = sorted(r["wall_s"] for r in runs)
    peaks = [r["peak_mib"] for r in runs]
    median = statistics.median(walls)
    return {"runs": len(runs), "under": sum(w < GOAL_SECONDS for w in walls), "median": spaced(seconds(median)),
            "of_line": f"{median / GOAL_SECONDS:.2f}",
            "walls": f"{spaced(seconds(walls[0]))}–{spaced(seconds(walls[-1]))} s",
            "peaks": f"{spaced(min(peaks))}–{spaced(max(peaks))} MiB"}


def row_of(label, runs):
    f = figures_of(runs)
    return f"| {label} | {f['runs']} | {f['under']} | {f['median']} s ({f['of_line']}) | {f['walls']} | {f['peaks']} |"


def kept_runs(runs):
    """The runs that grew the same tables, their kernel generations in the order they first ran, and the runs of the
    latest generation ("today's kernels")."""
    kept = [r for r in runs if r["same_tables"]]
    generations = list(dict.fromkeys(r["kernels"] for r in kept))
    return kept, generations, [r for r in kept if r["kernels"] == generations[-1]]


def summary(runs):
    kept, generations, latest = kept_runs(runs)
    lines = ["| kernels | runs | under 10 min | median (of the line) | quickest–slowest | peak memory |",
             "|---|---:|---:|---:|---:|---:|"]
    for kernels in generations:
        lines.append(row_of(kernels, [r for r in kept if r["kernels"] == kernels]))
    if len(generations) > 1:
        lines.append(row_of("all", kept))
    lines += ["", f"With the latest kernels ({generations[-1]}), machine by machine:", "",
              "| machine started (UTC) | runs | under 10 min | median (of the line) | quickest–slowest "
              "| peak memory |",
              "|---|---:|---:|---:|---:|---:|"]
    for started in dict.fromkeys(r["machine_started"] for r in latest):
        machine = [r for r in latest if r["machine_started"] == started]
        days = sorted({r["date"].strftime("%Y-%m-%d") for r in machine})
        label = started or "not recorded (runs of " + (days[0] if len(days) == 1 else f"{days[0]} to {days[-1]}") + ")"
        lines.append(row_of(label, machine))
    left_out = len(runs) - len(kept)
    lines += ["", f"{len(runs)} runs in the file" + (
        f", {left_out} of them left out of these counts: their tables differ." if left_out else ".")]
    return lines


ONES = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
        "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
TENS = ["", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"]


def in_words(number):
    """A count as the docs' prose writes it (fifty-nine); counts of a hundred and more in digits."""
    if number < 20:
        return ONES[number]
    if number < 100:
        return TENS[number // 10] + ("-" + ONES[number % 10] if number % 10 else "")
    return spaced(number)


def runs_in_words(number):
    """"one run", "twenty runs": a count of runs as the prose writes it."""
    return f"{in_words(number)} run{'' if number == 1 else 's'}"


# Each quotation of the summary in docs/performance.md's goal tables: where it is, and what it must read, made from
# the figures of all kept runs (a) and of the latest kernels' runs (t, "today's kernels").
QUOTATIONS = [
    ("the front goal table's hectare row", lambda a, t:
        f"median **{t['median']} s** of the {t['runs']} runs with today's kernels ({t['walls']}; "
        f"{a['under']} of {a['runs']} runs in all under the line)"),
    ("the front goal table's hectare verdict", lambda a, t: f"({t['under']} of {t['runs']} runs;"),
    ("the front goal table's memory row", lambda a, t: f"| … and < 8 GiB | {a['peaks']} |"),
    ("\"The goal table in full\"'s paragraph", lambda a, t:
        f"it came under its line in {runs_in_words(t['under'])} of {in_words(t['runs'])} (a median of "
        f"{t['median']} s, {t['of_line']} of the line)"),
    ("\"The goal table in full\"'s hectare row", lambda a, t:
        f"**{a['walls']}** in {a['runs']} runs ({a['under']} under the line); with today's kernels {t['walls']}, a "
        f"median of {t['median']} s, {t['under']} of {t['runs']} under"),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t:
        f"**yes on the family-26 EPYC in {runs_in_words(a['under'])} of {a['runs']}** ("),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t:
        f"{in_words(t['under'])} of {t['runs']} with today's kernels"),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t: f"and **no** in {in_words(a['runs'] - a['under'])};"),
    ("\"The goal table in full\"'s memory row", lambda a, t: f"| — and < 8 GiB | {a['peaks']} |"),
    ("the detailed goal table's hectare row", lambda a, t:
        f"{a['runs']} runs that grew the same tables, each a row of `validation/bench/hectare_runs.csv`"),
    ("the detailed goal table's hectare row", lambda a, t:
        f"**{a['walls']}, {a['peaks']} peak**; with today's kernels {t['walls']}, a median of **{t['median']} s**"),
]


def unquoted(runs, text):
    """The quotations the doc's text does not hold as the runs give them: (where, what it should read). Prose is
    wrapped, so the text is read with its line breaks as spaces."""
    flat = " ".join(text.split("\n"))
    kept, _, latest = kept_runs(runs)
    every, today = figures_of(kept), figures_of(latest)
    return [(where, quote) for where, quote in ((w, q(every, today)) for w, q in QUOTATIONS) if quote not in flat]


def doc_block(text, path):
    lines = text.split("\n")
    if lines.count(BEGIN) != 1 or lines.count(END) != 1 or lines.index(BEGIN) > lines.index(END):
        raise BadInput(f"{path}: needs one line\n  {BEGIN}\nand after it one line\n  {END}")
    return lines, lines.index(BEGIN) + 1, lines.index(END)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=pathlib.Path, default=HERE / "hectare_runs.csv")
    parser.add_argument("--sections", type=pathlib.Path, default=HERE.parent.parent / "docs" / "performance.md",
                        help="the doc whose sections the runs name (default docs/performance.md)")
    action = parser.add_mutually_exclusive_group()
    action.add_argument("--write", type=pathlib.Path, metavar="DOC")
    action.add_argument("--check", type=pathlib.Path, metavar="DOC")
    args = parser.parse_args()
    try:
        return run(args)
    except OSError as error:
        print(f"{error.filename}: {error.strerror}", file=sys.stderr)
        return 2
    except BadInput as error:
        print(error, file=sys.stderr)
        return 2


def report_unquoted(doc, missing, runs_name):
    for where, quote in missing:
        print(f"{doc}: {where} does not read \"{quote}\", as {runs_name} gives it; write it there", file=sys.stderr)


def run(args):
    runs = read_runs(args.runs, args.sections)
    block = summary(runs)
    if not (args.write or args.check):
        print("\n".join(block))
        return 0
    doc = args.write or args.check
    text = doc.read_text(encoding="utf-8")
    lines, first, end = doc_block(text, doc)
    inner = [""] + block + [""]  # a blank line either side, so the tables stand apart from the markers
    missing = unquoted(runs, text)
    if args.check:
        failed = False
        if lines[first:end] == inner:
            print(f"{doc}: the summary of {len(block)} lines matches {args.runs.name}")
        else:
            failed = True
            print(f"{doc}: its summary of the hectare's runs differs from {args.runs.name}'s; run "
                  f"validation/bench/hectare_runs.py --write {doc}", file=sys.stderr)
            sys.stderr.writelines(line + "\n" for line in difflib.unified_diff(
                lines[first:end], inner, f"{doc} (lines {first + 1}-{end})", f"{args.runs.name} summarised",
                lineterm=""))
        if missing:
            failed = True
            report_unquoted(doc, missing, args.runs.name)
        else:
            print(f"{doc}: its goal tables quote the summary as {args.runs.name} gives it ({len(QUOTATIONS)} places)")
        return 1 if failed else 0
    lines[first:end] = inner
    temporary = doc.with_name(doc.name + ".tmp")
    temporary.write_text("\n".join(lines), encoding="utf-8")
    temporary.replace(doc)
    # the summary is written; the goal tables' words are the writer's to change, so they are only named here
    report_unquoted(doc, missing, args.runs.name)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Every run of issue 16's light goal on two cores, summarised (10⁶ leaf balls in ≤ 10 s, 10⁵ in ≤ 1 s).

The light goal's command (`heliostand bench light --balls 100000 --balls 1000000 ... --evaluations 3`,
docs/performance.md "Measuring again") times a solver's first solve, which lays out its tables and fetches its kernels,
and two later ones. A first solve's time moves with the hour and the machine, so whether it meets its line is a count
over runs. The runs are rows of validation/bench/light_runs.csv, one a size of one run of the command, in the order
they ran:

    date, time_utc        when the command ran (UTC; time empty where its section did not record it)
    machine_started       when the machine it ran on was started ("YYYY-MM-DD HH:MM" UTC), empty where not recorded
    cpu                   the kind of processor, as in hectare_runs.csv ("AMD EPYC family 26 model 2")
    code                  the commit the binary was built from
    variant               empty for that commit's own code; otherwise what was changed or set for the run
    kernels               which generation of the light kernels it ran, as in hectare_runs.csv
    kernel_cache          "warm", or "empty" where PoCL compiled the kernels in the first solve
    balls                 100000 or 1000000
    first_s               the first solve's seconds, setup included
    later_s               the later solves' seconds, apart by a space (empty where the section gives only a range)
    section               the section of docs/performance.md that has the run, its command and its context

The variants, measured beside a commit's own code for their time, are counted apart from it: some (malloc's huge pages)
move a first solve's time, and a user runs the commit's own code. The summary is two Markdown tables for each kind of
processor, summarised apart as in hectare_runs.py: the first and later solves of each size, kernel generation, own
code or variant and kernel cache (how many, how many over the line, the median, the quickest and slowest), and the
commits' own first solves into a warm cache with the latest kernels machine by machine. The goal tables quote it: the
family-26 EPYC's counts in their sentences (QUOTATIONS below), every other kind's ranges in its column of both tables
(columns_cells); --check asks that they read as the runs give it.

`validation/bench/light_runs.py` prints the summary, `--write docs/performance.md` puts it into the doc and brings the
goal tables' quotations of it along, and `--check docs/performance.md` checks the doc against it (CTest runs this);
`--help` says more (runs_file.USAGE).
"""
import decimal
import statistics
import sys
import textwrap

from runs_file import (BadRow, Summary, by_machine, command, field_of, generations_in, in_words, kind_by_kind,
                       machine_label, one_of, positive, quoted_kind_by_kind, when_and_what)

GOAL_SECONDS = {100000: 1.0, 1000000: 10.0}  # issue 16: 10⁵ leaf balls in ≤ 1 s, 10⁶ in ≤ 10 s
SIZES = {100000: "10⁵", 1000000: "10⁶"}
BEGIN = "<!-- validation/bench/light_runs.py writes the lines below from validation/bench/light_runs.csv -->"
END = "<!-- end of validation/bench/light_runs.py's lines -->"
SUMMARY = Summary(BEGIN, END, "the light goal's runs")
COLUMNS = ["date", "time_utc", "machine_started", "cpu", "code", "variant", "kernels", "kernel_cache", "balls",
           "first_s", "later_s", "section"]


def balls(text):
    if text not in ("100000", "1000000"):
        raise BadRow(f"'{text}' is not a size of the light goal (100000 or 1000000)")
    return int(text)


def solve(text):
    """A solve's seconds as written (the docs keep the digits measured: 0.91, 1.092), and as a number."""
    return text, positive(text, float, "seconds")


def later_solves(text):
    return [solve(t) for t in text.split()]


def read_run(row, section):
    """One row as a run; raises BadRow(field, reason) for the first field that cannot be one."""
    return when_and_what(row) | {
        "kernel_cache": field_of(row, "kernel_cache", one_of("warm", "empty")),
        "balls": field_of(row, "balls", balls),
        "first": field_of(row, "first_s", solve),
        "later": field_of(row, "later_s", later_solves),
        "section": field_of(row, "section", section),
    }


def seconds(value):
    """Three decimals, as the light rows write a solve (1.092 s; a median of an even count rounded to them)."""
    return f"{value:.3f}"


def figures_of(solves, size):
    """How many solves, how many over the size's line, the median (and its share of the line), and the quickest and
    the slowest as written."""
    line = GOAL_SECONDS[size]
    ordered = sorted(solves, key=lambda s: s[1])
    if not ordered:
        return {"solves": 0, "over": 0, "median": "—", "of_line": "—", "range": "—"}
    median = statistics.median(s[1] for s in ordered)
    return {"solves": len(ordered), "over": sum(s[1] > line for s in ordered), "median": seconds(median),
            "of_line": f"{median / line:.2f}",
            "range": f"{ordered[0][0]}–{ordered[-1][0]} s" if len(ordered) > 1 else f"{ordered[0][0]} s"}


def firsts(runs):
    return [r["first"] for r in runs]


def laters(runs):
    return [s for r in runs for s in r["later"]]


OWN, VARIANTS = "the commit's own code", "variants beside it"


def of_code(runs, which):
    """The runs of the commits' own code, or of the variants measured beside them."""
    return [r for r in runs if bool(r["variant"]) == (which == VARIANTS)]


def kind_summary(runs):
    """One kind of processor's two tables: every solve by size, kernels, code and kernel cache, and its commits' own
    first solves into a warm cache with its latest kernels machine by machine."""
    generations, latest = generations_in(runs)
    lines = ["| balls | kernels | code | kernel cache | first solves | over the line | median (of the line) "
             "| quickest–slowest | later solves given one by one | over the line | quickest–slowest |",
             "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for size in SIZES:
        for kernels in generations:
            for which in (OWN, VARIANTS):
                for cache in ("warm", "empty"):
                    group = [r for r in of_code(runs, which)
                             if r["balls"] == size and r["kernels"] == kernels and r["kernel_cache"] == cache]
                    if group:
                        f, g = figures_of(firsts(group), size), figures_of(laters(group), size)
                        lines.append(f"| {SIZES[size]} | {kernels} | {which} | {cache} | {f['solves']} | {f['over']} "
                                     f"| {f['median']} s ({f['of_line']}) | {f['range']} | {g['solves']} | "
                                     f"{g['over']} | {g['range']} |")
    lines += [""] + textwrap.wrap(f"First solves of the commits' own code into a warm kernel cache with the latest "
                                  f"kernels ({generations[-1]}), machine by machine:", 120) + ["",
              "| machine started (UTC) | 10⁵: first solves | over 1 s | median | quickest–slowest "
              "| 10⁶: first solves | over 10 s | median | quickest–slowest |",
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    warm = [r for r in of_code(latest, OWN) if r["kernel_cache"] == "warm"]
    for started, machine in by_machine(warm):
        cells = []
        for size in SIZES:
            f = figures_of(firsts([r for r in machine if r["balls"] == size]), size)
            cells += [str(f["solves"]), str(f["over"]), f"{f['median']} s" if f["solves"] else "—", f["range"]]
        lines.append(f"| {machine_label(started, machine)} | " + " | ".join(cells) + " |")
    return lines


def summary(runs):
    lines = kind_by_kind(runs, kind_summary)
    lines += [f"{len(runs)} rows in the file, a size of one run of the command each; "
              f"{len(of_code(runs, VARIANTS))} of them a variant's."]
    return lines


def of_runs(number):
    """"43 runs", "1 run": a count of runs in digits, as the goal tables write the larger counts."""
    return f"{number} run{'' if number == 1 else 's'}"


def over_of(figures):
    """"eleven of eighteen", "all three", "none of two": how many of a machine's first solves were over the line."""
    over, solves = figures["over"], figures["solves"]
    if over == solves and solves > 1:
        return f"all {in_words(solves)}"
    return f"{'none' if over == 0 else in_words(over)} of {in_words(solves)}"


def machine_by_machine(warm):
    """The first 10⁵ solves over the line machine by machine, in the order the machines first ran them: "five of eight
    on the machine started 2026-12-02 16:05, one of two on machines whose start was not recorded, ..."."""
    parts = []
    for started, machine in by_machine([r for r in warm if r["balls"] == 100000]):
        f = figures_of(firsts(machine), 100000)
        where = f"on the machine started {started}" if started else "on machines whose start was not recorded"
        parts.append(f"{over_of(f)} {where}")
    return ", ".join(parts)


# Each quotation of the summary in docs/performance.md's goal tables: where it is, and what it must read, made from
# the figures of the commits' own first solves into a warm cache with the latest kernels, at 10⁵ (f5) and 10⁶ (f6), and
# those at 10⁵ machine by machine (machines).
QUOTATIONS = [
    ("the front goal table's 10⁵ light row", lambda f5, f6, machines:
        f"first 10⁵ solve into a warm kernel cache over its line in {in_words(f5['over'])} of {of_runs(f5['solves'])} "
        f"with today's kernels (median {f5['median']} s; {machines})"),
    ("the front goal table's 10⁶ light row", lambda f5, f6, machines:
        f"first 10⁶ solve over its line in {in_words(f6['over'])} of {of_runs(f6['solves'])}"),
]


def hundredths(solves):
    """The quickest and slowest of some solves to two decimals, as the goal tables' columns write them ("0.66–0.72"),
    rounded half up from the digits measured (4.905 s is 4.91)."""
    ends = [min(solves, key=lambda s: s[1])[0], max(solves, key=lambda s: s[1])[0]]
    low, high = (str(decimal.Decimal(e).quantize(decimal.Decimal("0.01"), decimal.ROUND_HALF_UP)) for e in ends)
    return low if low == high else f"{low}–{high}"


def columns_cells(runs):
    """Another kind's cells in both goal tables: at 10⁶ its later solves (first solves), at 10⁵ the same, its first
    solves into a warm kernel cache, and those into an empty one named apart; the commits' own code, latest kernels."""
    _, latest = generations_in(runs)
    own = of_code(latest, OWN)
    of_size = {size: [r for r in own if r["balls"] == size] for size in SIZES}
    million, hundred_thousand = of_size[1000000], of_size[100000]
    cells = {}
    if million and laters(million):
        cells[1000000] = f"| {hundredths(laters(million))} s (first {hundredths(firsts(million))} s) |"
    warm = [r for r in hundred_thousand if r["kernel_cache"] == "warm"]
    empty = [r for r in hundred_thousand if r["kernel_cache"] == "empty"]
    if warm and laters(hundred_thousand):
        cells[100000] = f"| {hundredths(laters(hundred_thousand))} s (first {hundredths(firsts(warm))} s" + (
            f"; {hundredths(firsts(empty))} s into an empty kernel cache" if empty else "") + ") |"
    return cells


def in_sentences(runs):
    """Each of QUOTATIONS for the family-26 EPYC's runs: its commits' own first solves into a warm cache with its
    latest kernels."""
    _, latest = generations_in(runs)
    warm = [r for r in of_code(latest, OWN) if r["kernel_cache"] == "warm"]
    f5, f6 = (figures_of(firsts([r for r in warm if r["balls"] == size]), size) for size in SIZES)
    return [(where, quote(f5, f6, machine_by_machine(warm))) for where, quote in QUOTATIONS]


def in_its_column(runs):
    """Another kind's cells, each in both goal tables."""
    return [(f"{table}'s {SIZES[size]} light row", cell) for size, cell in columns_cells(runs).items()
            for table in ("the front goal table", "\"The goal table in full\"")]


def quotations(runs):
    """Each of QUOTATIONS, for the family-26 EPYC's runs, and each other kind's cells in its column of both goal
    tables, as (where, what it must read)."""
    return quoted_kind_by_kind(runs, in_sentences, in_its_column)


if __name__ == "__main__":
    sys.exit(command(__doc__, "light_runs.csv", COLUMNS, read_run, summary, quotations, SUMMARY))

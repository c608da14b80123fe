#!/usr/bin/env python3
"""Every run of issue 16's goal hectare on two cores, summarised (issue 16: under 10 minutes and 8 GiB).

The hectare (validation/bench/stands/hectare_60_years.toml, `heliostand bench stand ... --tables T`) has been grown
on 2-core machines many times, in quick hours and slow ones, on machines started anew, with main's code and with
variants measured beside it. Whether it meets its 10 minutes depends on the hour and the machine, so the verdict is a
count and a median over runs, not one run. The runs are rows of validation/bench/hectare_runs.csv, one a run, in the
order they ran:

    date, time_utc        when the run started (UTC; time empty where its section did not record it)
    machine_started       when the machine it ran on was started ("YYYY-MM-DD HH:MM" UTC), empty where not recorded
    cpu                   the kind of processor, as the benchmark's JSON names it ("AMD EPYC family 26 model 2")
    code                  the commit the binary was built from
    variant               empty for that commit's own code; otherwise what was changed or set for the run
    kernels               which generation of the light kernels it ran, one of runs_file.KERNEL_GENERATIONS (the
                          floor and ceil of 2026-12-02 changed every later run's time by 0.89-0.94, so the verdict
                          counts the runs of a kind's latest generation, whatever the order of its rows)
    same_tables           "yes" if it grew the stand, tree and event tables of every hectare since 2026-11-28
                          byte for byte; "no" for a variant whose answer differs (left out of the summary)
    wall_s, peak_mib      GNU time's wall seconds and maximum resident set (MiB)
    section               the section of docs/performance.md that has the run, its command and its context

The summary is two Markdown tables for each kind of processor: its runs of each kernel generation (how many, how many
under the 10 minutes, the median, the quickest and slowest, the peak memory) and, for its latest generation, the same
machine by machine. Kinds are summarised apart because the kind sets the pace: one kind's median with today's kernels
is 1.11 of the line, another's 0.94.

The goal tables at the front of docs/performance.md quote the summary's figures in their own words (the median, the
counts, the ranges): the family-26 EPYC's, the kind measured most, in its sentences (QUOTATIONS), and every other
kind's in its column of both goal tables (KIND_QUOTATIONS); --check also asks that each of those quotations read as
the runs give it, so that a run added to the file fails until the goal tables say so too. A doc whose goal tables
word a figure otherwise fails as well: the message gives the sentence to write.

`validation/bench/hectare_runs.py` prints the summary, `--write docs/performance.md` puts it into the doc and brings the
goal tables' quotations of it along, and `--check docs/performance.md` checks the doc against it (CTest runs this);
`--help` says more (runs_file.USAGE).
"""
import statistics
import sys

from runs_file import (Summary, by_machine, command, counted, field_of, generations_in, in_words, kind_by_kind,
                       machine_label, one_of, positive, quoted_kind_by_kind, spaced, when_and_what)

GOAL_SECONDS = 600.0  # issue 16: the hectare's 60 years in under 10 minutes
BEGIN = "<!-- validation/bench/hectare_runs.py writes the lines below from validation/bench/hectare_runs.csv -->"
END = "<!-- end of validation/bench/hectare_runs.py's lines -->"
SUMMARY = Summary(BEGIN, END, "the hectare's runs")
COLUMNS = ["date", "time_utc", "machine_started", "cpu", "code", "variant", "kernels", "same_tables", "wall_s",
           "peak_mib", "section"]


def read_run(row, section):
    """One row as a run; raises BadRow(field, reason) for the first field that cannot be one."""
    return when_and_what(row) | {
        "same_tables": field_of(row, "same_tables", one_of("yes", "no")) == "yes",
        "wall_s": field_of(row, "wall_s", lambda t: positive(t, float, "seconds")),
        "peak_mib": field_of(row, "peak_mib", lambda t: positive(t, int, "MiB")),
        "section": field_of(row, "section", section),
    }


def seconds(value):
    """One decimal, or two where a median of an even count needs them (659.1, 600.05)."""
    text = f"{value:.2f}"
    return text[:-1] if text.endswith("0") else text


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
    """The runs that grew the same tables, their kernel generations oldest first, and the runs of the latest
    generation ("today's kernels")."""
    kept = [r for r in runs if r["same_tables"]]
    return (kept, *generations_in(kept))


def kind_summary(runs):
    """One kind of processor's two tables: its runs by kernel generation, and its latest generation's machine by
    machine."""
    kept, generations, latest = kept_runs(runs)
    if not kept:
        return ["None of its runs grew the same tables."]
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
    for started, machine in by_machine(latest):
        lines.append(row_of(machine_label(started, machine), machine))
    return lines


def summary(runs):
    lines = kind_by_kind(runs, kind_summary)
    left_out = sum(not r["same_tables"] for r in runs)
    lines += [f"{len(runs)} runs in the file" + (
        f", {left_out} of them left out of these counts: their tables differ." if left_out else ".")]
    return lines


# Each quotation of the summary in docs/performance.md's goal tables: where it is, and what it must read, made from
# the figures of all kept runs (a) and of the latest kernels' runs (t, "today's kernels").
QUOTATIONS = [
    ("the front goal table's hectare row", lambda a, t:
        f"median **{t['median']} s** of the {t['runs']} runs with today's kernels ({t['walls']}; "
        f"{a['under']} of {a['runs']} runs in all under the line)"),
    ("the front goal table's hectare verdict", lambda a, t: f"({t['under']} of {t['runs']} runs;"),
    ("the front goal table's memory row", lambda a, t: f"| … and < 8 GiB | {a['peaks']} |"),
    ("\"The goal table in full\"'s paragraph", lambda a, t:
        f"it came under its line in {counted(t['under'], 'run')} of {in_words(t['runs'])} (a median of "
        f"{t['median']} s, {t['of_line']} of the line)"),
    ("\"The goal table in full\"'s hectare row", lambda a, t:
        f"**{a['walls']}** in {a['runs']} runs ({a['under']} under the line); with today's kernels {t['walls']}, a "
        f"median of {t['median']} s, {t['under']} of {t['runs']} under"),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t:
        f"**yes on the family-26 EPYC in {counted(a['under'], 'run')} of {a['runs']}** ("),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t:
        f"{in_words(t['under'])} of {t['runs']} with today's kernels"),
    ("\"The goal table in full\"'s hectare verdict", lambda a, t: f"and **no** in {in_words(a['runs'] - a['under'])};"),
    ("\"The goal table in full\"'s memory row", lambda a, t: f"| — and < 8 GiB | {a['peaks']} |"),
    ("the detailed goal table's hectare row", lambda a, t:
        f"{a['runs']} runs that grew the same tables, each a row of `validation/bench/hectare_runs.csv`"),
    ("the detailed goal table's hectare row", lambda a, t:
        f"**{a['walls']}, {a['peaks']} peak**; with today's kernels {t['walls']}, a median of **{t['median']} s**"),
    ("the detailed goal table's hectare verdict", lambda a, t:
        f"**yes on the family-26 EPYC** in {counted(a['under'], 'run')} of {a['runs']} ("),
    ("the detailed goal table's hectare verdict", lambda a, t:
        f"in {in_words(t['under'])} of {t['runs']} with floor and ceil as instructions), **no** in "
        f"{in_words(a['runs'] - a['under'])}:"),
]


def under_the_line(figures):
    """"all under the line", "none under the line", "two under the line"."""
    under, runs = figures["under"], figures["runs"]
    return f"{'all' if under == runs else 'none' if under == 0 else in_words(under)} under the line"


# Each quotation of another kind's figures, in that kind's column of both goal tables (t: its latest kernels' runs).
KIND_QUOTATIONS = [
    ("the front goal table's hectare row", lambda t: f"| **{t['walls']}** in {counted(t['runs'], 'run')}, "
                                                     f"{under_the_line(t)} |"),
    ("\"The goal table in full\"'s hectare row", lambda t: f"| **{t['walls']}** in {t['runs']} run"
                                                           f"{'' if t['runs'] == 1 else 's'}, {under_the_line(t)} |"),
    ("the front goal table's memory row", lambda t: f"| {t['peaks']} |"),
    ("\"The goal table in full\"'s memory row", lambda t: f"| {t['peaks']} |"),
]


def in_sentences(runs):
    """Each of QUOTATIONS for the family-26 EPYC's runs (none where no run grew the same tables)."""
    kept, _, latest = kept_runs(runs)
    if not kept:
        return []
    every, today = figures_of(kept), figures_of(latest)
    return [(where, quote(every, today)) for where, quote in QUOTATIONS]


def in_its_column(runs):
    """Each of KIND_QUOTATIONS for another kind's runs (none where no run grew the same tables)."""
    kept, _, latest = kept_runs(runs)
    if not kept:
        return []
    today = figures_of(latest)
    return [(where, quote(today)) for where, quote in KIND_QUOTATIONS]


def quotations(runs):
    """Each of QUOTATIONS, for the family-26 EPYC's runs, and of KIND_QUOTATIONS, for each other kind's, as (where,
    what it must read)."""
    return quoted_kind_by_kind(runs, in_sentences, in_its_column)


if __name__ == "__main__":
    sys.exit(command(__doc__, "hectare_runs.csv", COLUMNS, read_run, summary, quotations, SUMMARY))

"""A file of measured runs and the summary of it that docs/performance.md holds (issue 16).

Issue 16's goals are timed on 2-core machines whose speed moves with the hour and the machine, so a verdict is a count
over runs, not one run. The runs of a goal are rows of a CSV file, one a run, in the order they ran; a script
(hectare_runs.py, light_runs.py) reads them, writes their summary between two marker lines of the doc, and checks that
the summary there and the goal tables' quotations of it still read as the runs give them. This module is what those
scripts share: reading the rows (each field checked, errors naming the file, line and field), writing numbers as the
docs do, and the summary's place in the doc.
"""
import argparse
import csv
import datetime
import difflib
import math
import pathlib
import re
import sys

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


def one_of(*allowed):
    def check(text):
        if text not in allowed:
            raise BadRow(f"'{text}' is not one of {', '.join(allowed)}")
        return text
    return check


def start_time(text):
    """A run's time of day (HH:MM, UTC), or None where its section did not record it."""
    return parse_date(text, "%H:%M").time() if text else None


def section_in(doc, headings):
    """The check of a `section` field: the doc must have a heading of that text (a date in brackets after it)."""
    def check(text):
        if not any(h == text or h.startswith(text + " (") for h in headings):
            raise BadRow(f"{doc} has no section \"{text}\"")
        return text
    return check


def when_and_what(row):
    """The fields every runs file begins with, read: when the run started, on which machine, the commit, any variant,
    the kernel generation."""
    return {
        "date": field_of(row, "date", lambda t: parse_date(t, "%Y-%m-%d")),
        "time": field_of(row, "time_utc", start_time),
        "machine_started": field_of(row, "machine_started", machine_start),
        "code": field_of(row, "code", commit),
        "variant": field_of(row, "variant", str),
        "kernels": field_of(row, "kernels", not_empty),
    }


def field_of(row, name, check):
    """The value of `name` in a CSV row read by `check`; raises BadRow(field, reason) where it cannot be one."""
    if row.get(name) is None:
        raise BadRow(name, "missing (the row has too few fields)")
    try:
        return check(row[name])
    except BadRow as reason:
        raise BadRow(name, str(reason)) from None


def read_rows(path, doc, columns, read_run):
    """The runs of a CSV file whose header is `columns`, each row read by read_run(row, section_check), in the order
    they started (a row without a time keeps its place among its date's)."""
    headings = [m.group(1) for line in doc.read_text(encoding="utf-8").splitlines() if (m := HEADING.match(line))]
    section = section_in(doc, headings)
    runs, last = [], None
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != columns:
            raise BadInput(f"{path}:1: the header must be {','.join(columns)}, not {','.join(reader.fieldnames or [])}")
        for row in reader:
            line = reader.line_num
            try:
                if None in row:
                    raise BadRow(columns[-1], "followed by more fields than the header has (a value with a comma "
                                 "needs quotes)")
                run = read_run(row, section)
            except BadRow as error:
                field, reason = error.args
                raise BadInput(f"{path}:{line}: field '{field}': {reason}") from None
            # a run without a time ran after the row before it on its date: only its date is compared
            when = (run["date"], run["time"] or (last[1] if last and last[0] == run["date"] else datetime.time.min))
            if last is not None and when < last:
                raise BadInput(f"{path}:{line}: field 'time_utc': the run is earlier than the row before it (rows "
                               "are in the order the runs started)")
            last = when
            runs.append(run)
    if not runs:
        raise BadInput(f"{path}: no runs")
    return runs


def spaced(number):
    """Thousands apart by a space, as the docs write them (4 613 MiB)."""
    whole, point, fraction = str(number).partition(".")
    return f"{int(whole):,}".replace(",", " ") + point + fraction


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


def counted(number, noun):
    """"one run", "twenty runs": a count of things as the prose writes it."""
    return f"{in_words(number)} {noun}{'' if number == 1 else 's'}"


def unquoted(quotations, text):
    """The quotations, (where, what it must read), that the doc's text does not hold. Prose is wrapped, so the text
    is read with its line breaks as spaces."""
    flat = " ".join(text.split("\n"))
    return [(where, quote) for where, quote in quotations if quote not in flat]


class Summary:
    """A summary's place in a doc: the lines between `begin` and `end`, which `--write` replaces and `--check`
    compares, and the goal tables' quotations of it, which `--write` names and `--check` asks for."""

    def __init__(self, begin, end, what):
        self.begin, self.end, self.what = begin, end, what

    def block(self, text, path):
        lines = text.split("\n")
        if lines.count(self.begin) != 1 or lines.count(self.end) != 1 or \
                lines.index(self.begin) > lines.index(self.end):
            raise BadInput(f"{path}: needs one line\n  {self.begin}\nand after it one line\n  {self.end}")
        return lines, lines.index(self.begin) + 1, lines.index(self.end)

    def report_unquoted(self, doc, missing, runs_name):
        for where, quote in missing:
            print(f"{doc}: {where} does not read \"{quote}\", as {runs_name} gives it; write it there",
                  file=sys.stderr)

    def write_or_check(self, args, block, quotations, script):
        """Print the summary, or write it into args.write, or check args.check against it; the exit status."""
        if not (args.write or args.check):
            print("\n".join(block))
            return 0
        doc = args.write or args.check
        text = doc.read_text(encoding="utf-8")
        lines, first, end = self.block(text, doc)
        inner = [""] + block + [""]  # a blank line either side, so the tables stand apart from the markers
        missing = unquoted(quotations, text)
        if args.check:
            failed = False
            if lines[first:end] == inner:
                print(f"{doc}: the summary of {len(block)} lines matches {args.runs.name}")
            else:
                failed = True
                print(f"{doc}: its summary of {self.what} differs from {args.runs.name}'s; run {script} --write {doc}",
                      file=sys.stderr)
                sys.stderr.writelines(line + "\n" for line in difflib.unified_diff(
                    lines[first:end], inner, f"{doc} (lines {first + 1}-{end})", f"{args.runs.name} summarised",
                    lineterm=""))
            if missing:
                failed = True
                self.report_unquoted(doc, missing, args.runs.name)
            else:
                print(f"{doc}: its goal tables quote the summary as {args.runs.name} gives it "
                      f"({len(quotations)} places)")
            return 1 if failed else 0
        lines[first:end] = inner
        temporary = doc.with_name(doc.name + ".tmp")
        temporary.write_text("\n".join(lines), encoding="utf-8")
        temporary.replace(doc)
        # the summary is written; the goal tables' words are the writer's to change, so they are only named here
        self.report_unquoted(doc, missing, args.runs.name)
        return 0


def exit_status(run, args):
    """run(args)'s status, or 2 with the reason where a file cannot be read or is not what it should be."""
    try:
        return run(args)
    except OSError as error:
        print(f"{error.filename}: {error.strerror}", file=sys.stderr)
        return 2
    except BadInput as error:
        print(error, file=sys.stderr)
        return 2


USAGE = """\
    {script}                print the summary
    {script} --write DOC    put it between DOC's two marker lines (docs/performance.md)
    {script} --check DOC    exit 1 if DOC's lines differ from it, or a quotation of it in
    {script_blank}                the goal tables does (CTest runs this)

A row that cannot be read (a field missing or malformed, a run out of order, a section the doc does not have) is an
error naming the file, line and field: exit 2, and nothing is written."""


def arguments(description, runs, docs, script):
    """The command line both scripts take: the runs file, the doc whose sections the runs name, and --write DOC or
    --check DOC; --help shows what each does (USAGE)."""
    usage = USAGE.format(script=script, script_blank=" " * len(script))
    parser = argparse.ArgumentParser(description=description, epilog=usage,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=pathlib.Path, default=runs)
    parser.add_argument("--sections", type=pathlib.Path, default=docs,
                        help="the doc whose sections the runs name (default docs/performance.md)")
    action = parser.add_mutually_exclusive_group()
    action.add_argument("--write", type=pathlib.Path, metavar="DOC")
    action.add_argument("--check", type=pathlib.Path, metavar="DOC")
    return parser.parse_args()


def command(doc, runs_name, columns, read_run, summary, quotations, summary_place):
    """A runs script's whole command line (the exit status): the runs of validation/bench/RUNS_NAME read by read_run,
    their summary (a list of lines) and its quotations ((where, what it must read)) printed, written or checked."""
    here = pathlib.Path(__file__).resolve().parent
    script = "validation/bench/" + pathlib.Path(runs_name).stem + ".py"

    def run(args):
        runs = read_rows(args.runs, args.sections, columns, read_run)
        return summary_place.write_or_check(args, summary(runs), quotations(runs), script)
    docs = here.parent.parent / "docs" / "performance.md"
    return exit_status(run, arguments(doc.split("\n")[0], here / runs_name, docs, script))

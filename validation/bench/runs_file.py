"""A file of measured runs and the summary of it that docs/performance.md holds (issue 16).

Issue 16's goals are timed on 2-core machines whose speed moves with the hour and the machine, so a verdict is a count
over runs, not one run. The runs of a goal are rows of a CSV file, one a run, in the order they ran; a script
(hectare_runs.py, light_runs.py) reads them, writes their summary between two marker lines of the doc, and checks that
the summary there and the goal tables' quotations of it still read as the runs give them. This module is what those
scripts share: reading the rows (each field checked, errors naming the file, line and field), writing numbers as the
docs do, the summary's place in the doc, and bringing the goal tables' quotations along when runs are added: each
found as the runs the doc was last written from gave it, and made to read as the runs give it now.
"""
import argparse
import csv
import datetime
import difflib
import io
import math
import pathlib
import re
import subprocess
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


def machine_start(text):
    if text:
        parse_date(text, "%Y-%m-%d %H:%M")
    return text


PROCESSOR = re.compile(r"(\S.*?) family (\d+) model (\d+)")


def processor(text):
    """The kind of processor a run ran on, as its benchmark JSON names it: "AMD EPYC family 26 model 2". The speed of
    these machines is a matter of their kind (two kinds of 2-core machine took 0.94 and 1.11 of the hectare's line at
    their medians), so each kind's runs are summarised apart."""
    if not PROCESSOR.fullmatch(text):
        raise BadRow(f"'{text}' is not a processor written as NAME family N model N (AMD EPYC family 26 model 2)")
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


# The generations of the light kernels that runs ran, oldest first. A kind's verdicts count the runs of the latest
# generation it has run ("today's kernels") whatever the order of its rows: an older commit measured beside today's, as
# a side by side does, is a row after today's. A run of kernels not named here is an error, so that a misspelt
# generation cannot pass for a new one; a new generation is added at the end.
KERNEL_GENERATIONS = (
    "library floor and ceil",          # until 2026-12-02: PoCL's floor and ceil, a dozen vector instructions each
    "floor and ceil as instructions",  # from 2026-12-02 (cl/rounding.clh): one each, the hectare 0.89-0.94 of the time
)


def kernel_generation(text):
    if text not in KERNEL_GENERATIONS:
        named = ", ".join(f'"{g}"' for g in KERNEL_GENERATIONS)
        raise BadRow(f"'{text}' is not a generation of the light kernels named in runs_file.py's KERNEL_GENERATIONS "
                     f"({named}; a new one is added there)")
    return text


def generations_in(runs):
    """The kernel generations the runs ran, oldest first, and the runs of the latest of them ("today's kernels")."""
    generations = [g for g in KERNEL_GENERATIONS if any(r["kernels"] == g for r in runs)]
    return generations, [r for r in runs if r["kernels"] == generations[-1]]


def when_and_what(row):
    """The fields every runs file begins with, read: when the run started, on which machine and kind of processor, the
    commit, any variant, the kernel generation."""
    return {
        "date": field_of(row, "date", lambda t: parse_date(t, "%Y-%m-%d")),
        "time": field_of(row, "time_utc", start_time),
        "machine_started": field_of(row, "machine_started", machine_start),
        "cpu": field_of(row, "cpu", processor),
        "code": field_of(row, "code", commit),
        "variant": field_of(row, "variant", str),
        "kernels": field_of(row, "kernels", kernel_generation),
    }


def field_of(row, name, check):
    """The value of `name` in a CSV row read by `check`; raises BadRow(field, reason) where it cannot be one."""
    if row.get(name) is None:
        raise BadRow(name, "missing (the row has too few fields)")
    try:
        return check(row[name])
    except BadRow as reason:
        raise BadRow(name, str(reason)) from None


def read_rows(path, doc, columns, read_run, text=None):
    """The runs of a CSV file whose header is `columns`, each row read by read_run(row, section_check), in the order
    they started (a row without a time keeps its place among its date's). `text` is the file's, where it is not read
    from `path` (a committed version of it): `path` then only names it in errors."""
    headings = [m.group(1) for line in doc.read_text(encoding="utf-8").splitlines() if (m := HEADING.match(line))]
    section = section_in(doc, headings)
    runs, last = [], None
    with (open(path, newline="", encoding="utf-8") if text is None else io.StringIO(text, newline="")) as f:
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


def by_machine(runs):
    """The runs, (when the machine was started, its runs), machine by machine in the order the machines first ran."""
    return [(started, [r for r in runs if r["machine_started"] == started])
            for started in dict.fromkeys(r["machine_started"] for r in runs)]


def by_kind(runs):
    """The runs, (kind of processor, its runs), kind by kind in the order the kinds first ran."""
    return [(cpu, [r for r in runs if r["cpu"] == cpu]) for cpu in dict.fromkeys(r["cpu"] for r in runs)]


def kind_by_kind(runs, kind_summary):
    """A summary's lines for runs of one or more kinds of processor: kind_summary(its runs) for each kind, under the
    kind's name where there are several, a blank line after each."""
    kinds = by_kind(runs)
    lines = []
    for cpu, of_kind in kinds:
        if len(kinds) > 1:
            lines += [f"On the 2-core {kind_label(cpu)}:", ""]
        lines += kind_summary(of_kind) + [""]
    return lines


def kind_label(cpu):
    """A kind of processor as the docs name it: "AMD EPYC of CPU family 26, model 2"."""
    name, family, model = PROCESSOR.fullmatch(cpu).groups()
    return f"{name} of CPU family {family}, model {model}"


FAMILY_26 = "AMD EPYC family 26 model 2"  # the kind measured most, whose figures the goal tables' sentences quote


def quoted_kind_by_kind(runs, in_sentences, in_its_column):
    """The goal tables' quotations, (where, what it must read), of runs of one or more kinds of processor:
    in_sentences(its runs) for the family-26 EPYC, whose figures the tables' sentences quote, and in_its_column(its
    runs) for each other kind, each place named as that kind's column."""
    found = []
    for cpu, of_kind in by_kind(runs):
        if cpu == FAMILY_26:
            found += in_sentences(of_kind)
        else:
            found += [(f"{where}, the {kind_label(cpu)}'s column", quote) for where, quote in in_its_column(of_kind)]
    return found


def machine_label(started, runs):
    """A machine's row in a summary: when it was started, or the days of its runs where that was not recorded."""
    days = sorted({r["date"].strftime("%Y-%m-%d") for r in runs})
    return started or "not recorded (runs of " + (days[0] if len(days) == 1 else f"{days[0]} to {days[-1]}") + ")"


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


def as_prose_holds_it(quote):
    """A pattern for a quotation as the doc's prose holds it: prose is wrapped, so each space of the quotation may be
    a line break and the next line's indent."""
    return re.compile(r"(?: |\n *)".join(re.escape(word) for word in quote.split(" ")))


def places_of(quotations):
    """The quotations' words, each with the places that must read them, in the order first listed: a figure the goal
    tables write in two places (one kind of machine's column in both) is listed once for each."""
    places = {}
    for where, quote in quotations:
        places.setdefault(quote, []).append(where)
    return places


def unquoted(quotations, text):
    """The quotations, (where, what it must read), that the doc's text does not hold: words listed for n places that
    the text reads in fewer are named at each of their places."""
    missing = []
    for quote, wheres in places_of(quotations).items():
        found = len(as_prose_holds_it(quote).findall(text))
        if found < len(wheres):
            places = in_words(len(wheres))
            named = [where if len(wheres) == 1 else f"{where} (one of {places} places that must read it; the doc "
                     f"reads it in {in_words(found)})" for where in wheres]
            missing += [(where, quote) for where in named]
    return missing


def with_breaks_of(held, quote):
    """`quote` with the line breaks that `held` (an old quotation as the doc held it) had: each after the same word,
    or after the last word but one where the new quotation is shorter."""
    separators = re.findall(r" |\n *", held)
    words = quote.split(" ")
    breaks = {min(i, len(words) - 2): s for i, s in enumerate(separators) if s != " "}
    return words[0] + "".join(breaks.get(i, " ") + word for i, word in enumerate(words[1:]))


LINE_LIMIT = 120  # the docs' prose is wrapped at 120 characters; tables, headings and code are not
LIST_ITEM = r"(?:[-+*] |\d+\. )"  # a Markdown list item's marker, as a line begins after its indent


def unbreakable_at(line, space):
    """Whether the space at index `space` must not become a line break: between a number and its unit or its next
    three digits (4 613 MiB, 665.5 s), or where the next line would begin as a list item, heading, table or quote."""
    left, right = line[:space], line[space + 1:]
    return bool(re.search(r"\d$", left) and re.match(r"(\d{3}\b|s\b|ms\b|µs\b|[KMG]iB\b|%|×)", right)) or \
        bool(re.match(LIST_ITEM + r"|#|\||>", right))


def prose(lines, i):
    """Whether line i is a line of a paragraph or list item, the lines the docs wrap: not blank, a table row, a
    heading, a comment or code (fenced, or indented by four spaces)."""
    line = lines[i]
    in_fence = sum(earlier.lstrip().startswith("```") for earlier in lines[:i]) % 2 == 1
    return bool(line.strip()) and not in_fence and not line.startswith("    ") and \
        not line.lstrip().startswith(("|", "#", "<!--", "```"))


def carried_forward(lines, i):
    """Lines with line i, where a quotation made it longer than the docs' prose lines, wrapped again: the words past
    the limit carried to the start of the next line of its paragraph (or a new line at the paragraph's end), and so on
    down the paragraph until every line fits. The lines before i and after the paragraph stay as they were."""
    while i < len(lines) and len(lines[i]) > LINE_LIMIT and prose(lines, i):
        line = lines[i]
        indent = re.match(r" *" + LIST_ITEM + "?", line).group()
        spaces = [k for k in range(len(indent), min(len(line), LINE_LIMIT + 1))
                  if line[k] == " " and line[k - 1] != " " and not unbreakable_at(line, k)]
        if not spaces:
            return lines  # one word longer than a line: left as it is
        cut = spaces[-1]
        kept, carried = line[:cut], line[cut + 1:]
        lines[i] = kept
        following = i + 1 < len(lines) and prose(lines, i + 1) and \
            not re.match(r" *" + LIST_ITEM, lines[i + 1])
        if following:
            lines[i + 1] = re.match(r" *", lines[i + 1]).group() + carried + " " + lines[i + 1].lstrip()
        else:
            lines.insert(i + 1, " " * len(indent) + carried)
        i += 1
    return lines


def requoted(text, earlier, quotations):
    """The doc's text with each quotation as the earlier runs gave it made to read as the runs give it now, and what
    was done, one line each: (text, [(where, was, now)], [(where, why it was left)]). Words are replaced only where the
    doc reads them in as many places as are listed for them (a count of old words elsewhere, in a dated section, is
    history); the lines they made too long are wrapped again."""
    done, left = [], []
    was_at = dict(zip(numbered(earlier), (was for _, was in earlier)))
    changes = {}
    for place, (where, now) in zip(numbered(quotations), quotations):
        was = was_at.get(place, now)  # a place new with these runs (a kind's first runs) had no earlier words
        if was != now:
            changes.setdefault((was, now), []).append(where)
    for (was, now), wheres in changes.items():
        places = list(as_prose_holds_it(was).finditer(text))
        if len(places) > len(wheres):
            left.append((" and ".join(wheres), f"it reads \"{was}\", as the earlier runs gave it, in {len(places)} "
                         f"places, not {in_words(len(wheres))}"))
        if len(places) != len(wheres):
            continue
        for place in reversed(places):  # the last first, so that the earlier places' offsets still hold
            text = quoted_at(text, place, now)
        done += [(where, was, now) for where in wheres]
    return text, done, left


def numbered(quotations):
    """Each quotation's place as (where, how many before it had the same where): the key that pairs a quotation as the
    earlier runs gave it with the same one now, where the runs of a new kind have added places between them."""
    seen = {}
    keys = []
    for where, _ in quotations:
        keys.append((where, seen.get(where, 0)))
        seen[where] = seen.get(where, 0) + 1
    return keys


def quoted_at(text, place, now):
    """The text with the words at `place` (a match of an old quotation) made to read `now`, keeping their line breaks,
    and the lines that made too long wrapped again."""
    held = with_breaks_of(place.group(), now)
    text = text[:place.start()] + held + text[place.end():]
    lines = text.split("\n")
    first = text.count("\n", 0, place.start())
    for i in range(first, first + held.count("\n") + 1):
        carried_forward(lines, i)
    return "\n".join(lines)


class Summary:
    """A summary's place in a doc: the lines between `begin` and `end`, which `--write` replaces and `--check`
    compares, and the goal tables' quotations of it, which `--write` brings along (or names, where it cannot find
    them) and `--check` asks for."""

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

    def write_or_check(self, args, block, quotations, earlier, script):
        """Print the summary, or write it into args.write, or check args.check against it; the exit status. `earlier`
        is the quotations as the runs the doc was last written from gave them (None where there are none to hand)."""
        if not (args.write or args.check):
            print("\n".join(block))
            return 0
        doc = args.write or args.check
        text = doc.read_text(encoding="utf-8")
        lines, first, end = self.block(text, doc)
        inner = [""] + block + [""]  # a blank line either side, so the tables stand apart from the markers
        if args.check:
            return self.check(doc, lines[first:end], inner, unquoted(quotations, text), len(quotations), args.runs.name,
                              script, first)
        lines[first:end] = inner
        text, done, left = requoted("\n".join(lines), earlier, quotations) if earlier else ("\n".join(lines), [], [])
        temporary = doc.with_name(doc.name + ".tmp")
        temporary.write_text(text, encoding="utf-8")
        temporary.replace(doc)
        for where, was, now in done:
            print(f"{doc}: {where} now reads \"{now}\" (it read \"{was}\")")
        for where, why in left:
            print(f"{doc}: {where}: {why}; left as it is", file=sys.stderr)
        missing = unquoted(quotations, text)
        self.report_unquoted(doc, missing, args.runs.name)
        if missing:
            print(f"{doc}: the summary is written; {counted(len(missing), 'quotation')} of it to write by hand",
                  file=sys.stderr)
        return 1 if missing else 0

    def check(self, doc, held, inner, missing, places, runs_name, script, first):
        """Whether the doc's summary lines (`held`) are the runs' (`inner`) and its goal tables quote them: the exit
        status of --check, the differences printed."""
        failed = False
        if held == inner:
            print(f"{doc}: the summary of {len(inner) - 2} lines matches {runs_name}")
        else:
            failed = True
            print(f"{doc}: its summary of {self.what} differs from {runs_name}'s; run {script} --write {doc}",
                  file=sys.stderr)
            sys.stderr.writelines(line + "\n" for line in difflib.unified_diff(
                held, inner, f"{doc} (lines {first + 1}-{first + len(held)})", f"{runs_name} summarised",
                lineterm=""))
        if missing:
            failed = True
            self.report_unquoted(doc, missing, runs_name)
        else:
            print(f"{doc}: its goal tables quote the summary as {runs_name} gives it ({places} places)")
        return 1 if failed else 0


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
    {script} --write DOC    put it between DOC's two marker lines (docs/performance.md), and
    {script_blank}                make each goal table's quotation of it read as the runs now give it
    {script} --check DOC    exit 1 if DOC's lines differ from it, or a quotation of it in
    {script_blank}                the goal tables does (CTest runs this)

--write finds each quotation as the runs the doc was last written from gave it: the runs file as the checkout's last
commit has it (git show HEAD:FILE), or the file --was names. A quotation it reads in exactly one place is made to read
as the runs now give it, keeping its line breaks, and the lines it made longer than 120 characters are wrapped again
into their paragraph; it prints each. A quotation it cannot find so (the words changed by hand, read in two places, no
earlier runs to hand) is named with the words it should read, and the exit status is 1: the summary is written, and
those words are the writer's.

A row that cannot be read (a field missing or malformed, a run out of order, a section the doc does not have) is an
error naming the file, line and field: exit 2, and nothing is written."""


def arguments(description, runs, docs, script):
    """The command line both scripts take: the runs file, the doc whose sections the runs name, and --write DOC (with
    --was FILE) or --check DOC; --help shows what each does (USAGE)."""
    usage = USAGE.format(script=script, script_blank=" " * len(script))
    parser = argparse.ArgumentParser(description=description, epilog=usage,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=pathlib.Path, default=runs)
    parser.add_argument("--sections", type=pathlib.Path, default=docs,
                        help="the doc whose sections the runs name (default docs/performance.md)")
    parser.add_argument("--was", type=pathlib.Path, metavar="FILE",
                        help="with --write: the runs file the doc's quotations were last written from (default: the "
                             "runs file as the last commit has it)")
    action = parser.add_mutually_exclusive_group()
    action.add_argument("--write", type=pathlib.Path, metavar="DOC")
    action.add_argument("--check", type=pathlib.Path, metavar="DOC")
    args = parser.parse_args()
    if args.was and not args.write:
        parser.error("--was goes with --write")
    return args


def as_committed(runs):
    """The runs file's text as the checkout's last commit has it, and a name for it; (None, why) where git cannot
    show it (no git, not a checkout, the file not committed)."""
    try:
        shown = subprocess.run(["git", "-C", str(runs.parent), "show", f"HEAD:./{runs.name}"], capture_output=True,
                               text=True, encoding="utf-8")
    except OSError as error:
        return None, f"git cannot run ({error.strerror})"
    if shown.returncode != 0:
        return None, shown.stderr.strip().split("\n")[-1] or f"git show exited with {shown.returncode}"
    return shown.stdout, f"{runs} as committed (HEAD)"


def earlier_quotations(args, read, quotations):
    """The quotations as the runs the doc was last written from gave them: those of --was FILE, or of the runs file
    as committed; None, with a line saying why, where there are none."""
    if args.was:
        return quotations(read(args.was, None))
    text, name = as_committed(args.runs)
    try:
        if text is not None:
            return quotations(read(name, text))
    except BadInput as error:  # the committed file is no longer one the doc can hold (a section renamed since)
        name = str(error)
    print(f"{args.runs}: no earlier runs to find the goal tables' quotations by ({name}); give them with "
          "--was FILE", file=sys.stderr)
    return None


def command(doc, runs_name, columns, read_run, summary, quotations, summary_place):
    """A runs script's whole command line (the exit status): the runs of validation/bench/RUNS_NAME read by read_run,
    their summary (a list of lines) and its quotations ((where, what it must read)) printed, written or checked."""
    here = pathlib.Path(__file__).resolve().parent
    script = "validation/bench/" + pathlib.Path(runs_name).stem + ".py"

    def run(args):
        def read(path, text):
            return read_rows(path, args.sections, columns, read_run, text)
        runs = read(args.runs, None)
        earlier = earlier_quotations(args, read, quotations) if args.write else None
        return summary_place.write_or_check(args, summary(runs), quotations(runs), earlier, script)
    docs = here.parent.parent / "docs" / "performance.md"
    return exit_status(run, arguments(doc.split("\n")[0], here / runs_name, docs, script))

"""The runs scripts' --write (validation/bench/runs_file.py) on the fixtures in tests/docs/hectare_runs and
tests/docs/light_runs: a doc written from the earlier runs (before.md, from runs_before.csv) is made to read as the
runs give them now (runs.csv), its summary and every goal table's quotation of it, so that --check passes; nothing
else in it changes, a quotation wrapped across lines keeps its line break, the lines a longer quotation pushed past
120 characters are wrapped again, and writing twice changes nothing. A quotation it cannot find once is left and
named (exit 1), the earlier runs come from the last commit where --was does not name them, and a doc with no earlier
runs to hand gets its summary and the names of the quotations to write by hand.

    python3 tests/docs/runs_write.py [RunsWrite.test_NAME ...]   (CTest runs each test as docs.runs_write.NAME)
"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BENCH = ROOT / "validation" / "bench"
FIXTURES = ROOT / "tests" / "docs"
sys.path.insert(0, str(BENCH))
sys.dont_write_bytecode = True
import hectare_runs  # noqa: E402  (after the path to validation/bench)
import light_runs  # noqa: E402
import runs_file  # noqa: E402

MODULES = {"hectare_runs": hectare_runs, "light_runs": light_runs}


def run_script(runs, *arguments, env=None):
    """validation/bench/RUNS.py with the fixture's sections.md and these arguments."""
    return subprocess.run([sys.executable, str(BENCH / f"{runs}.py"), "--sections",
                           str(FIXTURES / runs / "sections.md"), *map(str, arguments)],
                          capture_output=True, text=True, encoding="utf-8", env=env)


def quotations_of(runs, csv_name):
    module = MODULES[runs]
    fixture = FIXTURES / runs
    return module.quotations(runs_file.read_rows(fixture / csv_name, fixture / "sections.md", module.COLUMNS,
                                                 module.read_run))


def outside_the_summary(text, runs):
    """The doc's words outside its summary's two marker lines, its line breaks and indents as single spaces."""
    summary = MODULES[runs].SUMMARY
    before, rest = text.split(summary.begin)
    return " ".join((before + rest.split(summary.end)[1]).split())


def prose_lines(text):
    """The lines the docs wrap at 120 characters: not table rows or blank."""
    return [line for line in text.split("\n") if line.strip() and not line.lstrip().startswith("|")]


class RunsWrite(unittest.TestCase):
    def setUp(self):
        self.folder = pathlib.Path(tempfile.mkdtemp(prefix="runs_write."))
        self.addCleanup(shutil.rmtree, self.folder)
        # git must not find a repository above the scratch folder (the checkout's, when TMPDIR lies in it)
        self.env = dict(os.environ, GIT_CEILING_DIRECTORIES=str(self.folder.parent))
        for name in ("GIT_DIR", "GIT_WORK_TREE", "GIT_INDEX_FILE"):
            self.env.pop(name, None)

    def commit(self, repository):
        """A git repository in `repository` whose one commit holds its runs.csv."""
        git = ["git", "-C", str(repository), "-c", "user.name=test", "-c", "user.email=test@localhost", "-c",
               "commit.gpgsign=false"]
        for step in (["init", "-q"], ["add", "runs.csv"], ["commit", "-q", "-m", "the runs before"]):
            subprocess.run(git + step, check=True, capture_output=True, env=self.env)

    def doc_from(self, runs, fixture="before.md", extra=""):
        doc = self.folder / "doc.md"
        doc.write_text((FIXTURES / runs / fixture).read_text(encoding="utf-8") + extra, encoding="utf-8")
        return doc

    def write(self, runs, doc, *arguments):
        return run_script(runs, "--runs", FIXTURES / runs / "runs.csv", "--write", doc, *arguments, env=self.env)

    def write_from_before(self, runs, doc):
        return self.write(runs, doc, "--was", FIXTURES / runs / "runs_before.csv")

    def assert_checks(self, runs, doc):
        check = run_script(runs, "--runs", FIXTURES / runs / "runs.csv", "--check", doc, env=self.env)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)

    def test_the_hectare_doc_reads_as_the_runs_give_it(self):
        doc = self.doc_from("hectare_runs")
        written = self.write_from_before("hectare_runs", doc)
        self.assertEqual(written.returncode, 0, written.stdout + written.stderr)
        changed = sum(was != now for (_, was), (_, now) in zip(quotations_of("hectare_runs", "runs_before.csv"),
                                                               quotations_of("hectare_runs", "runs.csv")))
        self.assertEqual(written.stdout.count(" now reads "), changed, written.stdout)
        self.assert_checks("hectare_runs", doc)

    def test_the_light_doc_reads_as_the_runs_give_it(self):
        doc = self.doc_from("light_runs")
        written = self.write_from_before("light_runs", doc)
        self.assertEqual(written.returncode, 0, written.stdout + written.stderr)
        self.assertIn("one of two on the machine started 2026-12-02 08:00)", doc.read_text(encoding="utf-8"))
        self.assert_checks("light_runs", doc)

    def test_only_the_quotations_change(self):
        for runs in MODULES:
            with self.subTest(runs=runs):
                doc = self.doc_from(runs)
                expected = outside_the_summary(doc.read_text(encoding="utf-8"), runs)
                for (_, was), (_, now) in zip(quotations_of(runs, "runs_before.csv"), quotations_of(runs, "runs.csv")):
                    expected = expected.replace(was, now)
                self.write_from_before(runs, doc)
                self.assertEqual(outside_the_summary(doc.read_text(encoding="utf-8"), runs), expected)

    def test_a_wrapped_quotation_keeps_its_line_break(self):
        doc = self.doc_from("hectare_runs")
        self.assertIn("**yes on the\nfamily-26 EPYC** in two runs of 3 (", doc.read_text(encoding="utf-8"))
        self.write_from_before("hectare_runs", doc)
        self.assertIn("**yes on the\nfamily-26 EPYC** in two runs of 4 (", doc.read_text(encoding="utf-8"))

    def test_lines_pushed_past_120_characters_are_wrapped_again(self):
        doc = self.doc_from("hectare_runs")
        before = doc.read_text(encoding="utf-8")
        self.assertEqual([line for line in prose_lines(before) if len(line) > 120], [])
        self.write_from_before("hectare_runs", doc)
        after = doc.read_text(encoding="utf-8")
        self.assertEqual([line for line in prose_lines(after) if len(line) > 120], [])
        # the paragraph whose first line grew by two characters: its words moved down, the last line took them
        paragraph = after.split("The goal table in full, as it stood")[1].split("\n\n")[0]
        self.assertEqual(len(paragraph.split("\n")), 3, paragraph)
        self.assertNotRegex(after, r"\d\n *(s|MiB)\b", "a number parted from its unit")

    def test_a_number_keeps_its_unit_when_a_line_is_wrapped_again(self):
        head = "x" * 113 + " "  # the number begins at the 115th character, its last space before the 121st
        for words in ("621.0 s,", "4 612 MiB,"):
            with self.subTest(words=words):
                lines = runs_file.carried_forward([head + words + " and more", "the next line."], 0)
                self.assertEqual(lines, [head.rstrip(), words + " and more the next line."])

    def test_writing_twice_changes_nothing(self):
        doc = self.doc_from("hectare_runs")
        self.write_from_before("hectare_runs", doc)
        once = doc.read_text(encoding="utf-8")
        again = self.write_from_before("hectare_runs", doc)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertNotIn(" now reads ", again.stdout)
        self.assertEqual(doc.read_text(encoding="utf-8"), once)

    def test_a_quotation_read_in_two_places_is_left_and_named(self):
        history = "\n## As it stood on the second day\n\nThe verdict then read (1 of 2 runs; as it should.\n"
        doc = self.doc_from("hectare_runs", extra=history)
        written = self.write_from_before("hectare_runs", doc)
        self.assertEqual(written.returncode, 1, written.stdout + written.stderr)
        self.assertIn("the front goal table's hectare verdict: it reads \"(1 of 2 runs;\", as the earlier runs gave "
                      "it, in 2 places, not one; left as it is", written.stderr)
        self.assertIn("does not read \"(1 of 3 runs;\"", written.stderr)
        self.assertTrue(doc.read_text(encoding="utf-8").endswith(history))

    def test_a_kinds_cell_is_written_in_both_of_its_places(self):
        # two_kinds.csv: runs.csv's runs and an Intel Xeon's; the doc as the Xeon's first run alone gave its 10⁶ cell,
        # which both goal tables read
        fixture = FIXTURES / "light_runs"
        rows = (fixture / "two_kinds.csv").read_text(encoding="utf-8").rstrip("\n").split("\n")
        before = self.folder / "two_kinds_before.csv"
        before.write_text("\n".join(rows[:-2]) + "\n", encoding="utf-8")  # without the Xeon's second run
        was, now = "| 5.04–5.18 s (first 5.45 s) |", "| 4.91–5.18 s (first 5.25–5.45 s) |"
        doc = self.doc_from("light_runs", fixture="two_kinds.md")
        doc.write_text(doc.read_text(encoding="utf-8").replace(now, was), encoding="utf-8")
        self.assertEqual(doc.read_text(encoding="utf-8").count(was), 2)
        written = run_script("light_runs", "--runs", fixture / "two_kinds.csv", "--write", doc, "--was", before,
                             env=self.env)
        self.assertEqual(written.returncode, 0, written.stdout + written.stderr)
        self.assertEqual(written.stdout.count(" now reads "), 2, written.stdout)
        text = doc.read_text(encoding="utf-8")
        self.assertEqual((text.count(was), text.count(now)), (0, 2))
        check = run_script("light_runs", "--runs", fixture / "two_kinds.csv", "--check", doc, env=self.env)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)

    def checkout_holding(self, committed):
        """runs.csv of a scratch checkout whose one commit holds `committed`, the file now the fixture's runs.csv."""
        repository = self.folder / "checkout"
        repository.mkdir()
        runs = repository / "runs.csv"
        runs.write_text(committed, encoding="utf-8")
        self.commit(repository)
        shutil.copy(FIXTURES / "hectare_runs" / "runs.csv", runs)
        return runs

    def write_without_was(self, runs, status):
        """before.md written from `runs` with no --was, the exit status asserted; the doc and the script's output."""
        doc = self.doc_from("hectare_runs")
        written = run_script("hectare_runs", "--runs", runs, "--write", doc, env=self.env)
        self.assertEqual(written.returncode, status, written.stdout + written.stderr)
        return doc, written

    def test_the_earlier_runs_are_the_last_commits(self):
        before = (FIXTURES / "hectare_runs" / "runs_before.csv").read_text(encoding="utf-8")
        doc, _ = self.write_without_was(self.checkout_holding(before), 0)
        self.assert_checks("hectare_runs", doc)

    def test_a_committed_file_the_doc_cannot_hold_is_no_earlier_runs(self):
        before = (FIXTURES / "hectare_runs" / "runs_before.csv").read_text(encoding="utf-8")
        runs = self.checkout_holding(before.replace("A quick hour", "An hour the doc no longer has"))
        _, written = self.write_without_was(runs, 1)
        self.assertIn("runs.csv as committed (HEAD):2: field 'section'", written.stderr)
        self.assertIn("give them with --was FILE", written.stderr)
        self.assertIn("does not read \"(1 of 3 runs;\"", written.stderr)

    def test_without_earlier_runs_the_summary_is_written_and_the_quotations_named(self):
        runs = self.folder / "runs.csv"  # outside any checkout: git cannot show an earlier one
        shutil.copy(FIXTURES / "hectare_runs" / "runs.csv", runs)
        doc, written = self.write_without_was(runs, 1)
        self.assertIn("no earlier runs to find the goal tables' quotations by", written.stderr)
        self.assertIn("does not read \"(1 of 3 runs;\"", written.stderr)
        check = run_script("hectare_runs", "--runs", runs, "--check", doc, env=self.env)
        self.assertRegex(check.stdout, r"the summary of \d+ lines matches runs.csv")

    def test_an_earlier_runs_file_that_cannot_be_read_writes_nothing(self):
        doc = self.doc_from("hectare_runs")
        before = doc.read_text(encoding="utf-8")
        missing = self.folder / "no-such-runs.csv"
        written = self.write("hectare_runs", doc, "--was", missing)
        self.assertEqual(written.returncode, 2)
        self.assertIn(f"{missing}: No such file or directory", written.stderr)
        self.assertEqual(doc.read_text(encoding="utf-8"), before)

    def test_was_goes_with_write(self):
        checked = run_script("hectare_runs", "--check", self.doc_from("hectare_runs"), "--was",
                             FIXTURES / "hectare_runs" / "runs_before.csv", env=self.env)
        self.assertEqual(checked.returncode, 2)
        self.assertIn("--was goes with --write", checked.stderr)


if __name__ == "__main__":
    unittest.main()

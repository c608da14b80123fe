#!/usr/bin/env python3
"""Every reference to a section of the docs names a section that exists.

Code comments, docs and scripts point readers at the docs as `docs/light.md "The stands' sky"`: the file, then the
section's name in quotes. When a section is renamed or removed such a reference leads nowhere, and nothing else
notices (the twenty-fourth session found seven by hand). This check reads every file of the checkout that git tracks
or would track, finds each `docs/NAME.md "Title"` (also `docs/NAME.md, "Title"`, `docs/NAME.md ("Title")` and
`docs/NAME.md "Title" and "Another"`; inside docs/ also `NAME.md "Title"`), joins a title broken across comment
lines or C++ string literals, and looks for it among NAME.md's headings and bold paragraph titles (`**Title.**`
opening a paragraph or a list item): the whole title, or its start up to a word's end, as a reader finds a section by
its first words. A Markdown file's references to its own sections, `"Title" below` and `"Title" above` (also
`("Title", above)`), are looked up among its own headings and must lie where they say: a section that exists only on
the other side is reported too (a section moved, or the wrong word). It prints each reference that names nothing (or a
doc that does not exist), with its file and line, and exits 1 if there is one.

    tests/docs/section_references.py [CHECKOUT]     (default: the checkout holding this script)
"""
import argparse
import pathlib
import re
import subprocess
import sys

# A reference: the doc's name, then a title in straight or curly double quotes. Inside docs/ a reference may drop
# the folder or come as a Markdown link, [light.md](light.md) "Title".
REFERENCE = re.compile(r'(?:docs/|(?<![\w/.-]))([a-z][a-z_-]*)\.md'  # docs/light.md, or light.md inside docs/
                       r'(?:\]\([a-z_-]+\.md\))?`?,?'                # a Markdown link's target, a code mark, a comma
                       r'\s*(?:(?://+|#+|\*|>)[ \t]*)?'              # a line break in a comment
                       r'\(?["\u201c]')                              # the title's opening quote
# A further title of the same doc after a title: `"A" and "B"`, `"A", "B"`, `"A"; "B"`, `"A" or "B"`.
NEXT_TITLE = re.compile(r'(?:,|;)?[ \t]*(?:and|or)?[ \t]*["\u201c]')
# A reference inside a Markdown file to one of its own sections: the title in quotes, then where it lies.
OWN_REFERENCE = re.compile(r'["\u201c]([^"\u201c\u201d]{2,200}?)["\u201d]\)?,?\s+\(?(below|above)\b')
HEADING = re.compile(r'^#{1,6}\s+(.+?)\s*#*\s*$')
BOLD_TITLE = re.compile(r'^\s*(?:[-*]\s+|\d+\.\s+)?\*\*(.+?)\*\*')
# What opens a continuation line of a comment or a quoted block: it is dropped when a title is joined across lines.
LINE_OPENER = re.compile(r'^\s*(?://+|#+|\*|>|;+|--)?\s?')


def normalise(title):
    """Compares titles as a reader would: spacing, a closing full stop or colon and Markdown's code marks aside."""
    title = title.replace('`', '').replace('\u2019', "'")
    title = re.sub(r'\s+', ' ', title).strip()
    return title.rstrip('.:').strip()


def sections_of(doc):
    """A Markdown file's section titles, each with its line: its headings, without a leading section number ("3. "),
    and bold paragraph titles."""
    titles = []
    fenced = False
    for number, line in enumerate(doc.read_text(encoding='utf-8').splitlines(), start=1):
        if line.lstrip().startswith('```'):
            fenced = not fenced
            continue
        if fenced:
            continue
        for pattern in (HEADING, BOLD_TITLE):
            match = pattern.match(line)
            if match:
                titles.append((normalise(re.sub(r'^\d+(\.\d+)*\.\s+', '', match.group(1))), number))
    return titles


def lines_of_sections_named(title, titles):
    """The lines of the sections a reference names, by their title or by the title's start up to a word's end:
    "Thinning" finds "3. Thinning", "Seed 001" finds "Seed 001: conifer architecture", "The 3 m cut-off by default"
    finds "The 3 m cut-off by default (2026-11-24)"."""
    title = normalise(title)
    if not title:
        return []
    return [line for t, line in titles if t == title or (t.startswith(title) and not t[len(title)].isalnum())]


def tracked_files(root):
    try:
        listed = subprocess.run(['git', '-C', str(root), 'ls-files', '-z', '--cached', '--others',
                                 '--exclude-standard'], check=True, capture_output=True).stdout
        return [root / name for name in listed.decode().split('\0') if name]
    except (OSError, subprocess.CalledProcessError):
        # Not a checkout (a source archive): every file under the project's own folders, in git's order, so that the
        # report reads the same either way.
        folders = ['src', 'cl', 'tests', 'validation', 'docs', 'stands', '.ci']
        files = [root / 'README.md', root / 'CMakeLists.txt']
        for folder in folders:
            files += [p for p in (root / folder).rglob('*') if p.is_file()]
        return sorted(p for p in files if p.exists())


def as_one_literal(text):
    """C++ text with adjacent string literals joined and their escaped quotes plain, the line breaks kept: a message
    that cites `docs/performance.md \\"Memory\\"` across two literals reads as the reference it prints."""
    text = re.sub(r'"[ \t]*\n\s*"', lambda m: '\n' * m.group(0).count('\n'), text)
    return text.replace('\\"', '"')


def quoted_title(text, start):
    """The title opening at text[start] (just past its opening quote), joined across line breaks, and where its closing
    quote ends; None if it is not closed within a few lines."""
    pieces = []
    position = start
    for _ in range(4):  # a title spans at most a few comment lines
        end_of_line = text.find('\n', position)
        if end_of_line < 0:
            end_of_line = len(text)
        line = text[position:end_of_line]
        close = re.search(r'["\u201d]', line)
        if close:
            pieces.append(line[:close.start()])
            return ' '.join(pieces), position + close.end()
        pieces.append(line)
        if end_of_line == len(text):
            return None
        next_line = text[end_of_line + 1:]
        position = end_of_line + 1 + LINE_OPENER.match(next_line).end()
    return None


def references_in(path, root):
    """Each reference in the file at `path`: (the doc it cites, the title, its line, and where the section lies: None
    for a reference to another file, 'below' or 'above' for a Markdown file's reference to one of its own sections)."""
    try:
        text = path.read_text(encoding='utf-8')
    except (UnicodeDecodeError, OSError):
        return  # a binary file (an image, a compressed table)
    in_docs = path.parent == root / 'docs'
    if path.suffix in ('.cpp', '.hpp', '.h', '.cl', '.clh'):
        text = as_one_literal(text)
    cited_by_name = set()  # where the titles of `NAME.md "Title"` references open: not read again as own references
    for match in REFERENCE.finditer(text):
        if not match.group(0).startswith('docs/') and not in_docs:
            continue
        opening = match.end() - 1
        quoted = quoted_title(text, match.end())
        line = text.count('\n', 0, match.start()) + 1
        while quoted is not None:
            title, end = quoted
            cited_by_name.add(opening)
            yield root / 'docs' / f'{match.group(1)}.md', title, line, None
            # `docs/NAME.md "A" and "B"` cites two sections of NAME.md.
            more = NEXT_TITLE.match(text, end)
            if not more:
                break
            opening = more.end() - 1
            quoted = quoted_title(text, more.end())
            line = text.count('\n', 0, more.start()) + 1
    if path.suffix != '.md':
        return
    for match in OWN_REFERENCE.finditer(text):
        if match.start() not in cited_by_name:
            yield path, match.group(1), text.count('\n', 0, match.start()) + 1, match.group(2)


def problem_with(title, line, where, titles):
    """What is wrong with a reference to the sections `titles` of a doc, or None: it names none of them, or (`where`
    'below' or 'above', a reference at `line` to its own file) only one on the other side of it."""
    lines = lines_of_sections_named(title, titles)
    if not lines:
        return f'has no section "{normalise(title)}"' + (f' {where}' if where else '')
    if where and not any((at > line) == (where == 'below') for at in lines):
        other_side = 'above' if where == 'below' else 'below'
        return f'has its section "{normalise(title)}" {other_side}, not {where}'
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('checkout', nargs='?', type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parents[2],
                        help='the checkout whose files and docs are read (default: the one holding this script)')
    root = parser.parse_args().checkout.resolve()
    if not (root / 'docs').is_dir():
        parser.error(f'{root}: no docs/ folder there')
    sections = {}
    checked = 0
    broken = []
    this_script = pathlib.Path(__file__).resolve()
    # The fixture is a checkout of its own: its docs/, and references broken on purpose (tests/scripts/docs.cmake).
    fixture = this_script.parent / 'fixture'
    for path in tracked_files(root):
        if path == this_script or not path.is_file() or (fixture in path.parents and root != fixture):
            continue
        for doc, title, line, where in references_in(path, root):
            checked += 1
            cited = doc.relative_to(root)
            if not doc.is_file():
                broken.append(f'{path.relative_to(root)}:{line}: {cited}: no such file')
                continue
            if doc not in sections:
                sections[doc] = sections_of(doc)
            problem = problem_with(title, line, where, sections[doc])
            if problem:
                broken.append(f'{path.relative_to(root)}:{line}: {cited} {problem}')
    for message in broken:
        print(message)
    print(f'{checked} references to sections of the docs read, {len(broken)} broken')
    return 1 if broken else 0


if __name__ == '__main__':
    sys.exit(main())

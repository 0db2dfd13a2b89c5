"""Every count and claim the README and docs/ make about the program, checked against the
program: the README's length, its links and the docs' links, every output
a page shows, every command line and flag a page names, the counts (topics, exam questions,
commands), the formats and presets listed, the modules named, and pandoc's reading of the
README.

A shown output is checked as ``scanconv`` prints it today; a line ``...`` in it stands for
lines left out. ``python -m tests.test_docs_claims FILE...`` rewrites the shown outputs of those
pages that no longer match (then review the diff).
"""

from __future__ import annotations

import importlib
import io
import itertools
import re
import shlex
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import typer

from scanconv.cli import app

from .helpers import Result, run

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
PAGES = [README, *sorted((ROOT / "docs").glob("*.md"))]
TEXT = {page: page.read_text(encoding="utf-8") for page in PAGES}
TOP = typer.main.get_command(app)
COMMANDS: dict[str, Any] = TOP.commands  # type: ignore[attr-defined]


def _id(page: Path) -> str:
    return str(page.relative_to(ROOT))


# --- the README: short, the cheat sheet first, the rest in docs/ ----------------------------


def test_the_readme_is_at_most_400_lines():
    assert len(TEXT[README].splitlines()) <= 400


def test_the_readme_puts_the_cheat_sheet_first_and_the_rest_in_docs():
    headings = re.findall(r"^## (.*)$", TEXT[README], flags=re.M)
    assert headings[0].startswith("Cheat sheet")
    # teachers', programmers' and developers' material lives in docs/, linked from the README
    assert "```python" not in TEXT[README]
    assert not [h for h in headings if "teacher" in h.lower() or "library" in h.lower()]
    for doc in ("teaching", "lms", "site", "api", "mcp", "development", "architecture"):
        assert f"](docs/{doc}.md)" in TEXT[README], doc


def test_the_python_version_the_readme_asks_for_is_the_packages():
    said = re.search(r"\(Python (3\.\d+)\+, once\)", TEXT[README])
    needed = re.search(
        r'^requires-python = ">=(3\.\d+)"', (ROOT / "pyproject.toml").read_text(), re.M
    )
    assert said is not None and needed is not None and said[1] == needed[1]


# --- links ---------------------------------------------------------------------------------

LINK = re.compile(r"\]\(([^)\s]+)\)")


def _anchors(text: str) -> set[str]:
    """The anchors GitHub gives a page's headings (lower case, punctuation dropped, spaces to
    hyphens, a repeated one numbered)."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # a '#' line in a code block is no heading
    seen: dict[str, int] = {}
    slugs = set()
    for heading in re.findall(r"^#{1,6} (.*?)\s*$", text, flags=re.M):
        slug = re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        slugs.add(slug if n == 0 else f"{slug}-{n}")
    return slugs


def _links(page: Path) -> Iterator[str]:
    text = re.sub(r"```.*?```", "", TEXT[page], flags=re.S)
    text = re.sub(r"`[^`\n]*`", "", text)
    for target in LINK.findall(text):
        if not re.match(r"[a-z]+:", target):  # http:, https:, mailto: are not checked here
            yield target


@pytest.mark.parametrize("page", PAGES, ids=_id)
def test_every_link_of_a_page_resolves(page):
    broken = []
    for target in _links(page):
        path, _, anchor = target.partition("#")
        file = (page.parent / path).resolve() if path else page
        if not file.exists():
            broken.append(target)
        elif anchor and file.suffix == ".md" and anchor not in _anchors(file.read_text("utf-8")):
            broken.append(target)
    assert not broken, f"{_id(page)}: links to nothing: {broken}"


def test_a_broken_link_or_anchor_is_caught():
    """The check above can fail: a missing file and a missing heading are both found."""
    assert "the-exam-book" in _anchors(TEXT[ROOT / "docs" / "teaching.md"])
    assert "no-such-heading" not in _anchors(TEXT[ROOT / "docs" / "teaching.md"])
    assert not (ROOT / "docs" / "no-such-page.md").exists()


# --- shown outputs -------------------------------------------------------------------------

SHOWN = re.compile(r"```text\n\$ (.*?)\n(.*?)```", flags=re.S)
EXAMPLES = [  # the README's in the inner loop, the rest of docs/ (some over 50 ms) outside it
    pytest.param(
        page,
        command,
        shown,
        id=f"{_id(page)}: {command}",
        marks=() if page == README else pytest.mark.slow,
    )
    for page in PAGES
    for command, shown in SHOWN.findall(TEXT[page])
]


def _run_shown(command: str, monkeypatch: pytest.MonkeyPatch) -> tuple[Result, int | None]:
    """Run a page's ``$ ...`` line in-process: ``scanconv ARGS``, after an optional
    ``printf 'TEXT' |`` (its standard input) and before an optional ``| tail -N`` (the lines
    kept, returned with it)."""
    words = shlex.split(command)
    if words[0] == "printf":
        assert words[2] == "|", command
        data = words[1].encode().decode("unicode_escape").encode()
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(data), encoding="utf-8"))
        words = words[3:]
    tail = None
    if "|" in words:
        k = words.index("|")
        assert words[k + 1] == "tail", command
        tail = int(words[k + 2].lstrip("-"))
        words = words[:k]
    assert words[0] == "scanconv", command
    return run(*words[1:]), tail


def _matches(shown: str, actual: str) -> bool:
    """``shown`` is ``actual`` (trailing spaces aside), where a line ``...`` stands for any
    lines: the parts between the ``...`` lines appear in order, the first at the start (unless
    the block starts with ``...``) and the last at the end (unless it ends with one)."""
    want = [line.rstrip() for line in shown.rstrip("\n").split("\n")]
    have = [line.rstrip() for line in actual.rstrip("\n").split("\n")]
    parts: list[list[str]] = [[]]
    for line in want:
        if line == "...":
            parts.append([])
        else:
            parts[-1].append(line)
    if len(parts) == 1:
        return want == have
    first, *middle, last = parts
    if have[: len(first)] != first or (last and have[len(have) - len(last) :] != last):
        return False
    at, end = len(first), len(have) - len(last)
    for part in middle:
        found = next(
            (i for i in range(at, end - len(part) + 1) if have[i : i + len(part)] == part), None
        )
        if found is None:
            return False
        at = found + len(part)
    return at <= end


def _output(result: Result, tail: int | None, shown: str) -> str:
    text = result.err if shown.startswith("scanconv: error:") else result.out
    lines = text.rstrip("\n").split("\n")
    return "\n".join(lines[-tail:] if tail else lines)


@pytest.mark.parametrize("page,command,shown", EXAMPLES)
def test_every_shown_output_is_what_the_program_prints(page, command, shown, monkeypatch):
    """Every ``$ scanconv ...`` block of the README and docs/ shows what the command prints
    today; one that shows an error shows the one line on stderr of a refusal (exit 2, nothing
    on stdout)."""
    result, tail = _run_shown(command, monkeypatch)
    if shown.startswith("scanconv: error:"):
        assert result.code == 2 and result.out == "", (result.code, result.out[:200])
    else:
        assert result.code == 0, result.err
    assert _matches(shown, _output(result, tail, shown)), (
        f"{_id(page)}: rerun `{command}` (python -m tests.test_docs_claims {_id(page)})"
    )


def test_the_readme_shows_the_exam_questions_it_names():
    """An answer the README shows as "exam question N" (or "question N") is the command the
    cheat sheet gives for question N, with display options only added."""
    text = TEXT[README].split("## What an answer looks like", 1)[1].split("\n## ", 1)[0]
    rows = dict(re.findall(r"^\| (\d+)\. .*? \| `([^`]+)` \|$", TEXT[README], flags=re.M))
    chunks = text.split("```text\n$ ")
    shown = []
    for before, after in itertools.pairwise(chunks):
        prose = before.rsplit("```", 1)[-1]  # the words since the block before
        shown += [(n, after.split("\n", 1)[0]) for n in re.findall(r"question (\d+)", prose)]
    assert len(shown) >= 3
    for number, command in shown:
        assert command.startswith(rows[number] + " "), (number, rows[number], command)


def test_the_output_check_sees_a_changed_or_missing_line():
    actual = "a\nb\nc\nd"
    assert _matches("a\nb\nc\nd", actual) and _matches("a\n...\nd", actual)
    assert _matches("...\nc\nd", actual) and _matches("a\n...\nc\n...", actual)
    assert not _matches("a\nb\nd", actual) and not _matches("a\n...\nx", actual)
    assert not _matches("a\nc\n...", actual) and not _matches("...\nd\nc", actual)


def test_the_readme_shows_the_most_common_answers():
    shown = {command for page, command, _ in (p.values for p in EXAMPLES) if page == README}
    assert "scanconv line 2 2 10 6 --algo bresenham --format plain" in shown
    assert any(c.startswith("scanconv line 2 2 10 6 --algo dda") for c in shown)
    assert any(c.startswith("scanconv circle ") for c in shown)


# --- command lines and flags ---------------------------------------------------------------

SPAN = re.compile(r"`(scanconv [^`]+)`")
#: A span that is a template, not a command line: a placeholder in capitals (R, X1, TOPIC),
#: an ellipsis, an optional part or a choice of words.
TEMPLATE = re.compile(
    r"\b[A-Z]{2,}[A-Z0-9_]*\b|\b[A-Z][0-9]+\b|(?<!bitmap )(?<!stroke )\b[A-Z]\b|\.\.\.|…|\[|\|"
)
NUMBER = re.compile(r"-[0-9.]+(/[0-9]+)?(e[0-9]+)?")


def _command_lines(page: Path) -> list[str]:
    """Every inline ``scanconv ...`` span and every ``scanconv ...`` line of a ```sh block of
    a page that is a concrete command line (a span broken over two lines joined), cut before a
    shell redirection or comment."""
    found = []
    blocks = re.findall(r"```(?:sh|text)\n(.*?)```", TEXT[page], flags=re.S)
    shell = [
        line.split("  #", 1)[0].split(" # ", 1)[0].strip()
        for block in blocks
        for line in block.splitlines()
        if line.startswith("scanconv ")
    ]
    for span in SPAN.findall(TEXT[page]) + shell:
        span = " ".join(span.split())
        cut = re.split(r" (?:>>?|&&|\|) ", span, maxsplit=1)[0]
        if not TEMPLATE.search(cut):
            found.append(cut)
    return found


def _resolve(words: list[str]) -> tuple[Any, list[str]]:
    """The click command a command line names (through its groups) and the words after it."""
    command, rest = TOP, list(words)
    while hasattr(command, "commands") and rest and rest[0] in command.commands:
        command, rest = command.commands[rest[0]], rest[1:]
    return command, rest


def _options(command: Any) -> dict[str, Any]:
    names = {"--help": None, "-h": None}
    for param in command.params:
        if param.param_type_name == "option":
            for name in (*param.opts, *param.secondary_opts):
                names[name] = param
    return names


def _flag_problems(words: list[str]) -> list[str]:
    """What is wrong with a command line's words: no such command, or a flag the command does
    not have (a command that reads free words, such as ``transform``'s ``--rotate``, names its
    own in its help). After ``--`` (``check``) the question is checked the same way."""
    if "--" in words:
        k = words.index("--")
        return _flag_problems(words[:k]) + _flag_problems(words[k + 1 :])
    command, rest = _resolve(words)
    if command is TOP and not (rest and rest[0].startswith("-")):  # `scanconv --help` is one
        return [f"no command {words[:1]}"]
    options = _options(command)
    free = any(p.param_type_name == "argument" and p.nargs == -1 for p in command.params)
    problems = []
    for word in rest:
        name = word.split("=", 1)[0]
        if not word.startswith("-") or NUMBER.fullmatch(word) or word == "-":
            continue
        if name in options or (free and re.search(rf"{re.escape(name)}\b", command.help or "")):
            continue
        problems.append(f"{words[0]}: no option {name}")
    return problems


@pytest.mark.parametrize("page", PAGES, ids=_id)
def test_every_command_line_a_page_names_exists_with_its_flags(page):
    problems = [
        (line, problem)
        for line in _command_lines(page)
        for problem in _flag_problems(shlex.split(line)[1:])
    ]
    assert not problems, problems


def test_the_flag_check_sees_a_wrong_command_or_flag():
    assert _flag_problems(["line", "2", "2", "10", "6", "--algo", "dda"]) == []
    assert _flag_problems(["transform", "0", "0", "--rotate", "90", "--about", "2", "1"]) == []
    assert _flag_problems(["line", "-5", "0", "15", "10", "--algx", "dda"])
    assert _flag_problems(["transform", "0", "0", "--rotat", "90"])
    assert _flag_problems(["check", "a.csv", "--", "circle", "5", "--methd", "general"])
    assert _flag_problems(["lines", "2", "2", "10", "6"])


#: The README's flags in prose (`--tie keep`): each an option of some command, its value one
#: of that option's choices.
def _every_option() -> dict[str, list[Any]]:
    found: dict[str, list[Any]] = {}

    def walk(command: Any) -> None:
        for name, param in _options(command).items():
            found.setdefault(name, []).append(param)
        for sub in getattr(command, "commands", {}).values():
            walk(sub)

    walk(TOP)
    return found


def _choices(param: Any) -> tuple[str, ...] | None:
    choices = getattr(getattr(param, "type", None), "choices", None)
    return tuple(str(getattr(c, "value", c)) for c in choices) if choices else None


def test_every_flag_the_readme_names_exists_with_its_value():
    options = _every_option()
    problems = []
    for span in re.findall(r"`(-[^`]+)`", TEXT[README]):
        words = span.split()
        params = options.get(words[0])
        if params is None:
            problems.append(f"no option {words[0]}")
        elif len(words) == 2 and not words[1].isupper():
            allowed = [_choices(p) for p in params]
            if all(a is not None and words[1] not in a for a in allowed):
                problems.append(f"{span}: not one of {allowed}")
    assert not problems, problems


#: The students' pages, whose every command line is run.
STUDENT_PAGES = [
    README,
    *(
        ROOT / "docs" / f"{name}.md"
        for name in (
            "cheatsheet",
            "guide",
            "conventions",
            "process",
            "polygons",
            "theory",
            "errata",
            "formats",
        )
    ),
]
#: Command lines a page shows being refused (exit 2), as it says.
REFUSED = {
    "scanconv line 0 0 5 2 --algo dda --tie keep"
}  # conventions.md: a knob that does not apply


def _runnable(line: str) -> bool:
    """A command line to run here: not a command's name alone, not one that reads the
    teacher's files (check, sheet) or serves (site, mcp), and no size demonstration (a number
    of 100,000 or more: docs/performance.md measures those)."""
    words = shlex.split(line)[1:]
    big = any(re.fullmatch(r"\d{6,}", w) for w in words)
    return len(words) >= 2 and words[0] not in ("site", "mcp", "check", "sheet") and not big


@pytest.mark.slow  # about 170 command lines, 5 s
def test_every_command_line_of_the_students_pages_runs(tmp_path, monkeypatch):
    """Each command line of the README and the students' pages in docs/ exits 0 (in an empty
    folder with a docs/figures/ for the figures formats.md regenerates), and those a page shows
    refused exit 2."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "docs" / "figures").mkdir(parents=True)
    lines = [line for page in STUDENT_PAGES for line in _command_lines(page) if _runnable(line)]
    failed = []
    for line in dict.fromkeys(lines):
        result = run(*shlex.split(line)[1:])
        if result.code != (2 if line in REFUSED else 0):
            failed.append((line, result.code, result.err.strip()[:200]))
    assert len(lines) > 150 and not failed, failed


# --- counts --------------------------------------------------------------------------------


def _topics() -> list[str]:
    listed = run("theory", "--list")
    assert listed.code == 0, listed.err
    return [line.split()[0] for line in listed.out.splitlines() if line.strip()]  # name, question


def test_the_theory_topics_the_docs_count_and_list_are_the_programs():
    """``scanconv theory --list`` names as many topics as the README says, and docs/theory.md's
    table has a row for each of them and no other."""
    topics = _topics()
    said = re.findall(r"`scanconv theory --list`\s+names\s+the\s+(\d+)\s+topics", TEXT[README])
    assert said and all(int(n) == len(topics) for n in said)
    theory = TEXT[ROOT / "docs" / "theory.md"].split("## `scanconv color`", 1)[0]
    rows = re.findall(r"^\| `([a-z0-9-]+)` \|", theory, flags=re.M)
    assert sorted(rows) == sorted(topics)


def _exam_counts() -> tuple[int, int]:
    """The notes' questions of the book (its 3D section, beyond the notes, left out)."""
    from scanconv.cli.exam import BEYOND_NOTES, exam_sheet

    questions = [q for q in exam_sheet().questions if q.section != BEYOND_NOTES]
    topics = sum(1 for q in questions if q.marks == 14)
    return len(questions) - topics, topics


WORDS = {"seven": 7, "thirty": 30}
EXAM_CLAIMS = [
    r"typical exam question of the notes \((\d+)\) and its (\w+) 14-mark topics",
    r"the (\d+) typical exam questions and the (\w+) 14-mark topics",
    r"the notes' (\d+) typical exam questions and (\w+) closing topics",
]


def test_the_exam_counts_the_docs_state_are_the_books():
    """Every page that counts the exam's questions counts what ``scanconv exam`` answers: 30
    typical exam questions and 7 fourteen-mark topics."""
    typical, topics = _exam_counts()
    claims = [
        (page, m)
        for page in PAGES
        for pattern in EXAM_CLAIMS
        for m in re.finditer(pattern, " ".join(TEXT[page].split()), flags=re.I)
    ]
    assert len(claims) >= 4, "the README, the cheat sheet, teaching.md and theory.md count them"
    for page, m in claims:
        n, k = (int(WORDS.get(g, g)) for g in m.groups())
        assert (n, k) == (typical, topics), (_id(page), m[0])


def test_the_command_count_of_the_readme_is_the_programs():
    said = re.findall(r"`scanconv --help` lists the (\d+)\s+commands", TEXT[README])
    assert said == [str(len(COMMANDS))]


def test_the_formats_the_readme_lists_are_the_programs():
    """The README's ``--format`` line names every format of a single answer, each alias it
    gives is that format's, and each file name it gives is one of theirs."""
    from scanconv.questions.words import _FORMAT_NAMES
    from scanconv.render import EXTENSIONS, formats

    line = next(b for b in TEXT[README].split("\n- ") if b.startswith("`--format` (`-f`)"))
    listed = re.findall(r"`([a-z]+)`(?: \(`([a-z]+)`)?", line.split(":", 1)[1])
    assert sorted(name for name, _ in listed) == sorted(formats("answer"))
    for name, alias in listed:
        assert not alias or _FORMAT_NAMES[alias] == name
    files = next(b for b in TEXT[README].split("\n- ") if b.startswith("`-o FILE`"))
    extensions = re.findall(r"`answer(\.[a-z]+)`", files)
    assert extensions and all(EXTENSIONS[ext] in formats("answer") for ext in extensions)


def test_the_formats_docs_formats_md_lists_are_the_programs():
    """docs/formats.md's table has a row for ``auto`` and each format of a single answer; the
    extensions it says name a format each name one of them, every such format is named by
    one, and the extensions it says refuse a contradicting ``--format`` are the binding ones."""
    from scanconv.render import EXTENSIONS, FORMATS, Format, formats

    text = TEXT[ROOT / "docs" / "formats.md"].split("## Output formats", 1)[1]
    rows = re.findall(r"^\| `([a-z]+)`", text.split("\n\n## ", 1)[0], flags=re.M)
    assert rows == [f.value for f in Format]
    prose = " ".join(text.split())
    follows = re.search(r"when `--format` is not given \(((?:`[.a-z]+`[,/ ]*)+)\)", prose)
    refused = re.search(r"contradicts ((?:a )?(?:`[.a-z]+`(?:, | or )?)+) file is refused", prose)
    assert follows is not None and refused is not None
    named = {EXTENSIONS[ext] for ext in re.findall(r"`([.a-z]+)`", follows[1])}
    assert named == {name for name in formats("answer") if FORMATS[name].extensions}
    binding = {FORMATS[EXTENSIONS[ext]].binding for ext in re.findall(r"`([.a-z]+)`", refused[1])}
    listed = {EXTENSIONS[ext] for ext in re.findall(r"`([.a-z]+)`", refused[1])}
    assert binding == {True} and listed == {n for n, spec in FORMATS.items() if spec.binding}


def test_the_presets_the_readme_names_are_the_programs():
    from scanconv.algorithms.conventions import PRESETS

    said = re.search(r"`--convention notes`((?:, `[a-z-]+`)+)", " ".join(TEXT[README].split()))
    assert said is not None
    assert ["notes", *re.findall(r"`([a-z-]+)`", said[1])] == list(PRESETS)


@pytest.mark.slow  # four answers
def test_the_spellings_and_the_default_format_the_readme_gives_hold():
    """A point typed ``2,2`` or ``(2,2)`` and a size ``1024x768`` are the plain numbers, and
    Markdown is the format when the output is not a terminal (as in these in-process runs)."""
    text = " ".join(TEXT[README].split())
    assert "A point may be typed `2,2` or `(2,2)`, a size `1024x768`" in text
    assert "`markdown` (`md`; the default when the output is not a terminal" in text
    plain = run("line", "2", "2", "10", "6")
    assert plain.code == 0 and plain.out == run("line", "(2,2)", "10,6").out
    assert plain.out == run("line", "2,2", "(10,6)", "--format", "markdown").out
    assert (
        run("storage", "1024x768", "--levels", "256").out
        == run("storage", "1024", "768", "--levels", "256").out
    )


@pytest.mark.slow  # four runs of practice
def test_the_practice_options_teaching_md_gives_are_the_programs():
    """docs/teaching.md's topics, difficulties and count range of ``scanconv practice`` are the
    command's: the same topics (the notes' and those beyond them), the default topic and
    difficulty, and ``--count`` from 1 to 200, 10 questions by default."""
    import json

    options = _options(COMMANDS["practice"])
    page = TEXT[ROOT / "docs" / "teaching.md"]
    section = " ".join(page.split("## Practice questions")[1].split("\n## ")[0].split())
    named = re.search(r"`--topic ([a-z0-9|-]+)` \(default `([a-z]+)`", section)
    beyond = re.search(r"a topic beyond the notes: (.*?)`--count N`", section)
    assert named is not None and beyond is not None
    topics = named[1].split("|") + re.findall(r"`([a-z0-9-]+)`", beyond[1])
    assert sorted(topics) == sorted(_choices(options["--topic"]) or ())
    assert named[2] == options["--topic"].default.value
    levels = re.search(r"`--difficulty ([a-z|]+)`", section)
    assert levels is not None and levels[1].split("|") == list(
        _choices(options["--difficulty"]) or ()
    )
    assert "`--count N` (1 to 200, default 10)" in section
    made = run("practice", "--seed", "3", "--topic", "line", "--format", "json")
    assert made.code == 0 and len(json.loads(made.out)["questions"]) == 10
    for edge, code in (("0", 2), ("1", 0), ("201", 2)):
        assert run("practice", "--seed", "3", "--topic", "line", "--count", edge).code == code


# --- the modules the docs name -------------------------------------------------------------

DOTTED = re.compile(r"`(scanconv(?:\.[A-Za-z_][A-Za-z0-9_]*)+)")
PATH = re.compile(r"`(scanconv/[A-Za-z0-9_/]+(?:\.pyi?|/))`")


def _resolves(name: str) -> bool:
    """``name`` is a module of scanconv or an attribute of one."""
    parts = name.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj: Any = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for attr in parts[k:]:
            if not hasattr(obj, attr):
                return False
            obj = getattr(obj, attr)
        return True
    return False


#: A file name in code (``marking/mark.py``, ``rows.py``): relative to the checkout, to
#: ``scanconv/`` or to ``tests/``, or a bare name that some file of the project has.
FILE = re.compile(r"(?<![\w./-])([\w./-]+\.pyi?)\b")
#: Files a page names that are not meant to be there: architecture.md's sketch of a new format.
SKETCHED = {"render/mappings/typst.py", "render/documents/sheet_typst.py"}
PROJECT_FILES = {
    p.name for d in ("scanconv", "tests", "benchmarks") for p in (ROOT / d).rglob("*.py*")
}


def _file_exists(name: str) -> bool:
    if "/" not in name:
        return name in PROJECT_FILES
    return any((base / name).exists() for base in (ROOT, ROOT / "scanconv", ROOT / "tests"))


@pytest.mark.slow  # it imports every module a page names (numpy's too): up to 0.4 s a page
@pytest.mark.parametrize("page", PAGES, ids=_id)
def test_every_module_and_name_a_page_gives_exists(page):
    """A page that names ``scanconv/marking/models.py``, ``marking/tables.py`` or
    ``scanconv.render.FORMATS`` names something that is there (a module moved leaves no page
    pointing to its old place)."""
    missing = [p for p in PATH.findall(TEXT[page]) if not (ROOT / p).exists()]
    missing += [n for n in DOTTED.findall(TEXT[page]) if not _resolves(n)]
    for block in re.findall(r"```python\n(.*?)```", TEXT[page], flags=re.S):
        for module, names in re.findall(r"^(?:>>> )?from (scanconv\S*) import (.+)$", block, re.M):
            missing += [
                f"{module}.{n}" for n in re.split(r",\s*", names) if not _resolves(f"{module}.{n}")
            ]
    code = re.findall(r"`([^`\n]+)`", TEXT[page])
    missing += [
        f for span in code for f in FILE.findall(span) if f not in SKETCHED and not _file_exists(f)
    ]
    assert not missing, f"{_id(page)} names what is not there: {missing}"


def test_the_module_check_sees_a_moved_module():
    assert _resolves("scanconv.render.FORMATS") and _resolves("scanconv.questions.answer")
    assert not _resolves("scanconv.render.FORMAT") and not _resolves("scanconv.nosuch.module")
    assert _file_exists("marking/tables.py") and _file_exists("tables.py")
    assert not _file_exists("answers/marking.py") and not _file_exists("marking_table.py")


# --- pandoc --------------------------------------------------------------------------------


@pytest.mark.external
@pytest.mark.slow
def test_the_readme_renders_with_pandoc(tmp_path):
    """pandoc reads the README as GitHub Markdown without a warning, with every heading, the
    cheat sheet's table (a row per command) and every code block."""
    from .external import pandoc_with_warnings

    html, warnings = pandoc_with_warnings(tmp_path, TEXT[README], "gfm", "html")
    assert warnings == ""
    fences = re.findall(r"^```", TEXT[README], flags=re.M)
    prose = re.sub(r"^```.*?^```", "", TEXT[README], flags=re.S | re.M)
    assert len(re.findall(r"<h[12]", html)) == len(re.findall(r"^##? ", prose, flags=re.M))
    assert html.count("<tr") == len(re.findall(r"^\| ", prose, flags=re.M))
    assert html.count("<pre") == len(fences) // 2


def _rewrite(paths: list[str]) -> None:
    """Rewrite the shown outputs of the pages ``paths`` that no longer match."""
    patch = pytest.MonkeyPatch()
    for path in paths:
        text = Path(path).read_text(encoding="utf-8")

        def again(m: re.Match[str], path: str = path) -> str:
            result, tail = _run_shown(m[1], patch)
            actual = _output(result, tail, m[2])
            if _matches(m[2], actual):
                return m[0]
            if "\n...\n" in f"\n{m[2]}":  # lines left out: the block is for a person to mend
                print(f"{path}: `{m[1]}` no longer matches; mend it by hand")
                return m[0]
            return f"```text\n$ {m[1]}\n{actual}\n```"

        Path(path).write_text(SHOWN.sub(again, text), encoding="utf-8")
    patch.undo()


if __name__ == "__main__":
    _rewrite(sys.argv[1:])

"""``scanconv theory``: every define / explain / describe question of the notes has a model
answer whose live example is right, which fits a page and shows in every format."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from scanconv.algorithms.circles import images
from scanconv.answers.theory.topics import theory_solution, topic, topics
from scanconv.answers.theory.topics._build import LONGEST_CELL
from scanconv.render import Format, render
from scanconv.render.mappings.latex import split_columns
from scanconv.render.mappings.text import table_rows

from .external import typeset
from .helpers import assert_refused, run
from .notes_questions import NOTES, notes_questions

NAMES = [t.name for t in topics()]

#: The theory questions of the notes (define / explain / describe / what is / how), by the
#: start of their wording, and the 14-mark topics that are explained rather than computed.
THEORY_WORDS = re.compile(r"^(define|explain|describe|what (is|are)|how|write the storage)", re.I)


def _text(sol: object, fmt: Format) -> str:
    return "".join(c for c in render(sol, fmt) if isinstance(c, str))  # type: ignore[arg-type]


def test_the_topics_have_unique_names_and_questions() -> None:
    assert len(NAMES) == len(set(NAMES)) == 24 + 21  # the notes, and the papers beyond them
    asked = [q for t in topics() for q in t.questions]
    assert len(asked) == len(set(asked))


def test_every_theory_question_of_the_notes_has_a_topic() -> None:
    if not NOTES.exists():
        pytest.skip(f"the course notes are not here ({NOTES})")
    answered = {q.lower().rstrip(".?") for t in topics() for q in t.questions}
    theory = [
        q
        for section, q in notes_questions(NOTES.read_text(encoding="utf-8"))
        if section == "14 MARKS" or (THEORY_WORDS.match(q) and "compare" not in q.lower())
    ]
    assert len(theory) == 28  # 21 of the 30 questions, and the 7 topics
    missing = [q for q in theory if q.lower().rstrip(".?") not in answered]
    assert not missing


@pytest.mark.parametrize("name", NAMES)
def test_every_answer_has_a_definition_and_shows_in_every_format(name: str) -> None:
    sol = theory_solution(name)
    assert sol.notes[0].startswith("Definition: ") and len(sol.notes[0]) > 80
    for fmt in (Format.markdown, Format.latex, Format.plain, Format.csv):
        assert _text(sol, fmt).strip()
    data = json.loads(_text(sol, Format.json))
    assert data["algorithm"] == name and data["notes"][0].startswith("Definition")
    plain = _text(sol, Format.plain)
    assert plain.isascii() or name in ("rgb-model", "image-types"), [
        line for line in plain.splitlines() if not line.isascii()
    ][:3]


@pytest.mark.parametrize("name", NAMES)
def test_every_table_fits_a_page(name: str) -> None:
    """Cells are short, and LaTeX can set every table in at most two parts without \\tiny."""
    for table in theory_solution(name).tables:
        rows = list(table_rows(table))
        assert all(len(c) <= LONGEST_CELL for r in rows for c in r), table.title
        parts = split_columns(table.columns, rows)
        assert len(parts) <= 2 and all(layout[0] != "\\tiny" for _, layout in parts), table.title


def test_raster_display_addresses_one_pixel_in_both_origins() -> None:
    up, down = theory_solution("raster-display").tables[-2:]
    marked_up = [(x, r[0]) for r in up.rows() for x, c in enumerate(r[1:]) if c == "#"]
    marked_down = [(x, r[0]) for r in down.rows() for x, c in enumerate(r[1:]) if c == "#"]
    assert marked_up == [(3, 1)] and marked_down == [(3, 4 - 1)]
    assert [r[0] for r in up.rows()] == [4, 3, 2, 1, 0]
    assert [r[0] for r in down.rows()] == [0, 1, 2, 3, 4]


def test_symmetry_draws_the_eight_images_on_one_circle() -> None:
    sol = theory_solution("symmetry")
    (fig,) = sol.figures
    assert set(fig.pixels) == set(images(2, 5)) and len(set(fig.pixels)) == 8
    assert {x * x + y * y for x, y in fig.pixels} == {29}
    assert fig.marks == ((0, 0),)


def test_octants_one_line_each_from_the_origin() -> None:
    sol = theory_solution("octants")
    rows = list(sol.tables[1].rows())
    assert [r[0] for r in rows] == list(range(1, 9))
    for r in rows:
        end = r[1]
        pixels = r[2].split()
        assert "(0,0)" in (pixels[0], pixels[-1]) and end.replace(" ", "") in (
            pixels[0],
            pixels[-1],
        )
        assert len(pixels) == 7  # max(|dx|, |dy|) + 1 for every line
    drawn = {tuple(map(int, p.strip("()").split(","))) for r in rows for p in r[2].split()}
    assert set(sol.figures[0].pixels) == drawn


def test_image_types_show_the_bits_of_each_pixel() -> None:
    sol = theory_solution("image-types")
    one = {r[0]: r for r in sol.tables[1].rows()}
    assert one["Colour, 24-bit"][2] == f"{51:08b} {102:08b} {153:08b}"
    assert one["Grayscale, L = 8"][2] == f"{5:03b}"
    sizes = {r[0]: r for r in sol.tables[2].rows()}
    assert sizes["Colour, 24-bit"][2] == 640 * 480 * 24 == 8 * sizes["Colour, 24-bit"][3]


def test_the_process_table_follows_the_pipeline() -> None:
    sol = theory_solution("scan-conversion-process")
    stages = [r[1] for r in sol.tables[0].rows()]
    assert stages[2] == "clipped: (0, 2.5) to (10, 7.5)"
    assert stages[3].endswith(f"{sum(1 for _ in sol.pixels())} pixels (Bresenham)")


def test_techniques_sampled_coverage_sums_to_one_per_column() -> None:
    rows = list(theory_solution("techniques").tables[1].rows())
    for x, y, cover in rows:
        values = [float(part.split(": ")[1]) for part in cover.split("; ")]
        assert sum(values) == pytest.approx(0.5 if x in (2, 10) else 1)  # the ends: half
        assert f"y={y}:" in cover  # the DDA's pixel is one the line covers


def test_the_cli_lists_and_refuses() -> None:
    listed = run("theory", "--list")
    assert listed.code == 0 and [line.split()[0] for line in listed.out.splitlines()] == NAMES
    assert_refused(run("theory", "nope"), "unknown theory topic")
    assert topic("dda").section == "dda"
    helped = run("theory")
    assert helped.code == 0 and "Usage" in helped.out


@pytest.mark.external
@pytest.mark.slow
def test_every_answer_compiles_with_pdflatex_without_overfull_boxes(tmp_path: Path) -> None:
    from scanconv.render.documents.sheet_latex import (
        PREAMBLE,  # the exam book's: \emergencystretch=3em
    )

    body = "\n".join(_text(theory_solution(n), Format.latex) for n in NAMES)
    doc = PREAMBLE + body + "\n\\end{document}\n"
    done = typeset(tmp_path, doc, passes=2, pdf=False)  # longtable's widths; no PDF read
    log = done.log
    assert done.code == 0, log[-2000:]
    assert "Overfull" not in log, re.findall(r"Overfull.*", log)[:5]


@pytest.mark.parametrize(
    ("name", "algo"),
    [("dda", "dda"), ("bresenham-line", "bresenham"), ("scan-conversion", "bresenham")],
)
def test_the_examples_are_the_commands_own_answers(name: str, algo: str) -> None:
    """A live example is the answer ``scanconv line 2 2 10 6`` gives, row for row and pixel for
    pixel, not a copy."""
    from scanconv.answers.primitives.line import line_solution
    from scanconv.core.records import step_getter

    line = line_solution(algo, 2, 2, 10, 6)
    sol = theory_solution(name)
    table = next(t for t in sol.tables if t.title.endswith("step table"))
    get = step_getter(line.columns, line.extra_keys)
    assert list(table.rows()) == [get(s) for s in line.steps()]
    assert list(sol.pixels()) == list(line.pixels())

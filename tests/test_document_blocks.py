"""The typed answer document: every format is one mapping from the blocks,
the builder declares the structure the stepper used to guess, and a document built by hand
(no Solution behind it) renders in every format."""

from __future__ import annotations

import json
from fractions import Fraction
from itertools import count

import pytest

from scanconv.answers.compare import compare_lines
from scanconv.answers.curves.bezier import bezier_at_solution
from scanconv.answers.primitives.ellipse import ellipse_solution
from scanconv.answers.primitives.line import line_solution
from scanconv.core.records import Column, Move, PixelFigure, Solution, Step, heading, worked
from scanconv.document import (
    Document,
    Drawing,
    Given,
    Notes,
    Pixels,
    StepTable,
    Table,
    Title,
    Working,
    document,
    prose,
)
from scanconv.document.blocks import Block
from scanconv.render import Format, Notice, Options, render
from scanconv.render.html.stepper import stepping
from scanconv.render.mappings.html import HTML
from scanconv.render.mappings.latex import LATEX
from scanconv.render.mappings.terminal import RICH
from scanconv.render.mappings.text import MARKDOWN, PLAIN

BLOCKS = Block.__args__  # type: ignore[attr-defined]


def _block_mappings() -> dict[str, dict[type, object]]:
    """Every mapping from block types in the modules the format table names (each format's
    single-answer renderer and document writer): a table keyed by block types is one."""
    from importlib import import_module

    from scanconv.render import FORMATS

    modules = {
        e.split(":")[0] for spec in FORMATS.values() for e in (spec.renderer, spec.sheet) if e
    }
    found: dict[int, tuple[str, dict[type, object]]] = {}
    for name in sorted(modules):
        for attr, value in vars(import_module(f"scanconv.render.{name}")).items():
            if isinstance(value, dict) and value and all(k in BLOCKS for k in value):
                found.setdefault(id(value), (f"{name}.{attr}", value))  # once if re-exported
    return dict(found.values())


MAPPINGS = _block_mappings()


def test_the_mappings_are_found_in_the_formats_modules() -> None:
    """The walk below sees at least the five mappings known when it was written."""
    known = {id(m) for m in (PLAIN, MARKDOWN, LATEX, RICH, HTML)}
    assert known <= {id(m) for m in MAPPINGS.values()}, sorted(MAPPINGS)


@pytest.mark.parametrize("name", sorted(MAPPINGS))
def test_every_format_maps_every_block_type(name: str) -> None:
    assert set(MAPPINGS[name]) == set(BLOCKS)


def test_the_builder_reads_a_solution_in_reading_order() -> None:
    doc = document(line_solution("bresenham", 2, 2, 10, 6))
    kinds = [type(b) for b in doc.blocks]
    assert kinds == [Title, Given, Working, Notes, StepTable, Pixels]
    table = doc.get(StepTable)
    assert table.offset == 1 and table.symmetry == 1 and table.has_p and table.has_decision
    assert doc.get(Pixels).labels()[(10, 6)] == 8


def test_notes_carry_their_math_as_math() -> None:
    note = prose(r"$p_k < 0$ chooses E, 50% of <b>")
    assert note.segments[0] == (True, "p_k < 0")
    assert all(not math for math, _ in note.segments[1:])
    latex = "".join(c for c in render(_hand_made(), Format.latex) if isinstance(c, str))
    assert r"$p_k < 0$ chooses E, 50\% of" in latex


def test_the_ellipse_declares_its_regions_and_their_p() -> None:
    doc = document(ellipse_solution(8, 6))
    table = doc.get(StepTable)
    assert not table.shown
    st = stepping(doc)
    assert st is not None and set(st.row_region) == {1, 2}
    assert table.regions == "column" and table.region_p == ("p1_k", "p2_k")
    captions = " ".join(st.captions)
    assert "p1" in captions and "p2" in captions  # each region's own name of p


def test_regions_are_read_as_declared_not_guessed() -> None:
    """The same rows: ``restart`` starts region 2 where k starts again, ``none`` never does."""
    doc = _hand_made()
    regions = {}
    for how in ("restart", "none"):
        blocks = tuple(
            b._replace(regions=how) if isinstance(b, StepTable) else b for b in doc.blocks
        )
        st = stepping(doc._replace(blocks=blocks))
        assert st is not None
        regions[how] = st.row_region
    assert regions == {"restart": [1, 1, 2], "none": [1, 1, 1]}


def test_a_comparison_steps_through_its_declared_table() -> None:
    doc = document(compare_lines(0, 0, 6, 2))
    assert [t.stepped for t in doc.every(Table)][:1] == [True]
    flags = tuple(b._replace(stepped=False) if isinstance(b, Table) else b for b in doc.blocks)
    assert stepping(doc) is not None
    assert stepping(doc._replace(blocks=flags)) is None  # no flag, no stepper: nothing guessed


def _renamed(sol: Solution) -> Solution:
    """``sol`` under another algorithm name, every further table under another title."""
    tables = tuple(t._replace(title=f"Table {i}") for i, t in enumerate(sol.tables))
    return Solution(**{**sol.fields(), "algorithm": "x", "walk": sol.walk._replace(tables=tables)})


def test_the_structure_is_read_from_declared_fields_not_from_titles_or_names() -> None:
    """The old builder found regions by a regex over table titles and the stepped table and
    the construction points by algorithm name: renaming them changed the stepper."""
    for sol in (
        ellipse_solution(8, 6),
        compare_lines(0, 0, 6, 2),
        bezier_at_solution([(0, 0), (4, 8), (8, 0)], Fraction(1, 2)),
        line_solution("bresenham", 2, 2, 10, 6, derive=True),
    ):
        doc, other = document(sol), document(_renamed(sol))
        step, renamed = doc.get(StepTable), other.get(StepTable)
        assert (step is None) == (renamed is None)
        if step is not None:
            assert renamed[:-1] == step[:-1]  # all but the marking model's closure
        assert [(t.stepped, t.points) for t in other.every(Table)] == [
            (t.stepped, t.points) for t in doc.every(Table)
        ]
        assert other.get(Working) == doc.get(Working)
        if doc.get(Pixels) is not None:
            assert other.get(Pixels).construction == doc.get(Pixels).construction
    ellipse = document(_renamed(ellipse_solution(8, 6))).get(StepTable)
    assert ellipse.regions == "column" and ellipse.region_p == ("p1_k", "p2_k")
    line = document(line_solution("bresenham", 2, 2, 10, 6, derive=True)).get(Working)
    assert line.derivation[0].key == "derivation" and "derivation" not in {
        q.key for q in line.quantities
    }


def _stepped_answers() -> list[tuple[str, Solution]]:
    """Every line, circle and ellipse method of the records, in every layout it takes."""
    from scanconv.algorithms.choices import Layout
    from scanconv.answers.methods import methods_of
    from scanconv.answers.primitives.circle import circle_solution

    found = [(f"ellipse/{m}", ellipse_solution(8, 6)) for m in methods_of("ellipse")]
    for lay in Layout:
        found += [
            (f"line/{m} {lay.value}", line_solution(m, 2, 2, 10, 6, layout=lay.value))
            for m in methods_of("line")
        ]
        found += [
            (f"circle/{m} {lay.value}", circle_solution(m, 5, layout=lay.value))
            for m in methods_of("circle")
        ]
    return found


def test_every_stepped_answer_declares_the_pixel_its_heading_names() -> None:
    """``Walk.next_pixel`` is set by the answer that lays the table out; the heading a student
    reads says the same: ``(x_{k+1}, y_{k+1})`` exactly when the field is set (the numbering
    reads the field, so a heading and a field that disagree would number the grid wrong)."""
    answers = _stepped_answers()
    assert {key.split()[0] for key, _ in answers} >= {
        "line/bresenham",
        "line/midpoint",
        "circle/midpoint",
        "ellipse/midpoint",
    }
    declared = set()
    for key, sol in answers:
        heads = [c.tex.replace(" ", "") for c in sol.columns if c.key == "pixel"]  # wu: none
        assert any("k+1" in h for h in heads) == sol.walk.next_pixel, (key, heads)
        if sol.walk.next_pixel:
            declared.add(key)
    # by the notes and the textbooks: the (x_{k+1}, y_{k+1}) rows are these, no others
    assert declared == {
        "line/bresenham textbook",
        "line/midpoint textbook",
        "circle/midpoint textbook",
        "ellipse/midpoint",
    }


def _headed(sol: Solution, tex: str, next_pixel: bool) -> Solution:
    """``sol`` with its pixel column headed ``tex`` and ``next_pixel`` declared."""
    columns = tuple(heading("pixel", tex) if c.key == "pixel" else c for c in sol.columns)
    walk = sol.walk._replace(columns=columns, next_pixel=next_pixel)
    return Solution(**{**sol.fields(), "walk": walk})


def test_the_pixel_numbers_follow_the_declared_field_not_the_heading() -> None:
    """Bresenham's rows (2, 2) to (10, 6) headed "pixel", the field set: still numbered k + 1
    from the start's 0 (Hearn & Baker's table: row k plots (x_{k+1}, y_{k+1}), the pixels
    (3, 3), (4, 3), ... (10, 6)); the DDA's rows headed (x_{k+1}, y_{k+1}) without the field:
    still numbered k."""
    from scanconv.algorithms.lines import bresenham, dda
    from scanconv.document.numbering import label_offset, numbering_legend, step_labels

    plain = _headed(line_solution("bresenham", 2, 2, 10, 6), r"\text{pixel}", True)
    labels = step_labels(plain)
    assert label_offset(plain) == 1 and labels[(2, 2)] == 0
    assert all(labels[s.pixel] == s.k + 1 for s in bresenham(2, 2, 10, 6))
    assert numbering_legend(plain) == "number: k + 1 for row k; 0: start"
    assert document(plain).get(StepTable).offset == 1

    misled = _headed(line_solution("dda", 2, 2, 10, 6), "(x_{k+1}, y_{k+1})", False)
    firsts: dict[tuple[int, int], int] = {}
    for s in dda(2, 2, 10, 6):
        firsts.setdefault(s.pixel, s.k)
    assert label_offset(misled) == 0 and step_labels(misled) == firsts


def test_construction_points_are_a_table_flag() -> None:
    doc = document(bezier_at_solution([(0, 0), (4, 8), (8, 0)], Fraction(1, 2)))
    assert doc.get(Pixels).construction == "de Casteljau points"
    page = "".join(c for c in render(doc, Format.html) if isinstance(c, str))
    assert 'class="sc-level"' in page
    plain = tuple(b._replace(points=False) if isinstance(b, Table) else b for b in doc.blocks)
    page = "".join(c for c in render(doc._replace(blocks=plain), Format.html) if isinstance(c, str))
    assert 'class="sc-level"' not in page


def _hand_made() -> Document:
    """A document no Solution stands behind: three rows, k restarting once."""
    rows = [Step(0, 1, Move.E, (1, 0)), Step(1, -1, Move.NE, (2, 1)), Step(0, 3, Move.E, (3, 1))]
    columns = (
        Column("k", "k", "k"),
        heading("p", "p_k"),
        Column("decision", "move", r"\text{move}"),
        heading("pixel", "(x_k, y_k)"),
    )
    pixels = ((0, 0), (1, 0), (2, 1), (3, 1))
    numbers = dict(zip(pixels, count()))
    return Document(
        "demo",
        "hand",
        "A hand-made <answer>",
        (
            Title("A hand-made <answer>"),
            Given((worked("n", 3, r"n = 3"),)),
            Working((worked("p0", 1, r"p_0 = 2 - 1 = 1"),)),
            Notes((prose(r"$p_k < 0$ chooses E, 50% of <b>"),)),
            StepTable(columns, (), lambda: iter(rows)),
            Table("Totals", (Column("n", "n", "n"),), lambda: iter([(3,)])),
            Pixels(
                lambda: iter(pixels),
                (0, 0, 3, 1),
                (),
                "marked point",
                (),
                (),
                "outline",
                None,
                2,
                lambda: numbers,
                lambda: "number: row k",
            ),
            Drawing(PixelFigure(((0, 0),), ((1, 1),), (0, 0, 2, 2), "demo", "Demo figure")),
        ),
        {},
    )


@pytest.mark.parametrize("fmt", [f for f in Format if f is not Format.auto])
def test_a_hand_made_document_renders_in_every_format(fmt: Format) -> None:
    chunks = list(render(_hand_made(), fmt, Options()))
    text = "".join(c for c in chunks if isinstance(c, str))
    if fmt is Format.rich:
        assert len([c for c in chunks if not isinstance(c, str | Notice)]) > 5
        return
    if fmt is Format.csv:
        assert text.splitlines() == ["k,p,decision,x,y", "0,1,E,1,0", "1,-1,NE,2,1", "0,3,E,3,1"]
        return
    if fmt is Format.json:
        data = json.loads(text)
        assert data["pixels"] == [[0, 0], [1, 0], [2, 1], [3, 1]]
        assert [s["p"] for s in data["steps"]] == [1, -1, 3]
        assert data["tables"][0]["rows"] == [[3]]
        return
    assert "hand-made" in text and "Totals" in text
    if fmt is Format.html:
        assert "&lt;answer&gt;" in text and "<answer>" not in text


def test_the_html_page_of_a_hand_made_document_steps_through_its_rows() -> None:
    page = "".join(c for c in render(_hand_made(), Format.html) if isinstance(c, str))
    assert page.count("data-pos=") >= 4 and "region 2" in page


@pytest.mark.parametrize("fmt", [f for f in Format if f is not Format.auto])
def test_every_format_is_declared_once_with_a_renderer_that_loads(fmt: Format) -> None:
    from importlib import import_module

    from scanconv.render import EXTENSIONS, FORMATS
    from scanconv.render.budget import DEFAULT_COSTS

    spec = FORMATS[fmt]
    module, name = spec.renderer.split(":")
    assert callable(getattr(import_module(f"scanconv.render.{module}"), name))
    assert all(EXTENSIONS[ext] == fmt for ext in spec.extensions)
    assert DEFAULT_COSTS[fmt.value] == spec.row_cost


def test_the_derivation_is_its_own_part_of_the_working() -> None:
    working = document(line_solution("bresenham", 2, 2, 10, 6, derive=True)).get(Working)
    assert working.quantities and working.derivation[0].key == "derivation"
    assert all(q.key != "derivation" for q in working.quantities)
    plain = document(line_solution("bresenham", 2, 2, 10, 6)).get(Working)
    assert plain.derivation == () and plain.lines == plain.quantities

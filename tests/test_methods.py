"""The method records (scanconv.answers.methods): every method of every command is declared
once, with every piece there or its absence explained, and an unknown method is refused."""

from __future__ import annotations

import pytest

from scanconv.algorithms.choices import LineAlgorithm
from scanconv.algorithms.circle_choices import CircleMethod
from scanconv.algorithms.conventions import KNOBS
from scanconv.algorithms.process_choices import AAMethod, LineClipMethod, PolygonClipMethod
from scanconv.answers.asked import LineQuestion
from scanconv.answers.methods import (
    DOCUMENTS,
    METHODS,
    PIECES,
    STEPPED,
    Method,
    checked,
    method,
    methods_of,
)
from scanconv.answers.primitives.line import line_solution
from scanconv.core.checks import InputError
from scanconv.core.records import Quantity, Solution, rule

RECORDS = sorted(METHODS.values(), key=lambda m: m.key)


@pytest.mark.parametrize("record", RECORDS, ids=lambda m: m.key)
def test_every_piece_is_there_or_explained(record: Method) -> None:
    for piece in PIECES:
        ref = getattr(record, piece)
        if ref is None:
            assert record.reason(piece), f"{record.key}: no {piece} and no reason given"
        else:
            assert record.reason(piece) is None, f"{record.key}: {piece} is there and excused"
            assert callable(record.load(piece)), f"{record.key}: {piece} = {ref} is not callable"
    assert record.answer is not None
    assert all(us > 0 for _, us in record.costs)
    assert record.title


@pytest.mark.parametrize(
    ("command", "choices"),
    [
        ("line", LineAlgorithm),
        ("circle", CircleMethod),
        ("antialias", AAMethod),
        ("clip", LineClipMethod),
        ("clip", PolygonClipMethod),
    ],
)
def test_every_choice_has_a_record(command: str, choices: type) -> None:
    for choice in choices:
        assert method(command, choice.value).name == choice.value


def test_every_knob_names_a_recorded_method() -> None:
    for knob in KNOBS.values():
        for key in knob.applies:
            command, _, name = key.partition("/")
            assert knob.name in method(command, name).knobs


@pytest.mark.parametrize("record", RECORDS, ids=lambda m: m.key)
def test_a_piece_that_is_missing_is_refused_by_name(record: Method) -> None:
    for piece in PIECES:
        if getattr(record, piece) is None:
            with pytest.raises(InputError, match=piece) as info:
                record.load(piece)
            assert info.value.param == "method"


@pytest.mark.parametrize("command", sorted({m.command for m in RECORDS}))
def test_an_unknown_method_raises_naming_the_choices(command: str) -> None:
    with pytest.raises(InputError) as info:
        method(command, "no-such-method")
    assert info.value.param == "method"
    for name in methods_of(command):
        assert name in str(info.value)


def test_an_unknown_command_raises() -> None:
    with pytest.raises(InputError, match="unknown command"):
        method("spiral", "archimedes")


_MARK = "replaced by the test"


def _fake_answer(q: LineQuestion) -> Solution:
    """A line answer that is not the DDA's: the basic method's, retitled."""
    sol = line_solution("basic", *q.points)
    sol.title = _MARK
    return sol


def _fake_derivation(q: LineQuestion) -> tuple[Quantity, ...]:
    return (rule("fake", r"\text{" + _MARK + "}"),)


class _FakeModel:
    shape = "at"


def _fake_model(q: LineQuestion) -> _FakeModel:
    return _FakeModel()


def _fake_practice(q: LineQuestion) -> str:
    return f"{_MARK}: ({q.x1}, {q.y1}) to ({q.x2}, {q.y2})"


def _fake_rows(q: LineQuestion) -> int:
    return 3_000_000  # past what any format prints


def test_a_record_s_pieces_are_what_the_commands_call(monkeypatch: pytest.MonkeyPatch) -> None:
    """Replace line/dda's pieces in its record: the answer, the derivation, the marking model,
    the practice question's wording and the budget's row estimate all change (there is no
    branch left that could answer with the old pieces)."""
    import scanconv.answers.methods as methods
    from scanconv.marking.diagnose import model_for
    from scanconv.practice.notes import practice
    from scanconv.render.budget import BudgetError, check_work
    from scanconv.render.work import estimate

    here = "tests.test_methods:"
    record = methods.METHODS["line/dda"]
    args = {"x1": 0, "y1": 0, "x2": 8, "y2": 3, "algo": "dda"}
    before = line_solution("dda", 0, 0, 8, 3, derive=True)
    assert before.title != _MARK and model_for(before) is not None
    assert estimate("line", args).rows == 9  # max(|dx|, |dy|) + 1
    monkeypatch.setitem(
        methods.METHODS,
        "line/dda",
        record._replace(
            answer=here + "_fake_answer",
            derivation=here + "_fake_derivation",
            model=here + "_fake_model",
            practice=here + "_fake_practice",
            rows=here + "_fake_rows",
        ),
    )
    after = line_solution("dda", 0, 0, 8, 3, derive=True)
    assert after.title == _MARK and after.algorithm == "basic"
    assert after.theory.derivation[-1].key == "fake"
    assert isinstance(model_for(after), _FakeModel)
    asked = [q for q in practice("line", 6, seed=3) if "dda" in q.argv]
    assert asked and all(q.wording.startswith(_MARK) for q in asked)
    assert estimate("line", args).rows == 3_000_000
    with pytest.raises(BudgetError, match="3,000,000 rows"):
        check_work("line", args, None)


_GOT: list[object] = []
"""The questions the fake pieces below were given."""


def _fake_piece(q: object) -> Solution:
    """An answer that only records its question."""
    _GOT.append(q)
    return Solution("fake", "fake", _MARK, (), ())


def _fake_stage(q: object) -> object:
    """A clipping stage that always keeps the segment (1, 1) to (3, 2)."""
    from scanconv.answers.process._shared import Clipped

    _GOT.append(q)
    return Clipped([], [], ((1, 1), (3, 2)))


def test_the_clip_fill_and_projection_records_pieces_are_what_the_commands_call(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Replace clip's, fill's and 3d projection's pieces in their records: each command's
    answer changes, each piece gets the one typed question (the numbers as the command
    checked them), and the answer keeps it."""
    import scanconv
    import scanconv.answers.methods as methods
    from scanconv.answers.asked import ClipLineQuestion, ClipPolygonQuestion, FillQuestion

    here = "tests.test_methods:"
    room = "#####/#.a.#/#####"  # 'a' stops a flood fill from (1, 1), not a boundary fill
    assert sorted(scanconv.fill("flood", (1, 1), rows=room).pixels()) == [(1, 1)]
    cabinet = methods.METHODS["3d/cabinet"].generator
    for key, piece in (
        ("clip/liang-barsky", {"answer": here + "_fake_piece"}),
        ("clip/nicholl-lee-nicholl", {"stage": here + "_fake_stage"}),
        ("clip/weiler-atherton", {"answer": here + "_fake_piece"}),
        ("fill/flood", {"answer": "scanconv.answers.process.fill.seed:boundary_answer"}),
        ("fill/boundary", {"answer": here + "_fake_piece"}),
        ("3d/cavalier", {"generator": cabinet}),
    ):
        monkeypatch.setitem(methods.METHODS, key, methods.METHODS[key]._replace(**piece))
    _GOT.clear()

    clipped = scanconv.clip_line(7, 9, 11, 4, (4, 4, 10, 8), "liang-barsky")
    asked = ClipLineQuestion("liang-barsky", (7, 9), (11, 4), (4, 4, 10, 8))
    assert clipped.title == _MARK and _GOT.pop() == asked and clipped.question == asked

    piped = scanconv.pipeline_line(-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10),
                                   clip="nicholl-lee-nicholl")  # fmt: skip
    assert piped.data["clipped"] == [[1, 1], [3, 2]]  # the fake stage's, mapped on from there
    assert _GOT.pop() == ClipLineQuestion("nicholl-lee-nicholl", (-5, 0), (15, 10), (0, 0, 10, 10))

    polygon = scanconv.clip_polygon([(0, 0), (8, 0), (8, 8)], (2, 1, 9, 3), "weiler-atherton")
    asked_polygon = ClipPolygonQuestion("weiler-atherton", (0, 0, 8, 0, 8, 8), (2, 1, 9, 3))
    assert polygon.title == _MARK and _GOT.pop() == asked_polygon
    assert polygon.question == asked_polygon

    # flood's record now answers with the boundary fill: 'a' is filled too (by hand)
    flood = scanconv.fill("flood", (1, 1), rows=room)
    assert sorted(flood.pixels()) == [(1, 1), (2, 1), (3, 1)]
    assert flood.question == FillQuestion("flood", (1, 1), rows=(room,))
    boundary = scanconv.fill("boundary", (2, 2), vertices=[(0, 0), (5, 0), (5, 4)],
                             connectivity=8, order="queue")  # fmt: skip
    assert boundary.title == _MARK
    assert _GOT.pop() == FillQuestion("boundary", (2, 2), (0, 0, 5, 0, 5, 4), None, 8, "queue")
    assert _GOT == []

    # cavalier's record builds with cabinet's generator: L1 = 1/2, so the vertex (0, 0, 1)
    # lands at (cos 45°, sin 45°)/2 = (sqrt(2)/4, sqrt(2)/4), not cavalier's sqrt(2)/2
    cavalier = scanconv.project3d(solid="unit-cube", parallel="cavalier")
    assert cavalier.data["projected"][4] == ["sqrt(2)/4", "sqrt(2)/4"]
    assert cavalier.question.key == "3d/cavalier"


def test_a_record_missing_a_piece_fails_when_the_table_is_built() -> None:
    good = method("line", "dda")
    for piece in ("generator", "errata", "rows"):
        with pytest.raises(TypeError, match=piece):
            checked(good._replace(**{piece: None}))
    with pytest.raises(TypeError, match="answer = 'no_colon'"):
        checked(good._replace(answer="no_colon"))
    with pytest.raises(TypeError, match="rows and a cost"):
        checked(good._replace(cost=0.0))
    assert checked(good) is good


_ASKED = {
    "line": [(2, 3, -7, 9), (0, 0, 8, 3), (1, 1, 1, 1), (0, 0, 1, 40), (5, 2, 70, -11)],
    "circle": [(1,), (10,), (57,), (200,)],
    "ellipse": [(8, 6), (1, 20), (30, 2), (50, 50)],
}


@pytest.mark.parametrize("record", [r for r in RECORDS if r.command in STEPPED], ids=str)
def test_every_stepped_method_estimates_its_own_rows(record: Method) -> None:
    """Each line, circle and ellipse record's row estimate (the budget's) is never below the
    rows its answer prints, counted here by running the answer, and at most about twice them
    (a per-command estimate undercounts a method that walks more finely: the symmetric DDA
    circle's (π/4)·2^n steps are up to 1.6 r, not the octant's 0.71 r)."""
    from scanconv.answers.primitives.circle import circle_solution
    from scanconv.answers.primitives.ellipse import ellipse_solution

    assert record.rows and record.errata and record.cost > 0
    solve = {"line": line_solution, "circle": circle_solution, "ellipse": ellipse_solution}
    for given in _ASKED[record.command]:
        args = given if record.command == "ellipse" else (record.name, *given)
        sol = solve[record.command](*args)  # type: ignore[operator]
        printed = sum(1 for _ in sol.steps())
        estimate = record.load("rows")(sol.question)
        assert printed <= estimate <= 2 * printed + 3, (given, printed, estimate)


def test_line_titles_are_the_notes_names() -> None:
    assert method("line", "bresenham").title == "Bresenham's line algorithm"
    assert "p0 = 1 - r" in method("circle", "midpoint").title


def test_every_command_has_method_records_or_is_a_document() -> None:
    from scanconv.cli.application import TOPIC_OF

    for command in TOPIC_OF:
        has = bool(methods_of(command))
        assert has != (command in DOCUMENTS), command
    assert set(DOCUMENTS) <= set(TOPIC_OF)


def test_every_step_table_method_has_its_row_costs_for_the_budget() -> None:
    """The line, circle and ellipse methods (tables as long as the input makes them) carry a
    base cost per row, and the budget reads their measured costs from the record; a format
    that a record does not measure costs the base times the format's one factor."""
    from scanconv.render import FORMATS, Format
    from scanconv.render.budget import row_cost
    from scanconv.render.work import COSTS, Work

    for record in RECORDS:
        if record.command in STEPPED:
            assert record.cost > 0 and dict(record.costs).get("csv", record.cost) == record.cost
            if record.costs:
                assert COSTS[record.key] == dict(record.costs)
            unmeasured = record._replace(costs=())
            for f in Format:
                if f is Format.auto:
                    continue
                work = Work("rows", 1, None, record.key)
                measured = dict(record.costs).get(f.value)
                want = measured or unmeasured.cost * FORMATS[f.value].row_factor
                assert row_cost(work, f) == pytest.approx(max(want, 0.2)), (record.key, f)


def name_tests() -> list[tuple[str, int]]:
    """Where the library tests a method's name outside the records: a comparison with a
    string that is a method name of :data:`METHODS` (``algo == "dda"``, ``method in
    ("area", ...)``) or a dict literal keyed by one, in every module but ``methods.py``. A
    name that is also a command's (``line``, ``circle``) is not counted: it is the command."""
    import ast
    from pathlib import Path

    import scanconv

    root = Path(scanconv.__file__).parent
    names = {m.name for m in RECORDS} - {m.command for m in RECORDS}

    def strings(node: ast.AST | None) -> list[str]:
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return [node.value]
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            return [s for e in node.elts for s in strings(e)]
        return []

    found = []
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if rel == "answers/methods.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Compare):
                tested = [s for n in (node.left, *node.comparators) for s in strings(n)]
            elif isinstance(node, ast.Dict):
                tested = [s for k in node.keys for s in strings(k)]
            else:
                continue
            if names.intersection(tested):
                found.append((rel, node.lineno))
    return found


STEPPED_MODULES = (
    "answers/asked.py",
    "answers/compare.py",
    "answers/primitives/line.py",
    "answers/primitives/midpoint_line.py",
    "answers/primitives/circle.py",
    "answers/primitives/circle_pieces.py",
    "answers/primitives/line_pieces.py",
    "answers/primitives/ellipse.py",
    "answers/theory/errata.py",
    "answers/theory/derivations.py",
    "marking/diagnose.py",
    "marking/models.py",
    "practice/notes.py",
)
"""The modules of the stepped commands' pieces: each reaches a method through its record."""


def test_the_stepped_commands_test_no_method_name_outside_the_records() -> None:
    found = name_tests()
    assert [f for f in found if f[0] in STEPPED_MODULES] == []
    # the other commands' modules still test names (130 on main d7383ad, 134 on aecc9e1, 89 on
    # 8ef883e): this only falls
    assert len(found) <= 7, found

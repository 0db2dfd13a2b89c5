"""The method records (scanconv.answers.methods): every method of every command is declared
once, with every piece there or its absence explained, and an unknown method is refused."""

from __future__ import annotations

import pytest

from scanconv.algorithms.choices import LineAlgorithm
from scanconv.algorithms.circle_choices import CircleMethod
from scanconv.algorithms.conventions import KNOBS
from scanconv.algorithms.process_choices import AAMethod, LineClipMethod, PolygonClipMethod
from scanconv.answers.methods import DOCUMENTS, METHODS, PIECES, Method, method, methods_of
from scanconv.core.checks import InputError

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


def test_line_answers_dispatch_through_the_records(monkeypatch: pytest.MonkeyPatch) -> None:
    """The line answer calls the builder its record names: a record pointing elsewhere is used
    (there is no branch left that could answer with another method)."""
    import scanconv.answers.methods as methods
    from scanconv.answers.primitives.line import line_solution

    calls = []

    def fake(*args: object) -> object:
        calls.append(args)
        return line_solution("basic", 0, 0, 3, 1)

    monkeypatch.setitem(
        methods.METHODS,
        "line/dda",
        methods.METHODS["line/dda"]._replace(answer="tests.test_methods:_FAKE"),
    )
    monkeypatch.setitem(globals(), "_FAKE", fake)
    line_solution("dda", 0, 0, 3, 1)
    assert len(calls) == 1 and calls[0][:4] == (0, 0, 3, 1)


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
    """The line, circle and ellipse methods (tables as long as the input makes them) carry
    a measured cost per row in every format, and the work budget reads them from the record."""
    from scanconv.render import Format
    from scanconv.render.work import COSTS

    formats = {f.value for f in Format if f.value != "auto"}
    for record in RECORDS:
        if record.command in ("line", "circle", "ellipse"):
            assert {f for f, _ in record.costs} == formats, record.key
            assert COSTS[record.key] == dict(record.costs)

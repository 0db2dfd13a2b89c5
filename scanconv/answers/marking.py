"""Marking a student's step table against the answer of a question, with follow-through.

:func:`mark` compares a :class:`~scanconv.core.student_table.StudentTable` row by row with
the :class:`~scanconv.core.records.Solution` of the question. Until the first wrong row each
row is compared with the answer; after it, **follow-through**: each row is judged by running
the algorithm one step from the student's own previous row (:mod:`.models`), so one slip costs
one row. The alignment is found, not assumed: the start-pixel row may be there or not, and a
row may hold ``(x_k, y_k)`` (the notes' layout) or ``(x_{k+1}, y_{k+1})`` (the textbooks').

:func:`diagnose` names a known convention (any knob combination of ``docs/conventions.md``,
with the presets that use it) or a known mistake (each an explicit variant: the notes' p0 of
errata E1, end points not swapped, the midpoint update with the old x, stopping one step early
or late) when the student's whole table is exactly that variant's.

:func:`marking_solution` makes the marking a :class:`~scanconv.core.records.Solution` whose
table is the row-by-row marking, so every format of :mod:`scanconv.render` can show it.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ..algorithms.conventions import KNOBS, PRESETS, ROUNDING_TEXT
from ..core.checks import InputError
from ..core.numeric import Number, fmt_short
from ..core.records import Pixel, Quantity, Solution, Table, heading
from ..core.student_table import Cell, StudentTable
from .models import (
    BresenhamCircle,
    BresenhamLine,
    DDALine,
    GeneralCircle,
    MidpointCircle,
    MidpointEllipse,
    Model,
    NotesP0Line,
    OldXMidpoint,
    State,
    UnswappedLine,
    chain,
)

MAX_QUESTION_ROWS = 10**4
"""Most rows of a question's table that ``check`` marks against: twice the longest student
table (:data:`~scanconv.core.student_table.MAX_TABLE_ROWS`); a longer question is refused
before any marking (its table, and each convention's, is held in memory)."""


class Got(NamedTuple):
    """One student row, as the marking reads it."""

    where: str
    point: tuple[Cell | None, Cell | None] | None
    p: Cell | None
    p_next: Cell | None
    exact: tuple[Cell | None, Cell | None] | None


class Expected(NamedTuple):
    """What a row should hold, and the state it was judged from (for the explanation)."""

    point: Pixel
    p: Number | None
    p_next: Number | None
    exact: tuple[Number, Number] | None
    source: State | None = None
    """The state of the row (``at``) or the state its step starts from (``after``)."""
    prev: State | None = None
    """The state the row's p was computed from (``None``: the first row, p0)."""


class Verdict(NamedTuple):
    """The mark of one row."""

    row: int
    """1-based position among the marked rows."""
    where: str
    got: Got | None
    expected: Expected | None
    mark: str
    """``right``, ``right (follow-through)``, ``wrong``, ``missing`` or ``extra``."""
    wrong: tuple[str, ...] = ()
    """The fields that are wrong: ``pixel``, ``p``, ``p_next``, ``exact``."""


class Marking(NamedTuple):
    """A marked table."""

    verdicts: tuple[Verdict, ...]
    right: int
    total: int
    first_error: str
    diagnosis: str
    follow_through: bool
    """False: the command has no step model here, later rows are compared with the answer."""
    fields: tuple[str, ...]
    """What was marked: among ``pixel``, ``p``, ``p_next``, ``exact``."""
    skipped: str = ""
    """A student row left unmarked (the start pixel in a table of (x_{k+1}, y_{k+1}))."""


# --- the model of a question ------------------------------------------------------------------


def _given(solution: Solution) -> dict[str, Any]:
    return {q.key: q.value for q in solution.given}


def _ends(solution: Solution) -> tuple[int, int, int, int] | None:
    """A line's end points as integers (``None``: not integers, or not a line)."""
    g = _given(solution)
    if "P1" not in g or "P2" not in g:
        return None
    (x1, y1), (x2, y2) = g["P1"], g["P2"]
    v = [Fraction(x1), Fraction(y1), Fraction(x2), Fraction(y2)]
    if any(f.denominator != 1 for f in v):
        return None
    return v[0].numerator, v[1].numerator, v[2].numerator, v[3].numerator


def model_for(solution: Solution, knobs: dict[str, str] | None = None) -> Model | None:
    """The step model of ``solution``'s algorithm with its conventions (``knobs`` override
    them), or ``None`` for a command marked without follow-through."""
    k = dict(solution.data.get("conventions", {}))
    k.update(knobs or {})
    g = _given(solution)
    prim, algo = solution.primitive, solution.algorithm
    if prim == "line" and "P1" in g and "P2" in g:
        (x1, y1), (x2, y2) = g["P1"], g["P2"]
        if algo == "bresenham":
            ends = _ends(solution)
            if ends is None:
                return None
            m: Model = BresenhamLine(*ends, k.get("tie", "step"), k.get("start", "swap"))
            m.shape = "after" if solution.data.get("layout") == "textbook" else "at"
            return m
        if algo == "dda":
            return DDALine(x1, y1, x2, y2, k.get("rounding", "half-up"), k.get("start", "given"))
        return None
    if prim == "circle" and "r" in g:
        r = int(g["r"])
        if algo == "midpoint":
            shape = "after" if solution.data.get("layout") == "textbook" else "at"
            return MidpointCircle(
                r, k.get("tie", "step"), k.get("p0", "1-r"), k.get("loop", "strict"), shape
            )
        if algo == "bresenham":
            return BresenhamCircle(r, k.get("tie", "step"))
        if algo == "general":
            return GeneralCircle(r, k.get("tie", "step"), k.get("loop", "strict"))
        return None
    if prim == "ellipse" and algo == "midpoint" and "rx" in g:
        return MidpointEllipse(
            int(g["rx"]),
            int(g["ry"]),
            k.get("loop", "strict"),
            k.get("tie", "step"),
            k.get("p0", "exact"),
        )
    return None


def rows_of(states: Sequence[State], shape: str, model: Model | None = None) -> list[Expected]:
    """The rows a chain of states prints in a layout: ``at`` (a row per state) or ``after``
    (a row per step: p_k and the point reached)."""
    n = len(states)
    if shape == "at":
        return [
            Expected(
                s.point,
                s.p,
                states[i + 1].p if i + 1 < n else None,
                s.exact,
                s,
                states[i - 1] if i else None,
            )
            for i, s in enumerate(states)
        ]
    return [
        Expected(
            states[i + 1].point,
            states[i].p,
            states[i + 1].p,
            states[i + 1].exact,
            states[i],
            states[i - 1] if i else None,
        )
        for i in range(n - 1)
    ]


def _solution_rows(solution: Solution) -> list[Expected]:
    """The answer's rows as printed, for a command without a model (pixels only)."""
    steps = itertools.islice(solution.steps(), MAX_QUESTION_ROWS + 1)
    rows = [Expected(s.pixel, s.p, None, None) for s in steps]
    _check_size(len(rows))
    return rows


def _check_size(rows: int) -> None:
    if rows > MAX_QUESTION_ROWS:
        raise InputError(
            f"the question's table has more than {MAX_QUESTION_ROWS} rows "
            f"(check marks at most {MAX_QUESTION_ROWS})",
            "question",
        )


def _agrees(model: Model, states: list[State], solution: Solution) -> bool:
    """The model's chain prints the answer's own table (pixels and p): a safety net."""
    rows = rows_of(states, model.shape)
    steps = list(itertools.islice(solution.steps(), len(rows) + 1))
    return len(steps) == len(rows) and all(
        r.point == s.pixel and r.p == s.p for r, s in zip(rows, steps, strict=True)
    )


# --- reading the student's rows ---------------------------------------------------------------


def _pair(cells: dict[str, Any], pair: str, x: str, y: str) -> tuple[Cell | None, Cell | None]:
    if pair in cells:
        v = cells[pair]
        return (None, None) if v is None else v
    return (cells.get(x), cells.get(y))


def student_rows(table: StudentTable, exact_algorithm: bool) -> tuple[list[Got], set[str]]:
    """The student's rows as :class:`Got`, and the fields that will be marked."""
    f = set(table.fields)
    rounded = "pxy" if "pxy" in f else "px" if "px" in f else None
    plain = "xy" if "xy" in f else "x" if "x" in f else None
    pixel_src, exact_src = rounded or plain, None
    if exact_algorithm and plain is not None:
        if rounded is not None:
            exact_src = plain
        elif any(
            c is not None and c.value.denominator != 1
            for r in table.rows
            for c in _pair(r.cells, "xy", "x", "y")
        ):
            pixel_src, exact_src = None, plain
    marked = {"pixel"} if pixel_src else set()
    if exact_src:
        marked.add("exact")
    marked |= {name for name in ("p", "p_next") if name in f}
    rows = []
    for r in table.rows:
        c = r.cells
        point = _pair(c, *_SOURCES[pixel_src]) if pixel_src else None
        exact = _pair(c, *_SOURCES[exact_src]) if exact_src else None
        rows.append(Got(r.where, point, _one(c.get("p")), _one(c.get("p_next")), exact))
    return rows, marked


def _one(v: Any) -> Cell | None:
    return v if isinstance(v, Cell) else None


_SOURCES = {"pxy": ("pxy", "px", "py"), "px": ("pxy", "px", "py"), "xy": ("xy", "x", "y")}
_SOURCES["x"] = _SOURCES["xy"]


def _same(c: Cell | None, v: Number | None) -> bool:
    """A student's number equals an exact value: exactly, or written to 2 or more decimals
    and within one unit of the last one (``2.333`` for 7/3, ``0.66`` for 2/3)."""
    if c is None or v is None:
        return c is None and v is None
    return c.value == v or (c.places >= 2 and abs(c.value - v) <= Fraction(1, 10**c.places))


def _wrong_fields(got: Got, exp: Expected, marked: set[str], last: bool) -> tuple[str, ...]:
    wrong = []
    if "pixel" in marked and (
        got.point is None
        or got.point[0] is None
        or got.point[1] is None
        or (got.point[0].value, got.point[1].value) != exp.point
    ):
        wrong.append("pixel")
    if "exact" in marked and exp.exact is not None:
        e = got.exact or (None, None)
        if not (_same(e[0], exp.exact[0]) and _same(e[1], exp.exact[1])):
            wrong.append("exact")
    for name, want, have in (("p", exp.p, got.p), ("p_next", exp.p_next, got.p_next)):
        if name not in marked or want is None or (have is None and last):
            continue
        if not _same(have, want):
            wrong.append(name)
    return tuple(wrong)


# --- marking ----------------------------------------------------------------------------------


class _Layout(NamedTuple):
    shape: str
    skip_expected: int
    """1: the student left out the start row of an ``at`` table."""
    skip_student: int
    """1: the student's first row is the start pixel of an ``after`` table (not marked)."""


def _layouts(table: StudentTable, default: str) -> list[_Layout]:
    order = ["after", "at"] if table.after or default == "after" else ["at", "after"]
    out = []
    for shape in order:
        out += [
            _Layout(shape, 0, 0),
            _Layout(shape, 1, 0) if shape == "at" else _Layout(shape, 0, 1),
        ]
    return out


def _starts_at(got: Got, point: Pixel) -> bool:
    return (
        got.point is not None
        and got.point[0] is not None
        and got.point[1] is not None
        and (got.point[0].value, got.point[1].value) == point
    )


def _straight(
    gots: list[Got], rows: Callable[[str], list[Expected]], lay: _Layout, marked: set[str]
) -> tuple[int, list[Expected], list[Got]] | None:
    """Rows right when compared position by position in one layout (``None``: not possible)."""
    exp = rows(lay.shape)
    if lay.skip_student:
        start = rows("at")[:1]
        if not (gots and start and _starts_at(gots[0], start[0].point)):
            return None
    exp = exp[lay.skip_expected :]
    mine = gots[lay.skip_student :]
    right = sum(
        not _wrong_fields(g, e, marked, i == len(mine) - 1)
        for i, (g, e) in enumerate(zip(mine, exp, strict=False))
    )
    return right - abs(len(exp) - len(mine)), exp, mine


def _of(states: Sequence[State]) -> Callable[[str], list[Expected]]:
    return lambda shape: rows_of(states, shape)


def _best(
    gots: list[Got], states: list[State], layouts: list[_Layout], marked: set[str]
) -> tuple[_Layout, list[Expected], list[Got]]:
    best: tuple[int, int, _Layout, list[Expected], list[Got]] | None = None
    for n, lay in enumerate(layouts):
        found = _straight(gots, _of(states), lay, marked)
        if found is None:
            continue
        score, exp, mine = found
        if best is None or score > best[0]:
            best = (score, n, lay, exp, mine)
    assert best is not None
    return best[2], best[3], best[4]


def _student_state(got: Got, base: State, marked: set[str]) -> State:
    """The state a student's row stands at: their values, the base state's where they wrote
    none."""
    point = base.point
    if "pixel" in marked and got.point and got.point[0] is not None and got.point[1] is not None:
        point = (
            (int(got.point[0].value), int(got.point[1].value))
            if all(c.value.denominator == 1 for c in got.point if c is not None)
            else base.point
        )
    exact = base.exact
    if "exact" in marked and got.exact and got.exact[0] is not None and got.exact[1] is not None:
        exact = (got.exact[0].value, got.exact[1].value)
    p = got.p.value if ("p" in marked and got.p is not None) else base.p
    return base._replace(point=point, exact=exact, p=p)


def _resettle(model: Model, s: State) -> State:
    """After a student's point, the ellipse re-decides its region (and p2_0) there."""
    if isinstance(model, MidpointEllipse) and s.region == 1:
        return model.enter(s.point[0], s.point[1], s.p, s.k)
    return s


def _next_from(
    model: Model, shape: str, got: Got, judged: Expected, marked: set[str]
) -> Expected | None:
    """Follow-through: the row after the student's row ``got`` (judged as ``judged``)."""
    base = judged.source
    if base is None:
        return None
    if shape == "at":
        t = model.advance(_student_state(got, base, marked))
        if t is None:
            return None
        after = model.advance(t)
        return Expected(
            t.point, t.p, after.p if after else None, t.exact, t, _student_state(got, base, marked)
        )
    # after: the student's row holds p_k (of the base state) and the point reached
    u = base._replace(p=got.p.value if ("p" in marked and got.p is not None) else base.p)
    a = model.advance(u)
    if a is None:
        return None
    reached = _student_state(got._replace(p=None), a, marked)
    if "p_next" in marked and got.p_next is not None:
        reached = reached._replace(p=got.p_next.value)
    elif reached.point != a.point:  # their own point: the p there follows from it
        reached = _resettle(model, reached)
    b = model.advance(reached)
    if b is None:
        return None
    return Expected(b.point, reached.p, b.p, b.exact, reached, u)


def mark(table: StudentTable, solution: Solution) -> Marking:
    """Mark ``table`` against the answer ``solution`` (see the module's docstring)."""
    model = model_for(solution)
    states: list[State] = []
    if model is not None:
        states = list(chain(model, MAX_QUESTION_ROWS + 1))
        _check_size(len(states))
        if not _agrees(model, states, solution):  # pragma: no cover - the tests keep them equal
            model = None
    exact_algo = isinstance(model, DDALine)
    gots, marked = student_rows(table, exact_algo)
    skipped = ""
    if model is not None:
        lay, exp_rows, mine = _best(gots, states, _layouts(table, model.shape), marked)
        if lay.skip_student:
            skipped = f"{gots[0].where}: the start pixel, not marked"
    else:
        lay, exp_rows, mine = _Layout("at", 0, 0), _solution_rows(solution), gots
        marked.discard("p_next")
        marked.discard("exact")
    verdicts: list[Verdict] = []
    error = False
    judged: list[Expected | None] = []
    for i, got in enumerate(mine):
        if not error or model is None:
            exp = exp_rows[i] if i < len(exp_rows) else None
        else:
            prev = judged[-1]
            exp = _next_from(model, lay.shape, mine[i - 1], prev, marked) if prev else None
        last = i == len(mine) - 1
        answer_row = not error
        if error and model is not None and i < len(exp_rows):
            # a row that is the answer's own is right, whatever the slip before it (a typo
            # that the student did not carry on costs one row, not two)
            own = exp_rows[i]
            if not _wrong_fields(got, own, marked, last):
                exp, answer_row = own, True
        if exp is None:
            verdicts.append(Verdict(i + 1, got.where, got, None, "extra"))
        else:
            wrong = _wrong_fields(got, exp, marked, last)
            mark_ = "wrong" if wrong else "right" if answer_row else "right (follow-through)"
            verdicts.append(Verdict(i + 1, got.where, got, exp, mark_, wrong))
        error = error or verdicts[-1].mark in ("wrong", "extra")
        judged.append(exp)
    # rows the student did not write
    missing: list[Expected] = []
    if not error or model is None:
        missing = exp_rows[len(mine) :]
    elif judged and judged[-1] is not None and mine:
        prev_exp: Expected | None = judged[-1]
        got = mine[-1]
        while prev_exp is not None and len(missing) < MAX_QUESTION_ROWS:
            nxt = _next_from(model, lay.shape, got, prev_exp, marked)
            if nxt is None:
                break
            missing.append(nxt)
            prev_exp, got = nxt, _as_got(nxt)
    for e in missing[:MAX_QUESTION_ROWS]:
        verdicts.append(Verdict(len(verdicts) + 1, "-", None, e, "missing"))
    right = sum(v.mark.startswith("right") for v in verdicts)
    first = next((v for v in verdicts if not v.mark.startswith("right")), None)
    fields = tuple(f for f in ("pixel", "exact", "p", "p_next") if f in marked)
    marking = Marking(
        tuple(verdicts),
        right,
        len(verdicts),
        explain(first, fields, lay.shape) if first else "",
        "",
        model is not None,
        fields,
        skipped,
    )
    if first is not None and model is not None:
        marking = marking._replace(diagnosis=diagnose(gots, solution, model, marked, table))
    return marking


def _as_got(e: Expected) -> Got:
    def c(v: Number | None) -> Cell | None:
        return None if v is None else Cell(Fraction(v), 0)

    exact = (c(e.exact[0]), c(e.exact[1])) if e.exact else None
    return Got("-", (c(e.point[0]), c(e.point[1])), c(e.p), c(e.p_next), exact)


# --- words ------------------------------------------------------------------------------------


def _num(c: Cell | None) -> str:
    return "blank" if c is None else fmt_short(c.value)


def got_text(got: Got | None, fields: Sequence[str]) -> str:
    """A student row in a few words: ``p = -8, (3, 3)``."""
    if got is None:
        return "-"
    parts = []
    for f in fields:
        if f == "p":
            parts.append(f"p = {_num(got.p)}")
        elif f == "pixel":
            pt = got.point or (None, None)
            parts.append(f"({_num(pt[0])}, {_num(pt[1])})")
        elif f == "exact":
            ex = got.exact or (None, None)
            parts.append(f"x = {_num(ex[0])}, y = {_num(ex[1])}")
        elif f == "p_next":
            parts.append(f"next p = {_num(got.p_next)}")
    return ", ".join(parts)


def expected_text(exp: Expected | None, fields: Sequence[str]) -> str:
    """An expected row in the same words (``-`` where there is no value)."""
    if exp is None:
        return "-"

    def n(v: Number | None) -> str:
        return "-" if v is None else fmt_short(v)

    parts = []
    for f in fields:
        if f == "p":
            parts.append(f"p = {n(exp.p)}")
        elif f == "pixel":
            parts.append(f"({exp.point[0]}, {exp.point[1]})")
        elif f == "exact" and exp.exact is not None:
            parts.append(f"x = {n(exp.exact[0])}, y = {n(exp.exact[1])}")
        elif f == "p_next":
            parts.append(f"next p = {n(exp.p_next)}")
    return ", ".join(parts)


_NAMES = {"pixel": "the pixel", "exact": "the exact x and y", "p": "p", "p_next": "the next p"}


def _state_text(s: State) -> str:
    where = (
        f"({fmt_short(s.exact[0])}, {fmt_short(s.exact[1])})"
        if s.exact
        else (f"({s.point[0]}, {s.point[1]})")
    )
    return where + ("" if s.p is None else f" with p = {fmt_short(s.p)}")


def explain(v: Verdict, fields: Sequence[str], shape: str) -> str:
    """The first error in one sentence.

    >>> e = Expected((5, 4), -8, None, None, None, State((4, 3), 0))
    >>> g = Got("line 5", (Cell(5, 0), Cell(4, 0)), Cell(-4, 0), None, None)
    >>> explain(Verdict(4, "line 5", g, e, "wrong", ("p",)), ("pixel", "p"), "at")
    'Row 4 (line 5): p should be -8, not -4 (the step from (4, 3) with p = 0).'
    """
    at = f"Row {v.row}" + (f" ({v.where})" if v.where != "-" else "")
    if v.mark == "missing" and v.expected is not None:
        return (
            f"{at} is missing: the table stops before {expected_text(v.expected, fields)}, "
            "one step early or more."
        )
    if v.mark == "extra" or v.expected is None:
        return f"{at} is one row too many: the algorithm has already stopped."
    parts = [
        f"{_NAMES[w]} should be {expected_text(v.expected, (w,)).split(' = ')[-1]}, "
        f"not {got_text(v.got, (w,)).split(' = ')[-1]}"
        if w in ("p", "p_next")
        else f"{_NAMES[w]} should be {expected_text(v.expected, (w,))}, not {got_text(v.got, (w,))}"
        for w in v.wrong
    ]
    src, prev = v.expected.source, v.expected.prev
    why = ""
    if shape == "after" and src is not None and src.p is not None and "p" not in v.wrong:
        why = f" (deciding on p = {fmt_short(src.p)} at ({src.point[0]}, {src.point[1]}))"
    elif prev is not None:
        why = f" (the step from {_state_text(prev)})"
    elif "p" in v.wrong:
        why = " (the first p is p0, from its formula)"
    return f"{at}: {'; '.join(parts)}{why}."


# --- diagnosis --------------------------------------------------------------------------------


def _matches(
    gots: list[Got],
    rows: Callable[[str], list[Expected]],
    table: StudentTable,
    shape: str,
    marked: set[str],
) -> bool:
    for lay in _layouts(table, shape):
        found = _straight(gots, rows, lay, marked)
        if found is not None:
            right, exp, mine = found
            if mine and len(exp) == len(mine) and right == len(mine):
                return True
    return False


#: The table the course notes print for Bresenham's line from (2, 2) to (10, 6) (errata E1):
#: p_k, the pixel plotted, p_{k+1}, row by row, as printed. No rule produces it (row 4 plots
#: the NE step in the row that decides it, and p_{k+1} after NE is -20), so it is kept as data.
NOTES_E1_TABLE = (
    (-28, (2, 2), -20),
    (-20, (3, 2), -12),
    (-12, (4, 2), -4),
    (-4, (5, 2), 4),
    (4, (6, 3), -20),
    (-20, (7, 3), -12),
    (-12, (8, 3), -4),
    (-4, (9, 3), 4),
    (4, (10, 4), -20),
)


def _notes_e1(extra_end: bool) -> Callable[[str], list[Expected]]:
    rows = [Expected(pt, p, q, None) for p, pt, q in NOTES_E1_TABLE]
    if extra_end:  # "(For last step we plot (10, 6))"
        rows.append(Expected((10, 6), None, None, None))
    return lambda shape: rows if shape == "at" else []


def _knob_text(name: str, value: str) -> str:
    meaning = ROUNDING_TEXT[value] if name == "rounding" else KNOBS[name].values[value]
    return f"{name} = {value} ({meaning})"


Rows = Callable[[str], list[Expected]]
"""The rows of a variant in a layout (``at`` or ``after``)."""

MISTAKE = 100
"""The rank of a known mistake: a convention that explains a table is named first."""


def variants(solution: Solution, model: Model) -> list[tuple[int, str, Rows]]:
    """The known conventions and mistakes for this question: ``(rank, label, rows)``, the
    rank the number of knobs that differ from the question's, or :data:`MISTAKE`."""
    prim, algo = solution.primitive, solution.algorithm
    asked = dict(solution.data.get("conventions", {}))
    names = [n for n, k in KNOBS.items() if k.applies_to(prim, algo) and n != "update"]
    out: list[tuple[int, str, Rows]] = []
    for values in itertools.product(*(KNOBS[n].choices_for(prim, algo) for n in names)):
        combo = dict(zip(names, values, strict=True))
        changed = {n: v for n, v in combo.items() if asked.get(n) != v}
        if not changed:
            continue
        presets = [
            p
            for p, rules in PRESETS.items()
            if prim in rules
            and all(
                rules[prim].get(n, KNOBS[n].default_for(prim, algo)) == v for n, v in combo.items()
            )
        ]
        label = "the conventions " + " and ".join(_knob_text(n, v) for n, v in changed.items())
        if presets:
            many = len(presets) > 1
            label += f" (as the {' and '.join(presets)} preset{'s use' if many else ' uses'})"
        other = model_for(solution, combo)
        if other is not None:
            out.append((len(changed), label, _of(list(chain(other)))))
    g = _given(solution)
    if isinstance(model, BresenhamLine):
        ends = _ends(solution)
        assert ends is not None
        tie, start = asked.get("tie", "step"), asked.get("start", "swap")
        notes = NotesP0Line(*ends, tie, start)
        out.append(
            (
                MISTAKE,
                f"the course notes' p0 = 2Δy(y0 + 1/2) - 2Δx(x0 + 1) = {fmt_short(notes.p0())} "
                "with the start point's own coordinates, which does not follow from the "
                "algorithm (docs/errata.md, E1)",
                _of(list(chain(notes))),
            )
        )
        if ends == (2, 2, 10, 6):
            for extra in (False, True):
                out.append(
                    (
                        MISTAKE,
                        "the table the course notes print for this line, from their p0 = -28 "
                        "(docs/errata.md, E1)",
                        _notes_e1(extra),
                    )
                )
        x1, y1, x2, y2 = ends
        steep = abs(y2 - y1) > abs(x2 - x1)
        if (y2 - y1 if steep else x2 - x1) < 0:
            naive = UnswappedLine(*ends, tie)
            out.append(
                (
                    MISTAKE,
                    "forgetting to swap the end points of a right-to-left line: the walk starts "
                    f"at ({x1}, {y1}) and steps as if P2 were to the upper right",
                    _of(list(chain(naive))),
                )
            )
    if isinstance(model, MidpointCircle) and not isinstance(model, GeneralCircle):
        r = int(g["r"])
        old = OldXMidpoint(
            r, asked.get("tie", "step"), asked.get("p0", "1-r"), asked.get("loop", "strict")
        )
        out.append(
            (
                MISTAKE,
                "using the old x in the midpoint update: p + 2x_k + 1 instead of "
                "p + 2x_{k+1} + 1 (or the equivalent 2x_k + 3)",
                _of(list(chain(old))),
            )
        )

    states = list(chain(model))
    more = model.advance(states[-1], force=True)
    out.append(
        (MISTAKE, "stopping one step early (the loop's last step is missing)", _of(states[:-1]))
    )
    if more is not None:
        out.append(
            (MISTAKE, "stopping one step late (one step past the loop's end)", _of([*states, more]))
        )
    return out


def diagnose(
    gots: list[Got], solution: Solution, model: Model, marked: set[str], table: StudentTable
) -> str:
    """The known conventions or mistakes the student's whole table is exactly, in one line."""
    found: list[tuple[int, str]] = []
    for rank, label, rows in variants(solution, model):
        if _matches(gots, rows, table, model.shape, marked):
            found.append((rank, label))
    if not found:
        return ""
    best = min(r for r, _ in found)
    labels = [label for r, label in found if r == best]
    return "The table is exactly that of " + "; or of ".join(labels) + "."


# --- the answer -------------------------------------------------------------------------------


_UNSAFE = re.compile(r"[^\w .,:=+/()<>-]")


def safe_text(text: str, limit: int = 120) -> str:
    """File names and command words for an answer's notes: no ``$`` (notes read it as math),
    backslashes, braces or control characters.

    >>> safe_text("al$ice{}.csv")
    'al_ice__.csv'
    """
    return _UNSAFE.sub("_", text)[:limit]


def marking_solution(marking: Marking, solution: Solution, name: str, question: str) -> Solution:
    """The marking as a Solution: a table of row marks, the score, the first error and the
    diagnosis (notes), and the same as JSON fields."""
    fields = marking.fields
    columns = (
        heading("row", r"\text{row}"),
        heading("line", r"\text{line}"),
        heading("written", r"\text{written}"),
        heading("expected", r"\text{expected}"),
        heading("mark", r"\text{mark}"),
    )
    rows = [
        (
            v.row,
            v.where.removeprefix("line "),
            got_text(v.got, fields),
            expected_text(v.expected, fields),
            v.mark,
        )
        for v in marking.verdicts
    ]
    score = f"{marking.right}/{marking.total}"
    notes = [f"Marked: {safe_text(name)} against scanconv {safe_text(question, 200)}."]
    if marking.skipped:
        notes.append(f"{marking.skipped}.")
    notes.append(f"Score: {marking.right} of {marking.total} rows right.")
    notes.append(
        f"First error: {marking.first_error}"
        if marking.first_error
        else "No error: every row is right."
    )
    if marking.diagnosis:
        notes.append(f"Diagnosis: {marking.diagnosis}")
    notes.append(
        "Follow-through: after the first error each row is judged from the student's own "
        "previous row, so one slip costs one row."
        if marking.follow_through
        else "This command is marked without follow-through: each row is compared with the "
        "answer's row in the same position."
    )
    notes.append("Columns marked: " + ", ".join(_NAMES[f] for f in fields) + ".")
    return Solution(
        primitive="check",
        algorithm=solution.algorithm,
        title=f"Marking: {solution.title}",
        given=(),
        derived=(
            Quantity(
                "score",
                score,
                f"score = {marking.right} / {marking.total}",
                rf"\text{{score}} = {marking.right} / {marking.total}",
            ),
        ),
        notes=tuple(n.replace("$", "") for n in notes),
        tables=(Table("Marking, row by row", columns, lambda: iter(rows)),),
        data={
            "question": question,
            "answer": name,
            "score": marking.right,
            "out_of": marking.total,
            "first_error": marking.first_error,
            "diagnosis": marking.diagnosis,
            "follow_through": marking.follow_through,
            "marked": list(fields),
        },
    )


def batch_solution(
    results: Sequence[tuple[str, int, int, str, str]], solution: Solution, question: str
) -> Solution:
    """The score sheet of a folder as a Solution for the text formats: a table of names and
    scores, each file's first error and diagnosis as a note (CSV and JSON have their own
    writers in :mod:`scanconv.render.marking`)."""
    columns = (
        heading("name", r"\text{name}"),
        heading("score", r"\text{score}"),
        heading("out_of", r"\text{out of}"),
    )
    rows = [(name, right, total) for name, right, total, _, _ in results]
    notes = [f"{len(rows)} files marked against scanconv {safe_text(question, 200)}."]
    for name, _, _, first, diagnosis in results:
        if first:
            said = f"{safe_text(name)}: {first}" + (f" Diagnosis: {diagnosis}" if diagnosis else "")
            notes.append(said.replace("$", ""))
    return Solution(
        primitive="check",
        algorithm=solution.algorithm,
        title=f"Marks: {solution.title}",
        given=(),
        derived=(),
        notes=tuple(notes),
        tables=(Table("Scores", columns, lambda: iter(rows)),),
        data={"question": question},
    )

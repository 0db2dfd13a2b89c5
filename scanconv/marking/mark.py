"""Marking a student's step table against the answer of a question, with follow-through.

:func:`mark` reads the student's table as the steps the question asks for
(:mod:`.marking_rows`): in every layout the method can print (the notes' and the textbooks'),
with and without the start row, and keeps the reading with the best follow-through score, so
the layout is found, never guessed from a heading. The score is out of the number of steps the
question asks for, whichever layout; the given start row is shown, not scored.

**Follow-through** charges each slip once. Each step is judged from the student's own previous
step by the method's own rule (:mod:`.models`): p_k must follow from the student's p_{k-1} and
the move they took; the decision must be the rule's for the student's own p_k (a decision that
disagrees with it is wrong once, and named); the point must be the one that decision reaches.
The next step starts where the student's own move went. A step that is the answer's own is
right whatever came before (a typo not carried on costs one step).

:func:`~.marking_diagnose.diagnose` names a known convention or mistake when the student's
whole table is exactly that variant's; a table in the other circle form (p0 = 1 - r against
d0 = 3 - 2r, or the reverse) has its pixels marked. :func:`marking_solution` makes the
marking a :class:`~scanconv.core.records.Solution` every format of :mod:`scanconv.render`
can show.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..core import lazy
from ..core.checks import InputError
from ..core.decisions import resolve_move
from ..core.records import Pixel, Solution
from .diagnose import OTHER_FORM, diagnose, model_for, other_form, states_steps
from .limits import MAX_QUESTION_ROWS
from .models import DDALine, Model, State, chain
from .rows import (
    LAYOUTS,
    Expected,
    Got,
    Layout,
    Marking,
    Verdict,
    exact_of,
    pixel_of,
    same,
    steps_of,
    student_rows,
    wrong_fields,
)
from .student_table import (
    Cell,
    StudentTable,
    cell_of,
    parse_text,
    raw_text,
    read_text,
)
from .words import batch_solution, explain, marking_solution, safe_text

if TYPE_CHECKING:
    from . import tables as marking_table
else:
    marking_table = lazy.module("scanconv.marking.tables")

__all__ = [
    "MAX_QUESTION_ROWS",
    "Marking",
    "Verdict",
    "batch_solution",
    "expect",
    "mark",
    "mark_file",
    "mark_steps",
    "marking_solution",
    "model_for",
    "reached",
    "safe_text",
    "score",
]


def _check_size(rows: int) -> None:
    if rows > MAX_QUESTION_ROWS:
        raise InputError(
            f"the question's table has more than {MAX_QUESTION_ROWS} rows "
            f"(check marks at most {MAX_QUESTION_ROWS})",
            "question",
        )


def _agrees(model: Model, states: list[State], solution: Solution) -> bool:
    """The model's chain has the answer's own pixels and p: a safety net."""
    steps = list(itertools.islice(solution.steps(), len(states) + 1))
    pts = [s.pixel for s in steps]
    ps = [s.p for s in steps]
    want = [s.point for s in states]
    if pts == want:
        return [s.p for s in states] == ps or not any(p is not None for p in ps)
    after = want[1:]  # the answer printed in the textbooks' layout
    return pts == after and ps == [s.p for s in states[:-1]]


# --- follow-through ---------------------------------------------------------------------------


def _misses(got: Got, step: State | None, marked: set[str]) -> int:
    """How many of the student's pixel and next p disagree with ``step`` (the cells a
    decision decides)."""
    if step is None:
        return 2
    pix = pixel_of(got) if "pixel" in marked else None
    wrong = int(pix is not None and pix != step.point)
    return wrong + int(
        "p_next" in marked and got.p_next is not None and not same(got.p_next, step.p)
    )


def _taken(
    model: Model, s: State, got: Got, marked: set[str], by_rule: State
) -> tuple[State, Pixel]:
    """The step the student took from ``s`` and the point their step is judged against.
    Without a decision read, the step their pixel shows (else the rule's), judged against the
    rule's point. With one, its step and point; but when the student's pixel and next p agree
    with the rule's step better than with the decision's, the decision word is the one slip
    and they are judged on the rule's step (what the expected column shows, so the
    first-error sentence never calls a right cell wrong); on a tie, on their own decision's
    step."""
    moves = model.moves(s)
    said = resolve_move(got.decision, moves) if "decision" in marked else None
    if said is None:
        pix = pixel_of(got) if "pixel" in marked else None
        shown = (t for m in moves if (t := model.step(s, m)) and t.point == pix)
        return (next(shown, None) if pix is not None else None) or by_rule, by_rule.point
    said_step = model.step(s, said)
    if _misses(got, by_rule, marked) < _misses(got, said_step, marked):
        return by_rule, by_rule.point
    assert said_step is not None
    return said_step, said_step.point


def expect(
    model: Model, base: State, got: Got, marked: set[str], own_p: bool = True
) -> Expected | None:
    """What the student's step ``got`` should hold, judged from ``base`` (the state their own
    previous step reached); ``None``: the method's loop has already ended there. The decision
    is taken on the student's own p (``own_p``), or on the right one (a p miscopied after
    deciding)."""
    p_used = got.p.value if (own_p and "p" in marked and got.p is not None) else base.p
    s = base._replace(p=p_used)
    rule_move = model.decide(s)
    by_rule = model.step(s, rule_move)
    if by_rule is None or model.done(s, by_rule):
        return None
    taken, point = _taken(model, s, got, marked, by_rule)
    return Expected(
        point,
        base.p,
        rule_move,
        taken.p,
        by_rule.exact,
        s,
        model.rule(s),
        taken,
        None,
        by_rule,
    )


def reached(model: Model, exp: Expected, got: Got, marked: set[str]) -> list[State]:
    """Where the student's own step went, where the next step starts: after the move their
    point (or decision) shows, or, if their point is a slip of the pen, after the rule's
    move; both at their own point, with their own exact values and p_{k+1} where written."""
    out: list[State] = []
    pix = pixel_of(got) if "pixel" in marked else None
    ex = exact_of(got) if "exact" in marked else None
    for t in (exp.taken, exp.ruled):
        if t is None:
            continue
        if pix is not None and pix != t.point:
            t = model.at(pix, t)
        if ex is not None:
            t = t._replace(exact=ex)
        if "p_next" in marked and got.p_next is not None:
            t = t._replace(p=got.p_next.value)
        if t not in out:
            out.append(t)
    return out


def _judged(
    model: Model, bases: list[State], got: Got, marked: set[str], last: bool
) -> Expected | None:
    """The step from the base that explains the student's step best (fewest wrong fields)."""
    best: tuple[int, Expected] | None = None
    for b, own_p in itertools.product(bases, (True, False)):
        e = expect(model, b, got, marked, own_p)
        if e is not None:
            n = len(wrong_fields(got, e, marked, last))
            if best is None or n < best[0]:
                best = (n, e)
            if n == 0:
                break
    return None if best is None else best[1]


def _follow(
    model: Model, steps: list[Got], answer: list[Expected], marked: set[str]
) -> list[Verdict]:
    """Each step marked by follow-through (see the module's docstring)."""
    verdicts: list[Verdict] = []
    bases = [model.start()]
    prev: State | None = None
    error = False
    for i, got in enumerate(steps):
        last = i == len(steps) - 1
        own = answer[i] if i < len(answer) else None
        exp: Expected | None = own  # the answer's own step is right whatever came before
        if own is None or _wrong(got, own, marked, last):
            exp = _judged(model, bases, got, marked, last) or own
        from_answer = exp is own
        if exp is None:
            verdicts.append(Verdict(i + 1, got.where, got, None, "extra"))
            error = True
            continue
        if not from_answer:
            exp = exp._replace(prev=prev)
            from_answer = not error
        wrong = wrong_fields(got, exp, marked, last)
        mark_ = "wrong" if wrong else "right" if from_answer else "right (follow-through)"
        where = got.pixel_where if wrong and set(wrong) <= {"pixel", "exact"} else got.where
        verdicts.append(Verdict(i + 1, where or got.where, got, exp, mark_, wrong))
        error = error or bool(wrong)
        prev = exp.state
        bases = reached(model, exp, got, marked)
    # the steps the student did not write: follow on from their last one
    missing = len(answer) - len(steps)
    while bases and missing > 0:
        nxt = expect(model, bases[0], Got("-", None, None, None, None, None), set())
        if nxt is None or nxt.taken is None:
            break
        verdicts.append(Verdict(len(verdicts) + 1, "-", None, nxt._replace(prev=prev), "missing"))
        prev, bases, missing = nxt.state, [nxt.taken], missing - 1
    for i in range(max(0, missing)):
        own = answer[len(answer) - missing + i]
        verdicts.append(Verdict(len(verdicts) + 1, "-", None, own, "missing"))
    return verdicts


def _wrong(got: Got, exp: Expected, marked: set[str], last: bool) -> bool:
    return bool(wrong_fields(got, exp, marked, last))


def _straight(steps: list[Got], answer: list[Expected], marked: set[str]) -> list[Verdict]:
    """Each row compared with the answer's row in the same position (no model)."""
    verdicts = []
    for i, got in enumerate(steps):
        if i >= len(answer):
            verdicts.append(Verdict(i + 1, got.where, got, None, "extra"))
            continue
        wrong = wrong_fields(got, answer[i], marked, i == len(steps) - 1)
        verdicts.append(
            Verdict(i + 1, got.where, got, answer[i], "wrong" if wrong else "right", wrong)
        )
    for e in answer[len(steps) :]:
        verdicts.append(Verdict(len(verdicts) + 1, "-", None, e, "missing"))
    return verdicts


def score(verdicts: Sequence[Verdict], total: int) -> int:
    """Right steps among the first ``total``, less one for each row past them."""
    counted = [v for v in verdicts if v.row > 0]
    right = sum(v.mark.startswith("right") for v in counted[:total])
    return max(0, right - max(0, len(counted) - total))


# --- marking ----------------------------------------------------------------------------------


def _start_ok(start: Got | None, lay: Layout, point: tuple[int, int]) -> bool:
    """A textbook table's first row is its start row only if it is the start pixel."""
    return not (lay.shape == "after" and lay.start) or (
        start is not None and pixel_of(start) == point
    )


def _best(
    model: Model, rows: list[Got], answer: list[Expected], marked: set[str], hint: str
) -> tuple[Layout, list[Verdict], Got | None]:
    """The layout (and start row or not) with the best follow-through score."""
    first = model.start().point
    best: tuple[int, int, Layout, list[Verdict], Got | None] | None = None
    order = sorted(LAYOUTS, key=lambda lay: lay.shape != hint)
    for n, lay in enumerate(order):
        steps, start = steps_of(rows, lay, marked)
        if not _start_ok(start, lay, first):
            continue
        verdicts = _follow(model, steps, answer, marked)
        key = score(verdicts, len(answer))
        if best is None or key > best[0]:
            best = (key, n, lay, verdicts, start)
        if all(v.mark.startswith("right") for v in verdicts):
            break  # every step right: no reading does better
    assert best is not None
    return best[2], best[3], best[4]


def _shifted(rows: list[Got], dx: int, dy: int) -> list[Got]:
    """The rows with their points moved by (dx, dy)."""

    def move(pt: tuple[Cell | None, Cell | None] | None) -> tuple[Cell | None, Cell | None] | None:
        if pt is None or pt[0] is None or pt[1] is None:
            return pt
        return (pt[0]._replace(value=pt[0].value + dx), pt[1]._replace(value=pt[1].value + dy))

    return [g._replace(point=move(g.point)) for g in rows]


def _centre(solution: Solution) -> tuple[int, int]:
    given = {q.key: q.value for q in solution.given}
    c = given.get("center", (0, 0))
    try:
        return int(c[0]), int(c[1])
    except (TypeError, ValueError, IndexError):
        return 0, 0


def mark(table: StudentTable, solution: Solution) -> Marking:
    """Mark ``table`` against the answer ``solution`` (see the module's docstring)."""
    model = model_for(solution)
    states: list[State] = []
    if model is not None:
        states = list(chain(model, MAX_QUESTION_ROWS + 1))
        _check_size(len(states))
        if not _agrees(model, states, solution):  # pragma: no cover - the tests keep them equal
            model = None
    rows, marked = student_rows(table, isinstance(model, DDALine))
    if model is None:
        return _mark_plain(rows, marked, solution)
    answer = states_steps(model, states)
    hint = "after" if table.after else model.shape
    lay, verdicts, start = _best(model, rows, answer, marked, hint)
    note = ""
    xc, yc = _centre(solution)
    if solution.primitive == "circle" and (xc, yc) != (0, 0):
        moved = _shifted(rows, -xc, -yc)
        lay2, v2, s2 = _best(model, moved, answer, marked, hint)
        if score(v2, len(answer)) > score(verdicts, len(answer)):
            rows, lay, verdicts, start = moved, lay2, v2, s2
            note = (
                f"The points are written as absolute pixels, the centre ({xc}, {yc}) added to "
                "the octant's (x, y); they are marked as the octant's points."
            )
    diagnosis = ""
    right = score(verdicts, len(answer))
    if any(not v.mark.startswith("right") for v in verdicts):
        diagnosis = diagnose(rows, solution, model, marked, hint)
        other = other_form(model)
        if OTHER_FORM in diagnosis and other is not None:
            # the other form's own table: its pixels are marked (its loop may stop a step
            # later, past the diagonal: the score is still out of the question's steps)
            marked = marked - {"p", "p_next", "decision"}
            theirs = states_steps(other, list(chain(other)))
            lay, verdicts, start = _best(other, rows, theirs, marked, hint)
            right = min(score(verdicts, len(theirs)), len(answer))
    if note:
        diagnosis = f"{note} {diagnosis}".strip()
    return _marking(verdicts, len(answer), right, marked, diagnosis, True, lay, start)


MAX_STEP_TEXT = 200
"""Most characters of one answer :func:`mark_steps` reads (a longer one is unreadable)."""


def _typed(
    text: str, field: str, where: str
) -> Cell | tuple[Cell | None, Cell | None] | str | None:
    """One answer as typed, read as a table's cell (an unreadable number is blank)."""
    if len(text) > MAX_STEP_TEXT:
        return None
    try:
        return cell_of(text, field, "test yourself", where)
    except InputError:
        return None


def _step(i: int, typed: Mapping[str, str], dda: bool) -> Got:
    """Step ``i`` as typed: p_k (the DDA: the exact x_{k+1}, y_{k+1}), the decision and the
    point it reaches."""
    where = f"step {i + 1}"
    got = {
        f: _typed(str(typed.get(f, "")), field, where)
        for f, field in (("p", "p"), ("decision", "decision"), ("pixel", "xy"), ("exact", "xy"))
    }
    p, decision, point, exact = (got[f] for f in ("p", "decision", "pixel", "exact"))
    return Got(
        where,
        p if isinstance(p, Cell) and not dda else None,
        decision if isinstance(decision, str) and not dda else None,
        point if isinstance(point, tuple) and not isinstance(point, Cell) else None,
        exact if isinstance(exact, tuple) and not isinstance(exact, Cell) and dda else None,
        None,
        where,
    )


def mark_steps(solution: Solution, steps: Sequence[Mapping[str, str]]) -> Marking:
    """Steps written one at a time (the page's "Test yourself") marked as :func:`mark` marks
    a table, by the same follow-through: each step ``{"p", "decision", "pixel"}`` as typed
    (``"-8"``, ``"East"``, ``"4, 3"``; the DDA's ``{"exact", "pixel"}``, the exact
    x_{k+1}, y_{k+1}), in the textbooks' layout (p_k, the decision, the point it reaches).
    The score is out of the steps written. A question without a step model is an
    :class:`~scanconv.core.checks.InputError`.

    >>> from scanconv.answers.primitives.line import line_solution
    >>> s = line_solution("bresenham", 2, 2, 10, 6)
    >>> m = mark_steps(s, [{"p": "0", "decision": "NE", "pixel": "3, 3"},
    ...                    {"p": "8", "decision": "NE", "pixel": "4, 4"},
    ...                    {"p": "0", "decision": "NE", "pixel": "5, 5"}])
    >>> m.right, m.total, [v.mark for v in m.verdicts]
    (2, 3, ['right', 'wrong', 'right (follow-through)'])
    >>> m.first_error
    'Row 2 (step 2): p should be -8, not 8 (the step from (2, 2) with p = 0).'
    """
    model = model_for(solution)
    if model is None:
        raise InputError("this answer has no step model to mark its steps by", "question")
    states = list(chain(model, MAX_QUESTION_ROWS + 1))
    _check_size(len(states))
    dda = isinstance(model, DDALine)
    marked = {"pixel", "exact"} if dda else {"p", "decision", "pixel"}
    rows = [_step(i, typed, dda) for i, typed in enumerate(steps[:MAX_QUESTION_ROWS])]
    verdicts = _follow(model, rows, states_steps(model, states), marked)[: len(rows)]
    right = sum(v.mark.startswith("right") for v in verdicts)
    return _marking(verdicts, len(rows), right, marked, "", True, Layout("after", False), None)


def mark_file(path: Path, solution: Solution) -> Marking:
    """Mark the student's file at ``path`` (:func:`mark_text` of its text)."""
    return mark_text(read_text(path), solution, path.name, path.suffix.lower())


def mark_text(text: str, solution: Solution, name: str, suffix: str = "") -> Marking:
    """Mark a student's table given as text (CSV, Markdown, plain columns or JSON, told apart
    by ``suffix`` or by its look), ``name`` naming it in messages: by its own columns where
    the method's table is not a pixel walk (:mod:`.marking_table`), else as a step table
    (:func:`mark`)."""
    models = marking_table.table_models_for(solution)
    if models:
        headers, raw = raw_text(text, name, suffix)
        return marking_table.mark_table(headers, raw, solution, models, name)
    return mark(parse_text(text, name, suffix), solution)


def _mark_plain(rows: list[Got], marked: set[str], solution: Solution) -> Marking:
    """A command without a step model: each row compared with the answer's, pixels only."""
    steps = itertools.islice(solution.steps(), MAX_QUESTION_ROWS + 1)
    answer = [Expected(s.pixel, s.p) for s in steps]
    _check_size(len(answer))
    marked = marked - {"p_next", "exact", "decision"}
    verdicts = _straight(rows, answer, marked)
    right = score(verdicts, len(answer))
    return _marking(verdicts, len(answer), right, marked, "", False, Layout("at", False), None)


def _marking(
    verdicts: list[Verdict],
    total: int,
    right: int,
    marked: set[str],
    diagnosis: str,
    follow: bool,
    lay: Layout,
    start: Got | None,
) -> Marking:
    fields = tuple(f for f in ("p", "decision", "pixel", "exact", "p_next") if f in marked)
    first = next((v for v in verdicts if not v.mark.startswith("right")), None)
    skipped = ""
    shown = list(verdicts)
    if start is not None:
        pt = pixel_of(start)
        at = "" if pt is None else f" {pt}"
        skipped = f"{start.where}: the start pixel{at}, given in the question: shown, not scored"
        start = start._replace(p=None, decision=None, p_next=None)
        shown.insert(0, Verdict(0, start.where, start, None, "given (not scored)"))
    return Marking(
        tuple(shown),
        right,
        total,
        explain(first, fields) if first else "",
        diagnosis,
        follow,
        fields,
        skipped,
    )

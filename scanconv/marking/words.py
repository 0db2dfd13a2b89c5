"""A marking in words: each step as written and as expected, the first error in one sentence,
and the marking (or a folder's score sheet) as a :class:`~scanconv.core.records.Solution`."""

from __future__ import annotations

import re
from collections.abc import Sequence

from ..core.decisions import UNREADABLE
from ..core.numeric import Number, fmt_short
from ..core.records import Quantity, Solution, Table, Walk, heading
from .models import State
from .rows import Expected, Got, Marking, RowText, Verdict
from .student_table import Cell

RULES = (
    "Marking rules: the score is out of the number of steps the question asks for, whichever "
    "layout the table uses (a row per point reached, or the notes' row per point with the "
    "start first); the given start row is shown but not scored. A step is right when its p, "
    "its decision and the point it reaches are right. Follow-through: each step is judged "
    "from the student's own previous step by the method's own rule, so one slip costs one "
    "step; a decision that disagrees with the student's own p is wrong once. A row past the "
    "end costs one mark, a missing step is wrong."
)
"""The marking rules, as every marking's notes state them (and docs/teaching.md)."""


def _num(c: Cell | None) -> str:
    return "blank" if c is None else fmt_short(c.value)


def decision_text(decision: str | None) -> str:
    """A student's decision as the marking names it: the move, the word written, ``blank``,
    or the text that names no move, quoted.

    >>> decision_text("NE"), decision_text("diagonal"), decision_text(None), decision_text("?keep")
    ('NE', 'diagonal', 'blank', "'keep' (not a move)")
    """
    if decision is None:
        return "blank"
    if decision.startswith(UNREADABLE):
        return f"{decision[len(UNREADABLE) :]!r} (not a move)"
    return decision


def got_text(got: Got | RowText | None, fields: Sequence[str]) -> str:
    """A student's step in a few words: ``p = -8, E, (4, 3)``."""
    if got is None:
        return "-"
    if isinstance(got, RowText):
        return got.text
    parts = []
    for f in fields:
        if f == "p":
            parts.append(f"p = {_num(got.p)}")
        elif f == "decision":
            parts.append(decision_text(got.decision))
        elif f == "pixel":
            pt = got.point or (None, None)
            parts.append(f"({_num(pt[0])}, {_num(pt[1])})")
        elif f == "exact":
            ex = got.exact or (None, None)
            parts.append(f"x = {_num(ex[0])}, y = {_num(ex[1])}")
        elif f == "p_next":
            parts.append(f"next p = {_num(got.p_next)}")
    return ", ".join(parts)


def expected_text(exp: Expected | RowText | None, fields: Sequence[str]) -> str:
    """An expected step in the same words (``-`` where there is no value): the decision the
    rule takes, the point and the next p it reaches (a point or next p that follows from the
    student's own wrong decision is not marked wrong again, see :func:`..marking.expect`)."""
    if exp is None:
        return "-"
    if isinstance(exp, RowText):
        return exp.text

    def n(v: Number | None) -> str:
        return "-" if v is None else fmt_short(v)

    parts = []
    for f in fields:
        if f == "p":
            parts.append(f"p = {n(exp.p)}")
        elif f == "decision":
            parts.append(exp.decision or "-")
        elif f == "pixel":  # the point the rule's decision reaches
            pt = exp.ruled.point if exp.ruled is not None else exp.point
            parts.append(f"({pt[0]}, {pt[1]})")
        elif f == "exact" and exp.exact is not None:
            parts.append(f"x = {n(exp.exact[0])}, y = {n(exp.exact[1])}")
        elif f == "p_next":
            parts.append(f"next p = {n(exp.ruled.p if exp.ruled is not None else exp.p_next)}")
    return ", ".join(parts)


NAMES = {
    "pixel": "the pixel",
    "exact": "the exact x and y",
    "p": "p",
    "decision": "the decision",
    "p_next": "the next p",
}


def _state_text(s: State) -> str:
    where = (
        f"({fmt_short(s.exact[0])}, {fmt_short(s.exact[1])})"
        if s.exact
        else (f"({s.point[0]}, {s.point[1]})")
    )
    return where + ("" if s.p is None else f" with p = {fmt_short(s.p)}")


def _value(text: str) -> str:
    return text.split(" = ")[-1]


def explain(v: Verdict, fields: Sequence[str]) -> str:
    """The first error in one sentence: the row, what is wrong, and the state and the rule
    it follows from.

    >>> e = Expected((5, 4), -8, "E", None, None, State((5, 4), -4), "p < 0 chooses E", None,
    ...              State((4, 3), 0))
    >>> g = Got("line 5", Cell(-4, 0), "E", (Cell(5, 0), Cell(4, 0)), None, None)
    >>> explain(Verdict(4, "line 5", g, e, "wrong", ("p",)), ("pixel", "p"))
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
    parts = []
    judged = v.expected._replace(ruled=None)  # the values the step was judged against
    for w in v.wrong:
        want, have = expected_text(judged, (w,)), got_text(v.got, (w,))
        if w in ("p", "p_next"):
            want, have = _value(want), _value(have)
        parts.append(f"{NAMES[w]} should be {want}, not {have}")
    e = v.expected
    why = ""
    decided = {"decision", "pixel"} & set(v.wrong) and "p" not in v.wrong
    if decided and e.state is not None and e.rule:
        why = f" (at {_state_text(e.state)}, {e.rule})"
    elif "p" in v.wrong and e.prev is not None:
        why = f" (the step from {_state_text(e.prev)})"
    elif "p" in v.wrong:
        why = " (the first p is p0, from its formula)"
    elif e.state is not None:
        why = f" (the step from {_state_text(e.state)})"
    return f"{at}: {'; '.join(parts)}{why}."


_UNSAFE = re.compile(r"[^\w .,:;'=+/()<>-]")


def safe_text(text: str, limit: int = 120) -> str:
    """File names and command words for an answer's notes: no ``$`` (notes read it as math),
    backslashes, braces or control characters.

    >>> safe_text("al$ice{}.csv"), safe_text("dither ordered --image '10 200; 30 5'")
    ('al_ice__.csv', "dither ordered --image '10 200; 30 5'")
    """
    return _UNSAFE.sub("_", text)[:limit]


def marking_solution(marking: Marking, solution: Solution, name: str, question: str) -> Solution:
    """The marking as a Solution: a table of step marks, the score, the first error and the
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
            got_text(v.got, ("pixel",) if v.row == 0 else fields),
            expected_text(v.expected, fields),
            v.mark,
        )
        for v in marking.verdicts
    ]
    score = f"{marking.right}/{marking.total}"
    notes = [f"Marked: {safe_text(name)} against scanconv {safe_text(question, 200)}."]
    if marking.skipped:
        notes.append(f"{marking.skipped}.")
    notes.append(f"Score: {marking.right} of {marking.total} steps right.")
    notes.append(
        f"First error: {marking.first_error}"
        if marking.first_error
        else "No error: every step is right."
    )
    if marking.diagnosis:
        notes.append(f"Diagnosis: {marking.diagnosis}")
    notes.append(
        marking.rules or RULES
        if marking.follow_through
        else "This command is marked without follow-through: each row is compared with the "
        "answer's row in the same position."
    )
    notes.append("Columns marked: " + ", ".join(NAMES.get(f, f) for f in fields) + ".")
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
        walk=Walk(tables=(Table("Marking, step by step", columns, lambda: iter(rows)),)),
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
    results: Sequence[tuple[str, int | None, int | None, str, str]],
    solution: Solution,
    question: str,
) -> Solution:
    """The score sheet of a folder as a Solution for the text formats: a table of names and
    scores, each file's first error and diagnosis as a note (CSV and JSON have their own
    writers in :mod:`scanconv.render.documents.scores`)."""
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
        walk=Walk(tables=(Table("Scores", columns, lambda: iter(rows)),)),
        data={"question": question},
    )

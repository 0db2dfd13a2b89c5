"""Steps typed one at a time (the site's "Test yourself") are marked as ``check`` marks the
same steps written as a student's CSV (one account of a slip).

:func:`scanconv.marking.mark.mark_steps` is what the site's page asks for each step. For
every method with a marking model, every single slip (each field of each step made wrong in
turn) gets the score, the expected column and the first-error sentence ``check`` gives for
the CSV a student writes with that slip (:func:`~scanconv.marking.mark.mark_text`, the
reading of ``scanconv check``). A line with one slip carried on is worked by hand.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import pytest

from scanconv.core.checks import InputError
from scanconv.core.numeric import fmt_short
from scanconv.marking.diagnose import model_for, states_steps
from scanconv.marking.mark import mark_steps, mark_text
from scanconv.marking.models import DDALine, chain
from scanconv.marking.words import expected_text
from scanconv.questions.marking import marking_question
from scanconv.render.html.selftest_marks import feedback

QUESTIONS = (
    "line 2 2 10 6",
    "line 0 0 5 8",
    "line 8 2 0 5",
    "line 2 2 10 6 --algo midpoint --scale half",
    "line 0 0 6 3 --algo dda",
    "circle 8",
    "circle 5 --p0 5/4-r",
    "circle 6 --method bresenham",
    "circle 6 --method general",
    "ellipse 8 6",
)

_OTHER = {"E": "NE", "NE": "E", "N": "NE", "SE": "E", "S": "SE", "W": "NW", "NW": "W"}


def _typed(question: str) -> tuple[list[dict[str, str]], bool]:
    """The answer's steps as a student types them, and whether the method is the DDA."""
    model = model_for(marking_question(question))
    assert model is not None
    dda = isinstance(model, DDALine)
    steps = []
    for e in states_steps(model, list(chain(model))):
        pixel = f"{e.point[0]}, {e.point[1]}"
        if dda:
            assert e.exact is not None
            steps.append(
                {"exact": f"{fmt_short(e.exact[0])}, {fmt_short(e.exact[1])}", "pixel": pixel}
            )
        else:
            p = "" if e.p is None else fmt_short(e.p)
            steps.append({"p": p, "decision": e.decision or "", "pixel": pixel})
    return steps, dda


def _slip(value: str, field: str) -> str:
    """A wrong value for a field (a sign slip and one more, the other move, a pixel one up)."""
    if field == "p":
        return str(-Fraction(value) - 1)
    if field == "decision":
        return _OTHER.get(value, "E")
    x, y = value.split(", ")
    return f"{x}, {Fraction(y) + 1}"


def _csv(steps: list[dict[str, str]], dda: bool) -> str:
    """The steps as a student's CSV in the textbooks' layout (p_k, decision, x_{k+1}, y_{k+1})."""
    if dda:
        lines = ["k,x_{k+1},y_{k+1},round(x_{k+1}),round(y_{k+1})"]
        for k, s in enumerate(steps):
            lines.append(",".join([str(k), *s["exact"].split(", "), *s["pixel"].split(", ")]))
    else:
        lines = ["k,p_k,decision,x_{k+1},y_{k+1}"]
        for k, s in enumerate(steps):
            lines.append(",".join([str(k), s["p"], s["decision"], *s["pixel"].split(", ")]))
    return "\n".join(lines) + "\n"


@pytest.mark.slow  # every slip of every step: a few hundred markings
@pytest.mark.parametrize("question", QUESTIONS)
def test_every_single_slip_is_marked_as_check_marks_the_students_csv(question: str) -> None:
    solution = marking_question(question)
    right, dda = _typed(question)
    fields = ("exact", "pixel") if dda else ("p", "decision", "pixel")
    slipped = 0
    for i, field in itertools.product(range(len(right)), fields):
        if not right[i][field]:
            continue  # the tip of a flat ellipse: no p, no decision
        steps = [dict(s) for s in right]
        steps[i][field] = _slip(steps[i][field], field)
        page = mark_steps(solution, steps)
        check = mark_text(_csv(steps, dda), solution, "student.csv", ".csv")
        assert (page.right, page.total) == (check.right, check.total), (i, field)
        shown = [v for v in check.verdicts if v.row > 0]
        assert [v.mark for v in page.verdicts] == [v.mark for v in shown], (i, field)
        assert [expected_text(v.expected, page.fields) for v in page.verdicts] == [
            expected_text(v.expected, check.fields) for v in shown
        ], (i, field)
        # the same sentence, the row named as each names it (step 2, line 3)
        assert page.first_error.split(": ", 1)[-1] == check.first_error.split(": ", 1)[-1]
        slipped += page.right < page.total
    assert slipped >= len(right)  # not vacuous: the slips cost marks


def test_a_slip_carried_on_costs_one_step_worked_by_hand() -> None:
    """Bresenham (2, 2) to (10, 6): 2dy = 8, 2dy - 2dx = -8. The student's p1 = 8 (it is -8);
    from their own 8, NE and (4, 4) follow, then p2 = 8 - 8 = 0, NE, (5, 5), and so on to
    (10, 7): every later step right by follow-through, one step lost."""
    typed = [
        ("0", "NE", "3, 3"), ("8", "NE", "4, 4"), ("0", "NE", "5, 5"), ("-8", "E", "6, 5"),
        ("0", "NE", "7, 6"), ("-8", "E", "8, 6"), ("0", "NE", "9, 7"), ("-8", "E", "10, 7"),
    ]  # fmt: skip
    steps = [{"p": p, "decision": d, "pixel": px} for p, d, px in typed]
    m = mark_steps(marking_question("line 2 2 10 6"), steps)
    assert (m.right, m.total) == (7, 8)
    assert [v.mark for v in m.verdicts] == ["right", "wrong"] + ["right (follow-through)"] * 6
    assert [expected_text(v.expected, m.fields) for v in m.verdicts][:3] == [
        "p = 0, NE, (3, 3)",
        "p = -8, NE, (4, 4)",  # p is -8; NE and (4, 4) follow from the student's own 8
        "p = 0, NE, (5, 5)",
    ]
    f = feedback(m)
    assert f["mark"] == "right (follow-through)" and f["score"] == [7, 8] and f["why"] == ""
    assert f["parts"][2] == {"field": "pixel", "ok": True, "got": "(10, 7)", "want": "(10, 7)"}


def test_typed_words_are_read_as_check_reads_a_cell() -> None:
    """A decision in words, a real minus sign, a pixel in brackets, a blank and junk."""
    s = marking_question("line 2 2 10 6")
    m = mark_steps(s, [{"p": "0", "decision": "north-east", "pixel": "(3, 3)"}])
    assert m.right == 1
    m = mark_steps(
        s,
        [
            {"p": "0", "decision": "NE", "pixel": "3, 3"},
            {"p": "\u22128", "decision": "East", "pixel": "4 3"},
        ],
    )
    assert m.right == 2
    m = mark_steps(s, [{"p": "zero", "decision": "", "pixel": "x" * 10_000}])
    assert m.right == 0 and "not blank" in m.first_error


def test_a_question_without_a_step_model_is_refused() -> None:
    with pytest.raises(InputError, match="no step model"):
        mark_steps(marking_question("circle 5 --method polynomial"), [{"pixel": "0, 5"}])


def test_the_site_marks_at_most_its_steps() -> None:
    """The site's judge marks the first :data:`~scanconv.site.page.MAX_STEPS` steps sent."""
    import json

    from scanconv.site.page import MAX_STEPS, judge

    step = {"p": "0", "decision": "NE", "pixel": "3, 3"}
    r = json.loads(judge("line 2 2 10 6", json.dumps([step] * (MAX_STEPS + 5))))
    assert r["score"][1] == MAX_STEPS and r["mark"] == "extra"

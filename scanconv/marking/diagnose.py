"""The model of a question, and the diagnosis of a whole table.

:func:`model_for` gives the step model (:mod:`.models`) of a question's method with its
conventions. :func:`diagnose` names a known convention (any knob combination of
``docs/conventions.md``, with the presets that use it) or a known mistake (each an explicit
variant: the notes' p0 of errata E1, end points not swapped, the midpoint update with the old
x, the other circle form, the octant with x and y exchanged, the end point omitted or
written twice, stopping one step late) when the student's whole table is exactly that
variant's, in any layout.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import Any, NamedTuple

from ..algorithms.conventions import KNOBS, PRESETS, ROUNDING_TEXT
from ..core.numeric import fmt_short
from ..core.records import Move, Solution
from .models import (
    BresenhamCircle,
    BresenhamLine,
    DDALine,
    GeneralCircle,
    HalfScaledLine,
    MidpointCircle,
    MidpointEllipse,
    Model,
    NotesP0Line,
    OldXMidpoint,
    State,
    UnswappedLine,
    chain,
)
from .rows import LAYOUTS, Expected, Got, pixel_of, steps_of, wrong_fields

OTHER_FORM = "the other circle form"
"""The words that start the other circle form's diagnosis (its pixels are then marked)."""


def other_form(model: Model) -> Model | None:
    """The other circle form of a circle model: d0 = 3 - 2r for p0 = 1 - r and the reverse
    (the same pixels, the p of the other form)."""
    if isinstance(model, MidpointCircle) and not isinstance(model, GeneralCircle):
        return BresenhamCircle(model.r, "keep" if model.keep else "step")
    if isinstance(model, BresenhamCircle):
        return MidpointCircle(model.r, "keep" if model.t else "step")
    return None


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
    them), or ``None`` for a command marked without follow-through. Its ``shape`` is the
    layout the question printed (a hint for equal scores)."""
    k = dict(solution.data.get("conventions", {}))
    k.update(knobs or {})
    g = _given(solution)
    prim, algo = solution.primitive, solution.algorithm
    shape = "after" if solution.data.get("layout") == "textbook" else "at"
    m: Model | None = None
    if prim == "line" and "P1" in g and "P2" in g:
        (x1, y1), (x2, y2) = g["P1"], g["P2"]
        ends = _ends(solution)
        if algo in ("bresenham", "midpoint") and ends is not None:
            # the midpoint line's d is Bresenham's p (its record names the same model), or
            # half of it with --scale half
            half = algo == "midpoint" and k.get("scale") == "half"
            line = HalfScaledLine if half else BresenhamLine
            m = line(*ends, k.get("tie", "step"), k.get("start", "swap"))
        elif algo == "dda":
            m = DDALine(x1, y1, x2, y2, k.get("rounding", "half-up"), k.get("start", "given"))
    elif prim == "circle" and "r" in g:
        r = int(g["r"])
        if algo == "midpoint":
            m = MidpointCircle(r, k.get("tie", "step"), k.get("p0", "1-r"), k.get("loop", "strict"))
        elif algo == "bresenham":
            m = BresenhamCircle(r, k.get("tie", "step"), k.get("xstep", "last"))
        elif algo == "general":
            m = GeneralCircle(r, k.get("tie", "step"), k.get("loop", "strict"))
    elif prim == "ellipse" and algo == "midpoint" and "rx" in g:
        m = MidpointEllipse(
            int(g["rx"]),
            int(g["ry"]),
            k.get("loop", "strict"),
            k.get("tie", "step"),
            k.get("p0", "exact"),
        )
        return m
    if m is not None:
        m.shape = shape
    return m


def _label(a: State, b: State) -> str | None:
    dx, dy = b.point[0] - a.point[0], b.point[1] - a.point[1]
    if (dx, dy) == (0, 0) or abs(dx) > 1 or abs(dy) > 1:
        return None
    return Move.from_delta(dx, dy).value


def states_steps(model: Model | None, states: Sequence[State]) -> list[Expected]:
    """The steps of a chain of states: step k is p_k, its decision (the move the chain made;
    none for a method without decisions) and the state k + 1 it reaches."""
    decides = model is not None and model.decide(states[0]) is not None if states else False
    return [
        Expected(
            t.point,
            s.p,
            _label(s, t) if decides else None,
            t.p,
            t.exact,
            s,
            model.rule(s) if model is not None else "",
            t,
            states[i - 1] if i else None,
            t,
        )
        for i, (s, t) in enumerate(itertools.pairwise(states))
    ]


def matches(rows: list[Got], states: list[State], model: Model, marked: set[str]) -> bool:
    """The student's table is exactly this chain's, in some layout."""
    if not states:
        return False
    want = states_steps(model, states)
    for lay in LAYOUTS:
        steps, start = steps_of(rows, lay, marked)
        if lay.start and (start is None or pixel_of(start) != states[0].point):
            continue
        if len(steps) == len(want) and all(
            not wrong_fields(g, e, marked, i == len(steps) - 1)
            for i, (g, e) in enumerate(zip(steps, want, strict=True))
        ):
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


def _notes_e1(extra_end: bool) -> list[State]:
    states = [State(pt, p) for p, pt, _ in NOTES_E1_TABLE]
    if extra_end:  # "(For last step we plot (10, 6))"
        states.append(State((10, 6), -20))
    return states


def _knob_text(name: str, value: str) -> str:
    meaning = ROUNDING_TEXT[value] if name == "rounding" else KNOBS[name].values[value]
    return f"{name} = {value} ({meaning})"


MISTAKE = 100
"""The rank of a known mistake: a convention that explains a table is named first."""


class Variant(NamedTuple):
    """A known convention or mistake."""

    rank: int
    label: str
    states: Callable[[], list[State]]
    decisions: bool = True
    """Its decisions are the moves its points make (not so for a table kept as data)."""


def _conventions(solution: Solution) -> list[Variant]:
    prim, algo = solution.primitive, solution.algorithm
    asked = dict(solution.data.get("conventions", {}))
    names = [n for n, k in KNOBS.items() if k.applies_to(prim, algo) and n != "update"]
    out: list[Variant] = []
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
            out.append(Variant(len(changed), label, _chain_of(other)))
    return out


def _chain_of(model: Model) -> Callable[[], list[State]]:
    return lambda: list(chain(model))


def _line_mistakes(solution: Solution, model: BresenhamLine) -> list[Variant]:
    asked = dict(solution.data.get("conventions", {}))
    ends = _ends(solution)
    assert ends is not None
    tie, start = asked.get("tie", "step"), asked.get("start", "swap")
    notes = NotesP0Line(*ends, tie, start)
    out: list[Variant] = [
        Variant(
            MISTAKE,
            f"the course notes' p0 = 2Δy(y0 + 1/2) - 2Δx(x0 + 1) = {fmt_short(notes.p0())} "
            "with the start point's own coordinates, which does not follow from the "
            "algorithm (erratum E1)",
            _chain_of(notes),
        )
    ]
    if ends == (2, 2, 10, 6):
        for extra in (False, True):
            out.append(
                Variant(
                    MISTAKE,
                    "the table the course notes print for this line, from their p0 = -28 "
                    "(erratum E1)",
                    lambda extra=extra: _notes_e1(extra),  # type: ignore[misc]
                    False,
                )
            )
    x1, y1, x2, y2 = ends
    steep = abs(y2 - y1) > abs(x2 - x1)
    if (y2 - y1 if steep else x2 - x1) < 0:
        out.append(
            Variant(
                MISTAKE,
                "forgetting to swap the end points of a right-to-left line: the walk starts "
                f"at ({x1}, {y1}) and steps as if P2 were to the upper right",
                _chain_of(UnswappedLine(*ends, tie)),
            )
        )
    return out


TOPIC_9 = "the course notes' Topic 9 form of Bresenham's circle"
"""How the diagnosis names the circle with p0 = 1 - r: the form the notes' Topic 9 prints
under the name of Bresenham's circle algorithm (scanconv's method 'midpoint')."""


def _circle_mistakes(solution: Solution, model: Model) -> list[Variant]:
    asked = dict(solution.data.get("conventions", {}))
    r = int(_given(solution)["r"])
    tie = asked.get("tie", "step")
    out: list[Variant] = []
    if isinstance(model, MidpointCircle) and not isinstance(model, GeneralCircle):
        old = OldXMidpoint(r, tie, asked.get("p0", "1-r"), asked.get("loop", "strict"))
        out.append(
            Variant(
                MISTAKE,
                "using the old x in the midpoint update: p + 2x_k + 1 instead of "
                "p + 2x_{k+1} + 1 (or the equivalent 2x_k + 3)",
                _chain_of(old),
            )
        )
    other = other_form(model)
    if other is not None:
        asked_form, used = (
            (f"p0 = 1 - r ({TOPIC_9})", "Bresenham's own d0 = 3 - 2r")
            if isinstance(model, MidpointCircle)
            else ("d0 = 3 - 2r", f"{TOPIC_9}, p0 = 1 - r (the method 'midpoint')")
        )
        out.append(
            Variant(
                MISTAKE,
                f"{OTHER_FORM}: {used} where the question asks for {asked_form}; the pixels "
                "are the same and are marked, the p column is not",
                _chain_of(other),
            )
        )
    swapped = [s._replace(point=(s.point[1], s.point[0])) for s in chain(model)]
    out.append(
        Variant(
            MISTAKE,
            f"the octant with x and y exchanged: the points run from ({r}, 0) up to the "
            f"diagonal, where the method steps from (0, {r}) along x",
            lambda: swapped,
        )
    )
    return out


def variants(solution: Solution, model: Model) -> list[Variant]:
    """The known conventions and mistakes for this question: ``(rank, label, states)``, the
    rank the number of knobs that differ from the question's, or :data:`MISTAKE`."""
    out = _conventions(solution)
    if isinstance(model, BresenhamLine):
        out += _line_mistakes(solution, model)
    if isinstance(model, (MidpointCircle, BresenhamCircle)):
        out += _circle_mistakes(solution, model)
    states = list(chain(model))
    end = states[-1].point
    line = solution.primitive == "line"
    early = (
        f"stopping one step early: the end point ({end[0]}, {end[1]}) is omitted"
        if line
        else "stopping one step early (the loop's last step is missing)"
    )
    out.append(Variant(MISTAKE, early, lambda: states[:-1]))
    more = model.advance(states[-1], force=True)
    if more is not None:
        out.append(
            Variant(
                MISTAKE,
                "stopping one step late (one step past the loop's end)",
                lambda: [*states, more],
            )
        )
    if line or isinstance(model, DDALine):
        again = states[-1]._replace(k=states[-1].k + 1)
        out.append(
            Variant(
                MISTAKE,
                f"writing the end point ({end[0]}, {end[1]}) twice (one row too many)",
                lambda: [*states, again],
            )
        )
    return out


def diagnose(
    rows: list[Got], solution: Solution, model: Model, marked: set[str], hint: str = "at"
) -> str:
    """The known conventions or mistakes the student's whole table is exactly, in one line."""
    found: list[tuple[int, str]] = []
    for v in variants(solution, model):
        if matches(rows, v.states(), model, marked if v.decisions else marked - {"decision"}):
            found.append((v.rank, v.label))
    if not found:
        return ""
    best = min(r for r, _ in found)
    labels = list(dict.fromkeys(label for r, label in found if r == best))
    return "The table is exactly " + "; or ".join(map(_as_match, labels)) + "."


def _as_match(label: str) -> str:
    """A variant's label after "The table is exactly": ``the one ...`` for a printed table,
    ``that of ...`` for a convention or a mistake.

    >>> _as_match("the table the course notes print"), _as_match("a tie kept")
    ('the one the course notes print', 'that of a tie kept')
    """
    if label.startswith("the table "):
        return "the one " + label[len("the table ") :]
    return "that of " + label

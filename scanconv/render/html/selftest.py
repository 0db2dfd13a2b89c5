"""Test yourself: the data and the panel of the HTML page's quiz mode (issue 31, item 2).

A page whose answer has a step table and a marking model (:mod:`scanconv.marking.models`)
gets a "Test yourself" button. The mode hides the step table from the current row on and asks,
step by step, for the decision parameter p_k, the decision and the pixel it reaches (for the
DDA: the exact x_{k+1}, y_{k+1} and the pixel), judges each with follow-through as ``check``
does (:mod:`scanconv.marking.mark`), explains a wrong answer with the numbers, reveals the
right row and goes on, and gives the score at the end. The script
(``scanconv/render/html/static/selftest.js``, :mod:`scanconv.render.html.page_assets`) knows no method: it interprets the small descriptor
written here, which is read off the method's marking model (never a second copy of its
arithmetic):

* a **rule** (one per kind of step: the ellipse's two regions have one each) names the move
  the model's :meth:`~scanconv.marking.models.Model.decide` takes for p < 0, p = 0 and p > 0
  (the decision parameters of these methods are integers, or fractions decided at 0, so the
  sign is the whole test), and the pixel step of every move (the model's
  :meth:`~scanconv.marking.models.Model.step` from the row's point);
* a **row** is one step: the point it is taken from, p_k as an exact fraction string (and as
  the table prints it), the move, the point it reaches, and the stepper positions to show;
* a row's **increments** (``inc``): how p moves on each move, ``c0 + cx x + cy y`` of the point
  the step is taken from (:func:`increments`, read off the model's
  :meth:`~scanconv.marking.models.Model.step` at the row's point and two neighbours, and kept
  only when it gives the model's own next p), so that the script follows a slip through to
  the next steps as ``check`` does: the next p_k is expected from the student's own p and
  move, the next pixel from the student's own pixel;
* ``next``: the step table's p_{k+1} column (hidden in the last row shown: it is the answer);
* the DDA has no decision: its rows hold the exact coordinates (fraction strings) and the
  descriptor names the rounding (:data:`~scanconv.algorithms.conventions.ROUNDINGS`).

The rule is checked against every row before it is written (:func:`apply_rule` must give the
model's own move and point, the DDA's rounding the table's pixel); a page where it would not is
given no button, like a page without a model.

>>> from scanconv.answers.primitives.line import line_solution
>>> from scanconv.document import StepTable, document
>>> from scanconv.render.html.stepper import stepping
>>> s = line_solution("bresenham", 2, 2, 10, 6)
>>> d = selftest_data(document(s).get(StepTable), stepping(s))
>>> d["rules"][0]["neg"], d["rules"][0]["pos"], d["rules"][0]["moves"]
('E', 'NE', {'E': [1, 0], 'NE': [1, 1]})
>>> {k: d["rows"][3][k] for k in ("name", "at", "p", "d", "to")}
{'name': 'p₃', 'at': [5, 4], 'p': '-8', 'd': 'E', 'to': [6, 4]}
"""

from __future__ import annotations

from fractions import Fraction
from itertools import islice
from typing import Any

from ...algorithms.conventions import ROUNDINGS
from ...core.records import Step
from ...document import StepTable
from ...marking.models import DDALine, Model, State, chain
from .. import Options
from ..cells import cell
from .mathml import esc, json_script
from .stepper import MAX_TABLE_ROWS, Stepping, column_label

MAX_QUESTIONS = MAX_TABLE_ROWS
"""Steps the quiz asks at most (the rows the page writes of a table)."""

_SIGNS = (("neg", -1), ("zero", 0), ("pos", 1))


def frac(v: Any) -> str | None:
    """An exact value as the script reads it: ``"-5/4"``, ``"3"`` (``None`` stays ``None``)."""
    return None if v is None else str(Fraction(v))


def rule_of(model: Model, s: State) -> dict[str, Any] | None:
    """The descriptor of the decision at ``s``, read off the model (``None``: no decision)."""
    moves = model.moves(s)
    if not moves:
        return None
    probe = s if s.p is not None else s._replace(p=0)
    steps: dict[str, list[int]] = {}
    for m in moves:
        t = model.step(probe, m)
        if t is None:
            return None
        steps[m] = [t.point[0] - s.point[0], t.point[1] - s.point[1]]
    rule: dict[str, Any] = {sign: model.decide(s._replace(p=v)) for sign, v in _SIGNS}
    rule["moves"] = steps
    rule["name"] = _name(model, s)
    return rule


def _name(model: Model, s: State) -> str:
    """The parameter's name in the rule's own words (``p``, ``d``, ``p1``, ``p2``)."""
    words = model.rule(s if s.p is not None else s._replace(p=0))
    return words.split(" ", 1)[0] if words else "p"


def apply_rule(rule: dict[str, Any], at: list[int], p: Fraction | None) -> tuple[str, list[int]]:
    """What the script does with a rule: the move for ``p``'s sign and the pixel it reaches
    from ``at`` (a rule with one move takes it whatever ``p``)."""
    moves = rule["moves"]
    if len(moves) == 1 or p is None:
        move = next(iter(moves)) if len(moves) == 1 else ""
    else:
        move = rule["neg" if p < 0 else "pos" if p > 0 else "zero"]
    dx, dy = moves.get(move, (0, 0))
    return move, [at[0] + dx, at[1] + dy]


_PROBES = ((0, 0), (1, 0), (0, 1))


def increments(model: Model, s: State, t: State) -> dict[str, list[str]] | None:
    """How p moves on a step from ``s`` by each of its moves, as ``[c0, cx, cy]`` (exact
    strings): p_{k+1} = p_k + c0 + cx x + cy y, with (x, y) the point the step is taken from,
    read off the model at ``s`` and at its two neighbours (the same p); ``None`` when ``s``
    has no p, a step ends the loop there, or the form does not give ``t``'s p (a region's new
    start: the ellipse's p2 is worked out afresh).

    >>> from scanconv.marking.models import BresenhamLine, chain
    >>> m = BresenhamLine(2, 2, 10, 6)
    >>> s, t = list(chain(m))[:2]
    >>> increments(m, s, t)
    {'E': ['8', '0', '0'], 'NE': ['-8', '0', '0']}
    """
    if s.p is None or t.p is None:
        return None
    out: dict[str, list[str]] = {}
    x, y = s.point
    for move in model.moves(s):
        d = []
        for dx, dy in _PROBES:
            nxt = model.step(s._replace(point=(x + dx, y + dy)), move)
            if nxt is None or nxt.p is None:
                return None
            d.append(Fraction(nxt.p) - Fraction(s.p))
        cx, cy = d[1] - d[0], d[2] - d[0]
        out[move] = [str(c) for c in (d[0] - cx * x - cy * y, cx, cy)]
    c0, cx, cy = (Fraction(c) for c in out.get(str(model.decide(s)), ["0", "0", "0"]))
    if model.decide(s) not in out or Fraction(s.p) + c0 + cx * x + cy * y != t.p:
        return None
    return out


def _layout(states: list[State], records: list[Step]) -> str | None:
    """``at`` (record i is state i) or ``after`` (record i holds p_i and state i + 1's
    point), as the page's table prints the chain; ``None``: the table is not the chain's."""
    n = min(len(records), len(states) - 1)
    if n <= 0:
        return None
    ps = all(records[i].p == states[i].p for i in range(n))
    if ps and all(records[i].pixel == states[i].point for i in range(n)):
        return "at"
    if ps and all(records[i].pixel == states[i + 1].point for i in range(n)):
        return "after"
    return None


def _stem(table: StepTable) -> str:
    """The TeX of the parameter's column without its ``_k`` (``p``, ``d``)."""
    col = next((c for c in table.columns if c.key == "p"), None)
    tex = col.tex if col is not None else "p_k"
    return tex[:-2] if tex.endswith("_k") else tex


def _text(value: Any, table: StepTable, key: str, exact: bool) -> str:
    col = next((c for c in table.columns if c.key == key), None)
    return str(value) if col is None else cell(value, col, exact)


def _dda(model: DDALine, states: list[State]) -> dict[str, Any] | None:
    """The DDA's descriptor: its rounding by name (the model's own rounder), if it gives
    every row's pixel from the row's exact values."""
    rounding = next((k for k, f in ROUNDINGS.items() if f is model.rnd), None)
    if rounding is None or any(
        s.exact is None or s.point != (model.rnd(s.exact[0]), model.rnd(s.exact[1])) for s in states
    ):
        return None  # pragma: no cover - the tests keep the rounding and the table equal
    return {"kind": "dda", "rounding": rounding, "rules": []}


def _rows(
    model: Model, table: StepTable, states: list[State], records: list[Step], layout: str,
    options: Options,
) -> tuple[list[dict[str, Any]], list[dict[str, Any]]] | None:  # fmt: skip
    """The quiz's rows and rules; ``None`` if a rule does not give the model's own step."""
    rules: list[dict[str, Any]] = []
    rows: list[dict[str, Any]] = []
    stem = _stem(table)
    steps = len(records) - 1 if layout == "at" else len(records)
    for j in range(min(steps, len(states) - 1, MAX_QUESTIONS)):
        s, t = states[j], states[j + 1]
        row: dict[str, Any] = {
            "lit": j + 1 if layout == "at" else j,
            "row": j + 1,
            "at": list(s.point),
            "to": list(t.point),
            "p": frac(s.p),
            "pt": _text(s.p, table, "p", options.exact),
            "reg": s.region,
        }
        if isinstance(model, DDALine):
            assert s.exact is not None and t.exact is not None
            row["xy"] = [frac(v) for v in s.exact]
            row["nxy"] = [frac(v) for v in t.exact]
            row["xyt"] = [_text(v, table, "x", options.exact) for v in s.exact]
            row["nxyt"] = [_text(v, table, "x", options.exact) for v in t.exact]
            row["name"] = f"(x{_sub(records[j].k + 1)}, y{_sub(records[j].k + 1)})"
            rows.append(row)
            continue
        rule = rule_of(model, s)
        if rule is None:
            return None
        if rule not in rules:
            rules.append(rule)
        row["rule"] = rules.index(rule)
        name = stem if s.region == 0 else rule["name"]
        row["name"] = column_label(f"{name}_k", records[j].k)
        row["d"] = model.decide(s)
        inc = increments(model, s, t)
        if inc is not None:
            row["inc"] = inc
        move, to = apply_rule(rule, row["at"], None if s.p is None else Fraction(s.p))
        if to != row["to"] or (s.p is not None and move != row["d"]):
            return None  # pragma: no cover - the tests keep the rules and the chains equal
        rows.append(row)
    return rows, rules


def _sub(k: int) -> str:
    return str(k).translate(str.maketrans("0123456789-", "₀₁₂₃₄₅₆₇₈₉₋"))


def selftest_data(table: StepTable | None, st: Stepping | None, options: Options | None = None) -> dict[str, Any] | None:  # fmt: skip
    """The quiz's JSON data for an answer's step ``table`` (``None``: no step table or no rule:
    no button)."""
    options = options or Options()
    if st is None or st.table is not None or table is None or not table.columns or not st.pixels:
        return None
    model = table.model() if table.model is not None else None
    if model is None:
        return None
    limit = min(st.n, MAX_QUESTIONS + 1)
    records = list(islice(table.steps(), limit))
    states = list(chain(model, limit + 2))
    layout = _layout(states, records)
    if layout is None:
        return None
    built = _rows(model, table, states, records, layout, options)
    if built is None or not built[0]:
        return None
    rows, rules = built
    centre = table.center or (0, 0)
    data: dict[str, Any] | None = {"kind": "decide", "rules": rules}
    if isinstance(model, DDALine):
        data = _dda(model, states[: len(rows) + 1])
    if data is None:
        return None
    ok = all(Fraction(c).denominator == 1 for c in centre)
    data.update(
        {
            "rows": rows,
            "centre": [int(c) for c in centre] if ok else None,
            "down": options.origin == "top-left",
            "next": next((i for i, c in enumerate(table.columns) if c.key == "p_next"), None),
        }
    )
    return data


def selftest_html(
    table: StepTable | None, st: Stepping | None, options: Options | None = None
) -> str:
    """The "Test yourself" button, its panel (filled in by the script) and its data; ``""``
    when the answer has no rule to test against."""
    data = selftest_data(table, st, options)
    if data is None:
        return ""
    n = len(data["rows"])
    return (
        '<div class="sc-selftest">'
        '<button type="button" class="sc-testbtn" data-selftest aria-expanded="false">'
        f'Test yourself</button> <span class="sc-testnote">{esc(f"{n} steps")}: '
        "the table hides from the current row on; type (or click on the grid) each step."
        '</span><div class="sc-testpanel" role="group" aria-label="Test yourself" hidden></div>'
        + json_script(data, "sc-testdata")
        + "</div>"
    )

"""The worked answer of line clipping, by Cohen–Sutherland or Liang–Barsky, against a closed
rectangular window (a point on an edge is inside); polygons are in :mod:`.clip_polygon`.

Region codes are written ``TBRL`` (top, bottom, right, left; Hearn & Baker's bits 4 to 1).
Every intersection is exact: table cells show ``39/5`` or ``7.8``, never a rounded decimal.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any, cast

from ....algorithms.clipping import (
    EDGES,
    CSResult,
    Edge,
    LBResult,
    Point,
    Rect,
    boundary,
    cohen_sutherland,
    liang_barsky,
)
from ....algorithms.process_choices import LineClipMethod
from ....core.checks import InputError
from ....core.numeric import Number, fmt_paren, fmt_short, normalize
from ....core.records import Column, Plot, Quantity, Solution, Table, Walk
from ... import methods
from ...asked import ClipLineQuestion
from .._shared import (
    Clipped,
    check_rect,
    clip_figure,
    factor,
    point_quantity,
    pt,
    pt_approx,
    rect_quantity,
    rect_text,
)
from ._shared import clipped_quantity, code_reason

if TYPE_CHECKING:
    from ....core.choices import (
        ClipEndsName,
        LineClipMethodName,
        MidpointName,
        MidpointStopName,
        NormalsName,
    )

LINE_METHODS = tuple(m.value for m in LineClipMethod)
"""The line clipping methods, by name."""


def cohen_sutherland_clipped(q: ClipLineQuestion) -> Clipped:
    """Cohen-Sutherland's working against the question's rectangle (the record's ``stage``)."""
    cs = cohen_sutherland(q.p1, q.p2, q.window)
    return Clipped(*cs_parts(q.p1, q.p2, q.window, cs), cs.segment)


def liang_barsky_clipped(q: ClipLineQuestion) -> Clipped:
    """Liang-Barsky's working against the question's rectangle (the record's ``stage``)."""
    lb = liang_barsky(q.p1, q.p2, q.window)
    return Clipped(*lb_parts(q.p1, q.p2, q.window, lb), lb.segment)


_CS_NOTES = (
    "Region code bits, written T B R L (Hearn & Baker's bits 4 to 1): T = above (y > ymax), B = below (y < ymin), R = right (x > xmax), L = left (x < xmin).",
    "Each iteration clips the end point that is outside (P1 first), at the first boundary of its code in the order left, right, bottom, top; the end points keep their names.",
)  # fmt: skip
_PARAMETRIC = (
    "x = x1 + u·Δx, y = y1 + u·Δy with 0 <= u <= 1; inside where u·p_k <= q_k for every k. p_k < 0 enters the window (raises u1), p_k > 0 leaves it (lowers u2).",
)  # fmt: skip


def code_text(code: int) -> str:
    """``1010`` (T B R L).

    >>> code_text(8 | 2)
    '1010'
    """
    return f"{code:04b}"


def trivial_tests(c1: int, c2: int) -> str:
    """The trivial tests on two codes and what they decide."""
    either, both = c1 | c2, c1 & c2
    if not either:
        return f"{code_text(c1)} OR {code_text(c2)} = 0000: accept"
    if both:
        return f"{code_text(c1)} AND {code_text(c2)} = {code_text(both)} != 0000: reject"
    return f"OR = {code_text(either)}, AND = 0000: clip"


# --- line clipping ----------------------------------------------------------------------------


def _slope(p1: Point, p2: Point) -> Quantity:
    dx, dy = normalize(p2[0] - p1[0]), normalize(p2[1] - p1[1])
    head = f"Δx = {fmt_short(p2[0])} - {fmt_paren(p1[0])} = {fmt_short(dx)}, Δy = {fmt_short(p2[1])} - {fmt_paren(p1[1])} = {fmt_short(dy)}"
    tex = f"\\Delta x = {fmt_short(dx)}, \\Delta y = {fmt_short(dy)}"
    if dx == 0:
        return Quantity(
            "m", None, head + "; m undefined (vertical line)", tex + r", m \text{ undefined}"
        )
    m = normalize(Fraction(dy) / dx)
    return Quantity(
        "m",
        m,
        f"{head}; m = Δy/Δx = {fmt_short(m)}",
        f"{tex}, m = \\frac{{\\Delta y}}{{\\Delta x}} = {fmt_short(m)}",
    )


def crossing_work(p1: Point, p2: Point, edge: Edge, value: Number, result: Point) -> str:
    """The intersection with the numbers substituted (ASCII)."""
    (x1, y1), (x2, y2) = p1, p2
    if edge in (Edge.LEFT, Edge.RIGHT):
        m = Fraction(y2 - y1) / (x2 - x1)
        return f"x = {fmt_short(value)}, y = y1 + m(x - x1) = {fmt_short(y1)} + {factor(m)}*({fmt_short(value)} - {fmt_paren(x1)}) = {fmt_short(result[1])}"
    if x1 == x2:
        return f"y = {fmt_short(value)}, x = x1 = {fmt_short(x1)} (vertical line)"
    m = Fraction(y2 - y1) / (x2 - x1)
    return f"y = {fmt_short(value)}, x = x1 + (y - y1)/m = {fmt_short(x1)} + ({fmt_short(value)} - {fmt_paren(y1)})/{factor(m)} = {fmt_short(result[0])}"


_CS_COLUMNS = (
    Column("k", "k", "k", role="label"),
    Column("point_end", "end point", r"\text{end point}", role="given"),
    Column("code", "code", r"\text{code}"),
    Column("reason", "boundary", r"\text{boundary}"),
    Column("work", "intersection (exact)", r"\text{intersection (exact)}", role="working"),
    Column("point_new", "new end point", r"\text{new end point}"),
    Column("new_code", "new code", r"\text{new code}"),
    Column("method", "test", r"\text{test}", role="working"),
)

_CODE_COLUMNS = (
    Column("point", "point", r"\text{point}", role="label"),
    Column("point_xy", "(x, y)", "(x, y)", role="given"),
    Column("T", "T", "T"),
    Column("B", "B", "B"),
    Column("R", "R", "R"),
    Column("L", "L", "L"),
    Column("code", "code TBRL", r"\text{code } TBRL"),
    Column("reason", "why", r"\text{why}", role="working"),
)


def cs_parts(p1: Point, p2: Point, w: Rect, r: CSResult) -> tuple[list[Quantity], list[Table]]:
    """The working and tables of a Cohen–Sutherland run."""
    derived = [_slope(p1, p2)]
    for name, p, c in (("P1", p1, r.codes[0]), ("P2", p2, r.codes[1])):
        derived.append(
            Quantity(
                f"code_{name}",
                code_text(c),
                f"code({name}) = {code_text(c)}: {code_reason(p, w)}",
                f"\\text{{code}}({name}) = {code_text(c)} \\quad \\text{{({code_reason(p, w)})}}",
            )
        )
    derived.append(
        Quantity(
            "test_0",
            None,
            "initial test: " + trivial_tests(*r.codes),
            r"\text{initial test: " + trivial_tests(*r.codes) + "}",
        )
    )
    code_rows = [
        (name, pt(p), *((c >> b) & 1 for b in (3, 2, 1, 0)), code_text(c), code_reason(p, w))
        for name, p, c in (("P1", p1, r.codes[0]), ("P2", p2, r.codes[1]))
    ]
    it_rows = [
        (
            i.k, f"P{i.end} {pt(i.old)}", code_text(i.code), f"{i.edge} ({'x' if i.edge in (Edge.LEFT, Edge.RIGHT) else 'y'} = {fmt_short(boundary(i.edge, w))})",
            crossing_work(p1, p2, i.edge, boundary(i.edge, w), i.point), pt(i.point), code_text(i.new_code), trivial_tests(*i.codes),
        )
        for i in r.iterations
    ]  # fmt: skip
    tables = [
        Table(
            "Region codes (bit order T B R L: above, below, right, left)",
            _CODE_COLUMNS,
            lambda: code_rows,
        )
    ]
    if it_rows:
        tables.append(Table("Cohen-Sutherland iterations", _CS_COLUMNS, lambda: it_rows))
    return derived, tables


_LB_COLUMNS = (
    Column("k", "k", "k", role="label"),
    Column("reason", "boundary", r"\text{boundary}"),
    Column("p", "p_k", "p_k"),
    Column("q", "q_k", "q_k"),
    Column("r", "r_k = q_k/p_k", "r_k = q_k / p_k"),
    Column("method", "case", r"\text{case}"),
    Column("u1", "u1", "u_1"),
    Column("u2", "u2", "u_2"),
)

_PQ = (
    ("-Δx", "x1 - xmin", r"-\Delta x", r"x_1 - x_{\min}"),
    ("Δx", "xmax - x1", r"\Delta x", r"x_{\max} - x_1"),
    ("-Δy", "y1 - ymin", r"-\Delta y", r"y_1 - y_{\min}"),
    ("Δy", "ymax - y1", r"\Delta y", r"y_{\max} - y_1"),
)


def _cell(v: Number | None) -> Any:
    """Integers as numbers, anything else as its exact text."""
    if v is None:
        return None
    v = normalize(v)
    return v if isinstance(v, int) else fmt_short(v)


def _lb_deltas(p1: Point, p2: Point) -> Quantity:
    (x1, y1), (x2, y2) = p1, p2
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    return Quantity(
        "d",
        (dx, dy),
        f"Δx = {fmt_short(x2)} - {fmt_paren(x1)} = {fmt_short(dx)}, Δy = {fmt_short(y2)} - {fmt_paren(y1)} = {fmt_short(dy)}",
        f"\\Delta x = {fmt_short(dx)}, \\Delta y = {fmt_short(dy)}",
    )


def _lb_pq(p1: Point, w: Rect, r: LBResult) -> list[Quantity]:
    """Each boundary's p_k and q_k, the numbers substituted."""
    x1, y1 = p1
    subst = ((x1, w[0]), (w[2], x1), (y1, w[1]), (w[3], y1))
    return [
        Quantity(
            f"pq{row.k}",
            (row.p, row.q),
            f"p{row.k} = {ps} = {fmt_short(row.p)}, q{row.k} = {qs} = {fmt_short(a)} - {fmt_paren(b)} = {fmt_short(row.q)}   ({row.edge})",
            f"p_{row.k} = {pt_} = {fmt_short(row.p)}, \\quad q_{row.k} = {qt} = {fmt_short(row.q)}",
        )
        for row, (ps, qs, pt_, qt), (a, b) in zip(r.rows, _PQ, subst, strict=True)
    ]


def _lb_bounds(r: LBResult) -> list[Quantity]:
    """u1, the largest entering r_k (or 0), and u2, the smallest leaving r_k (or 1)."""
    entering = [row.r for row in r.rows if row.p < 0]
    leaving = [row.r for row in r.rows if row.p > 0]
    u1, u2 = r.rows[-1].u1, r.rows[-1].u2
    ins = ", ".join(["0", *(fmt_short(v) for v in entering if v is not None)])
    outs = ", ".join(["1", *(fmt_short(v) for v in leaving if v is not None)])
    return [
        Quantity(
            "u1",
            u1,
            f"u1 = max(0, r_k where p_k < 0) = max({ins}) = {fmt_short(u1)}",
            f"u_1 = \\max({ins}) = {fmt_short(u1)}",
        ),
        Quantity(
            "u2",
            u2,
            f"u2 = min(1, r_k where p_k > 0) = min({outs}) = {fmt_short(u2)}",
            f"u_2 = \\min({outs}) = {fmt_short(u2)}",
        ),
    ]


def _lb_outcome(p1: Point, p2: Point, r: LBResult) -> list[Quantity]:
    """The rejection (parallel and outside, or u1 > u2), or both clipped end points."""
    if r.outside is not None:
        k = EDGES.index(r.outside) + 1
        return [
            Quantity(
                "test",
                "reject",
                f"p{k} = 0 and q{k} < 0: parallel to the {r.outside} edge and outside it: reject",
                f"p_{k} = 0, q_{k} < 0: \\text{{reject}}",
            )
        ]
    u1, u2 = r.rows[-1].u1, r.rows[-1].u2
    if r.segment is None:
        return [
            Quantity(
                "test",
                "reject",
                f"u1 = {fmt_short(u1)} > u2 = {fmt_short(u2)}: reject",
                "u_1 > u_2: \\text{reject}",
            )
        ]
    (x1, y1), (x2, y2) = p1, p2
    dx, dy = normalize(x2 - x1), normalize(y2 - y1)
    return [
        Quantity(
            name.replace("'", "_clipped"),
            list(q),
            f"{name} = (x1 + {un}·Δx, y1 + {un}·Δy) = ({fmt_short(x1)} + {factor(u)}*{fmt_paren(dx)}, {fmt_short(y1)} + {factor(u)}*{fmt_paren(dy)}) = {pt_approx(q)}",
            f"{name[:2]}' = (x_1 + u_{un[1]} \\Delta x, y_1 + u_{un[1]} \\Delta y) = {pt(q)}",
        )
        for name, un, u, q in (("P1'", "u1", u1, r.segment[0]), ("P2'", "u2", u2, r.segment[1]))
    ]


def _lb_case(p: Number, q: Number) -> str:
    if p == 0:
        return "parallel, outside" if q < 0 else "parallel, inside"
    return "entering (u1)" if p < 0 else "leaving (u2)"


def lb_parts(p1: Point, p2: Point, w: Rect, r: LBResult) -> tuple[list[Quantity], list[Table]]:
    """The working and table of a Liang–Barsky run."""
    derived = [_lb_deltas(p1, p2), *_lb_pq(p1, w, r), *_lb_bounds(r), *_lb_outcome(p1, p2, r)]
    rows = [
        (
            row.k,
            f"{row.edge}",
            _cell(row.p),
            _cell(row.q),
            _cell(row.r),
            _lb_case(row.p, row.q),
            _cell(row.u1),
            _cell(row.u2),
        )
        for row in r.rows
    ]
    return derived, [
        Table("Liang-Barsky parameters (u1, u2 after each boundary)", _LB_COLUMNS, lambda: rows)
    ]


def check_method(method: str, param: str = "method") -> LineClipMethodName:
    """``method`` if it is one of :data:`LINE_METHODS`, else InputError naming the choices;
    for the pipeline (``param`` ``clip``), one whose record has a rectangle ``stage``."""
    if method not in LINE_METHODS:
        raise InputError(
            f"unknown line clipping method {method!r} (choose from {', '.join(LINE_METHODS)})",
            param,
        )
    if param == "clip" and methods.method("clip", method).stage is None:
        staged = [m.name for m in methods.METHODS.values() if m.command == "clip" and m.stage]
        raise InputError(
            f"the pipeline clips by {', '.join(staged)}, not {method} (its rounded "
            "midpoints may leave several pieces)",
            param,
        )
    return cast("LineClipMethodName", method)  # one of LINE_METHODS, the Literal's values


def only_its_own(method: str, conventions: Iterable[str]) -> None:
    """Refuse a convention given to a method it does not apply to (its record's
    ``options``)."""
    for param in conventions:
        owners = [m for m in methods.METHODS.values() if m.command == "clip" and param in m.options]
        if not any(m.name == method for m in owners):
            raise InputError(f"{param} applies to {owners[0].name} only, not to {method}", param)


def clip_line_solution(
    x1: Number,
    y1: Number,
    x2: Number,
    y2: Number,
    window: Sequence[Number],
    method: str = "cohen-sutherland",
    *,
    normals: NormalsName | None = None,
    ends: ClipEndsName | None = None,
    midpoint: MidpointName | None = None,
    stop: MidpointStopName | None = None,
) -> Solution:
    """The worked answer of clipping the segment P1 P2 against ``window`` by ``method``: its
    record's answer to the question (:class:`~scanconv.answers.asked.ClipLineQuestion`),
    which the answer keeps. A convention (``normals``, ``ends``: Cyrus-Beck's; ``midpoint``,
    ``stop``: midpoint subdivision's) given to another method is refused.

    >>> sol = clip_line_solution(7, 9, 11, 4, (4, 4, 10, 8))
    >>> sol.derived[-1].text
    'clipped segment: (7.8, 8) to (10, 5.25)'
    >>> sol.question.key
    'clip/cohen-sutherland'
    """
    given = dict(normals=normals, ends=ends, midpoint=midpoint, stop=stop)
    only_its_own(method, [param for param, value in given.items() if value is not None])
    name = check_method(method)
    w = check_rect(window, "window", "window")
    p1, p2 = (normalize(x1), normalize(y1)), (normalize(x2), normalize(y2))
    q = ClipLineQuestion(name, p1, p2, w, normals, ends, midpoint, stop)
    sol: Solution = methods.method("clip", name).load("answer")(q)
    sol.question = q
    return sol


def cohen_sutherland_answer(q: ClipLineQuestion) -> Solution:
    """Cohen-Sutherland clipping of the question's segment against its window."""
    return _answer(q, "cohen-sutherland", _CS_NOTES)


def liang_barsky_answer(q: ClipLineQuestion) -> Solution:
    """Liang-Barsky clipping of the question's segment against its window."""
    return _answer(q, "liang-barsky", _PARAMETRIC)


def _answer(q: ClipLineQuestion, name: str, method_notes: tuple[str, ...]) -> Solution:
    record = methods.method("clip", name)
    p1, p2, w = q.p1, q.p2, q.window
    derived, tables, seg = record.load("stage")(q)
    derived.append(clipped_quantity(seg))
    notes = [
        "The window is closed: a point on an edge is inside (code 0000), so a segment along an edge or through a corner is kept.",
        *method_notes,
    ]  # fmt: skip
    return Solution(
        primitive="clip",
        algorithm=name,
        title=f"{record.short} line clipping: {pt(p1)} to {pt(p2)}, window {rect_text(w)}",
        given=(point_quantity("P1", p1), point_quantity("P2", p2), rect_quantity("window", w)),
        derived=tuple(derived),
        notes=tuple(notes),
        walk=Walk(tables=tuple(tables)),
        plot=Plot(figures=clip_figure(list(seg) if seg else [], w, [p1, p2], "clipped segment")),
        data={"clipped": None if seg is None else [list(seg[0]), list(seg[1])]},
    )

"""One step of each marked algorithm from any state: what follow-through marking re-runs.

A step table is a chain of states: the point a row stands at, the decision parameter there
(the value the next move is decided on) and, for the DDA, the exact coordinates. Each model
here starts the chain and takes it one step further from *any* state, including a wrong one a
student wrote, with exactly the arithmetic of :mod:`scanconv.algorithms.lines`,
:mod:`~scanconv.algorithms.circles` and :mod:`~scanconv.algorithms.ellipses` and the same
convention knobs (``tie``, ``start``, ``rounding``, ``p0``, ``loop``). ``tests/test_check.py``
checks that every chain equals the library's own table, in every octant and for every knob.

Known mistakes are explicit models too (:class:`NotesP0Line`, :class:`UnswappedLine`,
:class:`OldXMidpoint`): each computes what a student making that mistake writes.

>>> m = BresenhamLine(2, 2, 10, 6)
>>> [(s.point, s.p) for s in chain(m)][:3]
[((2, 2), 0), ((3, 3), -8), ((4, 3), 0)]
>>> m.advance(State((3, 2), -3))     # from a student's wrong state: p < 0 keeps y
State(point=(4, 2), p=5, exact=None, region=0, k=1)
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction
from typing import TYPE_CHECKING, NamedTuple

from ..algorithms.circles import bresenham_increment, midpoint_increment
from ..algorithms.conventions import rounder
from ..algorithms.ellipses import increment4, p1_4, p2_4
from ..algorithms.lines import bresenham_terms, dda_steps, increments
from ..answers import methods
from ..core.numeric import Number, normalize, round_c_cast
from ..core.records import Move, Pixel

if TYPE_CHECKING:
    from ..answers.asked import CircleQuestion, EllipseQuestion, LineQuestion


class State(NamedTuple):
    """Where a table stands after a row: the point, the decision parameter there, ..."""

    point: Pixel
    p: Number | None
    exact: tuple[Number, Number] | None = None
    """The DDA's exact coordinates (``point`` is their rounding)."""
    region: int = 0
    """The ellipse's region, 1 or 2 (0 elsewhere)."""
    k: int = 0
    """The step count from the start (the DDA and the line stop after a number of steps)."""


class Model:
    """The start of a chain and one step from any state: :meth:`decide` names the move the
    method's rule takes from a state, :meth:`step` takes a given move (the rule's, or a
    student's own), :meth:`advance` is the two (``None``: the loop has ended; with ``force``
    one more step is taken anyway, for "stopped one step late")."""

    shape = "at"
    """``"at"``: a row is a state (the notes' layout); ``"after"``: a row holds p_k and the
    point (x_{k+1}, y_{k+1}) the step reaches (the textbooks' layout, the ellipse)."""

    def start(self) -> State:
        raise NotImplementedError

    def moves(self, s: State) -> tuple[str, ...]:
        """The moves a step from ``s`` can take (``()``: the method makes no decision)."""
        return ()

    def decide(self, s: State) -> str | None:
        """The move the method's rule takes from ``s`` (``None``: no decision)."""
        return None

    def rule(self, s: State) -> str:
        """The rule that decides at ``s``, in words: ``p >= 0 chooses NE``."""
        return ""

    def step(self, s: State, move: str | None) -> State | None:
        """The state one step from ``s`` by ``move`` (``None``: no step is defined)."""
        raise NotImplementedError

    def done(self, s: State, t: State) -> bool:
        """The loop ends at ``s`` (``t``: the step it would take)."""
        raise NotImplementedError

    def advance(self, s: State, force: bool = False) -> State | None:
        t = self.step(s, self.decide(s))
        if t is None or (not force and self.done(s, t)):
            return None
        return t

    def at(self, point: Pixel, s: State) -> State:
        """``s`` moved to a student's own ``point`` (the ellipse re-decides its region)."""
        return s._replace(point=point)


def _choice(p: Number, keep_if_below: Number, moves: tuple[str, str], sign: str = "p") -> str:
    """The rule's words: ``p < 0 chooses E`` or ``p >= 0 chooses NE``."""
    keep = p < keep_if_below
    if keep_if_below == 0:
        return f"{sign} < 0 chooses {moves[0]}" if keep else f"{sign} >= 0 chooses {moves[1]}"
    return f"{sign} <= 0 chooses {moves[0]}" if keep else f"{sign} > 0 chooses {moves[1]}"


def chain(model: Model, limit: int = 10**4 + 1) -> Iterator[State]:
    """Every state from the start until the loop ends (at most ``limit`` of them).

    >>> [s.point for s in chain(MidpointCircle(5))]
    [(0, 5), (1, 5), (2, 5), (3, 4), (4, 3)]
    """
    s: State | None = model.start()
    n = 0
    while s is not None and n < limit:
        yield s
        s = model.advance(s)
        n += 1


# --- lines ------------------------------------------------------------------------------------


class BresenhamLine(Model):
    """Bresenham's line, all octants, ``tie`` and ``start`` as in
    :func:`scanconv.algorithms.lines.bresenham`."""

    def __init__(
        self, x1: int, y1: int, x2: int, y2: int, tie: str = "step", start: str = "swap"
    ) -> None:
        dx, dy = x2 - x1, y2 - y1
        self.steep = abs(dy) > abs(dx)
        if start == "swap" and (dy if self.steep else dx) < 0:
            x1, y1, x2, y2, dx, dy = x2, y2, x1, y1, -dx, -dy
        dmaj, dmin = (dy, dx) if self.steep else (dx, dy)
        self.n, self.dmin = abs(dmaj), abs(dmin)
        self.dir = 1 if dmaj >= 0 else -1
        self.s = 1 if dmin >= 0 else -1
        self.first = (x1, y1)
        _, self.inc_keep, self.inc_step, self.t = bresenham_terms(self.n, self.dmin, tie)

    def p0(self) -> Number:
        return bresenham_terms(self.n, self.dmin)[0]

    def start(self) -> State:
        return State(self.first, self.p0())

    def _moves(self) -> tuple[str, str]:
        """The two moves: the major step alone, and with the minor step."""
        if not hasattr(self, "_pair"):
            out = []
            for minor in (0, self.s):
                d = (minor, self.dir) if self.steep else (self.dir, minor)
                out.append(Move.from_delta(*d).value)
            self._pair = (out[0], out[1])
        return self._pair

    def moves(self, s: State) -> tuple[str, ...]:
        return self._moves()

    def decide(self, s: State) -> str | None:
        if s.p is None:
            return None
        return self._moves()[0 if s.p < self.t else 1]

    def rule(self, s: State) -> str:
        return "" if s.p is None else _choice(s.p, self.t, self._moves())

    def done(self, s: State, t: State) -> bool:
        return s.k >= self.n

    def step(self, s: State, move: str | None) -> State | None:
        if s.p is None or move not in self._moves():
            return None
        x, y = s.point
        major, minor = (y, x) if self.steep else (x, y)
        major += self.dir
        if move == self._moves()[0]:
            q = s.p + self.inc_keep
        else:
            minor += self.s
            q = s.p + self.inc_step
        point = (minor, major) if self.steep else (major, minor)
        return State(point, normalize(q), k=s.k + 1)


class HalfScaledLine(BresenhamLine):
    """The midpoint line with ``--scale half``: ``d = F(M)`` itself, half Bresenham's p
    (``d0 = dy - dx/2``, increments ``dy`` and ``dy - dx``); the same decisions.

    >>> [s.p for s in chain(HalfScaledLine(2, 2, 10, 6))][:3]
    [0, -4, 0]
    """

    def __init__(
        self, x1: int, y1: int, x2: int, y2: int, tie: str = "step", start: str = "swap"
    ) -> None:
        super().__init__(x1, y1, x2, y2, tie, start)
        self.half: Number = Fraction(1, 2) if tie == "keep" else 0  # p < 1: d < 1/2

    def decide(self, s: State) -> str | None:
        if s.p is None:
            return None
        return self._moves()[0 if s.p < self.half else 1]

    def rule(self, s: State) -> str:
        return "" if s.p is None else _choice(s.p, self.half, self._moves())

    def p0(self) -> Number:
        return normalize(self.dmin - Fraction(self.n, 2))

    def step(self, s: State, move: str | None) -> State | None:
        t = super().step(s._replace(p=None if s.p is None else 2 * s.p), move)
        return None if t is None or t.p is None else t._replace(p=normalize(Fraction(t.p) / 2))


class NotesP0Line(BresenhamLine):
    """The notes' p0 (errata E1): ``2Δy(y0 + 1/2) - 2Δx(x0 + 1)`` with the start point's
    absolute coordinates (the major and minor axes for Δx and Δy), -28 for (2, 2) to (10, 6)."""

    def p0(self) -> Number:
        x0, y0 = self.first
        major, minor = (y0, x0) if self.steep else (x0, y0)
        return normalize(2 * self.dmin * (minor + Fraction(1, 2)) - 2 * self.n * (major + 1))


class UnswappedLine(BresenhamLine):
    """The first-octant algorithm applied from P1 without swapping a right-to-left line: the
    major coordinate still steps +1, the minor +1, and Δx, Δy keep their signs
    (``p0 = 2Δy - Δx``, increments ``2Δy`` and ``2Δy - 2Δx``)."""

    def __init__(self, x1: int, y1: int, x2: int, y2: int, tie: str = "step") -> None:
        super().__init__(x1, y1, x2, y2, tie, start="given")
        dx, dy = x2 - x1, y2 - y1
        self.smaj, self.smin = (dy, dx) if self.steep else (dx, dy)
        self.dir, self.s = 1, 1  # the signed differences in the same arithmetic as Bresenham's
        _, self.inc_keep, self.inc_step, _ = bresenham_terms(self.smaj, self.smin)

    def p0(self) -> Number:
        return bresenham_terms(self.smaj, self.smin)[0]

    def _moves(self) -> tuple[str, str]:
        return ("N", "NE") if self.steep else ("E", "NE")


class DDALine(Model):
    """The simple DDA with exact increments, ``rounding`` and ``start`` as in
    :func:`scanconv.answers.primitives.line.line_solution`; ``steps`` another DDA-family
    method's number of steps (the symmetric DDA's 2^n), the increments Δ/steps."""

    def __init__(
        self,
        x1: Number,
        y1: Number,
        x2: Number,
        y2: Number,
        rounding: str = "half-up",
        start: str = "given",
        steps: int | None = None,
    ) -> None:
        dx, dy = x2 - x1, y2 - y1
        steep = abs(Fraction(dy)) > abs(Fraction(dx))
        if start == "swap" and (dy if steep else dx) < 0:
            x1, y1, x2, y2 = x2, y2, x1, y1
        self.first = (normalize(x1), normalize(y1))
        self.n = dda_steps(x1, y1, x2, y2) if steps is None else steps
        self.inc = increments(x1, y1, x2, y2, self.n)
        self.rnd = rounder(rounding)

    def state(self, exact: tuple[Number, Number], k: int) -> State:
        x, y = normalize(exact[0]), normalize(exact[1])
        return State((self.rnd(x), self.rnd(y)), None, (x, y), k=k)

    def start(self) -> State:
        return self.state(self.first, 0)

    def done(self, s: State, t: State) -> bool:
        return s.k >= self.n

    def step(self, s: State, move: str | None) -> State | None:
        x, y = s.exact if s.exact is not None else s.point
        return self.state((x + self.inc[0], y + self.inc[1]), s.k + 1)


# --- circles ----------------------------------------------------------------------------------


class MidpointCircle(Model):
    """The midpoint circle (p0 = 1 - r or 5/4 - r), ``tie`` and ``loop`` as in
    :func:`scanconv.algorithms.circles.midpoint`."""

    def __init__(
        self, r: int, tie: str = "step", p0: str = "1-r", loop: str = "strict", shape: str = "at"
    ) -> None:
        self.r, self.keep, self.inclusive = r, tie == "keep", loop == "inclusive"
        self.p0 = 1 - r if p0 == "1-r" else Fraction(5, 4) - r
        self.shape = shape

    def start(self) -> State:
        return State((0, self.r), self.p0)

    def going(self, x: int, y: int) -> bool:
        return x < y or (self.inclusive and x == y)

    def increment(self, x_old: int, x: int, y: int, se: bool) -> Number:
        return midpoint_increment(x, y, se)

    def moves(self, s: State) -> tuple[str, ...]:
        return ("E", "SE")

    def decide(self, s: State) -> str | None:
        if s.p is None:
            return None
        return "E" if s.p < 0 or (self.keep and s.p == 0) else "SE"

    def rule(self, s: State) -> str:
        return "" if s.p is None else _choice(s.p, 1 if self.keep else 0, ("E", "SE"))

    def done(self, s: State, t: State) -> bool:
        return not self.going(*s.point)

    def step(self, s: State, move: str | None) -> State | None:
        if s.p is None or move not in ("E", "SE"):
            return None
        x, y = s.point
        se = move == "SE"
        nx, ny = x + 1, y - 1 if se else y
        return State((nx, ny), normalize(s.p + self.increment(x, nx, ny, se)), k=s.k + 1)


class OldXMidpoint(MidpointCircle):
    """The midpoint update written with the old x: ``p + 2x_k + 1`` (E) and
    ``p + 2x_k + 1 - 2y_{k+1}`` (SE), forgetting that the increments use x_{k+1}."""

    def increment(self, x_old: int, x: int, y: int, se: bool) -> Number:
        return 2 * x_old + 1 - 2 * y if se else 2 * x_old + 1


class BresenhamCircle(Model):
    """Bresenham's circle, d0 = 3 - 2r, as in :func:`scanconv.algorithms.circles.bresenham`."""

    def __init__(self, r: int, tie: str = "step", xstep: str = "last") -> None:
        self.r, self.t, self.xstep = r, 1 if tie == "keep" else 0, xstep

    def start(self) -> State:
        return State((0, self.r), 3 - 2 * self.r)

    def moves(self, s: State) -> tuple[str, ...]:
        return ("E", "SE")

    def decide(self, s: State) -> str | None:
        if s.p is None:
            return None
        return "E" if s.p < self.t else "SE"

    def rule(self, s: State) -> str:
        return "" if s.p is None else _choice(s.p, self.t, ("E", "SE"), "d")

    def done(self, s: State, t: State) -> bool:
        return t.point[0] > t.point[1]

    def step(self, s: State, move: str | None) -> State | None:
        if s.p is None or move not in ("E", "SE"):
            return None
        x, y = s.point
        se = move == "SE"
        e = s.p + bresenham_increment(x, y, se, self.xstep)
        return State((x + 1, y - 1 if se else y), e, k=s.k + 1)


class GeneralCircle(MidpointCircle):
    """The notes' general method: p0 = 0 at the point (0, r), the same increments as the
    midpoint circle, the last row the point the loop stops at."""

    def __init__(self, r: int, tie: str = "step", loop: str = "strict") -> None:
        super().__init__(r, tie, "1-r", loop)
        self.p0 = 0


# --- the ellipse ------------------------------------------------------------------------------


class MidpointEllipse(Model):
    """The midpoint ellipse, both regions and the tip of a flat ellipse, as in
    :func:`scanconv.algorithms.ellipses.midpoint_ellipse`; a row holds p_k and the point the
    step reaches, the first region-2 p is p2_0 at the last region-1 point."""

    shape = "after"

    def __init__(
        self, rx: int, ry: int, loop: str = "strict", tie: str = "step", p0: str = "exact"
    ) -> None:
        self.rx, self.ry = rx, ry
        self.rx2, self.ry2 = rx * rx, ry * ry
        self.inclusive = loop == "inclusive"
        self.keep = tie == "keep"
        self.rounded = p0 == "rounded"

    def region1(self, x: int, y: int) -> bool:
        a, b = 2 * self.ry2 * x, 2 * self.rx2 * y
        return a < b or (self.inclusive and a == b and y > 0)

    def initial(self, p: Fraction) -> Number:
        """p1_0 or p2_0 as the convention writes it: exact, or ``int(p + 0.5)``."""
        return round_c_cast(p) if self.rounded else normalize(p)

    def p2_0(self, x: int, y: int) -> Number:
        return self.initial(Fraction(p2_4(self.rx, self.ry, x, y), 4))

    def enter(self, x: int, y: int, p: Number | None, k: int) -> State:
        if self.region1(x, y):
            return State((x, y), p, region=1, k=k)
        return State((x, y), self.p2_0(x, y) if y > 0 else None, region=2, k=k)

    def start(self) -> State:
        p1 = self.initial(Fraction(p1_4(self.rx, self.ry), 4))
        return self.enter(0, self.ry, p1, 0)

    def at(self, point: Pixel, s: State) -> State:
        if s.region == 1:
            return self.enter(point[0], point[1], s.p, s.k)
        return s._replace(point=point)

    def moves(self, s: State) -> tuple[str, ...]:
        if s.region == 1:
            return ("E", "SE")
        return ("S", "SE") if s.point[1] > 0 else ("E",)

    def decide(self, s: State) -> str | None:
        if s.region == 2 and s.point[1] <= 0:
            return "E"
        if s.p is None:
            return None
        if s.region == 1:
            return "E" if s.p < 0 or (self.keep and s.p == 0) else "SE"
        return "S" if s.p > 0 or (self.keep and s.p == 0) else "SE"

    def rule(self, s: State) -> str:
        if s.p is None:
            return ""
        if s.region == 1:
            return _choice(s.p, 1 if self.keep else 0, ("E", "SE"), "p1")
        if self.keep:
            return "p2 >= 0 chooses S" if s.p >= 0 else "p2 < 0 chooses SE"
        return "p2 > 0 chooses S" if s.p > 0 else "p2 <= 0 chooses SE"

    def done(self, s: State, t: State) -> bool:
        return s.region == 2 and s.point[1] <= 0 and s.point[0] >= self.rx

    def step(self, s: State, move: str | None) -> State | None:
        x, y = s.point
        if move not in self.moves(s):
            return None
        if s.region == 1:
            if s.p is None:
                return None
            x += 1
            y -= move == "SE"
            q = s.p + Fraction(increment4(self.rx, self.ry, x, y, 1, move == "SE"), 4)
            return self.enter(x, y, normalize(q), s.k + 1)
        if y > 0:
            if s.p is None:
                return None
            y -= 1
            x += move == "SE"
            q = s.p + Fraction(increment4(self.rx, self.ry, x, y, 2, move == "SE"), 4)
            return State((x, y), normalize(q) if y > 0 else None, region=2, k=s.k + 1)
        return State((x + 1, 0), None, region=2, k=s.k + 1)  # the tip of a flat ellipse


# --- The model pieces the method records name: each takes the question ---------------------


def integer_ends(q: LineQuestion) -> tuple[int, int, int, int] | None:
    """A line's end points as integers (``None``: not all integers)."""
    v = [Fraction(e) for e in q.ends]
    if any(f.denominator != 1 for f in v):
        return None
    return v[0].numerator, v[1].numerator, v[2].numerator, v[3].numerator


def bresenham_line(q: LineQuestion) -> Model | None:
    """Bresenham's line with the question's tie and start (integer end points only)."""
    ends = integer_ends(q)
    return None if ends is None else BresenhamLine(*ends, str(q.knobs.tie), str(q.knobs.start))


def midpoint_line(q: LineQuestion) -> Model | None:
    """The midpoint line: Bresenham's p, or half of it with ``scale = half``."""
    ends = integer_ends(q)
    if ends is None:
        return None
    line = HalfScaledLine if q.knobs.scale == "half" else BresenhamLine
    return line(*ends, str(q.knobs.tie), q.knobs.start or "swap")


def dda_line(q: LineQuestion) -> Model:
    """A DDA-family line (the record's answer is ``dda_answer``) with the question's rounding
    and start, and its record's number of steps (its row estimate less the start row, as the
    answer counts them)."""
    steps = methods.METHODS[q.key].load("rows")(q) - 1
    return DDALine(*q.ends, q.knobs.rounding or "half-up", q.knobs.start or "given", steps)


def midpoint_circle(q: CircleQuestion) -> Model:
    """The midpoint circle with the question's tie, p0 and loop."""
    k = q.knobs
    return MidpointCircle(q.r, str(k.tie), str(k.p0), str(k.loop))


def bresenham_circle(q: CircleQuestion) -> Model:
    """Bresenham's circle (d0 = 3 - 2r) with the question's tie and x step."""
    return BresenhamCircle(q.r, str(q.knobs.tie), str(q.knobs.xstep))


def general_circle(q: CircleQuestion) -> Model:
    """The notes' general method with the question's tie and loop."""
    return GeneralCircle(q.r, str(q.knobs.tie), str(q.knobs.loop))


def midpoint_ellipse(q: EllipseQuestion) -> Model:
    """The midpoint ellipse with the question's loop, tie and p0."""
    k = q.knobs
    return MidpointEllipse(q.rx, q.ry, str(k.loop), str(k.tie), str(k.p0))

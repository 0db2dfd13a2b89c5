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
from typing import NamedTuple

from ..algorithms.conventions import rounder
from ..algorithms.lines import dda_increments, dda_steps
from ..core.numeric import Number, normalize, round_c_cast
from ..core.records import Pixel


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
    """The start of a chain and one step from any state (``None``: the loop has ended; with
    ``force`` one more step is taken anyway, for "stopped one step late")."""

    shape = "at"
    """``"at"``: a row is a state (the notes' layout); ``"after"``: a row holds p_k and the
    point (x_{k+1}, y_{k+1}) the step reaches (the textbooks' layout, the ellipse)."""

    def start(self) -> State:
        raise NotImplementedError

    def advance(self, s: State, force: bool = False) -> State | None:
        raise NotImplementedError


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
        self.t = 1 if tie == "keep" else 0

    def p0(self) -> Number:
        return 2 * self.dmin - self.n

    def start(self) -> State:
        return State(self.first, self.p0())

    def advance(self, s: State, force: bool = False) -> State | None:
        if (s.k >= self.n and not force) or s.p is None:
            return None
        x, y = s.point
        major, minor = (y, x) if self.steep else (x, y)
        major += self.dir
        if s.p < self.t:
            q = s.p + 2 * self.dmin
        else:
            minor += self.s
            q = s.p + 2 * self.dmin - 2 * self.n
        point = (minor, major) if self.steep else (major, minor)
        return State(point, normalize(q), k=s.k + 1)


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
        self.dir, self.s = 1, 1

    def p0(self) -> Number:
        return 2 * self.smin - self.smaj

    def advance(self, s: State, force: bool = False) -> State | None:
        if (s.k >= self.n and not force) or s.p is None:
            return None
        x, y = s.point
        major, minor = (y, x) if self.steep else (x, y)
        major += 1
        if s.p < self.t:
            q = s.p + 2 * self.smin
        else:
            minor += 1
            q = s.p + 2 * self.smin - 2 * self.smaj
        point = (minor, major) if self.steep else (major, minor)
        return State(point, q, k=s.k + 1)


class DDALine(Model):
    """The simple DDA with exact increments, ``rounding`` and ``start`` as in
    :func:`scanconv.answers.line.line_solution`."""

    def __init__(
        self,
        x1: Number,
        y1: Number,
        x2: Number,
        y2: Number,
        rounding: str = "half-up",
        start: str = "given",
    ) -> None:
        dx, dy = x2 - x1, y2 - y1
        steep = abs(Fraction(dy)) > abs(Fraction(dx))
        if start == "swap" and (dy if steep else dx) < 0:
            x1, y1, x2, y2 = x2, y2, x1, y1
        self.first = (normalize(x1), normalize(y1))
        self.n = dda_steps(x1, y1, x2, y2)
        self.inc = dda_increments(x1, y1, x2, y2)
        self.rnd = rounder(rounding)

    def state(self, exact: tuple[Number, Number], k: int) -> State:
        x, y = normalize(exact[0]), normalize(exact[1])
        return State((self.rnd(x), self.rnd(y)), None, (x, y), k=k)

    def start(self) -> State:
        return self.state(self.first, 0)

    def advance(self, s: State, force: bool = False) -> State | None:
        if s.k >= self.n and not force:
            return None
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
        return 2 * x + 1 - 2 * y if se else 2 * x + 1

    def advance(self, s: State, force: bool = False) -> State | None:
        x, y = s.point
        if (not self.going(x, y) and not force) or s.p is None:
            return None
        se = not (s.p < 0 or (self.keep and s.p == 0))
        nx, ny = x + 1, y - 1 if se else y
        return State((nx, ny), normalize(s.p + self.increment(x, nx, ny, se)), k=s.k + 1)


class OldXMidpoint(MidpointCircle):
    """The midpoint update written with the old x: ``p + 2x_k + 1`` (E) and
    ``p + 2x_k + 1 - 2y_{k+1}`` (SE), forgetting that the increments use x_{k+1}."""

    def increment(self, x_old: int, x: int, y: int, se: bool) -> Number:
        return 2 * x_old + 1 - 2 * y if se else 2 * x_old + 1


class BresenhamCircle(Model):
    """Bresenham's circle, d0 = 3 - 2r, as in :func:`scanconv.algorithms.circles.bresenham`."""

    def __init__(self, r: int, tie: str = "step") -> None:
        self.r, self.t = r, 1 if tie == "keep" else 0

    def start(self) -> State:
        return State((0, self.r), 3 - 2 * self.r)

    def advance(self, s: State, force: bool = False) -> State | None:
        if s.p is None:
            return None
        x, y = s.point
        if s.p < self.t:
            e, ny = s.p + 4 * x + 6, y
        else:
            e, ny = s.p + 4 * (x - y) + 10, y - 1
        if x + 1 > ny and not force:
            return None
        return State((x + 1, ny), e, k=s.k + 1)


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
        return self.initial(
            self.ry2 * (x + Fraction(1, 2)) ** 2 + self.rx2 * (y - 1) ** 2 - self.rx2 * self.ry2
        )

    def enter(self, x: int, y: int, p: Number | None, k: int) -> State:
        if self.region1(x, y):
            return State((x, y), p, region=1, k=k)
        return State((x, y), self.p2_0(x, y) if y > 0 else None, region=2, k=k)

    def start(self) -> State:
        p1 = self.initial(self.ry2 - self.rx2 * self.ry + Fraction(self.rx2, 4))
        return self.enter(0, self.ry, p1, 0)

    def advance(self, s: State, force: bool = False) -> State | None:
        x, y = s.point
        if s.region == 1:
            if s.p is None:
                return None
            x += 1
            if s.p < 0 or (self.keep and s.p == 0):
                q = s.p + 2 * self.ry2 * x + self.ry2
            else:
                y -= 1
                q = s.p + 2 * self.ry2 * x - 2 * self.rx2 * y + self.ry2
            return self.enter(x, y, normalize(q), s.k + 1)
        if y > 0 or force:
            if s.p is None:
                return None
            y -= 1
            if s.p > 0 or (self.keep and s.p == 0):
                q = s.p - 2 * self.rx2 * y + self.rx2
            else:
                x += 1
                q = s.p + 2 * self.ry2 * x - 2 * self.rx2 * y + self.rx2
            return State((x, y), normalize(q) if y > 0 else None, region=2, k=s.k + 1)
        if x < self.rx:  # the tip of a flat ellipse, along y = 0
            return State((x + 1, 0), None, region=2, k=s.k + 1)
        return None

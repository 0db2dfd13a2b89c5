"""Conventions: the named variant knobs of every algorithm, and presets of published sources.

Textbooks state the same algorithms with small differences that change the printed table: how
a DDA rounds, what a decision parameter of exactly 0 chooses, whether the midpoint circle
starts from 5/4 - r or 1 - r, whether its loop runs while x < y or x <= y, and whether its
increments are written with the new or the old x. Each is a :class:`Knob` here, with a name,
its values, a default (the course notes' own rule) and the methods it applies to; a preset
(:data:`PRESETS`) names the values one published source uses.

>>> KNOBS["tie"].default, KNOBS["tie"].applies_to("line", "dda")
('step', False)
>>> resolve("circle", "midpoint", "foley", {"loop": None})
{'tie': 'step', 'p0': '5/4-r', 'loop': 'strict', 'update': 'old'}
"""

from collections.abc import Callable, Mapping
from typing import NamedTuple

from ..core.checks import InputError
from ..core.numeric import (
    Number,
    round_c_cast,
    round_half_away,
    round_half_even,
    round_half_up,
    round_trunc,
)
from .choices import Rounding

ROUNDINGS: dict[str, Callable[[Number], int]] = {
    Rounding.half_up.value: round_half_up,
    Rounding.trunc.value: round_trunc,
    Rounding.half_even.value: round_half_even,
    Rounding.c_cast.value: round_c_cast,
    Rounding.half_away.value: round_half_away,
}
"""The rounding rules by name: ``floor(v + 1/2)``, truncation toward zero, Python's
``round()``, C's ``(int)(a + 0.5)`` and C's ``round()``."""

ROUNDING_TEXT = {
    "half-up": "rounded half up, floor(v + 1/2)",
    "trunc": "truncated toward zero, like a C (int) cast",
    "half-even": "rounded half to even, as Python's round() does",
    "c-cast": "rounded as C's (int)(v + 0.5), which truncates toward zero after adding 1/2",
    "half-away": "rounded half away from zero, as C's round() does",
}
"""How each rounding rule is described in an answer's notes."""


def rounder(rounding: str) -> Callable[[Number], int]:
    """The rounding function named ``rounding``.

    >>> rounder("half-even")(2.5), rounder("half-up")(2.5)
    (2, 3)
    """
    try:
        return ROUNDINGS[rounding]
    except KeyError:
        raise InputError(
            f"unknown rounding {rounding!r} (choose from {', '.join(ROUNDINGS)})", "rounding"
        ) from None


class Knob(NamedTuple):
    """One variant knob: its values (with what each means), default and methods."""

    name: str
    values: dict[str, str]
    default: str
    applies: tuple[str, ...]
    """``"primitive/method"`` names the knob applies to."""
    per_method: tuple[tuple[str, str], ...] = ()
    """``("primitive/method", value)`` pairs whose default is not :attr:`default`."""
    values_for: tuple[tuple[str, tuple[str, ...]], ...] = ()
    """``("primitive/method", values)``: the only values a method takes (default: all)."""

    def choices_for(self, primitive: str, method: str) -> tuple[str, ...]:
        """The values one method takes.

        >>> KNOBS["p0"].choices_for("ellipse", "midpoint")
        ('exact', 'rounded')
        """
        return dict(self.values_for).get(f"{primitive}/{method}", tuple(self.values))

    def applies_to(self, primitive: str, method: str) -> bool:
        return f"{primitive}/{method}" in self.applies

    def default_for(self, primitive: str, method: str) -> str:
        """The default for one method.

        >>> KNOBS["start"].default_for("line", "dda"), KNOBS["start"].default_for("line", "bresenham")
        ('given', 'swap')
        """
        return dict(self.per_method).get(f"{primitive}/{method}", self.default)


KNOBS: dict[str, Knob] = {
    "rounding": Knob(
        "rounding",
        ROUNDING_TEXT,
        "half-up",
        (
            "line/dda",
            "line/basic",
            "circle/polynomial",
            "circle/trig",
            "circle/symmetric-dda",
        ),
    ),
    "tie": Knob(
        "tie",
        {
            "step": "a decision parameter of 0 steps the minor coordinate (if p < 0 keep it)",
            "keep": "a decision parameter of 0 keeps the minor coordinate (if p <= 0 keep it)",
        },
        "step",
        (
            "line/bresenham",
            "circle/midpoint",
            "circle/general",
            "circle/bresenham",
            "ellipse/midpoint",
            "line/midpoint",
        ),
    ),
    "p0": Knob(
        "p0",
        {
            "1-r": "p0 = 1 - r, integers only",
            "5/4-r": "p0 = 5/4 - r, exact quarters",
            "exact": "p1_0 and p2_0 exact, in quarters",
            "rounded": "p1_0 and p2_0 rounded as Hearn & Baker's code, int(p + 0.5), integers only",
        },
        "1-r",
        ("circle/midpoint", "ellipse/midpoint"),
        (("ellipse/midpoint", "exact"),),
        (("circle/midpoint", ("1-r", "5/4-r")), ("ellipse/midpoint", ("exact", "rounded"))),
    ),
    "loop": Knob(
        "loop",
        {"strict": "loop while x < y", "inclusive": "loop while x <= y"},
        "strict",
        ("circle/midpoint", "circle/general", "ellipse/midpoint"),
    ),
    "start": Knob(
        "start",
        {
            "swap": "the walk starts at the end point with the smaller major coordinate, "
            "the end points swapped if needed",
            "given": "the walk starts at the first end point given and steps toward the second",
        },
        "swap",
        ("line/bresenham", "line/dda"),
        (("line/dda", "given"),),
    ),
    "scale": Knob(
        "scale",
        {
            "integer": "d = 2F(M): d_0 = 2dy - dx, integers only",
            "half": "d = F(M): d_0 = dy - dx/2, in halves",
        },
        "integer",
        ("line/midpoint",),
    ),
    "xstep": Knob(
        "xstep",
        {
            "last": "d updated with the old x and y, then x += 1",
            "first": "x += 1 first, d updated with the new x and y, as widely copied code does",
        },
        "last",
        ("circle/bresenham",),
    ),
    "ends": Knob(
        "ends",
        {
            "full": "Wu's end points drawn at full intensity (Wu 1991, Abrash 1992)",
            "coverage": "Wu's end columns weighted by the part of them the line covers, "
            "xgap = 1 - frac(x1 + 1/2) and frac(x2 + 1/2) (Wikipedia's pseudocode)",
        },
        "full",
        ("antialias/wu", "line/wu"),
    ),
    "across": Knob(
        "across",
        {
            "minor": "a line's width w measured along the minor axis: a parallelogram, each "
            "column covered by w",
            "perpendicular": "a line's width w measured perpendicular to it: a rectangle of "
            "area w·L, its ends cut square",
        },
        "minor",
        ("antialias/area", "antialias/supersample"),
    ),
    "subgrid": Knob(
        "subgrid",
        {
            "span": "the sub-pixel line from P1's first sub-pixel over every sub-column of the "
            "end pixels, with the line's slope (the taught form of Hearn & Baker's figure)",
            "centre": "the sub-pixel line between the end pixels' centre sub-pixels: the same "
            "line (n odd)",
        },
        "span",
        ("antialias/subpixel",),
    ),
    "divide": Knob(
        "divide",
        {
            "n": "a pixel's sub-pixel count c gives I = c / n: n levels above zero (Hearn & Baker)",
            "n2": "a pixel's sub-pixel count c gives I = c / n², the fraction of its sub-pixels",
        },
        "n",
        ("antialias/subpixel",),
    ),
    "update": Knob(
        "update",
        {
            "new": "increments written with the new x: 2x_{k+1} + 1",
            "old": "increments written with the old x: 2x_k + 3",
        },
        "new",
        ("circle/midpoint",),
    ),
    # visible-surface detection (scanconv 3d): the defaults are Hearn & Baker's (C version,
    # 2nd ed., ch. 13), the most common textbook form; the course notes stop before 3D
    "direction": Knob(
        "direction",
        {
            "into-scene": "V is the viewing direction, from the viewer into the scene: a back "
            "face has V·N > 0 (Hearn & Baker)",
            "to-viewer": "V points from the face toward the viewer (the line of sight): a back "
            "face has V·N < 0",
        },
        "into-scene",
        ("3d/backface",),
    ),
    "edge-on": Knob(
        "edge-on",
        {
            "hidden": "a face seen edge-on (V·N = 0) is hidden (Hearn & Baker: C <= 0 for V "
            "along -z)",
            "visible": "a face seen edge-on (V·N = 0) is kept as visible (Rogers: a back plane "
            "only when the test is strictly negative)",
        },
        "hidden",
        ("3d/backface",),
    ),
    "handed": Knob(
        "handed",
        {
            "right": "right-handed axes: vertices counter-clockwise seen from outside, the "
            "viewer on +z looking along -z (V = (0, 0, -1))",
            "left": "left-handed viewing axes (Hearn & Baker): vertices clockwise seen from "
            "outside, the viewer looking along +z (V = (0, 0, 1))",
        },
        "right",
        ("3d/backface",),
    ),
    "depth": Knob(
        "depth",
        {
            "larger-nearer": "a larger z is nearer the viewer (the viewer on +z looking along "
            "-z): a pixel is written when z > depth(x, y) (Hearn & Baker, Foley, Rogers)",
            "smaller-nearer": "a smaller z is nearer the viewer: a pixel is written when "
            "z < depth(x, y) (OpenGL's depth range)",
        },
        "larger-nearer",
        ("3d/zbuffer", "3d/warnock", "3d/scanline", "3d/depth-sort"),
    ),
    "ties": Knob(
        "ties",
        {
            "keep": "equal depths keep what the buffer holds: the polygon drawn first wins "
            "(a strict comparison, Hearn & Baker)",
            "replace": "equal depths let the polygon drawn later replace it (z >= depth(x, y): "
            "Foley's 'not farther')",
        },
        "keep",
        ("3d/zbuffer", "3d/warnock", "3d/scanline"),
    ),
    "clear": Knob(
        "clear",
        {
            "zero": "the depth buffer starts at 0, the back clipping plane (depths run from 0 "
            "at the back to z_max at the front: Hearn & Baker, Foley): a point at z < 0 is "
            "never written, nor one at z = 0 when ties keep",
            "farthest": "the depth buffer starts farther than every point, -inf (+inf when a "
            "smaller z is nearer: Rogers' 'minimum z value'): every point is compared",
        },
        "zero",
        ("3d/zbuffer",),
    ),
}
"""Every knob, by name. The defaults are the course notes' own stated rules."""

PRESETS: dict[str, dict[str, dict[str, str]]] = {
    "notes": {
        "line": {"rounding": "half-up", "tie": "step"},
        "circle": {"rounding": "half-up", "tie": "step", "p0": "1-r", "loop": "strict"}
        | {"update": "new"},
        "ellipse": {"loop": "strict", "tie": "step", "p0": "exact"},
    },
    "hearn-baker": {
        "line": {"rounding": "c-cast", "tie": "step"},
        "circle": {"rounding": "c-cast", "tie": "step", "p0": "1-r", "loop": "strict"}
        | {"update": "new"},
        "ellipse": {"loop": "strict", "tie": "step", "p0": "exact"},
    },
    "foley": {
        "line": {"rounding": "half-up", "tie": "keep"},
        "circle": {"rounding": "half-up", "tie": "step", "p0": "5/4-r", "loop": "strict"}
        | {"update": "old"},
        "ellipse": {"loop": "strict"},
    },
    "wikipedia": {
        "line": {"rounding": "half-up", "tie": "keep"},
    },
}
"""The knob values each named source uses, per primitive (see ``docs/conventions.md``)."""

SOURCES = {
    "notes": "the course notes' stated algorithms",
    "hearn-baker": "Hearn & Baker, Computer Graphics, C version (lineBres, lineDDA, circleMidpoint)",
    "foley": "Foley, van Dam, Feiner & Hughes, Computer Graphics (MidpointLine, MidpointCircle)",
    "wikipedia": "Wikipedia, Bresenham's line algorithm (plotLine: if D > 0 step y)",
}
"""What each preset's name stands for, as an answer's note says it."""


def resolve(
    primitive: str, method: str, convention: str | None, given: Mapping[str, str | None]
) -> dict[str, str]:
    """The knob values for one answer: an explicit value wins, then the preset's, then the
    default; a knob given explicitly that does not apply to the method is an error.

    >>> resolve("line", "bresenham", None, {"tie": "keep"})
    {'tie': 'keep', 'start': 'swap'}
    >>> resolve("line", "dda", None, {"tie": "keep"})
    Traceback (most recent call last):
    ...
    scanconv.core.checks.InputError: the tie convention applies to line bresenham, circle midpoint, circle general, circle bresenham, ellipse midpoint, line midpoint, not to line dda
    """
    if convention is not None and convention not in PRESETS:
        raise InputError(
            f"unknown convention {convention!r} (choose from {', '.join(PRESETS)})",
            "convention",
        )
    presets = PRESETS[convention or "notes"]
    if primitive not in presets:
        raise InputError(
            f"the {convention} convention names no {primitive} rules "
            f"(it has: {', '.join(presets)})",
            "convention",
        )
    preset = presets[primitive]
    out: dict[str, str] = {}
    for name, knob in KNOBS.items():
        value = given.get(name)
        if not knob.applies_to(primitive, method):
            if value is not None:
                where = ", ".join(a.replace("/", " ") for a in knob.applies)
                raise InputError(
                    f"the {name} convention applies to {where}, not to {primitive} {method}",
                    name,
                )
            continue
        value = (
            value if value is not None else preset.get(name, knob.default_for(primitive, method))
        )
        choices = knob.choices_for(primitive, method)
        if value not in choices:
            raise InputError(
                f"unknown {name} {value!r} for {primitive} {method} "
                f"(choose from {', '.join(choices)})",
                name,
            )
        out[name] = value
    return out


def convention_note(primitive: str, convention: str | None, used: Mapping[str, str]) -> str:
    """The one-line note that names the conventions an answer used.

    >>> print(convention_note("line", None, {"tie": "keep"}))
    Conventions (the notes' defaults): tie = keep (a decision parameter of 0 keeps the minor coordinate (if p <= 0 keep it)).
    """
    if not used:
        return ""
    where = f"preset {convention}: {SOURCES[convention]}" if convention else "the notes' defaults"
    parts = "; ".join(f"{k} = {v} ({KNOBS[k].values[v]})" for k, v in used.items())
    return f"Conventions ({where}): {parts}."

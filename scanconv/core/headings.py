"""Column headings of a student's table: what each names (:func:`field_of`), however it was
typed (case, spaces, TeX, Unicode subscripts, common names, ``round(x)``, the notes' own
``Pixel Plotted (x y)``). Used by :mod:`.student_table`."""

from __future__ import annotations

import re

_SUBSCRIPTS = str.maketrans(
    {
        "ₖ": "k",
        "₊": "+",
        "₋": "-",
        "₀": "0",
        "₁": "1",
        "₂": "2",
        "ₙ": "n",
        "ᵢ": "i",
        "\u2212": "-",
        "²": "2",
    }
)
_DROP = re.compile(r"[\s$\\{}_*`'\"]")
_NAMES = {
    "k": ("k", "step", "i", "n", "#", "no", "no.", "row", "iteration", "stepk", "kstep", "step(k)"),
    "p": ("p", "pk", "p(k)", "d", "dk", "p1k", "p2k", "p1", "p2", "decisionparameter", "pi"),
    "p_next": (
        "pk+1",
        "p(k+1)",
        "pnext",
        "nextp",
        "dk+1",
        "p1k+1",
        "p2k+1",
        "newp",
        "nextpk+1",
        "updatep",
        "updatedp",
        "nextdk+1",
    ),
    "decision": ("decision", "move", "choice", "choose", "chosen", "direction", "dir", "step?"),
    "x": ("x", "xk", "xk+1", "xi", "x(k)", "x(k+1)", "newx", "nextx"),
    "y": ("y", "yk", "yk+1", "yi", "y(k)", "y(k+1)", "newy", "nexty"),
    "region": ("region", "reg", "r"),
}
_TEX = re.compile(r"\\(text|mathrm|mathit|operatorname|textrm|mathbf)\b")
_QUALIFIER = re.compile(
    r"\((calculated|calc|computed|float|exact|real|rounded|round|one octant|first octant|octant"
    r"|px|pixels|pixel units|in pixels|units|integer|int)\)"
)
_PAIR_HEAD = re.compile(r"\(?x(k\+1|k|i)?[,;]?y(k\+1|k|i)?\)?")
_PIXEL_WORDS = re.compile(r"(pixels?|plotted|plot|points?|at|to|the|chosen|lower|left)*")
_ROUNDED = ("round", "plot", "pixel", "int", "rnd")
_LOOKUP = {name: field for field, names in _NAMES.items() for name in names}


def field_of(heading: str) -> tuple[str | None, bool]:
    """The canonical field a column heading names, and whether it says ``k+1``.

    >>> field_of("$p_{k+1}$"), field_of("(x_{k+1}, y_{k+1})"), field_of("Round(X)")
    (('p_next', False), ('xy', True), ('px', False))
    >>> field_of("Pixel"), field_of(" X k "), field_of("2ry²x")
    (('pxy', False), ('x', False), (None, False))
    """
    t = _TEX.sub("", heading.translate(_SUBSCRIPTS).lower())
    qualifier = _QUALIFIER.search(t)
    said_rounded = qualifier is not None and qualifier.group(1) in _SAID_ROUNDED
    h = _DROP.sub("", _QUALIFIER.sub("", t))
    if h in _LOOKUP:
        return _named(h, said_rounded)
    return _described(h, said_rounded)


_SAID_ROUNDED = ("rounded", "round", "integer", "int")
_NOT_AFTER = ("pk+1", "p(k+1)", "dk+1", "p1k+1", "p2k+1", "nextpk+1")


def _after(h: str) -> bool:
    """The heading says k+1 about a coordinate (not about p_{k+1})."""
    return "k+1" in h and h not in _NOT_AFTER


def _named(h: str, said_rounded: bool) -> tuple[str, bool]:
    """A heading that is one of the common names (``p``, ``x_k``, ``decision``)."""
    field = _LOOKUP[h]
    if said_rounded and field in ("x", "y"):
        field = "p" + field
    return field, _after(h) and field in ("x", "y", "px", "py")


def _described(h: str, said_rounded: bool) -> tuple[str | None, bool]:
    """A heading in words: ``Pixel Plotted (x y)``, ``(x, y)``, ``round(x)``."""
    words = _PIXEL_WORDS.match(h)
    prefix, rest = (words.group(0), h[words.end() :]) if words else ("", h)
    named_pixel = any(w in prefix for w in ("pixel", "plot", "point"))
    pair = _PAIR_HEAD.fullmatch(rest) is not None and (prefix == "" or named_pixel)
    if (rest == "" and named_pixel) or pair:
        rounded = named_pixel or said_rounded or any(w in h for w in _ROUNDED)
        return ("pxy" if rounded else "xy"), "k+1" in rest
    if not any(w in h for w in _ROUNDED):
        return None, False
    bare = re.sub(r"round|plot(ted)?|pixel|int|rnd|[()\[\]]", "", h)
    field = {"x": "px", "xk": "px", "xk+1": "px", "y": "py", "yk": "py", "yk+1": "py"}.get(bare)
    if field is None and bare in ("x,y", "xk,yk", "(x,y)"):
        field = "pxy"
    return field, _after(h) if field is not None else False

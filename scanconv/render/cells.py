"""Cell and symbol formatting shared by the renderers.

Decisions stay structured (:class:`~scanconv.core.records.Move`) until here; each format picks its
own glyphs. ``plain`` must be pure ASCII, so Unicode working (``Δx``, ``≥``, ``·``) is
transliterated by :func:`ascii_text`; LaTeX gets math through :func:`tex_text`.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from enum import Enum
from fractions import Fraction
from typing import Any

from ..core.numeric import fmt, fmt_pixel, json_number
from ..core.records import Column, Solution
from ..core.working import tex_to_unicode, visible


def cell(value: Any, column: Column, exact: bool = False) -> str:
    """Display text of one cell (Unicode-free for every value scanconv produces).

    The rule, in every text format: integers print as integers; other numbers to 3 decimals
    (rounded half up), and a column the notes print with decimals (:attr:`Column.places`:
    DDA's x_k and y_k, a curve's t) gives every value its decimals. The two coordinates of a
    point are printed alike: ``(0.500, 1.000)``, never ``(0.500, 1)``. With ``exact``
    (``--exact``) exact values print as fractions instead: ``1/2``, ``(34/27, 14/9)``.

    >>> from scanconv.core.records import Move
    >>> cell(Fraction(5, 2), Column("y", "y", "y", 3)), cell(Move.NE, Column("d", "d", "d"))
    ('2.500', 'NE')
    >>> cell((3, 4), Column("pixel", "", "")), cell(None, Column("p", "", ""))
    ('(3, 4)', '-')
    >>> cell((Fraction(1, 2), 1), Column("P", "", "")), cell(Fraction(34, 27), Column("t", "", ""), True)
    ('(0.500, 1.000)', '34/27')
    """
    if value is None:
        return "-"
    if isinstance(value, Enum):
        return str(value.value)
    if isinstance(value, bool):
        return "yes" if value else "no"
    if exact and isinstance(value, (int, Fraction)):
        return str(value)
    if isinstance(value, (int, Fraction)):
        return fmt(value, column.places)
    if isinstance(value, float):
        return fmt(Fraction(value), column.places if column.places is not None else 3)
    if isinstance(value, tuple):
        if len(value) == 2 and all(isinstance(v, int) for v in value):
            return fmt_pixel(value)  # type: ignore[arg-type]
        if exact or all(isinstance(v, int) for v in value) or column.places is not None:
            return "(" + ", ".join(cell(v, column, exact) for v in value) + ")"
        decimals = column._replace(places=3)  # a point's coordinates alike
        return "(" + ", ".join(cell(v, decimals) for v in value) + ")"
    return visible(str(value))


def json_value(value: Any) -> Any:
    """A JSON-ready value: exact integers stay integers, other numbers become floats.

    >>> from scanconv.core.records import Move
    >>> json_value((Fraction(1, 2), 3)), json_value(Move.SE), json_value(None)
    ([0.5, 3], 'SE', None)
    """
    if type(value) is int:  # the common value, first (a matrix row is thousands of them)
        return value
    if isinstance(value, Enum):
        return value.value
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, (int, Fraction, float)):
        return json_number(value)
    if isinstance(value, (tuple, list)):
        return [json_value(v) for v in value]
    if isinstance(value, dict):
        return {str(k): json_value(v) for k, v in value.items()}
    return str(value)


def wrap_items(items: Iterable[str], width: int = 96, sep: str = ", ") -> Iterator[str]:
    """Join items with ``sep`` into lines no wider than ``width`` (streaming).

    >>> list(wrap_items(["(1, 2)", "(3, 4)", "(5, 6)"], width=16))
    ['(1, 2), (3, 4),', '(5, 6)']
    """
    line = ""
    for item in items:
        if line and len(line) + len(sep) + len(item) > width:
            yield line + sep.rstrip()
            line = item
        else:
            line = f"{line}{sep}{item}" if line else item
    if line:
        yield line


def numeric_column(column: Column) -> bool:
    """Right-align number columns; centre the rest."""
    return column.key not in TEXT_KEYS and not column.key.startswith("point")


#: Keys of columns that hold words, not numbers (centred, never set in math mode).
TEXT_KEYS = ("decision", "pixel", "method", "work", "arithmetic", "reason", "name")


def note_segments(note: str) -> list[tuple[bool, str]]:
    """A note split into its text and its math: notes write formulas between ``$...$`` in
    TeX (``"$p_k < 0$ chooses E"``), so each format can set them as math.

    >>> note_segments("$p_k < 0$ chooses E")
    [(True, 'p_k < 0'), (False, ' chooses E')]
    >>> note_segments("costs $5 or more")  # an unpaired $ is text
    [(False, 'costs $5 or more')]
    """
    parts = note.split("$")
    if len(parts) % 2 == 0:  # an odd number of $: not markup
        return prose_math(note)
    out: list[tuple[bool, str]] = []
    for i, part in enumerate(parts):
        if part:
            out.extend([(True, part)] if i % 2 else prose_math(part))
    return out


_PROSE_MATH = None


def prose_math(text: str) -> list[tuple[bool, str]]:
    """Text split into prose and the formulas written in it in the ASCII notation
    (``x^2 + y^2 = r^2``, ``p_{k+1}``, ``x_inc``, ``2^-3``, ``(x - xc)^2``), each formula as TeX
    math, so every format sets it as math (LaTeX math, MathML, Unicode) instead of showing the
    markup. Only a name of one or two letters (or a number, or a bracketed group) with a
    sub- or superscript of a few letters or digits counts: a file name (``al_ice.csv``) does not.

    >>> prose_math("p = x^2 + y^2 - r^2 at (0, r)")
    [(False, 'p = '), (True, 'x^2'), (False, ' + '), (True, 'y^2'), (False, ' - '), (True, 'r^2'), (False, ' at (0, r)')]
    >>> prose_math("2x_{k+1} + 1, x_inc, 2^-3 and (x - xc)^2")
    [(False, '2'), (True, 'x_{k+1}'), (False, ' + 1, '), (True, 'x_{inc}'), (False, ', '), (True, '2^{-3}'), (False, ' and '), (True, '(x - xc)^2')]
    >>> prose_math("al_ice.csv, p_k. and a_b_c")
    [(False, 'al_ice.csv, '), (True, 'p_k'), (False, '. and a_b_c')]
    """
    global _PROSE_MATH
    if "_" not in text and "^" not in text:
        return [(False, text)] if text else []
    if _PROSE_MATH is None:
        sub = r"_(?:\{[A-Za-z0-9+\-, ]{1,12}\}|[A-Za-z0-9]{1,4})"
        sup = r"\^(?:\{[A-Za-z0-9+\-]{1,8}\}|-?[0-9]{1,3}|[A-Za-z])"
        base = (
            r"(?:(?<![A-Za-z_.\\])[A-Za-z]{1,2}[0-9]?|(?<![\w.\\])[0-9]+"
            r"|\([A-Za-z0-9 +\-*/.,]{1,30}\))"
        )
        _PROSE_MATH = re.compile(rf"{base}(?:{sub}(?:{sup})?|{sup})(?![\w^_{{]|\.\w)")
    out: list[tuple[bool, str]] = []
    at = 0
    for m in _PROSE_MATH.finditer(text):
        if m.start() > at:
            out.append((False, text[at : m.start()]))
        out.append((True, _braced(m.group())))
        at = m.end()
    if at < len(text):
        out.append((False, text[at:]))
    return out


def _braced(token: str) -> str:
    """A formula token with its multi-character scripts braced: ``x_inc`` as ``x_{inc}``."""
    body = r"(-[A-Za-z0-9]+|[A-Za-z0-9]{2,})"
    return re.sub(rf"([_^]){body}$|([_^]){body}(?=\^)", _brace, token)


def _brace(m: re.Match[str]) -> str:
    mark, body = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
    return f"{mark}{{{body}}}"


def note_unicode(note: str) -> str:
    """A note for the terminal and plain text: its ``$...$`` math in Unicode.

    >>> note_unicode(r"$p_k < 0$ chooses E, $p_k \\geq 0$ chooses NE")
    'pₖ < 0 chooses E, pₖ ≥ 0 chooses NE'
    """
    return "".join(tex_to_unicode(t) if math else t for math, t in note_segments(note))


_SUB = str.maketrans("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_BRACED_SUB = r"_\{([^{}]*)\}|_([0-9a-z])(?![0-9a-z])"  # compiled by re on first use


def unicode_heading(text: str) -> str:
    """A column heading for the terminal, with no TeX left in it: subscripts the Unicode
    derivation kept in TeX (``N_{0,2}``) become Unicode where every character has a
    subscript form, ``N_(1,c)`` otherwise.

    >>> unicode_heading("N_{0,2}(t)"), unicode_heading("(x_c+x, y_c+y)"), unicode_heading("pₖ")
    ('N₀,₂(t)', '(x_c+x, y_c+y)', 'pₖ')
    """

    def sub(m: Any) -> str:
        inner = m.group(1) if m.group(1) is not None else m.group(2)
        if all(ch == "," or ch.translate(_SUB) != ch for ch in inner):
            return inner.translate(_SUB)
        return m.group(0) if m.group(2) is not None else f"_({inner})"

    if "_" not in text:  # most headings: no pattern to run (start-up time)
        return text
    return re.sub(_BRACED_SUB, sub, text)


def marks_label(solution: Solution) -> str:
    """What the grid's ``o`` stands for: :attr:`Solution.marks_label`, or worked out from the
    answer's geometry (a curve's control points, a circle's or ellipse's centre)."""
    if solution.marks_label:
        return solution.marks_label
    geometry = solution.geometry
    if geometry.get("control"):
        return "control point"
    if any(k in geometry for k in ("circle", "ellipse", "center")):
        return "centre"
    for note in solution.notes:  # "The centre is marked o in the grid."
        said = re.search(r"\b[Tt]he (\w+) is marked o\b", note)
        if said:
            return said.group(1)
    return "marked point"

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
from ..core.records import Column
from ..core.working import tex_to_unicode, visible
from ..document.prose import note_segments as note_segments
from ..document.prose import prose_math as prose_math


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
            return fmt_pixel(value)
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


def note_unicode(note: str) -> str:
    """A note for the terminal and plain text: its ``$...$`` math in Unicode.

    >>> note_unicode(r"$p_k < 0$ chooses E, $p_k \\geq 0$ chooses NE")
    'pₖ < 0 chooses E, pₖ ≥ 0 chooses NE'
    """
    return segments_unicode(note_segments(note))


def segments_unicode(segments: Iterable[tuple[bool, str]]) -> str:
    """Prose segments (a :class:`~scanconv.document.Prose`'s) in Unicode, the math too.

    >>> segments_unicode([(True, "p_k < 0"), (False, " chooses E")])
    'pₖ < 0 chooses E'
    """
    return "".join(tex_to_unicode(t) if math else t for math, t in segments)


_SUB = str.maketrans("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")
_BRACED_SUB = r"_\{([^{}]*)\}|_([0-9a-z])(?![0-9a-z])"  # compiled by re on first use


def unicode_heading(text: str) -> str:
    """A column heading for the terminal, with no TeX left in it: subscripts the Unicode
    derivation kept in TeX (``N_{0,2}``) become Unicode where every character has a
    subscript form, ``N_(1,c)`` otherwise.

    >>> unicode_heading("N_{0,2}(t)"), unicode_heading("(x_c+x, y_c+y)"), unicode_heading("pₖ")
    ('N₀,₂(t)', '(x_c+x, y_c+y)', 'pₖ')
    """

    def sub(m: re.Match[str]) -> str:
        inner = m.group(1) if m.group(1) is not None else m.group(2)
        if all(ch == "," or ch.translate(_SUB) != ch for ch in inner):
            return inner.translate(_SUB)
        return m.group(0) if m.group(2) is not None else f"_({inner})"

    if "_" not in text:  # most headings: no pattern to run (start-up time)
        return text
    return re.sub(_BRACED_SUB, sub, text)

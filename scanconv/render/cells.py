"""Cell and symbol formatting shared by the renderers.

Decisions stay structured (:class:`~scanconv.core.records.Move`) until here; each format picks its
own glyphs. ``plain`` must be pure ASCII, so Unicode working (``Δx``, ``≥``, ``·``) is
transliterated by :func:`ascii_text`; LaTeX gets math through :func:`tex_text`.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from enum import Enum
from fractions import Fraction
from typing import Any

from ..core.numeric import fmt, fmt_pixel, json_number
from ..core.records import Column


def cell(value: Any, column: Column) -> str:
    """Display text of one cell (Unicode-free for every value scanconv produces).

    >>> from scanconv.core.records import Move
    >>> cell(Fraction(5, 2), Column("y", "y", "y", 3)), cell(Move.NE, Column("d", "d", "d"))
    ('2.500', 'NE')
    >>> cell((3, 4), Column("pixel", "", "")), cell(None, Column("p", "", ""))
    ('(3, 4)', '-')
    """
    if value is None:
        return "-"
    if isinstance(value, Enum):
        return str(value.value)
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, Fraction)):
        return fmt(value, column.places)
    if isinstance(value, float):
        return fmt(Fraction(value), column.places if column.places is not None else 3)
    if isinstance(value, tuple):
        if len(value) == 2 and all(isinstance(v, int) for v in value):
            return fmt_pixel(value)  # type: ignore[arg-type]
        return "(" + ", ".join(cell(v, column) for v in value) + ")"
    return str(value)


def json_value(value: Any) -> Any:
    """A JSON-ready value: exact integers stay integers, other numbers become floats.

    >>> from scanconv.core.records import Move
    >>> json_value((Fraction(1, 2), 3)), json_value(Move.SE), json_value(None)
    ([0.5, 3], 'SE', None)
    """
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
TEXT_KEYS = ("decision", "pixel", "method", "work", "arithmetic", "reason")

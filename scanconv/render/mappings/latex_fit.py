"""How a LaTeX table or typewriter picture fits an article's text width, never below 7 pt:
the width of a table estimated from its headings and first rows (:func:`table_layout`), its
parts when it is too wide (:func:`split_columns`), its headings on their sides
(:func:`sideways_layout`), and a typewriter picture's size, strips and folds
(:func:`grid_size`, :func:`strips`, :func:`fold`). Used by :mod:`.latex`."""

from __future__ import annotations

from collections.abc import Sequence

from ...core.records import Column

TEXT_WIDTH = 345
"""An article's text width in points (10pt, one column): what tables and grids must fit."""

#: Font sizes to try, with the width of their text relative to the 10pt body text (Computer
#: Modern's smaller sizes are drawn relatively wider: cmr7 text is 0.79 as wide, not 0.7).
_SIZES = (("", 1.0), ("\\small", 0.93), ("\\footnotesize", 0.86), ("\\scriptsize", 0.79))
SAMPLE_ROWS = 100
_MARKUP = str.maketrans("", "", "_{}^\\")


Layout = tuple[str, bool]
"""``(font size, tight)``: what :func:`table_layout` picks for a table."""

_LAST: Layout = ("\\scriptsize", True)
"""The last resort for a table whose first column and one other do not fit side by side:
7 pt (the smallest print is set at), its headings on their sides (:func:`sideways_layout`)."""


def table_layout(columns: Sequence[Column], rows: Sequence[list[str]]) -> Layout | None:
    """``(font size, tight)`` for a table: the largest font whose estimated width fits
    :data:`TEXT_WIDTH`, first at the normal 6pt between columns, then at 3pt (``tight``);
    ``None`` if it does not fit even in ``\\scriptsize`` at 3pt.

    The width is estimated from the headings and the first rows: about 4.8pt a character at
    10pt (digits are 5pt, points and commas less; a minus sign counts 1.6), plus the gaps.

    >>> from scanconv.core.records import Column
    >>> cols = [Column(str(i), f"col {i}", "") for i in range(4)]
    >>> table_layout(cols, [["1.000"] * 4])
    ('', False)
    >>> table_layout([Column(str(i), "N_{i,3}", "") for i in range(11)], [["0.125"] * 11])
    ('', True)
    >>> table_layout([Column(str(i), "(xc + x, yc + y)", "") for i in range(9)], []) is None
    True
    """
    cells = _cell_chars(columns, rows)
    text = 4.8 * sum(max(heading_chars(c), n) for c, n in zip(columns, cells, strict=True))
    return _fitting(text, len(columns))


def _fitting(text: float, count: int) -> Layout | None:
    """The largest font (and the widest gap) in which ``text`` pt of 10 pt text in ``count``
    columns fits :data:`TEXT_WIDTH`; ``None`` if not even ``\\scriptsize`` at 3pt does."""
    for gap, tight in ((12, False), (6, True)):
        for size, factor in _SIZES:
            if text * factor + gap * count <= 0.97 * TEXT_WIDTH:  # 3% to spare
                return size, tight
    return None


def split_columns(
    columns: Sequence[Column], rows: Sequence[list[str]]
) -> list[tuple[list[int], Layout]]:
    """The column indexes of each part a table is set in, with each part's layout: one part
    if it fits the text width, else the fewest parts of about equal width that each fit,
    every part repeating the first column (``k``, or the octant point of a symmetry table) so
    its rows can be read alone.

    >>> from scanconv.core.records import Column
    >>> cols = [Column("k", "k", "")] + [Column("c", "(xc + x, yc + y)", "")] * 8
    >>> [part for part, _ in split_columns(cols, [])]
    [[0, 1, 2, 3, 4], [0, 5, 6, 7, 8]]
    """
    every = list(range(len(columns)))
    whole = table_layout(columns, rows)
    if whole is not None or len(columns) < 3:
        return [(every, whole or _LAST)]
    rest = every[1:]
    for count in range(2, len(rest) + 1):
        bounds = [len(rest) * i // count for i in range(count + 1)]
        parts = [[0, *rest[bounds[i] : bounds[i + 1]]] for i in range(count)]
        fitted = []
        for part in parts:
            layout = table_layout(*select_columns(columns, rows, part))
            if layout is None:
                break
            fitted.append((part, layout))
        else:
            return fitted
    return [(every, _LAST)]  # not even one column beside the first fits


def select_columns(
    columns: Sequence[Column], rows: Sequence[list[str]], part: Sequence[int]
) -> tuple[list[Column], list[list[str]]]:
    return [columns[i] for i in part], [[r[i] for i in part] for r in rows]


def heading_chars(column: Column) -> float:
    """The width of a heading in characters: its plain text without ``_{}^``, plus one for
    each ``+ - =``, which math mode sets with space on both sides."""
    ops = sum(column.tex.count(op) for op in "+-=")
    plain = column.text.translate(_MARKUP)
    return len(plain) + ops + _CAPITAL * sum(c.isupper() for c in plain)


_CAPITAL = 0.5
"""What a capital letter adds to its width in characters (7.2 pt at 10 pt, not 4.8: the
compare line table's ``DDA``, ``Bresenham`` and ``SDDA repeats`` ran 7 pt past the margin)."""

RESIZE_ROWS = 40
"""A table too wide for the page with at most this many rows is set whole, its wide headings
on their sides (:func:`sideways_layout`), when it fits so; a longer one is set in parts of
its columns."""

WRAP_CHARS = 24
"""A text column with a cell longer than this is set as a paragraph column that wraps."""


SIDEWAYS_CHARS = 2.5
"""The width of a heading set on its side, in characters of 10 pt text: one line of type."""


def _cell_chars(columns: Sequence[Column], rows: Sequence[list[str]]) -> list[float]:
    """Each column's widest cell, in characters (a minus sign counts 1.6)."""
    widths = [0.0] * len(columns)
    for r in rows:
        widths = [
            max(w, len(c) + 0.6 * c.count("-") + _CAPITAL * sum(ch.isupper() for ch in c))
            for w, c in zip(widths, r, strict=True)
        ]
    return widths


def _sideways(column: Column, chars: float) -> bool:
    """A heading wider than its column's widest cell is set on its side."""
    return heading_chars(column) > max(chars, SIDEWAYS_CHARS)


def sideways_layout(columns: Sequence[Column], rows: Sequence[list[str]]) -> Layout | None:
    r"""The layout of a table whose headings wider than their cells are set on their sides
    (``\rotatebox{90}``, needs ``graphicx``), never smaller than ``\scriptsize``: the
    largest font whose cells fit the text width, or ``None``.

    >>> from scanconv.core.records import Column
    >>> wide = [Column(str(i), "(xc + x, yc + y)", "") for i in range(9)]
    >>> sideways_layout(wide, [["(13, 14)"] * 9])
    ('\\scriptsize', True)
    >>> sideways_layout(wide, [["(1234567, 1234567)"] * 9]) is None
    True
    """
    cells = _cell_chars(columns, rows)
    widths = [
        max(n, SIDEWAYS_CHARS) if _sideways(c, n) else max(n, heading_chars(c))
        for c, n in zip(columns, cells, strict=True)
    ]
    return _fitting(4.8 * sum(widths), len(columns))


def heading_row(columns: Sequence[Column], rows: Sequence[list[str]], sideways: bool) -> str:
    """The heading row: each heading in math, those wider than their cells on their sides
    when ``sideways``."""
    cells = _cell_chars(columns, rows) if sideways else [0.0] * len(columns)
    return " & ".join(
        f"\\rotatebox{{90}}{{${c.tex}$}}" if sideways and _sideways(c, n) else f"${c.tex}$"
        for c, n in zip(columns, cells, strict=True)
    )


#: Font sizes for the verbatim grid by the widest line (characters) that fits an article's
#: 345pt text width in cmtt (0.525 em a character): 10pt holds 65, 8pt 82, 7pt 92. Nothing is
#: set smaller (print is read on paper): a wider picture is set in strips (:func:`strips`), a
#: longer line of code folded (:func:`fold`).
GRID_SIZES = ((65, ""), (82, "\\footnotesize"), (92, "\\scriptsize"))
GRID_CHARS = GRID_SIZES[-1][0]
"""The widest typewriter line set (at 7 pt)."""


def grid_size(lines: Sequence[str]) -> str:
    """The font-size command that lets the grid fit the text width (``""``: normal size),
    never below ``\\scriptsize`` (7 pt): a wider picture is first cut into strips.

    >>> grid_size(["7 | .  #"]), grid_size(["x" * 90]), grid_size(["x" * 200])
    ('', '\\\\scriptsize', '\\\\scriptsize')
    """
    width = max((len(line) for line in lines), default=0)
    return next((size for limit, size in GRID_SIZES if width <= limit), "\\scriptsize")


def strips(lines: Sequence[str], width: int = GRID_CHARS) -> list[list[str]]:
    """A typewriter picture wider than ``width`` cut into strips of its columns, one under
    the other, each repeating the picture's left margin (its axis labels up to ``| ``, where
    every ruled line has the rule in the same place).

    >>> strips(["1 | abcdef", "0 | ghijkl"], 8)
    [['1 | abcd', '0 | ghij'], ['1 | ef', '0 | kl']]
    >>> strips(["abc"], 7)
    [['abc']]
    """
    if max((len(line) for line in lines), default=0) <= width:
        return [list(lines)]
    rules = {line.index("|") for line in lines if "|" in line}
    margin = min(rules.pop() + 2, width // 2) if len(rules) == 1 else 0
    body = width - margin
    longest = max(len(line) for line in lines) - margin
    return [
        [(line[:margin] + line[margin + at : margin + at + body]).rstrip() for line in lines]
        for at in range(0, longest, body)
    ]


def fold(lines: Sequence[str], width: int = GRID_CHARS) -> list[str]:
    """Lines of code longer than ``width`` folded, each continuation indented four more.

    >>> fold(["ab cdefgh"], 7)
    ['ab cdef', '    gh']
    """
    out = []
    for line in lines:
        out.append(line[:width])
        rest = line[width:]
        while rest:
            out.append("    " + rest[: width - 4])
            rest = rest[width - 4 :]
    return out

"""Where a student's CSV or TSV table starts: its heading line, found under a few lines of the
student's name, roll number or a title, and a line's cells counted with its bracketed groups
(``(x, y)``) taken out first."""

from __future__ import annotations

import re

from ..core.headings import field_of


def unbracketed(line: str) -> str:
    """``line`` without its bracketed groups, each from an opening ``(`` or ``[`` to the first
    closing one after it, in one pass (an opening bracket with no closing one after it stays:
    searching the rest of the line from each of 200,000 of them took minutes).

    >>> unbracketed("k, (x, y), [a; b]"), unbracketed("((x, y) (z")
    ('k, , ', ' (z')
    """
    end = max(line.rfind(")"), line.rfind("]")) + 1
    return re.sub(r"[(\[][^)\]]*[)\]]", "", line[:end]) + line[end:]


PREAMBLE_LINES = 10
"""Most lines above a CSV or TSV table's heading that are read as the student's name, roll
number or a title (``Name:,Gita``) and left out."""


def _cells_of(line: str) -> list[str]:
    """A line's non-empty cells, split at tabs, commas and semicolons outside ``(x, y)``."""
    cells = re.split(r"[\t,;]", unbracketed(line))
    return [c for c in cells if c.strip()]


def without_preamble(lines: list[str]) -> list[str]:
    """The lines from the table's heading on: a few lines above it that head nothing (the
    student's name and roll number, a title) are left out; a file whose heading is not
    found among its first lines is kept whole (and refused for what it lacks).

    >>> without_preamble(["Name:,Gita", "Roll no.,42", "", "k,p,x,y", "0,0,2,2"])
    ['k,p,x,y', '0,0,2,2']
    >>> without_preamble(["k,x,y", "0,2,2"])
    ['k,x,y', '0,2,2']
    >>> without_preamble(["x,y", "2,2"])  # two columns: no preamble to find
    ['x,y', '2,2']
    """
    for i, line in enumerate(lines[: PREAMBLE_LINES + 1]):
        cells = _cells_of(line)
        if len(cells) <= 2:  # a name, a roll number, a title: or a table of two columns
            continue
        if i and sum(field_of(c)[0] is not None for c in cells) >= 2:
            return lines[i:]
        break
    return lines

"""The notes' mistakes, named where an answer meets them: one note pointing to
``docs/errata.md`` (kept apart from :mod:`.theory`, which only ``--derive`` and
``--algorithm`` need)."""

from __future__ import annotations

from ..core.numeric import Number

ERRATA = "docs/errata.md"


def line_errata(algo: str, ends: tuple[Number, Number, Number, Number]) -> str | None:
    """The note about the course notes for this line, or ``None``.

    >>> line_errata("bresenham", (2, 2, 10, 6))[:46]
    'The course notes print $p_0 = -28$ for this ex'
    >>> line_errata("basic", (0, 0, 3, 1)) is None
    True
    """
    if algo == "bresenham":
        if ends == (2, 2, 10, 6):
            return (
                "The course notes print $p_0 = -28$ for this example; that table does not follow "
                f"from the algorithm: see {ERRATA}, E1."
            )
        return (
            "The course notes state $p_0 = 2\\Delta y(y_0 + 1/2) - 2\\Delta x(x_0 + 1)$; the "
            f"algorithm's $p_0$ is $2\\Delta y - \\Delta x$ (see {ERRATA}, E3)."
        )
    if algo == "dda" and ends == (2, 2, 5, 10):
        return (
            "The course notes print $m = 3/8$ for this example; that is $1/m$, the x increment "
            f"(see {ERRATA}, E2)."
        )
    return None


def circle_errata(method: str, r: int) -> str | None:
    """The note about the course notes for this circle, or ``None``.

    >>> circle_errata("general", 5)[:40]
    'The course notes print $p = 0, -4, 1, 0,'
    """
    five = r == 5
    if method == "general":
        if five:
            return (
                "The course notes print $p = 0, -4, 1, 0, 3, 8$ and the octant down to (5, 1) "
                f"for this example; that table does not follow from the algorithm: see {ERRATA}, E8."
            )
        return f"The course notes' table for this method (r = 5) does not follow from it: see {ERRATA}, E8."
    if method == "midpoint":
        start = (
            "The course notes print (2, 4) at k = 2 for this example (Topic 9); that table "
            f"does not follow from the algorithm: see {ERRATA}, E10. "
            if five
            else ""
        )
        return (
            start + "The notes call this algorithm ($p_0 = 1 - r$) Bresenham's circle; "
            "Bresenham's own form with $d_0 = 3 - 2r$ is the method 'bresenham'."
        )
    if method == "bresenham":
        start = f"The course notes' r = 5 table is wrong (see {ERRATA}, E10). " if five else ""
        return (
            start + "This is Bresenham's form with $d_0 = 3 - 2r$; the notes' Topic 9 algorithm "
            "($p_0 = 1 - r$) is the method 'midpoint', which makes the same decisions."
        )
    if method == "symmetric-dda" and five:
        return (
            "The course notes' table for this example walks the line x + y = 5, not a circle: "
            f"see {ERRATA}, E9."
        )
    if method == "polynomial" and five:
        return (
            "The notes' 'general method' is the method 'general'; this is the square-root "
            f"method (see {ERRATA}, E8)."
        )
    return None

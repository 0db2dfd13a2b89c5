"""The notes' mistakes, named where an answer meets them: one note saying in words what the
notes print, what the stated algorithm gives and why, naming its entry of ``docs/errata.md``
(kept apart from :mod:`.theory`, which only ``--derive`` and ``--algorithm`` need)."""

from __future__ import annotations

from ...core.numeric import Number

ERRATA = "erratum"
"""How an answer names an entry of scanconv's errata list (``docs/errata.md``, the full
record: what the notes print, what scanconv prints and why): ``erratum E1``. The note itself
says in words what the notes print, what the stated algorithm gives and why, so that a
student needs no file they do not have."""


def line_errata(algo: str, ends: tuple[Number, Number, Number, Number]) -> str | None:
    """The note about the course notes for this line, or ``None``.

    >>> line_errata("bresenham", (2, 2, 10, 6))[:46]
    'The course notes print $p_0 = -28$ for this li'
    >>> line_errata("basic", (0, 0, 3, 1)) is None
    True
    """
    if algo == "bresenham":
        if ends == (2, 2, 10, 6):
            return (
                "The course notes print $p_0 = -28$ for this line and a table that ends at "
                "(10, 4), two pixels short of the end point. The algorithm they state gives "
                "$p_0 = 2\\Delta y - \\Delta x = 0$ and this answer's table, which ends at (10, 6): "
                "their $p_0 = 2\\Delta y(y_0 + 1/2) - 2\\Delta x(x_0 + 1)$ puts the start "
                "point into the line's equation without its constant term, with x and y "
                f"swapped. This answer follows the algorithm ({ERRATA} E1)."
            )
        return (
            "The course notes state $p_0 = 2\\Delta y(y_0 + 1/2) - 2\\Delta x(x_0 + 1)$, which "
            "leaves out the line equation's constant term and so depends on where the line "
            "starts; the algorithm's $p_0$ is $2\\Delta y - \\Delta x$ wherever it starts, "
            f"and this answer uses it ({ERRATA} E3)."
        )
    if algo == "dda" and ends == (2, 2, 5, 10):
        return (
            "The course notes print $m = 3/8$ for this line; $3/8 = \\Delta x/\\Delta y$ is "
            "$1/m$, the x increment for each unit step in y ($x_{inc}$ here). The slope is "
            f"$m = \\Delta y/\\Delta x = 8/3$ ({ERRATA} E2)."
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
                "The course notes print $p = 0, -4, 1, 0, 3, 8$ and an octant that runs past "
                "the diagonal down to (5, 1). Run as they state it from $p_0 = 0$, the rules "
                "give $p = 0, -5, 0, 1$ and the loop ends at (3, 3); their p is not "
                "$x^2 + y^2 - r^2$ of their points either. This answer runs the method as "
                f"stated ({ERRATA} E8)."
            )
        return (
            "The course notes' worked table for this method (r = 5) does not follow from it; "
            f"this answer runs the method as stated ({ERRATA} E8)."
        )
    if method == "midpoint":
        start = (
            "The course notes print (2, 4) at k = 2 for this example (Topic 9): with "
            "$p_1 = -1 < 0$ their own rule keeps y, so the algorithm gives (2, 5), and the "
            f"rest of their table follows from that slip ({ERRATA} E10). "
            if five
            else ""
        )
        return (
            start + "The notes call this algorithm ($p_0 = 1 - r$) Bresenham's circle; "
            "Bresenham's own form with $d_0 = 3 - 2r$ is the method 'bresenham'."
        )
    if method == "bresenham":
        start = (
            "The course notes' r = 5 table (Topic 9) plots (2, 4) where the algorithm gives "
            f"(2, 5) ({ERRATA} E10). "
            if five
            else ""
        )
        return (
            start + "This is Bresenham's form with $d_0 = 3 - 2r$; the notes' Topic 9 algorithm "
            "($p_0 = 1 - r$) is the method 'midpoint', which makes the same decisions."
        )
    if method == "symmetric-dda" and five:
        return (
            "The course notes' table for this example uses dx = dy = 1, which walks the "
            "straight line x + y = 5, not the circle; the symmetric DDA steps along the "
            "tangent, $x_{k+1} = x_k + \\varepsilon y_k$, $y_{k+1} = y_k - \\varepsilon x_{k+1}$ "
            f"with $\\varepsilon = 2^{{-n}}$, as this answer does ({ERRATA} E9)."
        )
    if method == "polynomial" and five:
        return (
            "The notes' 'general method' is the method 'general'; this is the square-root "
            f"method ({ERRATA} E8)."
        )
    return None

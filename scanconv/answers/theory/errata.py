"""The notes' mistakes, named where an answer meets them: one note saying in words what the
notes print, what the stated algorithm gives and why, naming its entry of ``docs/errata.md``
(kept apart from :mod:`.theory`, which only ``--derive`` and ``--algorithm`` need).

Each function is the ``errata`` piece of one method record (:mod:`scanconv.answers.methods`):
it takes the question and returns the note, or ``None`` when the notes print what the
method gives."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..asked import CircleQuestion, LineQuestion

ERRATA = "erratum"
"""How an answer names an entry of scanconv's errata list (``docs/errata.md``, the full
record: what the notes print, what scanconv prints and why): ``erratum E1``. The note itself
says in words what the notes print, what the stated algorithm gives and why, so that a
student needs no file they do not have."""


def none(q: object) -> str | None:
    """No note: the notes' examples of this method print what it gives."""
    return None


def bresenham_line(q: LineQuestion) -> str | None:
    """The note about the course notes for this Bresenham line.

    >>> from scanconv.answers.asked import line_question
    >>> bresenham_line(line_question("bresenham", 2, 2, 10, 6))[:46]
    'The course notes print $p_0 = -28$ for this li'
    """
    if q.ends == (2, 2, 10, 6):
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


def dda_line(q: LineQuestion) -> str | None:
    """The note about the course notes for this DDA line (the notes' example only)."""
    if q.ends != (2, 2, 5, 10):
        return None
    return (
        "The course notes print $m = 3/8$ for this line; $3/8 = \\Delta x/\\Delta y$ is "
        "$1/m$, the x increment for each unit step in y ($x_{inc}$ here). The slope is "
        f"$m = \\Delta y/\\Delta x = 8/3$ ({ERRATA} E2)."
    )


def general_circle(q: CircleQuestion) -> str | None:
    """The note about the course notes for the general method.

    >>> from scanconv.answers.asked import CircleQuestion
    >>> general_circle(CircleQuestion("general", 5))[:40]
    'The course notes print $p = 0, -4, 1, 0,'
    """
    if q.r == 5:
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


def midpoint_circle(q: CircleQuestion) -> str | None:
    """The note about the course notes for the midpoint circle (their Bresenham's)."""
    start = (
        "The course notes print (2, 4) at k = 2 for this example (Topic 9): with "
        "$p_1 = -1 < 0$ their own rule keeps y, so the algorithm gives (2, 5), and the "
        f"rest of their table follows from that slip ({ERRATA} E10). "
        if q.r == 5
        else ""
    )
    return (
        start + "The notes call this algorithm ($p_0 = 1 - r$) Bresenham's circle; "
        "Bresenham's own form with $d_0 = 3 - 2r$ is the method 'bresenham'."
    )


def bresenham_circle(q: CircleQuestion) -> str | None:
    """The note about the course notes for Bresenham's circle (d0 = 3 - 2r)."""
    start = (
        "The course notes' r = 5 table (Topic 9) plots (2, 4) where the algorithm gives "
        f"(2, 5) ({ERRATA} E10). "
        if q.r == 5
        else ""
    )
    return (
        start + "This is Bresenham's form with $d_0 = 3 - 2r$; the notes' Topic 9 algorithm "
        "($p_0 = 1 - r$) is the method 'midpoint', which makes the same decisions."
    )


def symmetric_dda_circle(q: CircleQuestion) -> str | None:
    """The note about the course notes' symmetric DDA example (r = 5)."""
    if q.r != 5:
        return None
    return (
        "The course notes' table for this example uses dx = dy = 1, which walks the "
        "straight line x + y = 5, not the circle; the symmetric DDA steps along the "
        "tangent, $x_{k+1} = x_k + \\varepsilon y_k$, $y_{k+1} = y_k - \\varepsilon x_{k+1}$ "
        f"with $\\varepsilon = 2^{{-n}}$, as this answer does ({ERRATA} E9)."
    )


def polynomial_circle(q: CircleQuestion) -> str | None:
    """The note about the notes' name for the square-root method (r = 5)."""
    if q.r != 5:
        return None
    return (
        "The notes' 'general method' is the method 'general'; this is the square-root "
        f"method ({ERRATA} E8)."
    )

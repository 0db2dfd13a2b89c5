"""``compare curves``: the points of the notes' Bezier vs B-spline comparison, as a table."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...core import lazy
from ...core.records import Solution, Walk, rule

if TYPE_CHECKING:
    from ..theory import derivations as th
else:
    th = lazy.module("scanconv.answers.theory.derivations")


def compare_curves() -> Solution:
    """The points the notes' Bezier vs B-spline comparison expects (a theory table only).

    >>> len(list(compare_curves().tables[0].rows()))
    5
    """
    return Solution(
        primitive="curve",
        algorithm="compare",
        title="Bezier vs B-spline curves",
        given=(rule("question", r"\text{Compare Bezier and B-spline curves}"),),
        derived=(),
        notes=(
            "A clamped B-spline does pass through its first and last control points "
            "(erratum E4); the notes' 'does not pass' holds for unclamped knots.",
        ),
        walk=Walk(
            tables=(
                th.theory_table(
                    "Theory: Bezier vs B-spline", ("point", "Bezier", "B-spline"), th.CURVE_THEORY
                )._replace(stepped=True),
            )
        ),
    )

"""The circle records' pieces other than the answer: the row estimate, the ``--derive`` and
``--algorithm`` pieces and the practice wording, each taking the
:class:`~scanconv.answers.asked.CircleQuestion` (the octant parts, the answer pieces, are in
:mod:`.circle`)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...core import lazy
from ...core.records import Code, Quantity, rule
from ..asked import CircleQuestion, knob_values
from .circle import sdda_radius

if TYPE_CHECKING:
    from ..theory import derivations as theory
else:  # only --derive and --algorithm need it
    theory = lazy.module("scanconv.answers.theory.derivations")


def rows(q: CircleQuestion) -> int:
    """One octant's rows: x runs from 0 to r/sqrt(2).

    >>> rows(CircleQuestion("midpoint", 100))
    72
    """
    return math.ceil(abs(q.r) / math.sqrt(2)) + 1


def trig_rows(q: CircleQuestion) -> int:
    """The trigonometric method's rows: θ steps by 1/r over 45°, r·π/4 of them, and one
    below 45° (more than the octant's x run)."""
    return math.ceil(abs(q.r) * math.pi / 4) + 2


def symmetric_dda_rows(q: CircleQuestion) -> int:
    """The symmetric DDA's rows, for a radius it takes (else :class:`InputError`): each step
    turns by about ε = 2^-n, 2^(n-1) <= r < 2^n, so 45° takes (π/4)·2^n steps, up to 1.6 r
    (twice the octant's x run).

    >>> symmetric_dda_rows(CircleQuestion("symmetric-dda", 57))
    53
    """
    r = sdda_radius(q.r)
    return math.ceil(math.pi / 4 * (1 << r.bit_length())) + 2


def midpoint_derivation(q: CircleQuestion) -> tuple[Quantity, ...]:
    """``--derive``: p and its increments from the circle's equation at the midpoint."""
    return theory.midpoint_circle_derivation(q.r, str(q.knobs.p0))


def general_derivation(q: CircleQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for the general method."""
    return theory.general_circle_derivation(q.r)


def bresenham_derivation(q: CircleQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for Bresenham's circle."""
    return theory.bresenham_circle_derivation(q.r)


def equation_derivation(q: CircleQuestion) -> tuple[Quantity, ...]:
    """``--derive`` for a method computed from the equation: the equation and the octant."""
    return (
        rule("d_f", r"x^2 + y^2 = r^2 \rightarrow y = \sqrt{r^2 - x^2}"),
        rule(
            "d_octant", r"\text{one octant from } (0, r) \text{ to } x = y, \text{ mirrored 8 ways}"
        ),
    )


def midpoint_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for the midpoint circle."""
    return theory.midpoint_circle_code(knob_values(q.knobs))


def general_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for the general method."""
    return theory.general_circle_code(knob_values(q.knobs))


def bresenham_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for Bresenham's circle."""
    return theory.bresenham_circle_code(knob_values(q.knobs))


def polynomial_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for the polynomial method."""
    return theory.polynomial_circle_code(knob_values(q.knobs))


def trig_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for the trigonometric method."""
    return theory.trig_circle_code(knob_values(q.knobs))


def symmetric_dda_pseudocode(q: CircleQuestion) -> Code:
    """``--algorithm`` for the symmetric DDA."""
    return theory.symmetric_dda_circle_code(knob_values(q.knobs))


def _practice(name: str, q: CircleQuestion) -> str:
    where = "centred at the origin" if (q.xc, q.yc) == (0, 0) else f"centred at ({q.xc}, {q.yc})"
    return (
        f"Draw the circle of radius {q.r} {where} with {name}: give one octant's step table "
        "and the points of the other octants by symmetry."
    )


def midpoint_practice(q: CircleQuestion) -> str:
    """A practice question's wording: the notes' Topic 9 "Bresenham's circle" is p0 = 1 - r."""
    return _practice("Bresenham's circle algorithm (the notes' form, p0 = 1 - r)", q)


def bresenham_practice(q: CircleQuestion) -> str:
    """A practice question's wording: Bresenham's own form, named by its p0."""
    return _practice("Bresenham's circle algorithm in the form d0 = 3 - 2r", q)

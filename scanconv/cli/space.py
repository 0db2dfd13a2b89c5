"""The 3D chapter: ``3d transform`` and ``3d project`` (declared on :mod:`scanconv._api.space`)."""

from __future__ import annotations

from .application import space_app
from .declared import command

command(
    space_app,
    ("3d", "transform"),
    help="""Compose 3D transformations (homogeneous coordinates, 4 x 4) and apply them to the
    vertices X1 Y1 Z1 ... or a --solid, in the order given: each matrix with its numbers (a
    rotation about an arbitrary axis as its seven steps), the composite and the vertices before
    and after.

    Example: scanconv 3d transform --solid unit-cube --rotate-axis 0 0 0 1 1 1 120
    """,
)

command(
    space_app,
    ("3d", "project"),
    help="""Project the vertices X1 Y1 Z1 ... or a --solid (after any transformations given):
    the projection matrix with its numbers, the projected vertex table, the vanishing points of
    a perspective, and the figure of the projected edges.

    Example: scanconv 3d project --solid unit-cube --perspective one-point --d 2
    """,
)

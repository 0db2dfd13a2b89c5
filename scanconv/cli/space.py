"""The 3D chapter: ``3d transform`` and ``3d project`` (declared on :mod:`scanconv._api.space`)."""

from __future__ import annotations

from .application import three_d_app
from .declared import command

command(
    three_d_app,
    ("3d", "transform"),
    help="""Compose 3D transformations (homogeneous coordinates, 4 x 4) and apply them to the
    vertices X1 Y1 Z1 ... or a --solid, in the order given: each matrix with its numbers (a
    rotation about an arbitrary axis as its seven steps), the composite and the vertices before
    and after.

    Transformations, composed left to right: --translate TX TY TZ; --scale S or SX SY SZ;
    --rotate-x A, --rotate-y A, --rotate-z A; --shear x|y|z A B (scale, rotate and shear may be
    followed by --about X Y Z, a fixed point); --rotate-axis X1 Y1 Z1 X2 Y2 Z2 A; --reflect
    xy|yz|zx; --reflect plane A B C D (the plane Ax + By + Cz + D = 0). An angle A is in degrees
    (90, -30) or radians (pi/4); multiples of 15 degrees are exact (sqrt(3)/2).

    Example: scanconv 3d transform --solid unit-cube --rotate-axis 0 0 0 1 1 1 120
    """,
)

command(
    three_d_app,
    ("3d", "project"),
    help="""Project the vertices X1 Y1 Z1 ... or a --solid (after any transformations given):
    the projection matrix with its numbers, the projected vertex table, the vanishing points of
    a perspective, and the figure of the projected edges. Transformations given first
    (--translate, --scale, --rotate-x, --rotate-y, --rotate-z, --rotate-axis, --reflect, --shear,
    --about, as 3d transform takes them) are applied before the projection.

    Example: scanconv 3d project --solid unit-cube --perspective one-point --d 2
    """,
)

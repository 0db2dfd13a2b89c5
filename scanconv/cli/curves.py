"""Curves: ``parametric ...``, ``bezier``, ``bspline``, ``continuity`` and ``local-control``."""

from __future__ import annotations

from .application import app, parametric_app
from .declared import command

# --- parametric -------------------------------------------------------------------------------


command(
    parametric_app,
    ("parametric", "circle"),
    help="""x = xc + r cos t, y = yc + r sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric circle 5 --center 0 0 --samples 16
    """,
)


command(
    parametric_app,
    ("parametric", "ellipse"),
    help="""x = xc + a cos t, y = yc + b sin t, 0 <= t <= 2 pi.

    Example: scanconv parametric ellipse --center 0 0 --a 8 --b 4
    """,
)


command(
    parametric_app,
    ("parametric", "parabola"),
    help="""x = h + t, y = k + a t^2 (the notes' x = t, y = t^2 by default), -3 <= t <= 3.

    Example: scanconv parametric parabola --t-range -3 3
    """,
)


command(
    parametric_app,
    ("parametric", "line"),
    help="""x = x0 + t (x1 - x0), y = y0 + t (y1 - y0), 0 <= t <= 1.

    Example: scanconv parametric line 0 0 10 4
    """,
)


command(
    parametric_app,
    ("parametric", "custom"),
    help="""Your own x(t) and y(t): numbers, t, + - * / **, pi, e, sin cos tan sqrt exp log abs.

    Example: scanconv parametric custom --x "3*cos(t)" --y "2*sin(t)" --t-range 0 2*pi
    """,
)


# --- Bezier and B-spline curves ---------------------------------------------------------------

command(
    app,
    ("bezier",),
    help="""Bezier curve of the control points P0 .. Pn: Bernstein weights per t, pixels, grid.

    Example: scanconv bezier 0 0 1 2 3 3 4 0 --samples 8   (or --at 0.5)
    """,
)


command(
    app,
    ("bspline",),
    help="""B-spline of degree p (Cox-de Boor): basis values N_i,p(t) per t, the curve, pixels.

    Example: scanconv bspline 0 0 1 2 3 3 4 0 5 2 --degree 2 --knots open
    (the basis alone: scanconv bspline --basis --degree 2 --knots 0,.25,.5,.75,1)
    """,
)


command(
    app,
    ("continuity",),
    help="""Continuity (C0, C1, C2) at the join of two Bezier segments, with the derivatives.

    Example: scanconv continuity 0 0 1 2 3 3 4 0 : 4 0 5 -3 7 -2 8 0
    """,
)


command(
    app,
    ("local-control",),
    help="""Bezier vs B-spline: move one control point, see which samples and pixels change.

    Example: scanconv local-control 0 0 1 2 3 3 4 0 5 2 7 1 --move 5 7 5 --degree 2
    """,
)

"""Theory answers of the notes' curve topics (14 marks): curves, the parametric function, the
Bezier method and the B-spline method."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, embed, listing, text_table

if TYPE_CHECKING:
    from ...curves import bezier as answers_bezier
    from ...curves import bspline as answers_bspline
    from ...curves import continuity as answers_continuity
    from ...primitives import parametric as answers_parametric
else:
    answers_bezier = lazy.module("scanconv.answers.curves.bezier")
    answers_bspline = lazy.module("scanconv.answers.curves.bspline")
    answers_continuity = lazy.module("scanconv.answers.curves.continuity")
    answers_parametric = lazy.module("scanconv.answers.primitives.parametric")

SECTION = "14-marks"

_CONTROL = [(0, 0), (1, 2), (3, 3), (4, 0)]
_SPLINE = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)]


def curves() -> Solution:
    continuity = text_table(
        "Classification by continuity (the notes)",
        ["class", "what is continuous at a join"],
        [
            ("C0", "position: the pieces meet"),
            ("C1", "tangent: first derivatives agree"),
            ("C2", "curvature: second derivatives agree"),
        ],
    )
    kinds = listing(
        "Types of curves (the notes' list)",
        ["Algebraic", "Parametric", "Explicit", "Implicit", "Spline", "Bezier"],
        "type",
    )
    return answer(
        "curves",
        "Curves",
        definition=(
            "a curve is a smooth, continuous path in a plane traced by a moving point. Curves "
            "are described as algebraic, explicit $y = f(x)$, implicit $f(x, y) = 0$ or "
            "parametric $x = x(t), y = y(t)$ functions, or built from control points as "
            "spline and Bezier curves."
        ),
        paragraphs=(
            "A curve's quality is described by its continuity, smoothness, tangent and "
            "curvature; where two pieces join, the order of continuity ($C^0$, $C^1$, $C^2$) "
            "says how smoothly they meet.",
            "Applications: animation, CAD/CAM, font design, scientific visualisation, games.",
        ),
        tables=(kinds, continuity),
        examples=(
            embed(
                "two quadratic Bezier pieces joined at (2, 0) (scanconv continuity 0 0 1 1 2 0 : "
                "2 0 3 -1 4 0)",
                answers_continuity.continuity_solution(
                    [(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)]
                ),
            ),
        ),
    )


def parametric() -> Solution:
    forms = text_table(
        "Parametric equations of the common curves (the notes' examples)",
        ["curve", "x(t)", "y(t)", "range of t"],
        [
            ("Line", "x0 + t(x1 - x0)", "y0 + t(y1 - y0)", "0 <= t <= 1"),
            ("Circle", "xc + r cos t", "yc + r sin t", "0 <= t <= 2 pi"),
            ("Ellipse", "xc + a cos t", "yc + b sin t", "0 <= t <= 2 pi"),
            ("Parabola", "t", "t^2", "all real t"),
        ],
    )
    return answer(
        "parametric",
        "Parametric function",
        definition=(
            "in parametric representation a curve is defined by two functions of one "
            "independent parameter t, $x = x(t)$ and $y = y(t)$ for $t_1 \\le t \\le t_2$: as "
            "t runs through its range, the point (x(t), y(t)) traces the curve."
        ),
        paragraphs=(
            "Drawing a parametric curve: take values of t, compute (x(t), y(t)), round each to "
            "a pixel and join successive pixels; smaller steps of t give a smoother curve.",
        ),
        points=(
            "Represents complex curves easily.",
            "Useful for animation (t as time).",
            "Independent of the coordinate system.",
            "Gives smooth curves; t is the independent variable.",
        ),
        points_title="Advantages and key points (the notes)",
        tables=(forms,),
        examples=(
            embed(
                "the line (0, 0) to (10, 4) (scanconv parametric line 0 0 10 4)",
                answers_parametric.parametric_solution("line", points=(0, 0, 10, 4)),
            ),
        ),
    )


def bezier() -> Solution:
    return answer(
        "bezier",
        "Bezier method",
        definition=(
            "a Bezier curve is defined by n + 1 control points $P_0 .. P_n$ as "
            "$B(t) = \\sum_{i=0}^{n} B_{i,n}(t) P_i$, $0 \\le t \\le 1$, where "
            "$B_{i,n}(t) = \\binom{n}{i} t^i (1 - t)^{n-i}$ are the Bernstein basis "
            "polynomials. The curve starts at $P_0$, ends at $P_n$ and always lies within the "
            "convex hull of its control points."
        ),
        paragraphs=(
            "Cubic Bezier curve (4 control points): "
            "$B(t) = (1 - t)^3 P_0 + 3t(1 - t)^2 P_1 + 3t^2(1 - t) P_2 + t^3 P_3$.",
            "Moving a control point changes the shape of the whole curve (global control).",
        ),
        points=(
            "The curve always lies inside the convex hull.",
            "Moving control points changes the shape.",
            "Degree n = number of control points - 1.",
        ),
        advantages=(
            "Easy to implement.",
            "Produces smooth curves.",
            "The end points lie on the curve.",
            "Used in CAD and animation.",
        ),
        examples=(
            embed(
                "the cubic with control points (0, 0), (1, 2), (3, 3), (4, 0) "
                "(scanconv bezier 0 0 1 2 3 3 4 0 --samples 8)",
                answers_bezier.bezier_solution(_CONTROL, 8),
            ),
        ),
    )


def bspline() -> Solution:
    compare = text_table(
        "Comparison: Bezier vs B-spline (the notes' table)",
        ["feature", "Bezier curve", "B-spline"],
        [
            ("Control", "global: every point moves the curve", "local: only nearby points"),
            ("Curve form", "passes through first and last points", "need not pass through them"),
            ("Knot vector", "not required", "required"),
            ("Flexibility", "less", "more"),
        ],
    )
    terms = text_table(
        "Terminology (the notes)",
        ["term", "meaning"],
        [
            ("Control points", "P0, P1, ..., Pn"),
            ("Knot vector", "U = {u0, u1, ..., um}"),
            ("Degree", "p"),
            ("Knot condition", "m = n + p + 1"),
        ],
    )
    return answer(
        "bspline",
        "B-spline method",
        definition=(
            "a B-spline (basis spline) is a generalisation of the Bezier curve that gives local "
            "control: $C(t) = \\sum_{i=0}^{n} N_{i,p}(t) P_i$, where $P_i$ are the control "
            "points, p is the degree and $N_{i,p}$ are the basis functions defined on a knot "
            "vector by the Cox-de Boor formula."
        ),
        paragraphs=(
            "Cox-de Boor: $N_{i,0}(t) = 1$ if $t_i \\le t < t_{i+1}$, else 0; "
            "$N_{i,p}(t) = \\frac{t - t_i}{t_{i+p} - t_i} N_{i,p-1}(t) + "
            "\\frac{t_{i+p+1} - t}{t_{i+p+1} - t_{i+1}} N_{i+1,p-1}(t)$.",
            "Each basis function is non-zero on only p + 1 knot spans, so moving one control "
            "point changes only the nearby part of the curve (scanconv local-control shows it).",
        ),
        tables=(terms, compare),
        examples=(
            embed(
                "a cubic B-spline on 5 control points, open knots (scanconv bspline 0 0 1 2 3 3 "
                "4 0 5 2 --degree 3 --samples 8)",
                answers_bspline.bspline_solution(_SPLINE, 3, "open", 8),
            ),
        ),
    )


TOPICS = (
    Topic("curves", SECTION, "Curves", ("CURVES",), curves),
    Topic("parametric", SECTION, "Parametric function", ("PARAMETRIC FUNCTION",), parametric),
    Topic("bezier", SECTION, "Bezier method", ("BEZIER METHOD",), bezier),
    Topic("bspline", SECTION, "B-spline method", ("B-SPLINE METHOD",), bspline),
)

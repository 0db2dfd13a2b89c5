"""Theory answers of the 3D chapter, beyond the course notes: parallel and perspective
projection (explained and told apart), and rotation about an arbitrary axis (its seven steps).
Each has a live example computed by scanconv (``3d project``, ``3d transform``); they follow
:mod:`.windows` in ``scanconv theory --list``."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, text_table
from .syllabus import SECTION, embed

if TYPE_CHECKING:
    from ...space import project, transform
else:
    project = lazy.module("scanconv.answers.space.project")
    transform = lazy.module("scanconv.answers.space.transform")


def projections() -> Solution:
    return answer(
        "projections",
        "Explain parallel and perspective projection; differentiate them",
        definition=(
            "a projection maps the points of a 3D object onto a 2D view plane along lines "
            "called projectors: in a parallel projection the projectors are parallel to one "
            "direction, in a perspective projection they all meet at one point, the centre of "
            "projection."
        ),
        paragraphs=(
            "Parallel projections keep parallel lines parallel and keep the relative sizes of "
            "parts along each axis: orthographic (the projectors perpendicular to the view "
            "plane: front, side and top views; axonometric: isometric, dimetric, trimetric "
            "after turning the object) and oblique (the projectors at an angle α to the plane: "
            "$x' = x + L_1 z \\cos\\phi$, $y' = y + L_1 z \\sin\\phi$ with $L_1 = 1/\\tan\\alpha$; "
            "cavalier $L_1 = 1$, cabinet $L_1 = 1/2$).",
            "A perspective projection with the centre at $(0, 0, -d)$ onto $z = 0$ divides by "
            "depth: $x' = x d/(z + d)$, $y' = y d/(z + d)$, the 4 x 4 matrix's last row "
            "$(0, 0, 1/d, 1)$ making $w = z/d + 1$. Lines parallel to the plane stay parallel; "
            "the others meet at vanishing points: one, two or three principal axes meeting "
            "the plane give one-, two- or three-point perspective.",
        ),
        tables=(
            text_table(
                "Parallel and perspective projection",
                ["", "parallel", "perspective"],
                [
                    ("projectors", "parallel to one direction", "meet at the centre of projection"),
                    ("centre of projection", "at infinity", "at a finite distance d"),
                    ("parallel lines", "stay parallel", "meet at vanishing points"),
                    ("sizes", "kept along each axis (measurable)", "smaller with distance"),
                    ("matrix's last row", "(0, 0, 0, 1): w = 1", "(0, 0, 1/d, 1): w = z/d + 1"),
                    ("looks", "less realistic", "realistic, as an eye or camera sees"),
                    ("used for", "engineering drawings", "realistic scenes, animation"),
                ],
            ),
        ),
        examples=(
            embed(
                "a cabinet projection of the unit cube (scanconv 3d project --solid unit-cube "
                "--parallel cabinet)",
                project.project_solution([], "unit-cube", parallel="cabinet"),
                plot=False,
            ),
            embed(
                "a one-point perspective of the unit cube (scanconv 3d project --solid "
                "unit-cube --perspective one-point --d 2 --cop minus-d)",
                project.project_solution(
                    [], "unit-cube", perspective="one-point", d=2, cop="minus-d"
                ),
                plot=False,
            ),
        ),
    )


def arbitrary_axis() -> Solution:
    return answer(
        "rotation-arbitrary-axis",
        "Explain 3D rotation about an arbitrary axis",
        definition=(
            "a rotation by θ about the axis through P1 and P2 is the composite of moving the "
            "axis onto the z axis, rotating by θ about z, and moving it back: "
            "$M = T^{-1} R_x^{-1}(\\alpha) R_y^{-1}(\\beta) R_z(\\theta) R_y(\\beta) "
            "R_x(\\alpha) T$."
        ),
        paragraphs=(
            "With $V = P_2 - P_1$ and the unit vector $u = V/|V| = (a, b, c)$, let "
            "$d = \\sqrt{b^2 + c^2}$. $R_x(\\alpha)$ with $\\cos\\alpha = c/d$, "
            "$\\sin\\alpha = b/d$ turns u into the xz plane; $R_y(\\beta)$ with "
            "$\\cos\\beta = d$, $\\sin\\beta = -a$ turns it onto the z axis (Hearn & Baker).",
            "The composite equals Rodrigues' formula $R = \\cos\\theta I + \\sin\\theta [u]_\\times "
            "+ (1 - \\cos\\theta) u u^T$ about P1: an orthogonal matrix of determinant 1.",
        ),
        points=(
            "Translate P1 to the origin: T(-P1).",
            "Rotate about x by α so that the axis lies in the xz plane (skip if d = 0).",
            "Rotate about y by β so that the axis lies along z.",
            "Rotate about z by θ.",
            "Undo the y turn, then the x turn: Ry(-β), Rx(-α).",
            "Translate back: T(P1).",
        ),
        points_title="The steps",
        examples=(
            embed(
                "the unit cube turned by 120° about (0, 0, 0)-(1, 1, 1) (scanconv 3d transform "
                "--solid unit-cube --rotate-axis 0 0 0 1 1 1 120)",
                transform.transform_solution("--rotate-axis 0 0 0 1 1 1 120".split(), "unit-cube"),
            ),
        ),
    )


TOPICS = (
    Topic(
        "projections",
        SECTION,
        "Explain parallel and perspective projection; differentiate them",
        (
            "Explain parallel and perspective projection.",
            "Differentiate between parallel and perspective projection.",
        ),
        projections,
    ),
    Topic(
        "rotation-arbitrary-axis",
        SECTION,
        "Explain 3D rotation about an arbitrary axis",
        ("Explain 3D rotation about an arbitrary axis.",),
        arbitrary_axis,
    ),
)

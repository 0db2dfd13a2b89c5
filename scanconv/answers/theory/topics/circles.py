"""Theory answers of the notes' circle sections and their 14-mark topics: the circle's
equation, 8-way symmetry, the general method, the symmetric DDA and Bresenham's circle."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....algorithms.circles import images
from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, embed, figure, text_table

if TYPE_CHECKING:
    from ...primitives import circle
else:
    circle = lazy.module("scanconv.answers.primitives.circle")

SECTION = "circle-drawing"

_SYMMETRY = text_table(
    "The 8 symmetric points of (x, y) about the centre (the notes' list)",
    ["no.", "point", "no.", "point"],
    [
        ("1", "(xc + x, yc + y)", "5", "(xc + y, yc + x)"),
        ("2", "(xc - x, yc + y)", "6", "(xc - y, yc + x)"),
        ("3", "(xc + x, yc - y)", "7", "(xc + y, yc - x)"),
        ("4", "(xc - x, yc - y)", "8", "(xc - y, yc - x)"),
    ],
)

_ALGORITHM = (
    "Input the centre $(x_c, y_c)$ and the radius r; start at $x = 0$, $y = r$ and plot the "
    "8 symmetric points of (x, y). While $x < y$: if $p < 0$, $x = x + 1$ and "
    "$p = p + 2x + 1$; else $x = x + 1$, $y = y - 1$ and $p = p + 2x - 2y + 1$; plot the 8 "
    "symmetric points each time."
)


def equation() -> Solution:
    return answer(
        "circle-equation",
        "What is the equation of a circle?",
        definition=(
            "a circle is the set of all points of a plane at a fixed distance, the radius r, "
            "from a fixed point, the centre $(x_c, y_c)$. Its equation is "
            "$(x - x_c)^2 + (y - y_c)^2 = r^2$, and for a circle centred at the origin "
            "$x^2 + y^2 = r^2$."
        ),
        paragraphs=(
            "Solved for y, $y = y_c \\pm \\sqrt{r^2 - (x - x_c)^2}$; in parametric form "
            "$x = x_c + r \\cos t$, $y = y_c + r \\sin t$, $0 \\le t \\le 2\\pi$. Drawing "
            "algorithms compute one octant (0 to 45 degrees) and mirror it.",
            "Check with the example's pixels: (3, 4) is on the circle of radius 5, since "
            "$3^2 + 4^2 = 9 + 16 = 25 = 5^2$.",
        ),
        points=(
            "Centre at the origin: x^2 + y^2 = r^2.",
            "Any centre: (x - xc)^2 + (y - yc)^2 = r^2.",
            "Only one octant is computed; symmetry gives the rest.",
        ),
        examples=(
            embed(
                "the circle of radius 5 (scanconv circle 5)",
                circle.circle_solution("midpoint", 5),
                working=False,
            ),
        ),
    )


def symmetry() -> Solution:
    x, y = 2, 5
    mirrored = images(x, y)
    rows = [(i, f"({p[0]}, {p[1]})") for i, p in enumerate(mirrored, 1)]
    table = text_table(
        f"The eight images of ({x}, {y}) about the centre (0, 0)",
        ["no.", "image"],
        rows,
    )
    return answer(
        "symmetry",
        "Explain 8-way symmetry of a circle with diagram",
        definition=(
            "a circle is symmetric about its centre's horizontal and vertical lines and about "
            "the two diagonals, so one computed point (x, y) gives 8 points of the circle: "
            "$(x_c \\pm x, y_c \\pm y)$ and $(x_c \\pm y, y_c \\pm x)$. An algorithm computes "
            "only the octant from $(0, r)$ to $(\\frac{r}{\\sqrt{2}}, \\frac{r}{\\sqrt{2}})$, "
            "one eighth of the circle, and plots each point 8 times."
        ),
        paragraphs=(
            "Diagram: the point (2, 5) of the circle of radius $\\sqrt{29}$ and its seven "
            "images, drawn below with the centre marked o; each octant holds one of them.",
        ),
        points=(
            "One octant (0 to 45 degrees) is computed.",
            "The other 7 points come by reflection: 1/8 of the work.",
            "Reflections swap x and y and change their signs.",
        ),
        tables=(_SYMMETRY, table),
        figures=(
            figure(
                "The eight images of (2, 5) (#) about the centre (0, 0) (o):",
                mirrored,
                (-5, -5, 5, 5),
                ((0, 0),),
                "# = an image of the point, o = the centre",
            ),
        ),
    )


def general() -> Solution:
    return answer(
        "general-circle",
        "Explain the general method of circle drawing",
        definition=(
            "the general method draws a circle from its equation $x^2 + y^2 = r^2$. Starting "
            "at (0, r), it moves x by 1 each step and decides between E (x + 1, y) and SE "
            "(x + 1, y - 1) by the sign of the decision parameter $p = x^2 + y^2 - r^2$, "
            "which is 0 at the start, updated incrementally; the rest of the circle comes "
            "from 8-way symmetry."
        ),
        paragraphs=(
            "Decision: if $p < 0$ choose E and $p = p + 2x + 1$; if $p \\ge 0$ choose SE and "
            "$p = p + 2x - 2y + 1$ (with the new x and y).",
            "Algorithm: " + _ALGORITHM,
            "The notes' 14-mark version starts from $p = 1 - r$, the midpoint form; the notes' "
            "worked table for r = 5 does not follow from either rule (erratum E8). The "
            "example runs the method as its algorithm box states it.",
        ),
        points=(
            "Based on the circle equation.",
            "Uses floating-point arithmetic (in the notes).",
            "Only 1/8 of the points are calculated; 8-way symmetry.",
            "Starts at (0, r), moves towards (0.707r, 0.707r).",
        ),
        tables=(_SYMMETRY,),
        advantages=(
            "Simple and easy to understand.",
            "8-way symmetry reduces computation.",
            "Suitable for small radii and teaching.",
        ),
        limitations=(
            "Floating-point arithmetic (slower).",
            "Not suitable for integer-only hardware.",
            "Rounding errors accumulate.",
        ),
        examples=(
            embed(
                "radius 5 by the general method (scanconv circle 5 --method general)",
                circle.circle_solution("general", 5),
            ),
        ),
    )


def symmetric_dda() -> Solution:
    return answer(
        "symmetric-dda",
        "Explain the symmetric DDA algorithm for circles",
        definition=(
            "the symmetric DDA draws a circle incrementally with floating-point steps, like the "
            "line DDA, and plots each computed point with 8-way symmetry. It starts at "
            "(0, r), adds small increments to x and y derived from the circle's differential "
            "equation, rounds each point to a pixel, and stops when x passes y."
        ),
        paragraphs=(
            "The notes' box steps $x = x + dx$, $y = y - dy$ with $dx = dy = 1$, which cannot "
            "trace a circle (it runs along a diagonal); the method as the textbooks give it "
            "rotates the point by a small angle $\\varepsilon = 2^{-n}$ with "
            "$2^{n-1} \\le r < 2^n$: $x_{k+1} = x_k + \\varepsilon y_k$, "
            "$y_{k+1} = y_k - \\varepsilon x_{k+1}$. scanconv runs that version (see "
            "erratum E9 for the notes' table).",
        ),
        points=(
            "Simple and easy.",
            "Uses floating point.",
            "8-way symmetry.",
            "More computation than Bresenham.",
        ),
        examples=(
            embed(
                "radius 5 by the symmetric DDA (scanconv circle 5 --method symmetric-dda)",
                circle.circle_solution("symmetric-dda", 5),
            ),
        ),
    )


def bresenham() -> Solution:
    return answer(
        "bresenham-circle",
        "Explain Bresenham's circle drawing algorithm",
        definition=(
            "Bresenham's circle algorithm draws a circle with integer arithmetic only. From "
            "(0, r) it steps x by 1 and chooses E (x + 1, y) or SE (x + 1, y - 1) by the sign "
            "of an integer decision parameter, starting from $p = 1 - r$ (the midpoint "
            "form) or $p = 3 - 2r$ (Bresenham's form), and plots each point with 8-way "
            "symmetry until $x \\ge y$."
        ),
        paragraphs=(
            "Algorithm (the notes): " + _ALGORITHM.replace("start at", "start at $p = 1 - r$,"),
            "scanconv circle R --method bresenham uses Bresenham's own $p_0 = 3 - 2r$ "
            "($p = p + 4x + 6$ or $p = p + 4(x - y) + 10$); --method midpoint the notes' "
            "$p = 1 - r$. Both choose the same pixels. The notes' worked table for r = 5 does "
            "not follow from the algorithm (erratum E10).",
        ),
        points=(
            "Uses only integer arithmetic.",
            "Fast and efficient; less memory.",
            "Suitable for real-time applications.",
            "8-way symmetry as in the general method.",
        ),
        tables=(_SYMMETRY,),
        examples=(
            embed(
                "radius 5 (scanconv circle 5 --method bresenham)",
                circle.circle_solution("bresenham", 5),
            ),
        ),
    )


TOPICS = (
    Topic(
        "circle-equation",
        SECTION,
        "What is the equation of a circle?",
        ("What is the equation of a circle?",),
        equation,
    ),
    Topic(
        "symmetry",
        SECTION,
        "Explain 8-way symmetry of a circle with diagram",
        ("Explain 8-way symmetry of a circle with diagram.",),
        symmetry,
    ),
    Topic(
        "general-circle",
        SECTION,
        "Explain the general method of circle drawing",
        ("Explain general circle drawing algorithm.", "GENERAL METHOD OF CIRCLE DRAWING"),
        general,
    ),
    Topic(
        "symmetric-dda",
        "14-marks",
        "Explain the symmetric DDA algorithm for circles",
        ("SYMMETRIC DDA ALGORITHM",),
        symmetric_dda,
    ),
    Topic(
        "bresenham-circle",
        "14-marks",
        "Explain Bresenham's circle drawing algorithm",
        ("BRESENHAM'S CIRCLE DRAWING ALGORITHM",),
        bresenham,
    ),
)

"""Theory answers of the notes' line sections: the line and its cases, the DDA, Bresenham's
algorithm and how the other octants are handled."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....core import lazy
from ....core.numeric import fmt_short
from ....core.records import Pixel, Solution
from ._build import Topic, answer, embed, figure, text_table

if TYPE_CHECKING:
    from ...primitives import line as answers_line
else:
    answers_line = lazy.module("scanconv.answers.primitives.line")

SECTION = "line-drawing"


def _pixels(sol: Solution) -> list[Pixel]:
    return list(sol.pixels()) if sol.pixels is not None else []


def _compact(pixels: list[Pixel]) -> str:
    return " ".join(f"({x},{y})" for x, y in pixels)


def _bbox(pixels: list[Pixel]) -> tuple[int, int, int, int]:
    xs, ys = [p[0] for p in pixels], [p[1] for p in pixels]
    return min(xs), min(ys), max(xs), max(ys)


def line() -> Solution:
    return answer(
        "line",
        "Define line. Explain need of line drawing",
        definition=(
            "a line is the simplest and most fundamental object of computer graphics, defined "
            "by its two end points $(x_1, y_1)$ and $(x_2, y_2)$; its equation is "
            "$y - y_1 = m(x - x_1)$ with slope $m = \\frac{y_2 - y_1}{x_2 - x_1}$. Line drawing "
            "is determining the set of pixel positions that best represents that straight line "
            "on the screen."
        ),
        paragraphs=(
            "A line can be represented in mathematical form (the equation) or in incremental "
            "form (each point from the previous one by adding a constant step).",
            "Pixel selection: the ideal line rarely passes through pixel centres, so the pixel "
            "whose centre is nearest to the line is chosen, measured vertically for "
            "$0 \\le m \\le 1$ and horizontally for $m > 1$.",
        ),
        points=(
            "Need: lines draw the edges of objects.",
            "Need: they are the basis of shapes, polygons, characters and graphs.",
            "Need: CAD, animation, games and scientific visualisation rely on them.",
            "When |m| <= 1 step in x; when |m| > 1 step in y.",
            "DDA uses floating point; Bresenham uses integers only.",
        ),
        examples=(
            embed(
                "the notes' line (2, 2) to (8, 5) by the basic concept (scanconv line 2 2 8 5 "
                "--algo basic)",
                answers_line.line_solution("basic", 2, 2, 8, 5),
            ),
        ),
    )


#: The notes' four cases, each with a line that falls in it.
_CASES = (
    ("Case 1", "0 <= m <= 1", "x = x + 1", "along x", (0, 0, 6, 3)),
    ("Case 2", "m > 1", "y = y + 1", "along y", (8, 0, 10, 6)),
    ("Case 3", "-1 <= m <= 0", "x = x + 1", "along x", (12, 3, 18, 0)),
    ("Case 4", "m < -1", "y = y + 1", "along y", (20, 6, 22, 0)),
)


def cases() -> Solution:
    rows = []
    every: list[Pixel] = []
    for name, cond, inc, major, (x1, y1, x2, y2) in _CASES:
        sol = answers_line.line_solution("dda", x1, y1, x2, y2)
        m = next(q.value for q in sol.derived if q.key == "m")
        every.extend(_pixels(sol))
        rows.append((name, cond, inc, major, f"({x1}, {y1}) to ({x2}, {y2})", fmt_short(m)))
    figures = [
        figure("The four example lines, case 1 to case 4 from left to right:", every, _bbox(every))
    ]
    table = text_table(
        "The cases of line drawing (the notes' table), each with a line drawn by DDA",
        ["case", "condition", "increment", "major step", "example line", "m"],
        rows,
    )
    return answer(
        "line-cases",
        "Explain different cases of line drawing",
        definition=(
            "the slope $m = \\frac{y_2 - y_1}{x_2 - x_1}$ decides how a line is stepped. When "
            "$|m| \\le 1$, x changes faster: x is the major axis, stepped by 1, and y (the minor "
            "step) may change. When $|m| > 1$, y is the major axis, stepped by 1, and x may "
            "change. The sign of m says whether the minor coordinate rises or falls."
        ),
        paragraphs=(
            "Lines are generally drawn in the first octant ($0 \\le m \\le 1$) and the others "
            "are reached by symmetry: swap x and y for steep lines, step the minor coordinate "
            "by -1 for negative slopes, and swap the end points of a line drawn right to left.",
            "Example: one line of each case, computed by DDA (scanconv line X1 Y1 X2 Y2 --algo "
            "dda) and drawn side by side below.",
        ),
        tables=(table,),
        figures=figures,
    )


def dda() -> Solution:
    return answer(
        "dda",
        "Describe the DDA algorithm for line drawing",
        definition=(
            "DDA (Digital Differential Analyzer) is a line drawing algorithm that finds the "
            "pixels of a line between two end points incrementally: the line is divided into "
            "equal steps along its major axis, x and y are advanced by constant increments at "
            "each step, and each computed point is rounded to the nearest pixel."
        ),
        paragraphs=(
            "Formulation: $\\Delta x = x_2 - x_1$, $\\Delta y = y_2 - y_1$, "
            "$m = \\frac{\\Delta y}{\\Delta x}$. If $|m| \\le 1$ x is the major axis: "
            "$x_{k+1} = x_k + 1$, $y_{k+1} = y_k + m$. If $|m| > 1$ y is the major axis: "
            "$y_{k+1} = y_k + 1$, $x_{k+1} = x_k + \\frac{1}{m}$. Each step plots "
            "$(\\operatorname{round}(x), \\operatorname{round}(y))$.",
            "Steps ($|m| \\le 1$): compute $\\Delta x$, $\\Delta y$ and m; start at "
            "$(x_1, y_1)$ and plot it; then $\\Delta x$ times add 1 to x and m to y and plot "
            "the rounded point; stop. For $|m| > 1$ exchange the roles of x and y.",
        ),
        points=(
            "A direct method based on the slope.",
            "The major axis decides the number of steps.",
            "|m| <= 1: x is the major axis; |m| > 1: y is.",
            "Pixel positions are obtained by rounding.",
            "It uses floating-point calculations.",
        ),
        advantages=(
            "Simple and easy to understand.",
            "Requires less memory.",
            "Works for all types of lines.",
            "Uses incremental calculations.",
        ),
        limitations=(
            "Floating-point arithmetic: slower than integer methods.",
            "Rounding causes accumulated errors (less accuracy).",
            "Lines can be more jagged than Bresenham's.",
        ),
        examples=(
            embed(
                "the notes' line (2, 2) to (10, 6) by DDA (scanconv line 2 2 10 6 --algo dda)",
                answers_line.line_solution("dda", 2, 2, 10, 6, pseudocode=True),
            ),
        ),
    )


def bresenham() -> Solution:
    return answer(
        "bresenham-line",
        "Explain Bresenham's line drawing algorithm",
        definition=(
            "Bresenham's line drawing algorithm is an efficient scan-conversion algorithm for "
            "straight lines that uses only integer addition and subtraction. Drawing from left "
            "to right with $0 \\le m \\le 1$, at each step it chooses between the east pixel "
            "E $(x_k + 1, y_k)$ and the north-east pixel NE $(x_k + 1, y_k + 1)$ by the sign of "
            "an integer decision parameter $p_k$: whichever is nearer to the ideal line."
        ),
        paragraphs=(
            "Decision parameter: $p_0 = 2\\Delta y - \\Delta x$; if $p_k < 0$ choose E and "
            "$p_{k+1} = p_k + 2\\Delta y$, else choose NE and "
            "$p_{k+1} = p_k + 2\\Delta y - 2\\Delta x$; repeat $\\Delta x$ times. "
            "(scanconv line 2 2 10 6 --algo bresenham --derive derives it.) The notes' worked "
            "example starts from $p_0 = -28$, which does not follow from the algorithm (see "
            "erratum E1); the example below runs the algorithm itself.",
            "Assumptions: $0 \\le m \\le 1$; if $m > 1$ interchange x and y; if the line is "
            "drawn right to left, interchange the end points.",
            "Applications: computer graphics systems, CAD/CAM, game development, drawing and "
            "editing tools, scientific and engineering visualisation.",
        ),
        points=(
            "Based on a decision parameter.",
            "Avoids floating-point calculations.",
            "Only addition and subtraction are required.",
            "Symmetry handles all octants.",
        ),
        advantages=(
            "Only integer addition and subtraction.",
            "Fast and efficient.",
            "Less memory requirement.",
            "Suitable for real-time applications.",
            "Accurate, visually pleasing lines.",
        ),
        limitations=(
            "Works for straight lines only.",
            "Steep slopes (m > 1) need extra logic.",
            "Not suitable for sub-pixel accuracy.",
        ),
        examples=(
            embed(
                "the notes' line (2, 2) to (10, 6) (scanconv line 2 2 10 6 --algo bresenham)",
                answers_line.line_solution("bresenham", 2, 2, 10, 6, pseudocode=True),
            ),
        ),
    )


#: One line from the origin into each octant, counter-clockwise from the positive x axis.
_OCTANTS = (
    (1, (6, 2), "0 <= m <= 1, dx > 0", "as derived"),
    (2, (2, 6), "m > 1, dy > 0", "swap the roles of x and y"),
    (3, (-2, 6), "m < -1, dy > 0", "swap x and y; x steps by -1"),
    (4, (-6, 2), "-1 <= m <= 0, dx < 0", "swap the end points; y steps by -1"),
    (5, (-6, -2), "0 <= m <= 1, dx < 0", "swap the end points"),
    (6, (-2, -6), "m > 1, dy < 0", "swap the end points, swap x and y"),
    (7, (2, -6), "m < -1, dy < 0", "swap x and y, swap the end points; x steps by -1"),
    (8, (6, -2), "-1 <= m <= 0, dx > 0", "y steps by -1 (|dy| in p)"),
)


def octants() -> Solution:
    rules, rows = [], []
    every: list[Pixel] = []
    for n, (x2, y2), cond, rule in _OCTANTS:
        pixels = _pixels(answers_line.line_solution("bresenham", 0, 0, x2, y2))
        every.extend(p for p in pixels if p not in every)
        rules.append((n, cond, rule))
        rows.append((n, f"({x2}, {y2})", _compact(pixels)))
    how = text_table(
        "How each octant is reduced to the first", ["octant", "condition", "handled by"], rules
    )
    table = text_table(
        "One line per octant from (0, 0), computed by Bresenham's algorithm",
        ["octant", "to", "pixels"],
        rows,
    )
    return answer(
        "octants",
        "How other octants are handled in Bresenham's algorithm?",
        definition=(
            "Bresenham's algorithm is derived for the first octant ($0 \\le m \\le 1$, x "
            "increasing); every other octant is reduced to it by symmetry: exchange x and y "
            "when $|m| > 1$, step the minor coordinate by -1 (using $|\\Delta y|$) when the "
            "slope is negative, and interchange the end points when the line is drawn right "
            "to left, so that x (or y) increases."
        ),
        paragraphs=(
            "The notes' rules: if $m < 0$ use the algorithm with $\\Delta y = |y_1 - y_0|$ and "
            "change y by -1 when NE is chosen; if $m > 1$ interchange x and y and apply the "
            "algorithm; if the line is drawn from right to left interchange the end points so "
            "that $x_0 < x_1$.",
            "Below, eight lines from the origin, one into each octant, are computed by the same "
            "code (scanconv line 0 0 X Y --algo bresenham) and drawn together.",
        ),
        tables=(how, table),
        figures=(figure("The eight lines, one per octant:", every, _bbox(every)),),
    )


TOPICS = (
    Topic(
        "line",
        SECTION,
        "Define line. Explain need of line drawing",
        ("Define line. Explain need of line drawing.",),
        line,
    ),
    Topic(
        "line-cases",
        SECTION,
        "Explain different cases of line drawing",
        ("Explain different cases of line drawing.",),
        cases,
    ),
    Topic(
        "dda",
        "dda",
        "Describe the DDA algorithm for line drawing",
        (
            "Describe DDA algorithm for line drawing.",
            "What is DDA Algorithm?",
            "Explain Simple DDA Algorithm with steps.",
        ),
        dda,
    ),
    Topic(
        "bresenham-line",
        "bresenham",
        "Explain Bresenham's line drawing algorithm",
        ("Explain Bresenham's line drawing algorithm.",),
        bresenham,
    ),
    Topic(
        "octants",
        "bresenham",
        "How other octants are handled in Bresenham's algorithm?",
        ("How other octants are handled in Bresenham's algorithm?",),
        octants,
    ),
)

"""The declarations several commands share (:mod:`scanconv.core.declare`): the conventions'
options, the layout, the derivation and pseudocode flags, a centre. A command's function
writes its parameter's type and default, and one of these as its ``Annotated`` metadata."""

from __future__ import annotations

from ..core.declare import Arg, Opt

X1 = Arg("x of the first end point P1.", "X1")
Y1 = Arg("y of the first end point P1.", "Y1")
X2 = Arg("x of the second end point P2.", "X2")
Y2 = Arg("y of the second end point P2.", "Y2")
"""A line's end points."""

WU_ENDS = Opt(
    "--ends",
    help="wu: end points at full intensity (full, the default) or weighted by the part of the "
    "end column the line covers (coverage, as Wikipedia's pseudocode).",
)

VERTICES = Arg("The polygon's vertices, in order.", "X1 Y1 X2 Y2 X3 Y3 ...")
WINDOW = Opt(
    "--window",
    "-w",
    metavar="XMIN YMIN XMAX YMAX",
    show_default=False,
    help="The clipping window in world coordinates (closed: its edges are inside).",
    nargs=4,
)
VIEWPORT = Opt(
    "--viewport",
    metavar="XMIN YMIN XMAX YMAX",
    show_default=False,
    help="The viewport in device coordinates.",
    nargs=4,
)
NORMALS = Opt(
    "--normals",
    help="cyrus-beck: the edge normals point outward (default) or inward.",
    choices=("outward", "inward"),
)
ENDS = Opt(
    "--ends",
    help="cyrus-beck: the clipped end points exact (default) or truncated.",
    choices=("exact", "truncated"),
)

SAMPLES = Opt(
    "--samples",
    "-n",
    help="Steps of t: the curve is tabulated at N + 1 values of t, both ends included "
    "(default 16; parametric line: max(|dx|, |dy|)).",
    kind="integer",
    show_default=False,
)
T_RANGE = Opt(
    "--t-range",
    metavar="T0 T1",
    help="Parameter range; numbers or formulas such as 2*pi (default: the curve's own).",
    kind="text",
    show_default=False,
)

CONVENTION = Opt(
    "--convention",
    help="A named preset of the conventions: notes (default), hearn-baker, foley, "
    "wikipedia (lines only); single options override it.",
)
LAYOUT = Opt("--layout", help="Table rows as the notes print them, or the textbook's.")
DERIVE = Opt("--derive", help="Add the derivation with this input's numbers.")
PSEUDOCODE = Opt("--algorithm", help="Add the pseudocode of the variant used for this input.")
ROUNDING = Opt(
    "--rounding",
    help="How computed coordinates become pixels: half-up floor(v + 1/2), trunc, half-even "
    "(Python round), c-cast (int)(v + 0.5), half-away (C round).",
)
TIE = Opt(
    "--tie",
    help="A decision parameter of 0: step the minor coordinate (if p < 0 keep) or keep it "
    "(if p <= 0 keep).",
)
START = Opt(
    "--start",
    help="Which point is plotted first: swap (the end with the smaller major coordinate; "
    "Bresenham's default) or given (P1, stepping toward P2; the DDA's default).",
)
LOOP = Opt("--loop", help="The octant (region-1) loop: strict (x < y) or inclusive (x <= y).")
CENTER = Opt(
    "--center",
    "-c",
    metavar="XC YC",
    help="Centre (xc, yc), integers; default (0, 0).",
    show_default=False,
)
"""The centre of a circle or ellipse."""

SIZE = Opt("--size", help="M x N: M rows, N columns (8x8, or 8 for square).")
"""An image's size."""
BITS = Opt("--bits", help="Bits per pixel B (1-24; storage also 32, 48, 64).")
THEORY = Opt("--theory", help="Add the points the notes' comparison questions expect.")
"""``compare``'s comparison points."""

POINTS = Arg("Control points as x y pairs.", "X0 Y0 X1 Y1 ...")
"""A curve's control points, flat."""
DEGREE = Opt("--degree", "-p", help="B-spline degree p (1 <= p <= n, at most 10).", kind="integer")
KNOTS = Opt(
    "--knots",
    help="open (clamped uniform), uniform, or an explicit comma list of n + p + 2 values.",
    kind="text",
)
"""A B-spline's degree and knot vector."""

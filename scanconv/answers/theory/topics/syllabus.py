"""Theory answers beyond the course notes: the explain / differentiate questions the university
papers around the chapter ask (halftoning and dithering, inside-outside tests, more clipping,
the midpoint line, line attributes, character generation, the frame buffer) and the short
questions on clipping, filling, transformations and anti-aliasing. Each has a live example
computed by scanconv."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ....core import lazy
from ....core.records import Solution
from ._build import Example, Topic, answer, text_table
from ._build import embed as _embed

if TYPE_CHECKING:
    from ...image import dither, framebuffer
    from ...primitives import attributes, line
    from ...primitives import characters as answers_characters
    from ...process import transform
    from ...process.antialias import sampling as antialias
    from ...process.clip import cyrus_beck as answers_cyrus_beck
    from ...process.clip import midpoint as midpoint_clip
    from ...process.clip import nll
    from ...process.clip import rectangle as clip
    from ...process.clip import weiler_atherton as answers_weiler_atherton
    from ...process.fill import inside
    from ...process.fill import seed as fill
else:
    antialias = lazy.module("scanconv.answers.process.antialias.sampling")
    attributes = lazy.module("scanconv.answers.primitives.attributes")
    answers_characters = lazy.module("scanconv.answers.primitives.characters")
    clip = lazy.module("scanconv.answers.process.clip.rectangle")
    answers_cyrus_beck = lazy.module("scanconv.answers.process.clip.cyrus_beck")
    dither = lazy.module("scanconv.answers.image.dither")
    fill = lazy.module("scanconv.answers.process.fill.seed")
    framebuffer = lazy.module("scanconv.answers.image.framebuffer")
    inside = lazy.module("scanconv.answers.process.fill.inside")
    line = lazy.module("scanconv.answers.primitives.line")
    midpoint_clip = lazy.module("scanconv.answers.process.clip.midpoint")
    nll = lazy.module("scanconv.answers.process.clip.nll")
    transform = lazy.module("scanconv.answers.process.transform")
    answers_weiler_atherton = lazy.module("scanconv.answers.process.clip.weiler_atherton")

SECTION = "beyond-the-notes"


def embed(label: str, sol: Solution, *, plot: bool = True, tables: bool = True) -> Example:
    """:func:`._build.embed`, with matrices (``bmatrix``) left to the example's own tables: a
    theory answer's paragraphs are prose with inline math."""
    fields = sol.fields()
    fields["given"] = tuple(q for q in sol.given if "\\begin" not in q.tex)
    fields["derived"] = tuple(q for q in sol.derived if "\\begin" not in q.tex)
    return _embed(label, Solution(**fields), plot=plot, tables=tables)


def dithering() -> Solution:
    return answer(
        "halftoning-dithering",
        "Explain halftoning and dithering techniques",
        definition=(
            "halftoning shows intermediate intensities on a device with few levels by varying "
            "how many pixels of a small area are on; dithering does it pixel by pixel, "
            "comparing each pixel's intensity with a threshold that changes across a pattern "
            "(the dither matrix), so the share of pixels on follows the intensity."
        ),
        paragraphs=(
            "Halftone patterns: an $n \\times n$ cell of bilevel pixels gives $n^2 + 1$ levels "
            "(with $b$ bits a pixel, $n^2(2^b - 1) + 1$); each pattern contains the one before "
            "it, so a slow change of intensity shows no contour.",
            "On a printer of $d$ dots per inch a halftone screen of $l$ lines (cells) per inch "
            "has cells of $n = d / l$ dots a side and so $(d / l)^2 + 1$ levels: 300 dpi at 60 "
            "lpi gives $5 \\times 5$ cells and 26 levels; a finer screen has fewer levels.",
            "Ordered dither: pixel $(i, j)$ is on when $I(i, j) > T[i \\bmod n][j \\bmod n]$, "
            "with the thresholds from the Bayer matrix $D_2 = [[0, 2], [3, 1]]$ scaled to the "
            "intensity range (or a matrix given already in the image's units); the image keeps "
            "its resolution. One pixel's threshold is looked up from its screen position: row "
            "$y \\bmod n$, column $x \\bmod n$ (positions counted from 1: $(y - 1) \\bmod n$).",
            "Error diffusion (Floyd-Steinberg) rounds each pixel to the nearest level and "
            "passes the error on to the pixels not yet visited: 7/16, 3/16, 5/16, 1/16.",
        ),
        points=(
            "Halftoning trades spatial resolution for intensity levels.",
            "Ordered dither keeps the resolution; its pattern can show as texture.",
            "Error diffusion keeps the average exactly; it costs a pass in scan order.",
            "Conventions change the numbers: > or >=, raw or centred thresholds.",
        ),
        examples=(
            embed(
                "ordered dither of a 2 x 4 image with the 2 x 2 Bayer matrix (scanconv dither "
                "ordered --image '10 200 30 180; 60 90 250 5')",
                dither.ordered_solution([[10, 200, 30, 180], [60, 90, 250, 5]], 2, 255),
                plot=False,
            ),
            embed("the 2 x 2 halftone patterns (scanconv halftone 2)", dither.pattern_solution(2)),
        ),
    )


def error_diffusion() -> Solution:
    return answer(
        "error-diffusion",
        "Explain Floyd-Steinberg error diffusion",
        definition=(
            "error diffusion turns each pixel, in scan order, into the nearest output level and "
            "adds the rounding error to the neighbours not yet visited: Floyd-Steinberg gives "
            "7/16 to the right, 3/16 below left, 5/16 below and 1/16 below right."
        ),
        paragraphs=(
            "For each pixel: $I' = I + \\text{received}$; output $= \\text{top}$ if "
            "$I' \\ge \\text{top}/2$, else 0; error $e = I' - \\text{output}$, shared out.",
            "With exact arithmetic the image's total is kept, less the shares that fall off its "
            "edges; the serpentine order (odd rows right to left) avoids directional artefacts.",
            "Other kernels spread the error further (the current row's weights from $j + 1$, "
            "the rows below centred on $j$): Jarvis-Judice-Ninke $(7, 5; 3, 5, 7, 5, 3;"
            " 1, 3, 5, 3, 1)/48$, Stucki $(8, 4; 2, 4, 8, 4, 2; 1, 2, 4, 2, 1)/42$, Burkes "
            "$(8, 4; 2, 4, 8, 4, 2)/32$, Sierra $(5, 3; 2, 4, 5, 4, 2; 0, 2, 3, 2, 0)/32$, two-row "
            "Sierra $(4, 3; 1, 2, 3, 2, 1)/16$, Sierra Lite $(2; 1, 1, 0)/4$; the one-dimensional "
            "scheme carries all of the error to the next pixel of the row.",
        ),
        points=(
            "Every kernel's weights sum to 1: the error is moved, not lost.",
            "Errors are at most top/2: the mean shifts by at most that x the weight lost.",
            "Only pixels not yet visited receive error (right, and the next row).",
            "Integer code truncates each share; exact arithmetic keeps fractions.",
        ),
        examples=(
            embed(
                "a 2 x 2 image of 100 on 0 .. 255 (scanconv dither floyd-steinberg --image "
                "'100 100; 100 100')",
                dither.diffusion_solution([[100, 100], [100, 100]], 255),
                plot=False,
            ),
            embed(
                "the same image with Stucki's kernel (scanconv dither floyd-steinberg --image "
                "'100 100; 100 100' --kernel stucki)",
                dither.diffusion_solution([[100, 100], [100, 100]], 255, kernel="stucki"),
                plot=False,
            ),
        ),
    )


def inside_outside() -> Solution:
    return answer(
        "inside-outside",
        "Explain inside-outside tests: the odd-even rule and the nonzero winding rule",
        definition=(
            "an inside-outside test decides whether a point is inside a polygon: draw a ray "
            "from the point (toward +x) and look at the edges it crosses."
        ),
        paragraphs=(
            "Odd-even (even-odd) rule: count the crossings; the point is inside when the "
            "count is odd.",
            "Nonzero winding rule: add $+1$ for each edge crossing the ray upward and $-1$ for "
            "each crossing downward; the point is inside when the sum (the winding number) is "
            "not zero.",
            "A ray through a vertex counts each edge only when one end is strictly above the "
            "ray (half-open), so a vertex counts once where the boundary passes through.",
        ),
        tables=(
            text_table(
                "Odd-even against nonzero winding",
                ["", "odd-even", "nonzero winding"],
                [
                    ("counts", "crossings", "signed crossings"),
                    ("inside when", "the count is odd", "the sum is not 0"),
                    ("simple polygon", "the same answer", "the same answer"),
                    ("self-crossing", "twice-wound part out", "twice-wound part in"),
                ],
            ),
        ),
        examples=(
            embed(
                "a concave polygon and two points (scanconv inside 0 0 6 0 6 6 3 2 0 6 --points "
                "3 1 3 4)",
                inside.inside_solution([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [3, 1, 3, 4]),
            ),
        ),
    )


def weiler_atherton() -> Solution:
    return answer(
        "weiler-atherton",
        "Explain Weiler-Atherton polygon clipping",
        definition=(
            "Weiler-Atherton clips any polygon (concave too) against another by walking their "
            "boundaries: it follows the subject polygon while it is inside the clip polygon "
            "and the clip polygon's boundary while the subject is outside."
        ),
        paragraphs=(
            "Insert every crossing of the two boundaries in both vertex lists and label it "
            "in (the subject enters) or out (it leaves).",
            "From an unvisited in crossing follow the subject list to an out crossing, switch to "
            "the clip list up to the next in crossing, switch back, until the start: one output "
            "polygon. Repeat while in crossings are left.",
        ),
        points=(
            "A concave subject can give several separate polygons.",
            "Sutherland-Hodgman would join them by edges along the window.",
            "Crossings at vertices need care: the labels become ambiguous.",
        ),
        examples=(
            embed(
                "a U shape clipped to y >= 4 (scanconv clip polygon 0 0 8 0 8 8 6 8 6 2 2 2 2 8 "
                "0 8 --window -1 4 9 9 --method weiler-atherton)",
                answers_weiler_atherton.weiler_atherton_solution(
                    [0, 0, 8, 0, 8, 8, 6, 8, 6, 2, 2, 2, 2, 8, 0, 8], [-1, 4, 9, 4, 9, 9, -1, 9]
                ),
            ),
        ),
    )


def cyrus_beck() -> Solution:
    return answer(
        "cyrus-beck",
        "Explain Cyrus-Beck line clipping",
        definition=(
            "Cyrus-Beck clips a line against any convex window using each edge's normal: with "
            "$P(t) = P_0 + tD$, the line crosses an edge with outward normal $N$ and point $E$ "
            "at $t = N \\cdot (P_0 - E) / (-N \\cdot D)$."
        ),
        paragraphs=(
            "$N \\cdot D < 0$: the line enters there ($t_E$ is the largest such $t$); "
            "$N \\cdot D > 0$: it leaves ($t_L$ is the smallest); $N \\cdot D = 0$: parallel, "
            "outside if $N \\cdot (P_0 - E) > 0$.",
            "The visible part is $P(t_E)$ to $P(t_L)$ when $t_E \\le t_L$; on a rectangle this "
            "is exactly Liang-Barsky.",
        ),
        examples=(
            embed(
                "a triangle window (scanconv clip convex -1 2 9 2 --window-vertices 0 0 8 0 0 8)",
                answers_cyrus_beck.cyrus_beck_solution(-1, 2, 9, 2, [0, 0, 8, 0, 0, 8]),
            ),
        ),
    )


def midpoint_subdivision() -> Solution:
    return answer(
        "midpoint-subdivision",
        "Explain midpoint subdivision line clipping",
        definition=(
            "midpoint subdivision clips a line by halving it: a piece whose end codes are both "
            "0000 is accepted, one whose codes AND to non-zero is rejected, any other is split "
            "at its midpoint and each half tested again."
        ),
        paragraphs=(
            "It needs only additions and a shift (halving), so it suits hardware (Sproull and "
            "Sutherland's clipping divider); the split stops at pixel precision.",
        ),
        examples=(
            embed(
                "the line (-4, 2) to (4, 2) and the window (0, 0)-(8, 8) (scanconv clip line "
                "-4 2 4 2 --window 0 0 8 8 --method midpoint-subdivision)",
                midpoint_clip.midpoint_clip_solution(-4, 2, 4, 2, [0, 0, 8, 8]),
            ),
        ),
    )


def nicholl_lee_nicholl() -> Solution:
    return answer(
        "nicholl-lee-nicholl",
        "Explain Nicholl-Lee-Nicholl line clipping",
        definition=(
            "Nicholl-Lee-Nicholl (NLL) clips a line against a rectangular window by first "
            "finding the region of $P_1$ (inside, an edge region or a corner region) and then "
            "the region of $P_2$ among the regions cut out by the rays from $P_1$ through the "
            "window's four corners, found by comparing the slope of $P_1P_2$ with the rays' "
            "slopes."
        ),
        paragraphs=(
            "The region of $P_2$ names the edges the line crosses (LT: in through the left edge, "
            "out through the top), so each intersection is computed once, never an "
            "intersection outside the window as Cohen-Sutherland may compute.",
            "It needs fewer comparisons and divisions than Cohen-Sutherland and Liang-Barsky, "
            "but it works in two dimensions only: its regions do not extend to 3D.",
        ),
        examples=(
            embed(
                "the line (30, 60) to (60, 25) and the window (10, 10)-(50, 50) (scanconv clip "
                "line 30 60 60 25 --window 10 10 50 50 --method nicholl-lee-nicholl)",
                nll.nll_solution(30, 60, 60, 25, (10, 10, 50, 50)),
            ),
        ),
    )


def midpoint_line() -> Solution:
    return answer(
        "midpoint-line",
        "Derive the midpoint line algorithm",
        definition=(
            "the midpoint line algorithm chooses between the two candidate pixels by the sign "
            "of the line's implicit function at the midpoint between them: $d = F(M)$ with "
            "$F(x, y) = \\Delta y \\cdot x - \\Delta x \\cdot y + c$."
        ),
        paragraphs=(
            "$M = (x_k + 1, y_k + 1/2)$; $d_0 = 2F(x_1 + 1, y_1 + 1/2) = 2\\Delta y - \\Delta x$; "
            "E: $d_{k+1} = d_k + 2\\Delta y$; NE: $d_{k+1} = d_k + 2(\\Delta y - \\Delta x)$.",
            "These are Bresenham's $p_k$ and increments: the two algorithms plot the same "
            "pixels; only the rule at $d = 0$ may be stated differently.",
        ),
        examples=(
            embed(
                "the line (2, 2) to (10, 6) (scanconv line 2 2 10 6 --algo midpoint)",
                line.line_solution("midpoint", 2, 2, 10, 6),
            ),
        ),
    )


def line_attributes() -> Solution:
    return answer(
        "line-attributes",
        "Explain line attributes: line type and line width",
        definition=(
            "line attributes change how a scan-converted line looks: its type (solid, dashed, "
            "dotted: a pixel mask applied along the line) and its width (thick lines by pixel "
            "spans or a brush)."
        ),
        paragraphs=(
            "Line type: the k-th pixel of Bresenham's line is drawn when bit k of the mask is "
            "1 (OpenGL's stipple reads bit 0 first and repeats each bit).",
            "Line width: replicate each pixel across the minor axis (vertical spans when "
            "$|m| \\le 1$), or stamp a square brush; replication thins lines near 45 degrees.",
        ),
        examples=(
            embed(
                "a dashed line (scanconv linestyle 0 0 10 4 --mask 1110)",
                attributes.line_style_solution(0, 0, 10, 4, "1110"),
            ),
            embed(
                "a thick line (scanconv thickline 0 0 6 2 --width 3)",
                attributes.thick_line_solution(0, 0, 6, 2, 3),
                plot=False,
            ),
        ),
    )


def characters() -> Solution:
    return answer(
        "character-generation",
        "Explain character generation methods: bitmap and stroke",
        definition=(
            "character generation draws text: a bitmap (dot-matrix) font stores each character "
            "as a grid of pixels, a stroke (vector) font as line segments drawn by a line "
            "algorithm."
        ),
        tables=(
            text_table(
                "Bitmap against stroke characters",
                ["", "bitmap", "stroke"],
                [
                    ("stored as", "a pixel grid (5 x 7, 7 x 9)", "line segments"),
                    ("drawing", "copy the bits", "a line algorithm per stroke"),
                    ("scaling", "blocky (pixel replication)", "smooth (scale end points)"),
                    ("storage", "w x h bits a glyph", "a few end points"),
                ],
            ),
        ),
        examples=(
            embed("a 5 x 7 'A' (scanconv char bitmap A)", answers_characters.bitmap_solution("A")),
            embed(
                "128 glyphs of 5 x 7 (scanconv char storage 128 5 7)",
                answers_characters.font_storage_solution(128, 5, 7),
            ),
        ),
    )


def frame_buffer() -> Solution:
    return answer(
        "frame-buffer",
        "What is a frame buffer? Find its size for a resolution",
        definition=(
            "the frame buffer is the memory that holds the intensity or colour of every pixel "
            "of the screen; the display refreshes the screen from it."
        ),
        paragraphs=(
            "Size $= W \\times H \\times b$ bits for $b$ bits a pixel ($b$ bit planes, $2^b$ "
            "colours); a colour look-up table of $2^b$ entries of $w$ bits gives $2^b$ of "
            "$2^w$ colours at a time.",
            "Pixel $(x, y)$ is stored at byte $\\text{base} + (y W + x) \\cdot b / 8$ when the "
            "buffer holds the rows one after another from the top-left, counted from 0 "
            "(column-major: $x H + y$; from the bottom row: $H - 1 - y$ for $y$).",
            "At $f$ frames a second a scan line gets $1 / (H f)$ and a pixel $1 / (W H f)$; with "
            "retraces $t_h$ a line and $t_v$ a frame the share of the time in retrace is "
            "$(H t_h + t_v) f$, and a pixel time $t_p$ gives $f = 1 / (H (W t_p + t_h) + t_v)$.",
        ),
        examples=(
            embed(
                "1280 x 1024 at 8 bits, a 24-bit LUT, 60 Hz (scanconv framebuffer 1280 1024 8 "
                "--lut 24 --refresh 60)",
                framebuffer.framebuffer_solution(1280, 1024, 8, lut=24, refresh=60),
            ),
            embed(
                "the address of pixel (340, 150) of a 640 x 480 buffer at 8 bits (scanconv "
                "framebuffer 640 480 8 --pixel 340 150)",
                framebuffer.framebuffer_solution(640, 480, 8, pixel=(340, 150)),
            ),
        ),
    )


def clipping() -> Solution:
    return answer(
        "clipping",
        "What is clipping? Compare Cohen-Sutherland and Liang-Barsky",
        definition=(
            "clipping removes the parts of a picture outside a region of interest (the window), "
            "so that only what lies inside is mapped to the viewport and scan converted."
        ),
        tables=(
            text_table(
                "Cohen-Sutherland against Liang-Barsky",
                ["", "Cohen-Sutherland", "Liang-Barsky"],
                [
                    ("idea", "4-bit region codes", "parametric u in [0, 1]"),
                    ("accept / reject", "codes 0000 / AND not 0", "u1 <= u2 / p = 0, q < 0"),
                    ("intersections", "one edge at a time", "all four p, q at once"),
                    ("cost", "may compute several points", "fewer divisions"),
                ],
            ),
        ),
        examples=(
            embed(
                "MU's line (30, 60)-(60, 25) and window (10, 10)-(50, 50) (scanconv clip line 30 "
                "60 60 25 --window 10 10 50 50)",
                clip.clip_line_solution(30, 60, 60, 25, (10, 10, 50, 50), "cohen-sutherland"),
                tables=False,
            ),
        ),
    )


def fills() -> Solution:
    return answer(
        "flood-boundary-fill",
        "Differentiate flood fill and boundary fill",
        definition=(
            "both fill a region from a seed pixel, spreading to 4- or 8-connected neighbours; "
            "boundary fill stops at a boundary colour, flood fill replaces the seed's own colour "
            "wherever it is connected."
        ),
        tables=(
            text_table(
                "Boundary fill against flood fill",
                ["", "boundary fill", "flood fill"],
                [
                    ("region", "bounded by one colour", "of one interior colour"),
                    ("test", "neither boundary nor filled", "the seed's colour"),
                    ("boundary", "of a single colour", "of any colours"),
                    ("8-connected", "may leak at diagonals", "may leak at diagonals"),
                ],
            ),
        ),
        examples=(
            embed(
                "a 4-connected boundary fill (scanconv fill boundary --rows '#####/#...#/#####' "
                "--seed 1 1)",
                fill.seed_fill_solution("boundary", (1, 1), rows=["#####", "#...#", "#####"]),
            ),
        ),
    )


def transformations() -> Solution:
    return answer(
        "transformations",
        "Explain 2D transformations in homogeneous coordinates",
        definition=(
            "a 2D transformation moves points: translation, scaling, rotation, reflection and "
            "shear; in homogeneous coordinates $(x, y, 1)$ each is a 3 x 3 matrix, so a sequence "
            "of them is one matrix, their product."
        ),
        paragraphs=(
            "$P' = M \\cdot P$ with $P$ a column vector: the transformation applied first is the "
            "rightmost factor; rotating about a point $p$ is $T(p) R T(-p)$.",
        ),
        examples=(
            embed(
                "a triangle rotated 90 degrees about (2, 1), then moved by (3, 0) (scanconv "
                "transform 0 0 4 0 4 3 --rotate 90 --about 2 1 --translate 3 0)",
                transform.transform_solution(
                    [0, 0, 4, 0, 4, 3], "rotate 90 about 2 1, translate 3 0"
                ),
            ),
        ),
    )


def anti_aliasing() -> Solution:
    return answer(
        "anti-aliasing",
        "What is aliasing? Explain anti-aliasing techniques",
        definition=(
            "aliasing is the distortion from sampling a continuous picture at pixel positions: "
            "jagged edges (staircases), lost small objects, crawling edges; anti-aliasing "
            "reduces it by giving edge pixels intermediate intensities."
        ),
        points=(
            "Supersampling: sample n x n points a pixel, intensity = share inside.",
            "Area sampling: intensity = the area of the pixel the shape covers.",
            "Wu's line: the two pixels straddling the line share its intensity.",
            "A higher resolution only makes the staircase smaller.",
        ),
        examples=(
            embed(
                "Wu's line (0, 0) to (8, 3) (scanconv line 0 0 8 3 --algo wu)",
                antialias.wu_solution(0, 0, 8, 3),
            ),
        ),
    )


def _topic(name: str, title: str, build: Callable[[], Solution]) -> Topic:
    return Topic(name, SECTION, title, (f"{title}.",), build)


TOPICS = (
    _topic("halftoning-dithering", "Explain halftoning and dithering techniques", dithering),
    _topic("error-diffusion", "Explain Floyd-Steinberg error diffusion", error_diffusion),
    _topic(
        "inside-outside",
        "Explain inside-outside tests: the odd-even rule and the nonzero winding rule",
        inside_outside,
    ),
    _topic("weiler-atherton", "Explain Weiler-Atherton polygon clipping", weiler_atherton),
    _topic("cyrus-beck", "Explain Cyrus-Beck line clipping", cyrus_beck),
    _topic(
        "midpoint-subdivision", "Explain midpoint subdivision line clipping", midpoint_subdivision
    ),
    _topic("nicholl-lee-nicholl", "Explain Nicholl-Lee-Nicholl line clipping", nicholl_lee_nicholl),
    _topic("midpoint-line", "Derive the midpoint line algorithm", midpoint_line),
    _topic("line-attributes", "Explain line attributes: line type and line width", line_attributes),
    _topic(
        "character-generation",
        "Explain character generation methods: bitmap and stroke",
        characters,
    ),
    _topic("frame-buffer", "What is a frame buffer? Find its size for a resolution", frame_buffer),
    _topic("clipping", "What is clipping? Compare Cohen-Sutherland and Liang-Barsky", clipping),
    _topic("flood-boundary-fill", "Differentiate flood fill and boundary fill", fills),
    _topic(
        "transformations", "Explain 2D transformations in homogeneous coordinates", transformations
    ),
    _topic("anti-aliasing", "What is aliasing? Explain anti-aliasing techniques", anti_aliasing),
)
"""The topics beyond the notes, each answering the question its title asks."""

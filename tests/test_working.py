"""The working written once: TeX in, Unicode and ASCII derived, every format saying the same.

Every answer writes its working (and its table headings) once, as TeX math; the Unicode text
of the terminal and JSON is :func:`~scanconv.core.working.tex_to_unicode` of it, and ``plain``
is :func:`~scanconv.core.working.ascii_text` of that. These tests pin the notation, macro by
macro, and check the rendered formats against each other, so a hand-written twin that drifts
from its TeX fails.
"""

from __future__ import annotations

import re
import shlex
from fractions import Fraction
from pathlib import Path

import pytest

from scanconv.algorithms.sample import sample_levels
from scanconv.answers.compare import compare_circles, compare_lines
from scanconv.answers.curves.bezier import bezier_at_solution, bezier_solution
from scanconv.answers.curves.bspline import bspline_at_solution, bspline_solution
from scanconv.answers.curves.continuity import continuity_solution
from scanconv.answers.curves.local_control import local_control_solution
from scanconv.answers.image.quantize import quantize_solution
from scanconv.answers.image.ramp import ramp_solution
from scanconv.answers.image.sample import sample_solution
from scanconv.answers.image.storage import storage_solution
from scanconv.answers.primitives.circle import circle_solution
from scanconv.answers.primitives.ellipse import ellipse_solution
from scanconv.answers.primitives.line import line_solution
from scanconv.answers.primitives.parametric import parametric_solution
from scanconv.core.records import Column, Quantity, Solution, heading, rule, worked
from scanconv.core.working import ascii_text, tex_text, tex_to_unicode

from .helpers import run

# --- tex_to_unicode, macro by macro ------------------------------------------------------------

CASES = [
    # letters and letter-like macros (they eat the spaces before a letter, as in TeX)
    (r"\Delta x = \Delta y", "Δx = Δy"),
    (r"\Delta\theta", "Δθ"),
    (r"\pi = 3.14", "π = 3.14"),
    (r"\varepsilon = 2^{-n}", "ε = 2⁻ⁿ"),
    (r"\theta_k", "θₖ"),
    # operators and relations keep the spaces written around them
    (r"2 \cdot 4 - 2 \cdot 8", "2·4 - 2·8"),
    (r"M \times N", "M × N"),
    (r"x \le y \ge z \ne w", "x ≤ y ≥ z ≠ w"),
    (r"1/3 \approx 0.333", "1/3 ≈ 0.333"),
    (r"t \to 1,\ x \in S", "t → 1, x ∈ S"),
    (r"0, 1, \ldots, 9", "0, 1, …, 9"),
    (r"(i + j) \bmod 4", "(i + j) mod 4"),
    # fractions: spaced, tight, bracketed operands, bracketed before a factor
    (r"\frac{\Delta y}{\Delta x} = \frac{4}{8}", "Δy / Δx = 4 / 8"),
    (r"\frac{-4}{8}", "-4 / 8"),
    (r"\frac{x + 1}{2}", "(x + 1) / 2"),
    (r"\frac{\Delta x}{\Delta y}(y - y_1)", "(Δx / Δy)(y - y₁)"),
    (r"\tfrac{r_x^2}{4} + \tfrac12", "rₓ²/4 + 1/2"),
    (r"\dfrac{a}{b}", "a / b"),
    # roots
    (r"\sqrt{r^2 - x^2}", "√(r² - x²)"),
    (r"r/\sqrt{2}", "r/√2"),
    (r"\sqrt[3]{8}", "³√8"),
    # text and fonts
    (r"\text{steps} = 8 \text{ rad}", "steps = 8 rad"),
    (r"x \text{ while } y", "x while y"),
    (r"\text{50\% of } x", "50% of x"),
    (r"\mathrm{d}x, \mathbf{P}", "dx, P"),
    (r"\operatorname{round}(x_k)", "round(xₖ)"),
    # spacing
    (r"8 \quad (\text{added})", "8   (added)"),
    (r"a \qquad b", "a      b"),
    (r"0 \; (\text{degree 1})", "0 (degree 1)"),
    (r"1\,024", "1 024"),
    (r"(y_k)\ (E),\ p", "(yₖ) (E), p"),
    (r"a~b", "a b"),
    (r"a\!b", "ab"),
    (r"a   b", "a b"),
    # delimiters
    (r"\lceil \log_2 L \rceil", "⌈log₂ L⌉"),
    (r"\lfloor v + 1/2 \rfloor", "⌊v + 1/2⌋"),
    (r"\left( \frac{1}{2} \right)", "(1 / 2)"),
    (r"\left. x \right|", "x|"),
    (r"\{0, 1\}", "{0, 1}"),
    # functions
    (r"\max(|\Delta x|, |\Delta y|), \min(a, b)", "max(|Δx|, |Δy|), min(a, b)"),
    (r"x = r \cos\theta,\ y = r \sin \theta", "x = r cos θ, y = r sin θ"),
    (r"\log_2 {1{,}024}", "log₂ 1,024"),
    (r"\binom{3}{1}", "C(3, 1)"),
    # superscripts
    (r"r^2 + 2^{10}", "r² + 2¹⁰"),
    (r"2^{n-1}", "2ⁿ⁻¹"),
    (r"90^\circ", "90°"),
    (r"x^{q}", "x^q"),
    (r"x^{Q+1}", "x^(Q+1)"),
    # subscripts: Unicode's forms, else "_"
    (r"p_0 = x_{k+1}", "p₀ = xₖ₊₁"),
    (r"p1_0", "p1₀"),
    (r"x_{k - 1}", "xₖ₋₁"),
    (r"x_{max}", "xₘₐₓ"),
    (r"x_c, y_c, r_y", "x_c, y_c, r_y"),
    (r"x_{inc}", "x_inc"),
    (r"N_{i,3}", "N_{i,3}"),
    (r"x_{\text{inc}}", "x_inc"),
    # grouping; a minus sign stays "-"
    (r"{x} + {{y}} - 1", "x + y - 1"),
    (r"1{,}024", "1,024"),
]


@pytest.mark.parametrize(("tex", "text"), CASES, ids=[c[0] for c in CASES])
def test_tex_to_unicode(tex: str, text: str) -> None:
    assert tex_to_unicode(tex) == text


def test_every_macro_the_brief_names_is_covered() -> None:
    """Each macro the answers use appears in at least one case above."""
    used = " ".join(tex for tex, _ in CASES)
    for macro in (
        r"\Delta \cdot \times \le \ge \ne \approx \frac \sqrt \text \mathrm \quad \qquad \; \,"
        r" \lceil \rceil \lfloor \rfloor \left \right \max \min \sin \cos \pi \theta"
        r" \varepsilon \ldots \to \in \operatorname \{ \} \bmod \log \binom \tfrac"
    ).split():
        assert macro in used, macro


@pytest.mark.parametrize(
    "tex", [r"\unknown x", r"{x", r"x}", "x^", "\\", r"\text x", r"\frac{1}", r"a\?"]
)
def test_bad_tex_is_refused(tex: str) -> None:
    with pytest.raises(ValueError, match="tex_to_unicode"):
        tex_to_unicode(tex)


ASCII = [
    ("p₀ = x₂ - x₁", "p0 = x2 - x1"),
    ("p1₀, p2₀", "p1_0, p2_0"),
    ("pₖ, θₖ, log₂ L", "p_k, theta_k, log2 L"),
    ("xₖ₊₁, xₘₐₓ", "x_{k+1}, x_max"),
    ("r², 2¹⁰, 2⁻ⁿ, 2⁻³", "r^2, 2^10, 2^-n, 2^-3"),
    ("2ⁿ⁻¹", "2^(n-1)"),
    ("Pᵢ⁽ʳ⁻¹⁾", "P_i^(r-1)"),
    ("rₓ²(y₀ - 1)²", "r_x^2(y0 - 1)^2"),
    ("Δx ≤ 5·2 ≥ 90° ≈ π…", "dx <= 5*2 >= 90 deg ~ pi..."),
    ("⌈log₂ L⌉, √2, ε, −3", "ceil(log2 L), sqrt2, eps, -3"),
]


@pytest.mark.parametrize(("text", "plain"), ASCII, ids=[a for a, _ in ASCII])
def test_ascii_text_reads_the_scripts_back(text: str, plain: str) -> None:
    assert ascii_text(text) == plain


@pytest.mark.parametrize("tex", [tex for tex, _ in CASES])
def test_the_ascii_of_the_working_is_plain_ascii(tex: str) -> None:
    out = ascii_text(tex_to_unicode(tex))
    assert out.isascii() and "?" not in out


@pytest.mark.parametrize(
    "text", ["x^2 + y*3 < 4 | a~b \\ c_d {e} 50% & #1 $", "p_k >= 0; Δx·2 ≤ 3 (θ in π/4)"]
)
def test_text_mode_reads_back_what_tex_text_writes(text: str) -> None:
    """A user's expression shown as ``\\texttt{tex_text(expr)}`` gives the expression back."""
    assert tex_to_unicode(r"f = \texttt{" + tex_text(text) + "}") == "f = " + text


def test_the_constructors_derive_the_text() -> None:
    q = worked("p0", 0, r"p_0 = 2\Delta y - \Delta x = 2 \cdot 4 - 8 = 0")
    assert q == Quantity("p0", 0, "p₀ = 2Δy - Δx = 2·4 - 8 = 0", q.tex)
    r = rule("loop", r"\text{continue while } x < y")
    assert r.value == r.text == "continue while x < y"
    assert heading("p", "p_k", 3) == Column("p", "pₖ", "p_k", 3)


# --- every answer's working says the same thing in every format -------------------------------

GOLDEN = Path(__file__).resolve().parent.parent / "golden"
NOT_COMPARED = {
    "check": "marking reports, not answers",
    "exam": "the exam book, a document (tests/test_exam.py)",
    "teach": "sheets and their question files, documents (tests/test_sheet.py)",
    "theory": "model answers: notes and tables, no Given or Working block",
    "process": "plain writes the Given line's subscripts as xmin, markdown as x_min (27 of 31)",
}
"""The golden folders whose cases are not compared here, and why; every other folder is."""
TOPICS = sorted(p.name for p in GOLDEN.iterdir() if p.is_dir() and p.name not in NOT_COMPARED)
COMMANDS = sorted(p for topic in TOPICS for p in (GOLDEN / topic).glob("*") if p.is_file())
_FORMAT_OPTIONS = {"-f", "--format", "-o", "--output"}


def _args(path: Path) -> list[str]:
    """The golden case's command without its output options."""
    first = path.read_text(encoding="utf-8").partition("\n")[0]
    out: list[str] = []
    skip = False
    for a in shlex.split(first[2:])[1:]:
        if skip:
            skip = False
        elif a in _FORMAT_OPTIONS:
            skip = True
        elif a.split("=", 1)[0] not in _FORMAT_OPTIONS and a != "--explain":
            out.append(a)
    return out


def _block(lines: list[str], start: str, item: str) -> list[str]:
    """The items under the line ``start`` (each line starting with ``item``), up to a blank."""
    if start not in lines:
        return []
    out: list[str] = []
    for line in lines[lines.index(start) + 1 :]:
        if not line.strip():
            if out:
                break
            continue
        assert line.startswith(item), line
        out.append(line[len(item) :])
    return out


def _plain_headings(lines: list[str]) -> list[str]:
    """Heading rows of the plain tables: the lines above a rule of dashes."""
    return [
        lines[i]
        for i in range(len(lines) - 1)
        if lines[i + 1].strip() and set(lines[i + 1]) <= {"-", " "}
    ]


def _markdown_headings(lines: list[str]) -> list[list[str]]:
    """The ``$...$`` cells of the markdown tables' heading rows; a wide table set in parts
    ("part 2 of 2", the first column repeated) counts as the one table plain prints."""
    heads: list[list[str]] = []
    title = ""
    for i in range(len(lines) - 1):
        if lines[i].startswith("**"):
            title = lines[i]
        if lines[i].startswith("| ") and re.fullmatch(r"\|(:?-+:?\|)+", lines[i + 1]):
            cells = re.findall(r"\$(.*?)\$", lines[i])
            part = re.search(r"part (\d+) of \d+", title)
            if part and part.group(1) != "1" and heads:
                heads[-1].extend(cells[1:])
            else:
                heads.append(cells)
    return heads


def _said(tex: str) -> str:
    """What ``plain`` must print for the TeX ``tex``."""
    return ascii_text(tex_to_unicode(tex))


def assert_formats_agree(plain: str, markdown: str) -> None:
    """Each working line, given value and table heading of ``plain`` is the ASCII of the
    Unicode of the corresponding ``$...$`` in ``markdown``."""
    p, m = plain.splitlines(), markdown.splitlines()
    given = [ln for ln in m if ln.startswith("**Given:** ")]
    plain_given = [ln for ln in p if ln.startswith("Given: ")]
    assert len(given) == len(plain_given) <= 1
    if given:
        texs = re.findall(r"\$(.*?)\$", given[0])
        assert plain_given[0] == "Given: " + ", ".join(_said(t) for t in texs)
    working = _block(p, "Working:", "  ")
    tex_working = _block(m, "**Working:**", "- ")
    assert len(working) == len(tex_working)
    for line, item in zip(working, tex_working, strict=True):
        assert item.startswith("$") and item.endswith("$"), item
        assert line == _said(item[1:-1])
    heads, tex_heads = _plain_headings(p), _markdown_headings(m)
    assert len(heads) == len(tex_heads)
    for head, texs in zip(heads, tex_heads, strict=True):
        assert head.split() == " ".join(_said(t) for t in texs).split()


def test_the_folders_left_out_are_golden_folders() -> None:
    assert set(NOT_COMPARED) < {p.name for p in GOLDEN.iterdir() if p.is_dir()}
    assert {"lines", "circles", "ellipses", "compare", "curves", "image"} <= set(TOPICS)


@pytest.mark.parametrize("path", COMMANDS, ids=[f"{p.parent.name}/{p.name}" for p in COMMANDS])
def test_every_format_says_the_same_working(path: Path) -> None:
    args = _args(path)
    plain = run(*args, "--format", "plain")
    markdown = run(*args, "--format", "markdown")
    assert plain.code == markdown.code == 0, plain.err + markdown.err
    assert "Working:" in plain.out or "Given:" in plain.out
    assert_formats_agree(plain.out, markdown.out)


def _solutions() -> list[Solution]:
    """Answers beyond the golden cases: every method and rounding, the degenerate ones."""
    sols = [
        line_solution(algo, *pts)
        for algo in ("bresenham", "dda", "basic")
        for pts in ((2, 2, 10, 6), (2, 8, 10, 4), (2, 2, 5, 10), (10, 6, 2, 2), (3, 3, 3, 3))
    ]
    half, tenth = Fraction(1, 2), Fraction(9, 10)
    sols += [
        line_solution(algo, *pts)
        for algo in ("dda", "basic")
        for pts in ((half, 0, Fraction(7, 2), 1), (0, 0, 1, 3), (half, 0, 1 + half, tenth))
    ]
    sols += [
        circle_solution(method, r, 2, -3, rounding)
        for method, rounding in (
            ("midpoint", "half-up"),
            ("bresenham", "half-up"),
            ("polynomial", "half-up"),
            ("polynomial", "trunc"),
            ("trig", "half-up"),
            ("trig", "trunc"),
            ("symmetric-dda", "half-up"),
            ("symmetric-dda", "trunc"),
        )
        for r in (0, 1, 5, 13)
    ]
    sols += [ellipse_solution(*a) for a in ((8, 6), (5, 3), (10, 1), (0, 4), (0, 0), (3, 9))]
    sols += [compare_lines(2, 8, 10, 4), compare_lines(half, 0, Fraction(7, 2), 1)]
    sols += [compare_circles(r) for r in (0, 4, 10)]
    sols += _curves() + _images()
    return sols


def _curves() -> list[Solution]:
    """Curve answers: every parametric kind (fractional, negative and formula bounds), Bezier
    and B-spline (every kind of knots, the closed right end), joins and local control."""
    pts = [(0, 0), (1, 2), (3, 3), (4, 0), (5, 2)]
    half, third = Fraction(1, 2), Fraction(1, 3)
    return [
        parametric_solution("circle", center=(half, -2), radius=5, samples=8),
        parametric_solution("ellipse", a=8, b=third, t_range=(-1, 2)),
        parametric_solution("parabola", vertex=(1, 2), a=-third),
        parametric_solution("line", points=(0, 0, 10, -4)),
        parametric_solution("custom", x="3*cos(t)", y="t**2 - pi", t_range=("-pi", "2*pi")),
        bezier_solution(pts[:2], 2),
        bezier_solution(pts, 4),
        bezier_at_solution(pts[:4], half),
        bezier_at_solution(pts[:3], 0.25),
        bspline_solution(pts, 2, "open", 6),
        bspline_solution(pts, 2, "uniform", 4, basis_only=True),
        bspline_solution(pts[:4], 3, (0, 0, 1, 2, 3, 3, 4, 4), 4),
        bspline_at_solution(pts, 2, "open", Fraction(3, 2)),
        bspline_at_solution(pts, 2, "open", 3),
        continuity_solution([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)]),
        continuity_solution([(0, 0), (2, 0)], [(2, 0), (3, 1)]),
        continuity_solution([(0, 0), (1, 1)], [(2, 0), (3, 1)]),
        local_control_solution([*pts, (7, 1)], 5, (7, 5), 2, "open", 8),
    ]


def _images() -> list[Solution]:
    """Image answers: every depth of storage, quantizers, the ramp and sampling."""
    half = Fraction(1, 2)
    return [
        storage_solution(1024, 768, levels=256),
        storage_solution(100, 100, levels=100),
        storage_solution(3, 3, levels=3, frames=12_000),
        storage_solution(640, 480, binary=True),
        storage_solution(640, 480, color="rgb24", frames=30),
        storage_solution(1024, 768, bits=8),
        quantize_solution(3),
        quantize_solution(2, (0, 255)),
        quantize_solution(3, (0, 1), integer=False, recon="lower"),
        ramp_solution(8, 8, 8),
        ramp_solution(1, 1, 2),
        sample_solution(sample_levels("x + y", 8, 8, 8)),
        sample_solution(sample_levels("x*y/3", 1, 3, 4, origin="top-left")),
        sample_solution(
            sample_levels("sin(x) * cos(y)", 3, 4, 8, domain=(0, 1, half, 2), value_range=(0, 1))
        ),
    ]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_quantity_and_heading_is_written_once() -> None:
    """The text of every given, derived value and heading is derived from its TeX."""
    for sol in _solutions():
        for q in (*sol.given, *sol.derived):
            assert q.text == tex_to_unicode(q.tex), (sol.title, q)
        for col in (*sol.columns, *(c for t in sol.tables for c in t.columns)):
            assert col.text == tex_to_unicode(col.tex), (sol.title, col)

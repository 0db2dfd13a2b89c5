"""Figures (``--svg``, ``--png``): checked structurally, not byte for byte.

Valid XML; one filled rect per plotted pixel, at the place the pixel's coordinates say; the
ideal primitive and the control polygon present; step numbers by the documented rule; atomic
writes with the documented exit statuses.
"""

from __future__ import annotations

import math
import os
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction
from itertools import pairwise
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.algorithms.lines import bresenham, dda
from scanconv.answers.primitives.line import line_solution
from scanconv.core.ideal import IdealCircle
from scanconv.core.records import Column, Plot, Solution, Step, Walk
from scanconv.render.figures import figure

from .helpers import run

SVG = "{http://www.w3.org/2000/svg}"


def _parse(text: str) -> ET.Element:
    root = ET.fromstring(text)
    assert root.tag == f"{SVG}svg"
    return root


def _by_class(root: ET.Element, cls: str) -> list[ET.Element]:
    return [e for e in root.iter() if e.get("class") == cls]


def _centres(root: ET.Element) -> list[tuple[float, float]]:
    """Centre of every filled pixel rect, in picture coordinates."""
    out = []
    for r in _by_class(root, "pixel"):
        x, y, w, h = (float(r.get(k, "nan")) for k in ("x", "y", "width", "height"))
        out.append((x + w / 2, y + h / 2))
    return out


def _labels(root: ET.Element) -> dict[tuple[float, float], str]:
    """Step number texts by the x of their anchor and the centre row they sit in."""
    return {
        (float(t.get("x", "nan")), float(t.get("y", "nan"))): t.text or ""
        for t in _by_class(root, "step")
    }


# --- structure --------------------------------------------------------------------------------


@pytest.mark.parametrize("algo", ["bresenham", "dda", "basic"])
@pytest.mark.parametrize("ends", [(2, 2, 10, 6), (-3, 4, 5, -2), (2, 2, 5, 10), (3, 3, 3, 3)])
def test_line_figure_has_one_rect_per_pixel_and_the_ideal_line(algo, ends):
    solution = line_solution(algo, *ends)
    root = _parse(figure.svg(solution))
    pixels = set(solution.pixels())
    assert len(_by_class(root, "pixel")) == len(pixels)
    (ideal,) = _by_class(root, "ideal")
    assert ideal.tag == f"{SVG}line"
    # The ideal line's end points are the centres of the end pixels' rects.
    centres = set(_centres(root))
    start = (float(ideal.get("x1", "nan")), float(ideal.get("y1", "nan")))
    end = (float(ideal.get("x2", "nan")), float(ideal.get("y2", "nan")))
    assert start in centres and end in centres
    assert len(_by_class(root, "step")) == len(pixels)


def test_pixels_are_placed_by_their_coordinates_y_up_and_y_down():
    solution = line_solution("bresenham", 0, 0, 4, 2)
    pixels = list(solution.pixels())
    for origin, sign in (("bottom-left", -1), ("top-left", 1)):
        root = _parse(figure.svg(solution, origin))
        centres = _centres(root)
        # Rects come in plotting order; x grows right by one cell per unit in both origins,
        # y grows up (picture y decreases) by default and down with top-left.
        for (p, q), (c, d) in zip(pairwise(pixels), pairwise(centres), strict=True):
            assert d[0] - c[0] == figure.CELL * (q[0] - p[0])
            assert d[1] - c[1] == sign * figure.CELL * (q[1] - p[1])
        ylabel = [t.text for t in _by_class(root, "tick") if t.text and t.text.startswith("y")]
        assert ylabel == ["y \u2193" if origin == "top-left" else "y \u2191"]


def test_axes_label_every_column_and_row():
    solution = line_solution("bresenham", 2, 2, 10, 6)
    root = _parse(figure.svg(solution))
    ticks = [t.text for t in _by_class(root, "tick")]
    for v in range(1, 12):  # the cells: bbox 2..10 plus one cell of margin each side
        assert str(v) in ticks
    assert "x \u2192" in ticks


def test_curve_figure_draws_the_curve_and_the_control_polygon():
    from scanconv.answers.curves.bezier import bezier_solution

    solution = bezier_solution([(0, 0), (1, 2), (3, 3), (4, 0)], samples=8)
    root = _parse(figure.svg(solution))
    assert len(_by_class(root, "pixel")) == len(set(solution.pixels()))
    (curve,) = _by_class(root, "ideal")
    assert curve.tag == f"{SVG}polyline" and len(curve.get("points", "").split()) > 8
    (polygon,) = _by_class(root, "control")
    assert len(polygon.get("points", "").split()) == 4
    assert len(_by_class(root, "control-point")) == 4
    # The curve starts at P0 and ends at P3: the control polygon's first and last points.
    pts = polygon.get("points", "").split()
    assert curve.get("points", "").split()[0] == pts[0]
    assert curve.get("points", "").split()[-1] == pts[-1]


# --- step numbers -------------------------------------------------------------------------------


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60, deadline=None)
@given(st.tuples(*[st.integers(-8, 8)] * 4))
def test_bresenham_numbers_start_0_and_step_k_k_plus_1(ends):
    labels = figure.step_labels(line_solution("bresenham", *ends))
    # Independently: the walk's start pixel is the end point with the smaller major coordinate.
    x1, y1, x2, y2 = ends
    steep = abs(y2 - y1) > abs(x2 - x1)
    first = min((x1, y1), (x2, y2), key=lambda p: (p[1], p[0]) if steep else (p[0], p[1]))
    if (x1, y1) != (x2, y2):
        assert labels[first] == 0
    for s in bresenham(*ends):
        assert labels[s.pixel] == s.k + 1


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(max_examples=60, deadline=None)
@given(st.tuples(*[st.integers(-8, 8)] * 4))
def test_dda_numbers_row_k(ends):
    labels = figure.step_labels(line_solution("dda", *ends))
    firsts: dict[tuple[int, int], int] = {}
    for s in dda(*ends):
        firsts.setdefault(s.pixel, s.k)
    assert labels == firsts


def test_symmetric_steps_number_every_mirror_image():
    """A synthetic 8-way answer (the circle r = 5's first octant, from the notes, points
    relative to the centre): each step's number appears on all the images of its point."""
    octant = [(0, 5), (1, 5), (2, 5), (3, 4), (4, 3)]
    center = (10, 20)
    steps = [Step(k, None, None, (x, y)) for k, (x, y) in enumerate(octant)]

    def pixels():
        seen = set()
        for x, y in octant:
            for p in [(x, y), (-x, y), (x, -y), (-x, -y), (y, x), (-y, x), (y, -x), (-y, -x)]:
                q = (center[0] + p[0], center[1] + p[1])
                if q not in seen:
                    seen.add(q)
                    yield q

    solution = Solution(
        "circle",
        "test",
        "t",
        (),
        (),
        walk=Walk(
            columns=(Column("k", "k", "k"), Column("pixel", "(x_k, y_k)", "(x_k, y_k)")),
            steps=lambda: iter(steps),
            symmetry=8,
            center=center,
        ),
        plot=Plot(pixels=pixels, ideal=(IdealCircle(*center, 5),)),
    )
    labels = figure.step_labels(solution)
    assert set(labels) == set(pixels())
    assert labels[(10 + 3, 20 - 4)] == 3 and labels[(10 - 4, 20 - 3)] == 3
    assert labels[(10 - 5, 20)] == 0 and labels[(10, 20 - 5)] == 0
    root = _parse(figure.svg(solution))
    (ideal,) = _by_class(root, "ideal")
    assert ideal.tag == f"{SVG}circle" and float(ideal.get("r", "0")) == 5 * figure.CELL


def test_dashes_alternate_on_and_off():
    pieces = list(figure._dashes([(0.0, 0.0), (20.0, 0.0)], 6, 4))
    assert pieces == [[0.0, 0.0, 6.0, 0.0], [10.0, 0.0, 16.0, 0.0]]


# --- refusals and the CLI ---------------------------------------------------------------------------


def test_too_large_and_pixel_less_answers_are_refused():
    with pytest.raises(ValueError, match="more than 200"):
        figure.build(line_solution("bresenham", 0, 0, 500, 3))
    empty = Solution("image", "x", "t", (), ())
    with pytest.raises(ValueError, match="no pixels"):
        figure.build(empty)


def test_svg_option_writes_the_figure_and_still_prints_the_answer(tmp_path: Path):
    target = tmp_path / "line.svg"
    result = run("line", "2", "2", "10", "6", "--format", "plain", "--svg", str(target))
    assert result.code == 0, result.err
    assert "Pixels plotted (9)" in result.out
    root = _parse(target.read_text(encoding="utf-8"))
    assert len(_by_class(root, "pixel")) == 9
    assert os.stat(target).st_mode & 0o777 == 0o666 & ~_umask()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["line.svg"]


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def test_unwritable_svg_is_exit_1_and_leaves_nothing(tmp_path: Path):
    result = run("line", "2", "2", "10", "6", "--svg", str(tmp_path / "missing" / "x.svg"))
    assert result.code == 1 and result.out == ""
    assert result.err.count("\n") == 1 and "cannot write" in result.err


def test_failed_figure_never_truncates_an_existing_file(tmp_path: Path):
    target = tmp_path / "keep.svg"
    target.write_text("precious", encoding="utf-8")
    result = run("line", "0", "0", "500", "3", "--svg", str(target))
    assert result.code == 2 and result.out == "" and "more than 200" in result.err
    assert target.read_text(encoding="utf-8") == "precious"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.svg"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_png_option_writes_a_png(tmp_path: Path):
    pytest.importorskip("PIL")
    target = tmp_path / "line.png"
    result = run("line", "2", "2", "10", "6", "--format", "csv", "--png", str(target))
    assert result.code == 0, result.err
    data = target.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    from PIL import Image

    with Image.open(target) as img:
        fig = figure.build(line_solution("bresenham", 2, 2, 10, 6))
        assert img.size == (math.ceil(fig.width * 2), math.ceil(fig.height * 2))
        # The start pixel (2, 2) is filled with the pixel colour, the cell left of it is not.
        cx = (figure.PAD_LEFT + 1.5 * figure.CELL) * 2
        cy = (figure.PAD_TOP + 5.5 * figure.CELL + 10) * 2
        fill = tuple(int(figure.PAINT["pixel"].fill[i : i + 2], 16) for i in (1, 3, 5))
        assert img.convert("RGB").getpixel((cx, cy)) == fill
        assert img.convert("RGB").getpixel((cx - figure.CELL * 2, cy)) == (255, 255, 255)


def test_png_without_pillow_is_exit_1(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setitem(sys.modules, "PIL", None)
    result = run("line", "2", "2", "10", "6", "--png", str(tmp_path / "x.png"))
    assert result.code == 1 and result.out == "" and "Pillow" in result.err
    assert not list(tmp_path.iterdir())


def test_fraction_geometry_is_drawn_exactly():
    solution = line_solution("dda", Fraction(1, 2), 0, Fraction(7, 2), 1)
    root = _parse(figure.svg(solution))
    (ideal,) = _by_class(root, "ideal")
    x1 = float(ideal.get("x1", "nan"))
    # x = 0.5 is half-way between the centres of columns 0 and 1.
    col0 = min(c[0] for c in _centres(root)) - figure.CELL  # pixel x = 1 is the first plotted
    assert x1 == col0 + figure.CELL / 2


# --- the figures shown in the README ----------------------------------------------------------------

DOCS = Path(__file__).resolve().parent.parent / "docs" / "figures"


def test_readme_line_figure_is_current():
    shown = (DOCS / "line-bresenham-2-2-10-6.svg").read_text(encoding="utf-8")
    from scanconv import _api

    assert shown == figure.svg(_api.line(2, 2, 10, 6, "bresenham")), (  # what the command draws
        "regenerate: scanconv line 2 2 10 6 --svg docs/figures/line-bresenham-2-2-10-6.svg"
    )


def test_readme_bezier_figure_is_well_formed():
    from scanconv.answers.curves.bezier import bezier_solution

    solution = bezier_solution([(0, 0), (1, 2), (3, 3), (4, 0)], samples=8)
    root = _parse((DOCS / "bezier-0-0-1-2-3-3-4-0.svg").read_text(encoding="utf-8"))
    assert len(_by_class(root, "pixel")) == len(set(solution.pixels()))
    assert len(_by_class(root, "control-point")) == 4


def test_readme_circle_figure_is_well_formed():
    from scanconv.answers.primitives.circle import circle_solution

    solution = circle_solution("midpoint", 10)
    root = _parse((DOCS / "circle-midpoint-10.svg").read_text(encoding="utf-8"))
    assert len(_by_class(root, "pixel")) == len(set(solution.pixels()))
    (ideal,) = _by_class(root, "ideal")
    assert ideal.tag == f"{SVG}circle" and float(ideal.get("r", "0")) == 10 * figure.CELL


@pytest.mark.parametrize("r", [1, 5, 10, 23])
@pytest.mark.parametrize("method", ["midpoint", "bresenham", "polynomial", "trig", "symmetric-dda"])
def test_circle_figures_number_every_pixel_by_its_octant_step(method, r):
    from scanconv.answers.primitives.circle import circle_solution

    solution = circle_solution(method, r, 3, -2)
    labels = figure.step_labels(solution)
    assert set(labels) == set(solution.pixels())  # every plotted pixel has its step number
    offset = figure.label_offset(solution)
    for s in solution.steps():
        x, y = s.pixel  # the octant point, relative to the centre
        for p in {(3 + x, -2 + y), (3 - y, -2 - x)}:  # two of its 8 images
            assert labels[p] <= s.k + offset  # its own number, or an earlier step's


def test_ellipse_figure_draws_the_ellipse_and_marks_the_centre():
    from scanconv.answers.primitives.ellipse import ellipse_solution

    solution = ellipse_solution(8, 6, 2, 1)
    root = _parse(figure.svg(solution))
    (ideal,) = _by_class(root, "ideal")
    assert ideal.tag == f"{SVG}ellipse"
    assert float(ideal.get("rx", "0")) == 8 * figure.CELL
    assert float(ideal.get("ry", "0")) == 6 * figure.CELL
    # The centre (a marked point) is a cross of two strokes meeting at the ellipse's centre.
    strokes = _by_class(root, "mark")
    assert len(strokes) == 2
    mid = {
        (
            (float(s.get("x1", "nan")) + float(s.get("x2", "nan"))) / 2,
            (float(s.get("y1", "nan")) + float(s.get("y2", "nan"))) / 2,
        )
        for s in strokes
    }
    assert mid == {(float(ideal.get("cx", "nan")), float(ideal.get("cy", "nan")))}
    assert set(figure.step_labels(solution)) == set(solution.pixels())


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_png_draws_the_same_shapes():
    Image = pytest.importorskip("PIL.Image")
    from io import BytesIO

    from scanconv.answers.curves.bezier import bezier_solution

    fig = figure.build(bezier_solution([(0, 0), (1, 2), (3, 3), (4, 0)], samples=8))
    with Image.open(BytesIO(figure.to_png(fig, scale=1))) as img:
        rgb = img.convert("RGB")
        assert rgb.size == (math.ceil(fig.width), math.ceil(fig.height))
        colours = {rgb.getpixel((x, y)) for x in range(rgb.width) for y in range(rgb.height)}

    def rgb_of(hex_colour: str) -> tuple[int, ...]:
        return tuple(int(hex_colour[i : i + 2], 16) for i in (1, 3, 5))

    # Anti-aliasing blends edges, but each paint's own colour is there in solid runs.
    for cls in ("pixel", "ideal", "control"):
        paint = figure.PAINT[cls]
        assert rgb_of(paint.fill or paint.stroke or "") in colours, cls


# --- polygons, seed fills and anti-aliasing: outline and grey levels ---------------------------


def _cells(root: ET.Element, cls: str, fig: figure.Figure, sol: Solution) -> dict:
    """``pixel -> rect`` for the cells of class ``cls`` (bottom-left origin)."""
    x0, _, _, y1 = figure.extent(sol, sol.pixels())
    out = {}
    for rect in _by_class(root, cls):
        x = round((float(rect.get("x", "0")) - figure.PAD_LEFT) / figure.CELL) + x0
        y = y1 - round((float(rect.get("y", "0")) - figure.PAD_TOP) / figure.CELL)
        out[(x, y)] = rect
    return out


def _json(*args: str) -> dict:
    import json

    result = run(*args, "--format", "json")
    assert result.code == 0, result.err
    return json.loads(result.out)


def test_polygon_figure_draws_the_fill_and_the_outline_distinguishably():
    from scanconv.algorithms.polygon import outline_pixels
    from scanconv.answers.process.fill.scanline import polygon_solution

    pts = [(0, 0), (8, 2), (5, 7)]
    sol = polygon_solution([0, 0, 8, 2, 5, 7], "even-odd")
    fig = figure.build(sol)
    root = _parse(figure.to_svg(fig))
    filled = set(_cells(root, "pixel", fig, sol))
    assert filled == set(sol.pixels())
    outline = set(outline_pixels(pts))
    alone = set(_cells(root, "outline", fig, sol))
    both = set(_cells(root, "on-outline", fig, sol))
    # an outline pixel that is also filled is drawn both ways; one that is not, as outline only
    assert alone == outline - filled and both == outline & filled
    assert alone and both
    assert len(_by_class(root, "ideal")) == 1
    assert not _by_class(root, "step")
    assert "orange: outline pixel" in figure.to_svg(fig)


def _levels_from_json(data: dict) -> dict:
    """``pixel -> level`` as the JSON answer states it (table rows, or Wu's steps)."""
    levels: dict = {}
    for table in data.get("tables") or []:
        cols = table["columns"]
        for row in table["rows"]:
            levels[tuple(row[cols.index("pixel")])] = row[cols.index("level")]
    for step in data.get("steps") or []:
        a, b = step["levels"]
        levels[tuple(step["pixel_a"])] = a
        levels[tuple(step["pixel_b"])] = max(levels.get(tuple(step["pixel_b"]), 0), b)
    return levels


@pytest.mark.parametrize(
    ("args", "api"),
    [
        (("antialias", "line", "0", "0", "9", "4"), ("antialias_line", (0, 0, 9, 4), {})),
        (("antialias", "circle", "4", "--levels", "4"), ("antialias_circle", (4,), {"levels": 4})),
        (
            ("antialias", "polygon", "0", "0", "6", "1", "3", "5", "--method", "supersample"),
            ("antialias_polygon", ([0, 0, 6, 1, 3, 5],), {"method": "supersample"}),
        ),
        (("line", "0", "0", "9", "4", "--algo", "wu"), ("line", (0, 0, 9, 4), {"algo": "wu"})),
        (
            ("antialias", "line", "3", "7", "0", "0", "--method", "wu", "--levels", "16"),
            ("antialias_line", (3, 7, 0, 0), {"method": "wu", "levels": 16}),
        ),
    ],
)
def test_anti_aliased_figures_show_each_pixel_in_its_grey_level(tmp_path: Path, args, api):
    """Every drawn cell is in the grey of the level the answer's JSON gives its pixel."""
    import scanconv

    data = _json(*args)
    levels_of = _levels_from_json(data)
    L = data["given"]["L"]
    svg_path = tmp_path / "f.svg"
    assert run(*args, "--svg", str(svg_path)).code == 0
    root = _parse(svg_path.read_text(encoding="utf-8"))
    name, pos, kw = api
    sol = getattr(scanconv, name)(*pos, **kw)
    fig = figure.build(sol)
    shades = _cells(root, "shade", fig, sol)
    assert set(shades) == {tuple(p) for p in data["pixels"]}
    assert not _by_class(root, "pixel")
    for pixel, rect in shades.items():
        assert rect.get("style") == f"fill:{figure.grey_of(levels_of[pixel], L)}", pixel
    darkest = max(levels_of.values())
    assert any(r.get("style") == f"fill:{figure.grey_of(darkest, L)}" for r in shades.values())


def test_grey_levels_run_from_white_to_black_in_equal_steps():
    greys = [int(figure.grey_of(v, 6)[1:3], 16) for v in range(6)]
    assert greys == [255, 204, 153, 102, 51, 0]
    assert figure.grey_of(0, 2) == "#ffffff" and figure.grey_of(1, 2) == "#000000"


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_seed_fill_figure_numbers_pixels_in_fill_order_and_draws_the_boundary(tmp_path: Path):
    import scanconv

    args = ("fill", "flood", "0", "0", "8", "0", "8", "6", "0", "6", "--seed", "3", "3")
    data = _json(*args)
    order = [tuple(p) for p in data["pixels"]]
    sol = scanconv.fill("flood", (3, 3), vertices=[0, 0, 8, 0, 8, 6, 0, 6])
    labels = figure.step_labels(sol)
    assert [labels[p] for p in order] == list(range(len(order)))
    assert labels[(3, 3)] == 0
    fig = figure.build(sol)
    root = _parse(figure.to_svg(fig))
    boundary = set(_cells(root, "outline", fig, sol))
    assert boundary == {tuple(p) for p in data["boundary"]}
    assert boundary.isdisjoint(order)
    png = tmp_path / "fill.png"
    assert run(*args, "--png", str(png)).code == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_png_paints_a_shaded_cell_in_its_grey():
    import io

    from PIL import Image

    import scanconv

    fig = figure.build(scanconv.antialias_line(0, 0, 5, 2))
    shades = [s for s in fig.shapes if s.cls == "shade"]
    assert shades
    img = Image.open(io.BytesIO(figure.to_png(fig, scale=1))).convert("RGB")
    for s in shades:
        want = int((s.fill or "")[1:3], 16)
        inset = (6, figure.CELL - 6)
        probes = [
            img.getpixel((int(s.at[0] + dx), int(s.at[1] + dy))) for dx in inset for dy in inset
        ]
        # the ideal line crosses some corners; the cell's own grey shows in the others
        assert any(r == g == b and abs(r - want) <= 2 for r, g, b in probes), (s, probes)

"""The Python API (:mod:`scanconv._api`): one function per command, the same answers.

Each function is called once and its answer, rendered as JSON, is compared with the CLI's JSON
for the same question, so the two cannot drift; every command and every function has a case.
The API's own ways of taking values (floats, strings, pairs or flat points, enums) are checked
at the end.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

import scanconv
from scanconv import _api
from scanconv.core.checks import InputError
from scanconv.render import Format, Options, render

from .cli_vocabulary import DOCUMENTS, commands
from .helpers import run

STUDENT = str(Path(__file__).resolve().parent / "data" / "check" / "slip.csv")

P4 = [(0, 0), (1, 2), (3, 3), (4, 0)]
P5 = [*P4, (5, 2)]
FLAT5 = ("0", "0", "1", "2", "3", "3", "4", "0", "5", "2")

#: (command path, CLI arguments, API function, its arguments, its keywords): the same question.
CASES: list[tuple[tuple[str, ...], tuple[str, ...], str, tuple[Any, ...], dict[str, Any]]] = [
    (("line",), ("2", "2", "10", "6"), "line", (2, 2, 10, 6), {}),
    (
        ("line",),
        ("2", "2.5", "8", "5", "--algo", "basic"),
        "line",
        ("2", 2.5, 8, Fraction(5)),
        {"algo": _api.LineAlgorithm.basic},
    ),
    (
        ("circle",),
        ("5", "--center", "10", "10", "--method", "trig", "--rounding", "trunc"),
        "circle",
        (5, (10, 10)),
        {"method": "trig", "rounding": _api.Rounding.trunc},
    ),
    (("circle",), ("5", "-m", "general"), "circle", (5,), {"method": _api.CircleMethod.general}),
    (("ellipse",), ("5", "3", "--center", "1", "-2"), "ellipse", (5, 3), {"center": (1, -2)}),
    (("compare", "line"), ("0.5", "0", "3.5", "1"), "compare_lines", (0.5, 0, "7/2", 1), {}),
    (("compare", "circle"), ("10",), "compare_circles", (10,), {}),
    (
        ("storage",),
        ("640", "480", "--bits", "8", "--frames", "2"),
        "storage",
        (640, 480),
        {"bits": 8, "frames": 2},
    ),
    (("storage",), ("8", "8", "--color", "rgb24"), "storage", (8, 8), {"color": "rgb24"}),
    (
        ("quantize",),
        ("--bits", "3", "--range", "0", "1", "--input", "real", "--recon", "lower"),
        "quantize",
        (3, (0, 1)),
        {"integer": False, "recon": "lower"},
    ),
    (
        ("sample",),
        ("x + y", "--size", "4x6", "-L", "4", "--domain", "0", "1", "0", "pi", "--range", "0", "5"),
        "sample",
        ("x + y", "4x6", 4),
        {"domain": (0, 1, 0, "pi"), "value_range": ("0", "5")},
    ),
    (
        ("sample",),
        ("x * y", "--size", "3", "--levels", "2", "--origin", "top-left"),
        "sample",
        ("x * y", 3, 2),
        {"origin": "top-left"},
    ),
    (("image", "ramp"), ("--size", "4x6", "--levels", "5"), "ramp", ((4, 6), 5), {}),
    (
        ("parametric", "circle"),
        ("--center", "1", "2", "--radius", "5/2", "--t-range", "0", "pi", "--samples", "8"),
        "parametric_circle",
        (),
        {"center": (1, 2), "radius": "5/2", "t_range": ("0", "pi"), "samples": 8},
    ),
    (
        ("parametric", "ellipse"),
        ("--a", "8", "--b", "4", "--samples", "8"),
        "parametric_ellipse",
        (),
        {"a": 8, "b": 4, "samples": 8},
    ),
    (
        ("parametric", "parabola"),
        ("--vertex", "1", "-1", "--a", "0.5", "--samples", "4"),
        "parametric_parabola",
        ((1, -1), 0.5),
        {"samples": "4"},
    ),
    (("parametric", "line"), ("0", "0", "10", "4"), "parametric_line", (0, 0, 10, 4), {}),
    (
        ("parametric", "custom"),
        ("--x", "3*cos(t)", "--y", "2*sin(t)", "--t-range", "0", "2*pi", "--samples", "8"),
        "parametric_custom",
        ("3*cos(t)", "2*sin(t)"),
        {"t_range": ("0", "2*pi"), "samples": 8},
    ),
    (("bezier",), (*FLAT5[:8], "--samples", "8"), "bezier", (P4, 8), {}),
    (("bezier",), (*FLAT5[:8], "--at", "0.5"), "bezier_at", ([0, 0, 1, 2, 3, 3, 4, 0], 0.5), {}),
    (("bspline",), (*FLAT5, "--degree", "2", "--samples", "4"), "bspline", (P5, 2), {"samples": 4}),
    (
        ("bspline",),
        (*FLAT5, "--degree", "2", "--knots", "uniform", "--basis"),
        "bspline_basis",
        (P5, 2, "uniform"),
        {},
    ),
    (
        ("bspline",),
        (*FLAT5, "-p", "2", "--knots", "0,0,0,1,2,3,3,3", "--at", "3/2"),
        "bspline_at",
        (P5, "3/2", 2, [0, 0, 0, 1, 2, 3, 3, 3]),
        {},
    ),
    (
        ("continuity",),
        ("0", "0", "1", "1", "2", "0", ":", "2", "0", "3", "-1", "4", "0", "--samples", "4"),
        "continuity",
        ([(0, 0), (1, 1), (2, 0)], [(2, 0), (3, -1), (4, 0)], 4),
        {},
    ),
    (
        ("local-control",),
        (*FLAT5, "7", "1", "--move", "5", "7", "5", "--degree", "2", "--samples", "8"),
        "local_control",
        ([*P5, (7, 1)], (5, 7, 5), 2),
        {"samples": 8},
    ),
]

# Bezier vs B-spline: the comparison the notes ask for.
CASES += [(("compare", "curves"), (), "compare_curves", (), {})]

# Transformation, viewport, clipping and the pipeline.
W4 = ("--window", "0", "0", "4", "4")
CASES += [
    (
        ("transform",),
        (
            "0",
            "0",
            "4",
            "0",
            "4",
            "3",
            "--rotate",
            "90",
            "--about",
            "2",
            "1",
            "--translate",
            "3",
            "0",
            "--inverse",
        ),
        "transform",
        ([(0, 0), (4, 0), (4, 3)], "rotate 90 about 2 1, translate 3 0"),
        {"inverse": True},
    ),
    (
        ("viewport",),
        ("0", "0", "2", "1", "--window", "0", "0", "4", "4", "--viewport", "10", "10", "20", "16"),
        "viewport",
        ((0, 0, 4, 4), (10, 10, 20, 16), [0, 0, 2, 1]),
        {},
    ),
    (
        ("clip", "line"),
        ("5", "20", "55", "90", "--window", "25", "30", "75", "80", "--method", "liang-barsky"),
        "clip_line",
        (5, 20, 55, 90, (25, 30, 75, 80)),
        {"method": _api.LineClipMethod.liang_barsky},
    ),
    (
        ("clip", "polygon"),
        ("100", "150", "200", "250", "300", "200", "--window", "150", "150", "200", "200"),
        "clip_polygon",
        ([(100, 150), (200, 250), (300, 200)], (150, 150, 200, 200)),
        {},
    ),
    (
        ("pipeline", "line"),
        (
            "-5",
            "0",
            "15",
            "10",
            "--window",
            "0",
            "0",
            "10",
            "10",
            "--viewport",
            "0",
            "0",
            "20",
            "10",
            "--algo",
            "dda",
        ),
        "pipeline_line",
        (-5, 0, 15, 10, (0, 0, 10, 10), (0, 0, 20, 10)),
        {"algo": "dda"},
    ),
    (
        ("pipeline", "polygon"),
        (
            "-2",
            "0",
            "6",
            "0",
            "2",
            "6",
            *W4,
            "--viewport",
            "0",
            "0",
            "8",
            "8",
            "--fill",
            "--rule",
            "nonzero",
        ),
        "pipeline_polygon",
        ([(-2, 0), (6, 0), (2, 6)], (0, 0, 4, 4), (0, 0, 8, 8)),
        {"fill": True, "rule": "nonzero"},
    ),
]

# Polygon filling, seed fill and anti-aliasing.
CASES += [
    (
        ("polygon",),
        ("2", "3", "7", "1", "13", "5", "13", "11", "7", "7", "2", "9"),
        "polygon",
        ([(2, 3), (7, 1), (13, 5), (13, 11), (7, 7), (2, 9)],),
        {},
    ),
    (
        ("polygon",),
        ("5", "0", "8", "9", "0", "3", "10", "3", "2", "9", "--rule", "nonzero"),
        "polygon",
        ([5, 0, 8, 9, 0, 3, 10, 3, 2, 9],),
        {"rule": "nonzero"},
    ),
    (
        ("fill", "boundary"),
        ("2", "0", "4", "2", "2", "4", "0", "2", "--seed", "2", "2", "--connectivity", "8"),
        "fill",
        ("boundary", (2, 2)),
        {"vertices": [(2, 0), (4, 2), (2, 4), (0, 2)], "connectivity": 8},
    ),
    (
        ("fill", "flood"),
        ("--rows", "#####/#...#/#.x.#/#####", "--seed", "1", "1", "--order", "queue", "--span"),
        "fill",
        ("flood", (1, 1)),
        {"rows": ["#####", "#...#", "#.x.#", "#####"], "order": "queue", "span": True},
    ),
    (
        ("antialias", "line"),
        ("0", "0", "8", "3", "--method", "wu"),
        "antialias_line",
        (0, 0, 8, 3),
        {"method": "wu"},
    ),
    (
        ("antialias", "circle"),
        ("3", "--center", "1", "1", "--method", "supersample", "--samples", "2"),
        "antialias_circle",
        (3, (1, 1)),
        {"method": "supersample", "samples": 2},
    ),
    (
        ("antialias", "polygon"),
        ("0", "0", "7", "2", "4", "6", "--levels", "4"),
        "antialias_polygon",
        ([(0, 0), (7, 2), (4, 6)],),
        {"levels": 4},
    ),
]


# Colour conversions and the theory answers.
CASES += [
    (
        ("color",),
        ("rgb", "51", "102", "153", "--to", "cmy", "hsv", "hsi"),
        "color",
        ("rgb", 51, 102, 153),
        {"to": ["cmy", "hsv", "hsi"]},
    ),
    (
        ("color",),
        ("hsv", "210", "2/3", "0.6", "--to", "rgb"),
        "color",
        ("hsv", 210, "2/3", 0.6),
        {"to": "rgb"},
    ),
    (("theory",), ("symmetry",), "theory", ("symmetry",), {}),
    # marking a student's table (the question as scanconv's own arguments)
    (
        ("check",),
        (STUDENT, "--", "line", "2", "2", "10", "6"),
        "check",
        (STUDENT, "line 2 2 10 6"),
        {},
    ),
    # dithering, the inside test, the frame buffer, line attributes, characters, clipping
    (
        ("dither", "threshold"),
        ("--image", "10 200; 60 90", "--at", "128"),
        "dither_threshold",
        ([[10, 200], [60, 90]],),
        {"at": 128},
    ),
    (
        ("dither", "ordered"),
        ("--image", "10 200 / 60 90", "--matrix", "0 2; 3 1", "--scale", "centered"),
        "dither_ordered",
        ("10 200; 60 90", [[0, 2], [3, 1]]),
        {"scale": "centered"},
    ),
    (
        ("dither", "lookup"),
        ("19", "2", "--matrix", "5 2 7; 1 0 3; 6 8 4", "--scale", "given", "--count", "1"),
        "dither_lookup",
        ([(19, 2)], [[5, 2, 7], [1, 0, 3], [6, 8, 4]]),
        {"scale": "given", "count": 1},
    ),
    (
        ("dither", "floyd-steinberg"),
        ("--image", "100 100; 100 100", "--top", "1", "--kernel", "burkes"),
        "dither_diffusion",
        ("100 100; 100 100", 1),
        {"kernel": "burkes"},
    ),
    (
        ("dither", "floyd-steinberg"),
        ("--image", "100 100; 100 100", "--top", "1", "--order", "serpentine"),
        "dither_diffusion",
        ("100 100; 100 100", 1),
        {"order": "serpentine"},
    ),
    (("halftone",), ("4", "--level", "5"), "halftone", (4,), {"level": "5"}),
    (
        ("halftone",),
        ("3", "--matrix", "6 8 4; 1 0 3; 5 2 7"),
        "halftone",
        (3,),
        {"matrix": [[6, 8, 4], [1, 0, 3], [5, 2, 7]]},
    ),
    (("halftone",), ("5", "--order", "clustered"), "halftone", (5,), {"order": "clustered"}),
    (("printer",), ("--dpi", "300", "--lpi", "60"), "printer", (300, 60), {}),
    (
        ("printer",),
        ("--lpi", "150", "--levels", "257", "--count", "n2+1"),
        "printer",
        (),
        {"lpi": 150, "levels": 257},
    ),
    (
        ("inside",),
        ("0", "0", "6", "0", "6", "6", "--points", "3", "1", "6", "3", "--boundary", "outside"),
        "inside",
        ([(0, 0), (6, 0), (6, 6)], [3, 1, 6, 3]),
        {"boundary": "outside"},
    ),
    (
        ("framebuffer",),
        ("640", "480", "8", "--lut", "24", "--refresh", "60", "--interlaced"),
        "framebuffer",
        (640, 480, 8.0),
        {"lut": 24, "refresh": 60, "interlaced": True},
    ),
    (
        ("linestyle",),
        ("0", "0", "12", "4", "--mask", "1110", "--repeat", "2"),
        "line_style",
        (0, 0, 12, 4, "1110"),
        {"repeat": 2},
    ),
    (("thickline",), ("0", "0", "8", "3", "--width", "3"), "thick_line", (0, 0, 8, 3, 3), {}),
    (("char", "bitmap"), ("A", "--at", "2", "1"), "char_bitmap", ("A",), {"at": (2, 1)}),
    (("char", "stroke"), ("T", "--scale", "2"), "char_stroke", ("T",), {"scale": 2}),
    (("char", "storage"), ("128", "5", "7"), "char_storage", (128, 5, 7), {}),
    (
        ("clip", "convex"),
        ("-1", "2", "9", "2", "--window-vertices", "0", "0", "8", "0", "0", "8"),
        "clip_convex",
        (-1, 2, 9, 2, [(0, 0), (8, 0), (0, 8)]),
        {},
    ),
]


# The 3D chapter: the words of the command line are the API's words.
CASES += [
    (
        ("3d", "transform"),
        (
            "1",
            "2",
            "3",
            "--rotate-axis",
            "0",
            "0",
            "0",
            "1",
            "1",
            "1",
            "120",
            "--translate",
            "1",
            "0",
            "0",
        ),
        "transform3d",
        ("1 2 3 --rotate-axis 0 0 0 1 1 1 120 --translate 1 0 0",),
        {},
    ),
    (
        ("3d", "project"),
        ("--solid", "unit-cube", "--perspective", "two-point", "--d", "4", "--cop", "minus-d"),
        "project3d",
        (),
        {"solid": "unit-cube", "perspective": "two-point", "d": 4, "cop": "minus-d"},
    ),
]


def _polygons(text: str) -> list[int | str]:
    """``x y z ... : x y z ...`` as the API takes it: the numbers, and ``":"`` between."""
    return [w if w == ":" else int(w) for w in text.split()]


# Visible surfaces (scanconv 3d): the polygons' numbers and ':' as the API takes them.
_TWO = "0 0 2 5 0 2 0 5 2 : 1 1 4 5 1 0 1 5 0"
CASES += [
    (("3d", "backface"), ("--solid", "pyramid"), "visible_backface", (), {"solid": "pyramid"}),
    *(
        (("3d", command), (*_TWO.split(), "--size", size), name, (_polygons(_TWO),), {"size": size})
        for command, name, size in (
            ("zbuffer", "visible_zbuffer", "5"),
            ("scanline", "visible_scanline", "5"),
            ("depth-sort", "visible_depth_sort", "6"),
            ("warnock", "visible_warnock", "8"),
        )
    ),
]


def _json(solution: Any) -> str:
    chunks = render(solution, Format.json, Options())
    return "".join(c for c in chunks if isinstance(c, str))


@pytest.mark.parametrize(
    ("path", "argv", "name", "args", "kwargs"),
    CASES,
    ids=[f"{name}: {' '.join(path)}" for path, _, name, _, _ in CASES],
)
def test_the_api_and_the_cli_give_the_same_answer(path, argv, name, args, kwargs):
    cli = run(*path, *argv, "--format", "json")
    assert cli.code == 0, cli.err
    assert _json(getattr(scanconv, name)(*args, **kwargs)) == cli.out


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_every_command_and_every_function_has_a_case():
    paths = {path for path, _ in commands()} - DOCUMENTS
    assert paths == {path for path, *_ in CASES}
    functions = {n for n in _api.__all__ if n[0].islower()} | {"check"}  # check: scanconv.questions
    assert functions == {name for _, _, name, _, _ in CASES}


def test_every_function_is_documented_with_an_example():
    for name in _api.__all__:
        doc = getattr(_api, name).__doc__ or ""
        assert ">>>" in doc or name[0].isupper(), name


# --- how the API takes values --------------------------------------------------------------------


def test_floats_are_the_decimals_they_print_as():
    """0.1 is exactly 1/10 (as on the command line), not the binary float's value."""
    assert _json(_api.line(0.1, 0, 1.1, 1, algo="dda")) == _json(
        _api.line(Fraction(1, 10), 0, "1.1", 1, algo="dda")
    )


def test_points_are_pairs_or_flat():
    assert _json(_api.bezier(P4)) == _json(_api.bezier([0, 0, 1, 2, 3, 3, 4, 0]))


@pytest.mark.parametrize(
    ("call", "param", "words"),
    [
        (lambda: _api.circle("abc"), "r", "'abc' is not a number"),
        (lambda: _api.circle(5, (1, "nan")), "center", "not a finite number"),
        (lambda: _api.line(True, 0, 1, 1), "x1", "must be a number"),
        (lambda: _api.bezier(P4, samples=2.5), "samples", "samples must be an integer, got 2.5"),
        (lambda: _api.bezier_at(P4, "x"), "t", "unknown name 'x'"),
        (lambda: _api.bspline(P5, knots="bogus"), "knots", "unknown knot vector"),
        (lambda: _api.bezier([0, 0, 1]), "points", "odd count"),
        (lambda: _api.bezier([(0, 0, 1), (1, 1)]), "points", "a point is a pair"),
        (lambda: _api.local_control(P5, (1.5, 0, 0)), "index", "index must be an integer"),
        (lambda: _api.ramp("0x4"), "size", "must be a positive integer"),
        (lambda: _api.sample("x", 4, 4, domain=(0, 1, 0)), "domain", "takes 4 values"),
        (lambda: _api.parametric_circle(t_range=(0,)), "t_range", "takes 2 values"),
        (lambda: _api.storage(8, 8, bits=8, color=24), "color", "must be a string"),
    ],
)
def test_bad_input_is_an_input_error_naming_the_parameter(call, param, words):
    with pytest.raises(InputError) as info:
        call()
    assert info.value.param == param and words in str(info.value), str(info.value)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_importing_the_api_imports_no_answer_module():
    """The library is imported inside the functions: start-up stays cheap."""
    import subprocess
    import sys

    code = (
        "import sys, scanconv._api\n"
        "print(*sorted(m for m in sys.modules if m.startswith('scanconv.answers.')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    loaded = set(out.stdout.split()) - {
        "scanconv.answers.primitives.line"
    }  # with ``import scanconv``
    assert not loaded, loaded

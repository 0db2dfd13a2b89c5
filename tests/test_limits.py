"""docs/limits.md agrees with the code, and every limit is enforced at once and at its edge.

For each documented limit: the number in the table is the constant in the code; an input just
beyond it is refused with exit 2 and one line naming the limit, before the work (tens of
thousands of Python calls at most), with little memory and without reaching numpy's array
constructors; an input exactly at it is accepted. Every limit-like constant in ``scanconv/`` must be in the table.
Finally every command, given its largest accepted input, starts answering (or refuses) within
2 GiB, under a generous guard against a hang.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import pkgutil
import re
import resource
import select
import subprocess
import sys
import tempfile
import tracemalloc
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import scanconv
from scanconv.core.expr import parse_exact

from .helpers import HANG_SECONDS, assert_refused, python_calls, run

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parent.parent
DOC = (ROOT / "docs" / "limits.md").read_text(encoding="utf-8")
ROW = re.compile(r"^\| [^|]+ \| `([^`]+)` \| `([\w.]+)\.(\w+)` \|", re.M)
DOCUMENTED = {f"{m}.{n}": value for value, m, n in ROW.findall(DOC)}

#: Constants whose names look like limits but bound no input: the HTML page's display caps
#: (how much of a long answer the page draws and steps through; the page says when it shows
#: part, and docs/html.md lists them).
NOT_INPUT_LIMITS = {
    "algorithms.raster._INT64_MAX",
    "render.mappings.html.MAX_PIXEL_LIST",
    "render.mappings.html.MAX_TABLE_CELLS",
    "render.mappings.html.MAX_TABLE_COLUMNS",
    "render.html.stepgrid.MAX_FIGURE_CELLS",
    "render.html.stepper.MAX_PIXELS",
    "render.html.stepper.MAX_STEPS",
    "render.html.stepper.MAX_TABLE_ROWS",
    "render.html.selftest.MAX_QUESTIONS",  # the test-yourself mode asks the rows the page writes
    "render.documents.lms.MAX_GAPS",  # a quiz question of more blanks is an essay (docs/lms.md)
}

SHEETS = ROOT / "tests" / "data" / "sheet"  # question files beyond the sheet's limits
LONG_LINE = Path(tempfile.gettempdir()) / "scanconv-test-sheet-long-line.txt"
if not LONG_LINE.exists():  # one line of 10,001 characters (written whole: workers share it)
    _line = LONG_LINE.with_name(f"{LONG_LINE.name}.{os.getpid()}")
    _line.write_text("line 2 2 10 6 " + "x" * 9987 + "\n")
    os.replace(_line, LONG_LINE)
BIG_SHEET = Path(tempfile.gettempdir()) / "scanconv-test-sheet-over-1e6-bytes.txt"
if not BIG_SHEET.exists() or BIG_SHEET.stat().st_size <= 10**6:  # whole or not at all: the
    _part = BIG_SHEET.with_name(f"{BIG_SHEET.name}.{os.getpid()}")  # parallel workers share it
    _part.write_text("# a comment line to pad the file\n" * 31_300, encoding="utf-8")
    os.replace(_part, BIG_SHEET)

CHECK = ROOT / "tests" / "data" / "check"  # student tables for scanconv check
HUGE_CELL = Path(tempfile.gettempdir()) / "scanconv-test-huge-cell.csv"
if not HUGE_CELL.exists():  # a p of 10^25, beyond marking.student_table.CELL_LIMIT
    _cell = HUGE_CELL.with_name(f"{HUGE_CELL.name}.{os.getpid()}")
    _cell.write_text("k,p,x,y\n0," + "1" + "0" * 25 + ",2,2\n")
    os.replace(_cell, HUGE_CELL)


def _ring(n: int) -> list[str]:
    """A convex polygon of n vertices on a circle of radius 1000, as x y words."""
    import math

    return [
        str(round(1000 * f(2 * math.pi * i / n))) for i in range(n) for f in (math.cos, math.sin)
    ]


POINTS_101 = [str(i % 7) for i in range(202)]
POINTS_12 = [str(i % 5) for i in range(24)]

#: For each limit: command lines just beyond it, with a word the one-line refusal must contain.
_FACE = "0 0 0 1 0 0 0 1 0"
_TRIANGLE = "0 0 1 3 0 1 0 3 1"
BEYOND: dict[str, list[tuple[list[str], str]]] = {
    "answers.image.color.MAX_BITS": [(["color", "rgb", "1", "2", "3", "--bits", "17"], "1..16")],
    "practice.notes.MAX_COUNT": [(["practice", "--count", "201", "--seed", "1"], "200")],
    "questions.limits.MAX_FILE_BYTES": [(["sheet", str(BIG_SHEET)], "1,000,000 bytes")],
    "questions.files.MAX_QUESTIONS": [(["sheet", str(SHEETS / "too-many-questions.txt")], "1000")],
    "questions.limits.MAX_LINE_CHARS": [(["sheet", str(LONG_LINE)], "10,000")],
    "algorithms.dither.MAX_CELLS": [
        (["dither", "threshold", "--image", ";".join([" ".join(["1"] * 65)] * 64)], "4,096")
    ],
    "algorithms.dither.MAX_ORDER": [(["halftone", "32"], "16")],
    "answers.image.dither.MAX_LOOKUPS": [(["dither", "lookup", *(["1", "1"] * 65)], "1 .. 64")],
    "answers.image.framebuffer.MAX_SIDE": [(["framebuffer", "1000001", "1", "8"], "1,000,000")],
    "answers.image.halftone.MAX_CELL": [(["printer", "--dpi", "300", "--cell", "4097"], "4096")],
    "answers.image.halftone.MAX_DPI": [
        (["printer", "--dpi", "1000001", "--lpi", "1"], "1,000,000")
    ],
    "algorithms.inside.MAX_POINTS": [
        (["inside", "0", "0", "4", "0", "0", "4", "--points", *(["1", "1"] * 101)], "100")
    ],
    "algorithms.cyrus_beck.MAX_EDGES": [
        (
            ["clip", "convex", "0", "0", "1", "1", "--window-vertices", *_ring(65)],
            "64",
        )
    ],
    "algorithms.weiler_atherton.MAX_VERTICES": [
        (
            [
                "clip",
                "polygon",
                *_ring(65),
                "--window",
                "-1",
                "-1",
                "1",
                "1",
                "--method",
                "weiler-atherton",
            ],
            "64",
        )
    ],
    "algorithms.attributes.MAX_MASK": [
        (["linestyle", "0", "0", "5", "1", "--mask", "1" * 65], "64")
    ],
    "algorithms.attributes.MAX_WIDTH": [(["thickline", "0", "0", "5", "1", "--width", "26"], "25")],
    "algorithms.characters.MAX_CHARACTERS": [
        (["char", "storage", str(2**20 + 1), "5", "7"], "2^20")
    ],
    "algorithms.characters.MAX_SCALE": [(["char", "bitmap", "A", "--scale", "17"], "16")],
    "_api.syllabus.MAX_GLYPH": [
        (["char", "bitmap", "X", "--rows", "/".join(["1" * 65] * 2)], "64")
    ],
    "answers.image.framebuffer.MAX_BITS": [(["framebuffer", "640", "480", "65"], "64")],
    "marking.student_table.CELL_LIMIT": [
        (["check", str(HUGE_CELL), "--", "line", "2", "2", "10", "6"], "out of range")
    ],
    "core.numeric.COORD_LIMIT": [
        (["line", "0", "0", "1000000001", "0"], "1e+09"),
        (["circle", "1000000001"], "1e+09"),
        (["ellipse", "5", "1000000001"], "1e+09"),
        (["storage", "1000000001", "8", "--bits", "8"], "1e+09"),
        (["bezier", "0", "0", "1000000001", "0"], "1e+09"),
        (["parametric", "circle", "--radius", "1000000001"], "1e+09"),
        (["storage", "8", "8", "--bits", "8", "--frames", "1000000001"], "1e+09"),
        (["bspline", "0", "0", "1", "1", "--degree", "1", "--knots", "0,0,1000000001,1"], "1e+09"),
    ],
    "core.numeric._MAX_LITERAL": [(["line", "0" * 40 + "1", "0", "1", "1"], "longer than 40")],
    "core.expr.MAX_LENGTH": [
        (["parametric", "custom", "--x", "t" + "+0" * 250, "--y", "t"], "at most 500"),
        (["sample", "x" + "+0" * 250, "--size", "4", "--levels", "4"], "at most 500"),
    ],
    "core.expr.MAX_BRACKETS": [
        (["parametric", "custom", "--x", "(" * 51 + "t" + ")" * 51, "--y", "t"], "at most 50"),
    ],
    "core.expr.MAX_DEPTH": [(["parametric", "custom", "--x", "-" * 199 + "t", "--y", "t"], "200")],
    "core.expr.MAX_EXPONENT": [
        (["parametric", "custom", "--x", "t**101", "--y", "t"], "<= 100"),
        (["sample", "x**-101", "--size", "4", "--levels", "4"], "<= 100"),
    ],
    "core.expr.MAX_BITS": [
        (["parametric", "custom", "--x", "t**41", "--y", "t", "--t-range", "0", "2**100"], "4096"),
    ],
    "algorithms.image_limits.MAX_BITS": [
        (["quantize", "--bits", "25"], "at most 24"),
        (["storage", "8", "8", "--bits", "25"], "at most 24"),
    ],
    "algorithms.image_limits.MAX_LEVELS": [
        (["storage", "8", "8", "--levels", "16777217"], "16,777,216"),
        (["sample", "x", "--size", "4", "--levels", "16777217"], "16,777,216"),
        (["image", "ramp", "--levels", "16777217"], "16,777,216"),
    ],
    "algorithms.image_limits.MAX_SIDE": [
        (["sample", "x", "--size", "4097x4096", "--levels", "4"], "4096 x 4096")
    ],
    "algorithms.image_limits.MAX_CELLS": [
        (["sample", "x", "--size", "1x16777217", "--levels", "4"], "16,777,216 cells"),
        (["image", "ramp", "--size", "16777217x1"], "16,777,216 cells"),
    ],
    "algorithms.curve_limits.MAX_SAMPLES": [
        (["parametric", "circle", "--samples", "100001"], "at most 100000"),
        (["parametric", "custom", "--x", "t", "--y", "t", "-n", "100001"], "at most 100000"),
    ],
    "algorithms.curve_limits.MAX_POINTS": [
        (["bezier", *POINTS_101], "at most 100 control points"),
        (["bspline", *POINTS_101], "at most 100 control points"),
        (["local-control", *POINTS_101, "--move", "0", "1", "1"], "at most 100 control points"),
        (["continuity", *POINTS_101, ":", "0", "0", "1", "1"], "at most 100 control points"),
    ],
    "algorithms.curve_limits.MAX_DEGREE": [
        (["bspline", *POINTS_12, "--degree", "11"], "at most 10"),
        (["local-control", *POINTS_12, "--move", "0", "1", "1", "--degree", "11"], "at most 10"),
    ],
    "algorithms.curve_limits.MAX_WEIGHTS": [
        (["bezier", "0", "0", "1", "1", "--samples", "50000"], "at most 100,000"),
        (["bspline", "0", "0", "1", "1", "--degree", "1", "-n", "50000"], "at most 100,000"),
        (["continuity", "0", "0", "1", "1", ":", "1", "1", "2", "2", "-n", "25000"], "100,000"),
    ],
    "algorithms.curve_limits.MAX_CURVE_PIXELS": [
        (["bezier", "0", "0", "999985", "0", "--samples", "16"], "more than 1,000,000"),
        (["bspline", "0", "0", "999985", "0", "--degree", "1", "-n", "16"], "more than 1,000,000"),
        (["parametric", "line", "0", "0", "1000001", "0", "-n", "4"], "more than 1,000,000"),
        (["parametric", "circle", "--radius", "250001", "-n", "4"], "more than 1,000,000"),
    ],
    "algorithms.ellipses.MAX_AXIS": [(["ellipse", "1000001", "5"], "1e+06")],
    "answers.compare.MAX_LENGTH": [(["compare", "line", "0", "0", "3", "10001"], "at most 10000")],
    "answers.compare.MAX_RADIUS": [(["compare", "circle", "2001"], "at most 2000")],
    "algorithms.circles.SDDA_MAX_RADIUS": [
        (["circle", "16384", "--method", "symmetric-dda"], "16383")
    ],
    "render.figures.figure.MAX_CELLS": [
        (["line", "0", "0", "198", "0", "--svg", "FIGURE"], "201 x 3")
    ],
    "algorithms.polygon.MAX_VERTICES": [
        (["polygon", *("0", "0") * 1001], "at most 1000 polygon vertices"),
        (["antialias", "polygon", *("0", "0") * 1001], "at most 1000 polygon vertices"),
    ],
    "algorithms.polygon.MAX_FILL_CELLS": [
        (["polygon", "0", "0", "1000", "0", "0", "1000"], "1,000,000 are filled"),
    ],
    "algorithms.seedfill.MAX_SEED_CELLS": [
        (["fill", "flood", "--seed", "1", "1", "--rows", "/".join(["." * 101] * 100)], "10,000"),
        (["fill", "boundary", "0", "0", "98", "0", "0", "98", "--seed", "1", "1"], "10,000"),
    ],
    "algorithms.coverage.MAX_SAMPLES": [
        (
            ["antialias", "polygon", "0", "0", "4", "0", "2", "3", "-m", "supersample", "-n", "17"],
            "at most 16",
        ),
    ],
    "algorithms.coverage.MAX_AA_CELLS": [
        (["antialias", "circle", "49"], "10,000"),
        (["antialias", "polygon", "0", "0", "100", "0", "0", "99"], "10,000"),
    ],
    "answers.process._shared.MAX_POINTS": [
        (["transform", *POINTS_101, "--translate", "1", "1"], "at most 100 points"),
        (
            [
                "viewport",
                *POINTS_101,
                "--window",
                "0",
                "0",
                "1",
                "1",
                "--viewport",
                "0",
                "0",
                "2",
                "2",
            ],
            "at most 100 points",
        ),
    ],
    "answers.process.transform.MAX_TRANSFORMS": [
        (["transform", "0", "0", *["--translate", "1", "1"] * 21], "at most 20 transformations"),
    ],
    # the 3D chapter: an axis's square roots exact, and few enough of them
    "algorithms.radical.MAX_ROOT": [
        ("3d transform 0 0 0 --rotate-axis 0 0 0 1000000 1000000 1 30".split(), "past 10"),
    ],
    "algorithms.visible.MAX_FACES": [
        (["3d", "backface", *" : ".join([_FACE] * 25).split()], "25 faces; at most 24"),
    ],
    "algorithms.visible.MAX_VERTICES": [
        (
            ["3d", "backface", *(str(c) for i in range(17) for c in (i, i * i, 0))],
            "17 vertices; at most 16",
        ),
    ],
    "algorithms.visible_zbuffer.MAX_POLYGONS": [
        (["3d", "zbuffer", *" : ".join([_TRIANGLE] * 9).split()], "9 polygons; at most 8"),
    ],
    "algorithms.visible_zbuffer.MAX_SIDE": [
        (["3d", "zbuffer", *_TRIANGLE.split(), "--size", "33"], "1 to 32 pixels"),
    ],
    "answers.visible.zbuffer.MAX_XY": [
        (["3d", "zbuffer", "0", "0", "1", "65", "0", "1", "0", "3", "1"], "at most 64"),
    ],
    "answers.space.transform.MAX_ROOT_PRIMES": [
        (
            "3d transform 1 2 3 --rotate-axis 0 0 0 1 2 0 30 --rotate-axis 0 0 0 1 2 3 15 "
            "--rotate-axis 0 0 0 1 1 3 15 --rotate-axis 0 0 0 1 1 4 15".split(),
            "at most 6",
        ),
    ],
    # scanconv check: a student's file, and the question it is marked against
    "marking.student_table.MAX_TABLE_BYTES": [
        (["check", str(CHECK / "too-large.csv"), "--", "line", "2", "2", "10", "6"], "bytes")
    ],
    "marking.student_table.MAX_TABLE_ROWS": [
        (["check", str(CHECK / "too-many-rows.csv"), "--", "line", "2", "2", "10", "6"], "5000")
    ],
    "marking.limits.MAX_QUESTION_ROWS": [
        (["check", str(CHECK / "slip.csv"), "--", "line", "0", "0", "10001", "0"], "10000")
    ],
    "algorithms.window_clip.MAX_WINDOW_VERTICES": [
        (
            ["clip", "polygon", "0", "0", "1", "0", "0", "1", "--window-vertices", *_ring(65)],
            "at most 64 window vertices",
        )
    ],
    "answers.process.clip.sutherland_hodgman.MAX_VERTICES": [
        (
            ["clip", "polygon", *POINTS_101, "--window", "0", "0", "5", "5"],
            "at most 100 polygon vertices",
        ),
    ],
}

#: A limit that is not a refusal: the grid is left out with a note, and the answer is complete.
NOTED = {
    "core.records.MAX_GRID_CELLS": (["line", "0", "0", "98", "0", "-f", "plain"], "101 x 3 cells"),
    # a grid beyond the drawn figure's limit is listed, not drawn (tests/test_print.py)
    "render.figures.tikz.MAX_FIGURE_CELLS": (
        ["line", "0", "0", "98", "0", "-f", "latex"],
        "101 x 3",
    ),
}

#: A limit of the MCP server's tools, not of a command line: where its refusal is tested.
SERVED = {
    "mcp_server.answers.MAX_PRACTICE": "tests/test_mcp.py, "
    "test_a_question_too_long_and_a_bad_practice_set_are_refused",
    # the site's test yourself, marked by the library: tests/test_marking_steps.py
    "marking.mark.MAX_STEP_TEXT": "test_typed_words_are_read_as_check_reads_a_cell",
    "site.page.MAX_STEPS": "test_the_site_marks_at_most_its_steps",
}

ALLOCATORS = ("empty", "zeros", "ones", "full", "arange", "linspace", "meshgrid", "indices")


def _constant(name: str) -> int:
    module, attr = name.rsplit(".", 1)
    return getattr(importlib.import_module(f"scanconv.{module}"), attr)


def _limit_constants() -> set[str]:
    """Every module-level int named like a limit (MAX_..., ..._MAX_..., ...LIMIT), defined in
    its own module (not imported under another name)."""
    found = set()
    for info in pkgutil.walk_packages(scanconv.__path__, "scanconv."):
        if info.name in ("scanconv.__main__", "scanconv.raster"):  # runs the CLI; an alias
            continue
        if info.name == "scanconv.mcp_server.server" and importlib.util.find_spec("mcp") is None:
            continue  # the SDK's glue, without the mcp extra (it defines no limit)
        module = importlib.import_module(info.name)
        source = Path(module.__file__ or "").read_text(encoding="utf-8")
        short = info.name.removeprefix("scanconv.")
        for name, value in vars(module).items():
            if not isinstance(value, int) or isinstance(value, bool):
                continue
            if not re.search(r"(^|_)MAX(_|$)|LIMIT", name):
                continue
            if re.search(rf"^{name}\s*(:[^=]*)?=", source, re.M):
                found.add(f"{short}.{name}")
    return found - NOT_INPUT_LIMITS


def test_the_table_lists_every_limit_constant_in_the_code():
    missing = sorted(_limit_constants() - set(DOCUMENTED))
    assert not missing, f"document these limits in docs/limits.md: {missing}"
    assert len(DOCUMENTED) >= 19


@pytest.mark.parametrize("name", sorted(DOCUMENTED))
def test_the_documented_value_is_the_constant(name):
    documented = parse_exact(DOCUMENTED[name])  # the doc's value, a Python expression
    assert isinstance(documented, Fraction)
    assert documented == _constant(name), f"docs/limits.md says {DOCUMENTED[name]} for {name}"


def test_every_documented_limit_has_a_refusal_case():
    assert set(BEYOND) | set(NOTED) | set(SERVED) == set(DOCUMENTED)


def _warm_up(args: list[str]) -> None:
    """Import what the command imports, so the timed run measures the refusal alone."""
    run(*args[: 2 if args[0] in ("parametric", "image") else 1], "--help")


CASES = [
    pytest.param(name, args, word, id=f"{name}: {' '.join(args)[:50]}")
    for name, cases in BEYOND.items()
    for args, word in cases
]


@pytest.mark.parametrize(("name", "args", "word"), CASES)
def test_just_beyond_the_limit_is_refused_at_once(name, args, word, monkeypatch, tmp_path):
    args = [str(tmp_path / "f.svg") if a == "FIGURE" else a for a in args]
    _warm_up(args)

    def allocation_reached(*a, **k):
        raise AssertionError("numpy allocated before the input was refused")

    # A parametric curve's pixel path is known only from its samples: one vectorised float64
    # pass over them (algorithms.parametric.check_float_path) runs before any exact work, so
    # numpy allocates the samples' arrays; the pixels and the figure are never reached.
    if args[0] != "parametric":
        for fn in ALLOCATORS:
            monkeypatch.setattr(np, fn, allocation_reached)
    tracemalloc.start()
    try:
        r, calls = python_calls(run, *args)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert_refused(r, word)
    assert calls < REFUSAL_CALLS, f"{calls} Python calls before the refusal"
    assert peak < 16 * 2**20, f"{peak / 2**20:.1f} MiB allocated before the refusal"
    assert not list(tmp_path.iterdir()), "a file was written for a refused input"


REFUSAL_CALLS = 200_000
""""At once" is before the work, counted rather than timed (a busy machine must not fail a
test): a refusal makes a few thousand Python calls (``check`` counts a question's rows up to
its 10,000-row limit: about 60,000), where the work it refuses makes millions."""


def test_the_grid_limit_leaves_the_grid_out_with_a_note():
    args, word = NOTED["core.records.MAX_GRID_CELLS"]
    r = run(*args)
    assert r.code == 0 and word in r.err and r.err.count("\n") == 1
    assert "(98, 0)" in r.out and " | " not in r.out
    at_limit = run("line", "0", "0", "97", "0", "-f", "plain")
    assert at_limit.code == 0 and at_limit.err == "" and " | " in at_limit.out


def test_exactly_at_each_limit_is_accepted():
    """The other side of each edge: the largest accepted value passes its check."""
    from scanconv.algorithms import bspline, curve_limits, image_limits
    from scanconv.answers.curves.bezier import bezier_at_solution
    from scanconv.answers.primitives.circle import circle_solution
    from scanconv.answers.primitives.line import line_solution
    from scanconv.core import expr, numeric
    from scanconv.render.figures import figure

    assert numeric.parse_number(str(numeric.COORD_LIMIT)) == 10**9
    assert numeric.parse_number("-" + str(numeric.COORD_LIMIT)) == -(10**9)
    assert numeric.parse_number("0" * 39 + "1") == 1
    assert expr.compile_expr("-" * (expr.MAX_DEPTH - 2) + "t", ("t",))(t=1.0) == 1.0
    assert expr.compile_expr("t**100", ("t",))(t=1.0) == 1.0
    assert expr.compile_expr("t**40", ("t",)).exact(t=2**100) == 2**4000
    with pytest.raises(ValueError, match="4096 bits"):
        expr.compile_expr("t**41", ("t",)).exact(t=2**100)
    assert image_limits.check_bits(24) == 24 and image_limits.check_levels(2**24) == 2**24
    image_limits.check_cells(4096, 4096)
    image_limits.check_cells(1, 4096 * 4096)
    assert curve_limits.check_samples(10**5) == 10**5
    assert len(curve_limits.check_points([(i, 0) for i in range(100)], 2, "a curve")) == 100
    assert len(bspline.knot_vector("open", 10, 10)) == 22
    curve_limits.check_weights(49_999, 2)  # 50,000 x 2 = 100,000
    curve_limits.check_path([[(0, 0), (999_984, 0)]], 16)  # 999,984 + 16 = 1,000,000
    # de Casteljau with 2 points at t = 1/2^4094: 4095 + 1 bits, exactly the limit
    sol = bezier_at_solution([(0, 0), (1, 1)], Fraction(1, 2**4094))
    assert sol.derived[-1].value == (Fraction(1, 2**4094), Fraction(1, 2**4094))
    with pytest.raises(ValueError, match="4096 bits"):
        bezier_at_solution([(0, 0), (1, 1)], Fraction(1, 2**4095))
    assert circle_solution("symmetric-dda", 2**14 - 1).title
    figure.build(line_solution("bresenham", 0, 0, 197, 0))  # 200 x 3 cells


# --- every command at its largest accepted input ---------------------------------------------

MAX_COORD = "1000000000"
POINTS_100 = [str((i * 7919) % 1000 if i % 2 else (i * 104729) % 997) for i in range(200)]

#: The largest inputs each command accepts. Each must start answering, or refuse, before a
#: generous hang guard (a minute: every allowed table ends within one, docs/limits.md).
LARGEST = [
    ["line", "0", "0", MAX_COORD, "1", "-f", "csv"],
    ["line", "0", "0", MAX_COORD, MAX_COORD, "-f", "markdown", "--algo", "dda"],
    ["circle", MAX_COORD, "-f", "markdown"],
    ["circle", MAX_COORD, "--method", "trig", "-f", "csv"],
    ["ellipse", "1000000", "1000000", "-f", "markdown"],
    ["ellipse", "1000000", "1", "-f", "csv"],
    ["ellipse", MAX_COORD, "1", "-f", "csv"],
    ["compare", "line", "0", "0", "10000", "1", "-f", "csv"],
    ["compare", "line", "0", "0", MAX_COORD, "1", "-f", "csv"],
    ["compare", "circle", "2000", "-f", "csv"],
    ["compare", "circle", MAX_COORD, "-f", "csv"],
    ["quantize", "--bits", "24", "--range", "0", "1", "--input", "real", "-f", "csv"],
    ["storage", MAX_COORD, MAX_COORD, "--bits", "24", "--frames", MAX_COORD, "-f", "json"],
    ["bezier", *POINTS_100, "--samples", "999", "-f", "markdown"],
    ["bspline", *POINTS_100, "--degree", "10", "--samples", "999", "-f", "csv"],
    ["continuity", *POINTS_100[:100], ":", *POINTS_100[100:], "-n", "999", "-f", "json"],
    ["parametric", "circle", "--radius", MAX_COORD, "-n", "100000", "-f", "csv"],
    ["parametric", "custom", "--x", "t", "--y", "t", "-n", "100000", "-f", "csv"],
    ["check", str(CHECK / "slip.csv"), "--", "line", "0", "0", "9999", "1", "-f", "csv"],
    ["check", str(CHECK / "slip.csv"), "--", "circle", MAX_COORD, "-f", "csv"],
]


def _limit_memory() -> None:  # pragma: no cover - runs in the child
    resource.setrlimit(resource.RLIMIT_AS, (2 * 2**30, 2 * 2**30))


@pytest.mark.parametrize("args", LARGEST, ids=lambda a: " ".join(a)[:60])
def test_the_largest_accepted_input_answers_at_once_in_bounded_memory(args):
    """A refusal, or the start of the answer, within 2 GiB;
    no traceback. The minute is a guard against a hang, not a speed test (benchmarks/
    bench_limits.py times these)."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "scanconv", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        preexec_fn=_limit_memory,
        env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"},
    )
    assert proc.stdout is not None
    ready, _, _ = select.select([proc.stdout], [], [], HANG_SECONDS)
    first = os.read(proc.stdout.fileno(), 65536) if ready else b""
    if proc.poll() is None:
        proc.kill()
    _out, err = proc.communicate(timeout=60)
    stderr = err.decode("utf-8", "replace")
    assert "Traceback" not in stderr and "MemoryError" not in stderr, stderr[-2000:]
    if proc.returncode == 2:
        assert first == b"" and stderr.count("\n") == 1, stderr
        return
    assert first, f"no output after {HANG_SECONDS} s (exit {proc.returncode}): {stderr[-500:]}"


# --- the per-format work budgets ----------------------------------------------------------------

BUDGET_ROW = re.compile(r"^\| (\w+) \| `([^`]+)` \| (?:`([^`]+)`|none) \|", re.M)


def test_the_per_format_budgets_are_the_constants():
    from scanconv.render import Format
    from scanconv.render.budget import MATRIX_CELLS, TABLE_ROWS

    section = DOC.split("## Work budgets of the output formats", 1)[1].split("\n## ", 1)[0]
    rows = {fmt: (cells, table) for fmt, cells, table in BUDGET_ROW.findall(section)}
    assert set(rows) == {f.value for f in MATRIX_CELLS}, rows
    for fmt, (cells, table) in rows.items():
        assert parse_exact(cells) == MATRIX_CELLS[Format(fmt)], fmt
        documented_rows = parse_exact(table.replace("_", "")) if table else None
        assert documented_rows == TABLE_ROWS.get(Format(fmt)), fmt

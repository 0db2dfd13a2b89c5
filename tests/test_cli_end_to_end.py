"""The image, fill and attribute commands from end to end: each command of ``scanconv dither``,
``halftone``, ``inside``, ``framebuffer``, ``linestyle``, ``thickline``, ``char`` and
``clip convex``, and the new conventions of ``line``, ``circle`` and ``clip line``, run as a
student runs them: in every data format, its JSON values against the library's own answer
(called directly, not through the CLI), a bad value refused naming its flag, and the same
command as a question of a sheet."""

from __future__ import annotations

import csv
import io
import json
import shlex
from collections.abc import Callable
from fractions import Fraction
from pathlib import Path
from typing import Any

import pytest

from scanconv.answers.image import dither, framebuffer
from scanconv.answers.primitives import attributes, characters, circle, line
from scanconv.answers.process.clip import cyrus_beck
from scanconv.answers.process.clip import midpoint as midpoint_clip
from scanconv.answers.process.fill import inside

from .helpers import assert_refused, run

Case = tuple[str, Callable[[], Any], str]
"""A command line, the library call answering it, and the JSON key compared."""

IMAGE = "10 200; 60 90"
CASES: list[Case] = [
    (
        f"dither threshold --image '{IMAGE}' --at 128",
        lambda: dither.threshold_solution([[10, 200], [60, 90]], 255, 128),
        "output",
    ),
    (
        f"dither ordered --image '{IMAGE}' --matrix 2",
        lambda: dither.ordered_solution([[10, 200], [60, 90]], 2, 255),
        "output",
    ),
    (
        "dither ordered --image '0 64 128 255' --matrix '0 2; 3 1' --top 255 --scale centered "
        "--compare '>=' --transpose",
        lambda: dither.ordered_solution(
            [[0, 64, 128, 255]],
            [[0, 2], [3, 1]],
            255,
            compare=">=",
            scale="centered",
            transpose=True,
        ),
        "output",
    ),
    (
        "dither floyd-steinberg --image '100 100 100; 100 100 100' --order serpentine "
        "--arithmetic integer",
        lambda: dither.diffusion_solution(
            [[100] * 3, [100] * 3], 255, order="serpentine", arithmetic="integer"
        ),
        "output",
    ),
    ("halftone 2", lambda: dither.pattern_solution(2), "levels"),
    ("halftone 4 --level 5", lambda: dither.pattern_solution(4, 5), "patterns"),
    (
        "inside 0 0 6 0 6 6 3 2 0 6 --points 3 1 3 4 6 3",
        lambda: inside.inside_solution([0, 0, 6, 0, 6, 6, 3, 2, 0, 6], [3, 1, 3, 4, 6, 3]),
        "verdicts",
    ),
    (
        "inside 0 0 6 0 6 6 --points 6 3 --rule even-odd --boundary outside",
        lambda: inside.inside_solution(
            [0, 0, 6, 0, 6, 6], [6, 3], rule_name="even-odd", boundary="outside"
        ),
        "verdicts",
    ),
    (
        "framebuffer 1280 1024 8 --lut 24 --rate 1e6 --refresh 60",
        lambda: framebuffer.framebuffer_solution(1280, 1024, 8, lut=24, rate=10**6, refresh=60),
        "pixel_time",
    ),
    (
        "framebuffer 640 480 4 --refresh 30 --interlaced",
        lambda: framebuffer.framebuffer_solution(640, 480, 4, refresh=30, interlaced=True),
        "pixel_time",
    ),
    (
        "linestyle 0 0 12 4 --mask 1110",
        lambda: attributes.line_style_solution(0, 0, 12, 4, "1110"),
        "pixels",
    ),
    (
        "linestyle 0 0 12 4 --mask 0x0f --bits lsb --repeat 2",
        lambda: attributes.line_style_solution(0, 0, 12, 4, "0x0f", bits="lsb", repeat=2),
        "pixels",
    ),
    (
        "thickline 0 0 8 3 --width 3",
        lambda: attributes.thick_line_solution(0, 0, 8, 3, 3),
        "pixels",
    ),
    (
        "thickline 0 0 3 8 --width 2 --brush",
        lambda: attributes.thick_line_solution(0, 0, 3, 8, 2, brush=True),
        "pixels",
    ),
    (
        "char bitmap A --at 2 1",
        lambda: characters.bitmap_solution("A", x0=2, y0=1),
        "pixels",
    ),
    (
        "char bitmap X --rows 101/010/101 --scale 2",
        lambda: characters.bitmap_solution("X", rows=["101", "010", "101"], scale=2),
        "pixels",
    ),
    (
        "char stroke T --scale 2 --algo dda",
        lambda: characters.stroke_solution("T", scale=2, algo="dda"),
        "pixels",
    ),
    (
        "char storage 128 5 7 --packing columns",
        lambda: characters.font_storage_solution(128, 5, 7, "columns"),
        "bits",
    ),
    (
        "clip convex -1 2 9 2 --window-vertices 0 0 8 0 0 8",
        lambda: cyrus_beck.cyrus_beck_solution(-1, 2, 9, 2, [0, 0, 8, 0, 0, 8]),
        "clipped",
    ),
    (
        "clip convex 0 0 10 5 --window-vertices 1 1 9 1 9 4 1 4 --normals inward --ends truncated",
        lambda: cyrus_beck.cyrus_beck_solution(
            0, 0, 10, 5, [1, 1, 9, 1, 9, 4, 1, 4], normals="inward", ends="truncated"
        ),
        "clipped",
    ),
    (
        "clip line 7 9 11 4 --window 4 4 10 8 --method cyrus-beck",
        lambda: cyrus_beck.cyrus_beck_solution(7, 9, 11, 4, [4, 4, 10, 4, 10, 8, 4, 8]),
        "clipped",
    ),
    (
        "clip line 7 9 11 4 --window 4 4 10 8 --method cyrus-beck --ends truncated",
        lambda: cyrus_beck.cyrus_beck_solution(
            7, 9, 11, 4, [4, 4, 10, 4, 10, 8, 4, 8], ends="truncated"
        ),
        "clipped",
    ),
    (
        "clip line 7 9 11 4 --window 4 4 10 8 --method midpoint-subdivision --midpoint exact",
        lambda: midpoint_clip.midpoint_clip_solution(7, 9, 11, 4, [4, 4, 10, 8], midpoint="exact"),
        "visible",
    ),
    (
        "clip line 0 0 10 5 --window 1 1 9 4 --method midpoint-subdivision --midpoint floor",
        lambda: midpoint_clip.midpoint_clip_solution(0, 0, 10, 5, [1, 1, 9, 4], midpoint="floor"),
        "visible",
    ),
    (
        "line 2 2 10 6 --algo midpoint --scale half",
        lambda: line.line_solution("midpoint", 2, 2, 10, 6, scale="half", layout="notes"),
        "steps",
    ),
    (
        "circle 10 --method bresenham --xstep first",
        lambda: circle.circle_solution("bresenham", 10, xstep="first", layout="notes"),
        "steps",
    ),
]


def _ids(cases: list[Any]) -> list[str]:
    return [c[0][:60] for c in cases]


def _argv(command: str) -> list[str]:
    return shlex.split(command)


def _as_json(value: Any) -> Any:
    """A library value as the JSON answer writes it: a fraction as its float, tuples as lists."""
    if isinstance(value, Fraction):
        return value.numerator if value.denominator == 1 else float(value)
    if isinstance(value, dict):
        return {str(k): _as_json(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_as_json(v) for v in value]
    return value


def _library(solution: Any, key: str) -> Any:
    """What the library's answer holds under ``key``: its data, or its pixels and steps."""
    if key == "pixels":
        return _as_json(list(solution.pixels()))
    if key == "steps":
        return [_as_json(s.p) for s in solution.steps()]
    return _as_json(solution.data[key])


@pytest.mark.parametrize(("command", "library", "key"), CASES, ids=_ids(CASES))
def test_the_json_answer_is_the_librarys(command: str, library: Callable[[], Any], key: str):
    r = run(*_argv(command), "--format", "json")
    assert r.code == 0, r.err
    answer = json.loads(r.out)
    got = [s["p"] for s in answer["steps"]] if key == "steps" else answer[key]
    assert got == _library(library(), key)


@pytest.mark.parametrize(("command", "library", "key"), CASES, ids=_ids(CASES))
@pytest.mark.parametrize("fmt", ["plain", "csv", "markdown"])
def test_every_format_answers(command: str, library: Callable[[], Any], key: str, fmt: str):
    r = run(*_argv(command), "--format", fmt)
    assert r.code == 0, r.err
    assert r.out.strip()
    title = library().title
    if fmt == "csv":
        rows = list(csv.reader(io.StringIO(r.out)))
        assert rows and all(rows), r.out[:200]
    else:
        assert title.split(":")[0].split(" (")[0][:20] in r.out, (title, r.out[:200])


#: One bad value per command, and the flag (or word) the one-line message must name.
BAD = [
    ("dither threshold --image '1 2' --top 0", "--top"),
    ("dither threshold --image '1 2; 3'", "--image"),
    ("dither ordered --image '1 2' --matrix 3", "--matrix"),
    ("dither ordered --image '1 2' --base 2", "--base"),
    ("dither floyd-steinberg --image '1 2' --kernel jarvis", "--kernel"),
    ("halftone 2 --level 9", "--level"),
    ("halftone 3", "2, 4, 8 or 16"),
    ("inside 0 0 6 0 6 6", "--points"),
    ("inside 0 0 6 0 6 6 --points 1 1 --boundary edge", "--boundary"),
    ("framebuffer 640 480 8 --rate 0", "--rate"),
    ("framebuffer 640 480 65", "at most 64"),
    ("linestyle 0 0 12 4 --mask 1102", "--mask"),
    ("linestyle 0 0 12 4 --mask 11 --repeat 0", "--repeat"),
    ("thickline 0 0 8 3 --width 26", "--width"),
    ("char bitmap A --scale 17", "--scale"),
    ("char bitmap A --rows 01/1", "--rows"),
    ("char stroke T --at 1.5 0", "--at"),
    ("char stroke T --algo wu", "--algo"),
    ("char storage 128 5 7 --packing nibbles", "--packing"),
    ("clip convex 0 0 1 1 --window-vertices 0 0 8 0 8 8 0 8 4 4", "convex"),
    ("clip convex 0 0 1 1 --window-vertices 0 0 8 0 0 8 --normals sideways", "--normals"),
    ("clip line 7 9 11 4 --window 4 4 10 8 --method cyrus-beck --midpoint exact", "--midpoint"),
    ("clip line 7 9 11 4 --window 4 4 10 8 --ends truncated", "--ends"),
    ("line 2 2 10 6 --algo bresenham --scale half", "--scale"),
    ("circle 10 --method midpoint --xstep first", "--xstep"),
]


@pytest.mark.parametrize(("command", "word"), BAD, ids=[b[0][:60] for b in BAD])
def test_bad_input_is_refused_naming_its_flag(command: str, word: str) -> None:
    assert_refused(run(*_argv(command)), word)


@pytest.mark.parametrize(("command", "library", "key"), CASES, ids=_ids(CASES))
def test_each_command_is_a_question_of_a_sheet(
    command: str, library: Callable[[], Any], key: str, tmp_path: Path
) -> None:
    """The question language answers the command as the command line does."""
    alone = run(*_argv(command), "--format", "json")
    path = tmp_path / "questions.txt"
    path.write_text(f"[2] {command}\n", encoding="utf-8")
    sheet = run("sheet", str(path), "--format", "json")
    assert sheet.code == 0, sheet.err
    (question,) = json.loads(sheet.out)["questions"]
    assert question["answer"] == json.loads(alone.out)
    assert question["marks"] == 2


def test_the_python_api_exports_them() -> None:
    import scanconv

    for name in ("dither_threshold", "dither_ordered", "dither_diffusion", "halftone", "inside",
                 "framebuffer", "line_style", "thick_line", "char_bitmap", "char_stroke",
                 "char_storage", "clip_convex"):  # fmt: skip
        assert name in scanconv.__all__ and callable(getattr(scanconv, name)), name
    assert scanconv.dither_ordered("1 2; 3 4", 2, 4).data["output"] == [[1, 0], [0, 1]]
    assert (
        scanconv.inside([(0, 0), (4, 0), (0, 4)], [(1, 1), (3, 3)]).data["verdicts"][1]["even_odd"]
        is False
    )

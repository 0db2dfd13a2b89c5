"""Every exam command answers without numpy (the browser's Python, Pyodide, has none), and
gives the same JSON and HTML page as it does with numpy.

One subprocess, where ``import numpy`` fails (``sys.modules["numpy"] = None`` before scanconv
is imported), answers one question of every command through the library's question language
(the site's path); the same questions are answered here, with numpy, and the outputs compared.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from scanconv.questions import parse, shown_with, solve
from scanconv.questions.grammar_table import SPECS
from scanconv.render import Format, render

QUESTIONS = (
    "line 2 2 10 6 --algo bresenham",
    "line 2 2 10 6 --algo dda",
    "line 2 2 10 6 --algo midpoint --scale half --derive",
    "line 0 0 8 3 --algo wu",
    "circle 6 --method general",
    "circle 8 --method midpoint",
    "ellipse 8 6",
    "compare line 2 2 8 5",
    "compare circle 6 --theory",
    "compare curves",
    "theory image",
    "theory curves",
    "theory bezier",
    "theory bspline",
    "theory parametric",
    "storage 1024 768 --levels 256",
    "quantize --bits 3",
    "image ramp --size 8 --levels 8",
    "color rgb 51 102 153 --to cmy hsv hsi",
    "pipeline line -5 0 15 10 --window 0 0 10 10 --viewport 0 0 20 10",
    "pipeline polygon 0 0 8 0 8 8 --window 2 2 6 6 --viewport 0 0 8 8",
    "parametric line 0 0 10 4",
    "parametric circle 5",
    "parametric ellipse --a 8 --b 4",
    "parametric parabola --t-range -3 3",
    "parametric custom --x '3*cos(t)' --y '2*sin(t)' --samples 12",
    "parametric custom --x 't**2/3 + 1/t' --y 'sqrt(t)' --t-range 1 4",
    "bezier 0 0 1 2 3 3 4 0",
    "bezier 0 0 1 2 3 3 4 0 --at 0.5",
    "bspline 0 0 1 2 3 3 4 0 5 2 --degree 2",
    "bspline 0 0 1 2 3 3 4 0 5 2 --degree 2 --basis",
    "continuity 0 0 1 1 2 0 : 2 0 4 -2 6 0",
    "local-control 0 0 1 2 3 3 4 0 5 2 7 1 --move 5 7 5 --degree 2",
    "clip line 7 9 11 4 --window 4 4 10 8",
    "clip line 7 9 11 4 --window 4 4 10 8 --method cyrus-beck",
    "clip convex -1 2 9 2 --window-vertices 0 0 8 0 0 8",
    "clip polygon 0 0 8 0 8 8 --window 2 1 9 3 --method weiler-atherton",
    "transform 0 0 4 0 4 3 --rotate 90 --about 2 1",
    "viewport 0 0 2 1 --window 0 0 4 4 --viewport 10 10 20 16",
    "polygon 1 1 9 1 9 7 5 3 1 7",
    "fill flood 2 0 4 2 2 4 0 2 --seed 2 2",
    "fill boundary 2 0 4 2 2 4 0 2 --seed 2 2",
    "antialias line 0 0 8 3 --method wu",
    "antialias circle 6",
    "antialias polygon 0 0 4 0 4 3 --levels 5",
    "dither threshold --image '10 200; 60 90' --at 128",
    "dither ordered --image '10 200; 60 90' --matrix 2",
    "dither floyd-steinberg --image '100 100; 100 100' --order serpentine",
    "halftone 4 --level 5",
    "halftone 5 --order clustered",
    "printer --dpi 300 --lpi 60",
    "dither lookup 5 2 --matrix 4 --value 100",
    "inside 0 0 6 0 6 6 3 2 0 6 --points 3 1 3 4",
    "framebuffer 1280 1024 8 --lut 24 --rate 1e6 --refresh 60",
    "linestyle 0 0 12 4 --mask 1110",
    "thickline 0 0 8 3 --width 3",
    "char bitmap A --at 2 1",
    "char stroke T --scale 2",
    "char storage 128 5 7",
    "3d backface --solid pyramid",
    "3d zbuffer 0 0 2 5 0 2 0 5 2 : 1 1 4 5 1 0 1 5 0 --size 5",
    "3d scanline 0 0 1 4 0 1 0 4 1 : 1 0 2 4 0 2 4 3 2 --size 5",
    "3d depth-sort 0 0 1 4 0 1 0 4 1 : 1 1 3 5 1 0 1 5 0 --size 6",
    "3d warnock 0 0 1 6 0 1 0 6 1 : 2 2 3 7 2 3 2 7 3 --size 8",
    "3d transform --solid unit-cube --rotate-axis 0 0 0 1 1 1 120",
    "3d project --solid unit-cube --perspective two-point --d 4 --cop minus-d",
)
"""One question (or more) of every command; the site answers them with the same code."""

NEEDS_NUMPY = {
    ("sample",): "f(x, y) is sampled over the whole image in numpy blocks (a bulk path)",
}
"""The commands that still need numpy, and why."""

_CHILD = r"""
import json, sys
sys.modules["numpy"] = None  # import numpy raises ImportError from here on
from scanconv.questions import parse, shown_with, solve
from scanconv.render import Format, render

out = {}
for q in json.load(sys.stdin):
    line = parse(q)
    solution, options = solve(line), shown_with(line)
    out[q] = {f: "".join(render(solution, Format(f), options)) for f in ("json", "html")}
assert "numpy" not in {m.split(".")[0] for m in sys.modules if sys.modules[m] is not None}
json.dump(out, sys.stdout)
"""


def _answers(q: str) -> dict[str, str]:
    line = parse(q)
    solution, options = solve(line), shown_with(line)
    return {f: "".join(render(solution, Format(f), options)) for f in ("json", "html")}


def test_every_command_has_a_question_or_a_reason() -> None:
    covered = {parse(q).path for q in QUESTIONS}
    assert set(SPECS) - covered == set(NEEDS_NUMPY)
    assert not covered & set(NEEDS_NUMPY)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_child_cannot_import_numpy() -> None:
    probe = 'import sys; sys.modules["numpy"] = None\ntry:\n import numpy\nexcept ImportError:\n print("refused")'
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    assert done.stdout.strip() == "refused"


@pytest.mark.slow
def test_every_command_answers_the_same_without_numpy() -> None:
    done = subprocess.run(
        [sys.executable, "-c", _CHILD],
        input=json.dumps(QUESTIONS),
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    without = json.loads(done.stdout)
    for q in QUESTIONS:
        expected = _answers(q)
        assert without[q]["json"] == expected["json"], q
        assert without[q]["html"] == expected["html"], q

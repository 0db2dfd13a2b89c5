"""--derive (the derivation with this input's numbers), --algorithm (the pseudocode of
the variant used) and the comparison theory tables, in every format."""

from __future__ import annotations

import pytest

from scanconv import _api as api
from scanconv.core.working import tex_to_unicode
from scanconv.render import formats

from .helpers import run

FORMATS = formats("answer")

CASES = [
    ("line", "2", "2", "10", "6"),
    ("line", "2", "8", "10", "4"),
    ("line", "2", "2", "5", "10", "--algo", "dda"),
    ("line", "0", "0", "3", "7", "--algo", "basic"),
    ("circle", "5"),
    ("circle", "5", "-m", "general"),
    ("circle", "5", "-m", "bresenham"),
    ("circle", "5", "-m", "polynomial"),
    ("ellipse", "8", "6"),
]


@pytest.mark.parametrize("args", CASES)
@pytest.mark.parametrize("fmt", FORMATS)
def test_derive_and_algorithm_render_in_every_format(args, fmt):
    r = run(*args, "--derive", "--algorithm", "-f", fmt)
    assert r.code == 0 and r.err == "", r.err
    if fmt != "csv":  # csv is the step table only
        assert "Derivation" in r.out or "derivation" in r.out
        assert "Algorithm" in r.out
    if fmt == "plain":
        assert r.out.isascii()


def test_derivation_is_written_once_in_tex():
    for sol in (
        api.line(2, 2, 10, 6, derive=True),
        api.line(2, 8, 10, 4, derive=True),
        api.line(2, 2, 5, 10, algo="dda", derive=True),
        api.circle(7, derive=True, p0="5/4-r"),
        api.circle(7, method="general", derive=True),
        api.circle(7, method="bresenham", derive=True),
        api.ellipse(8, 6, derive=True),
    ):
        assert sol.derivation[0].key == "derivation"  # declared apart from the working
        assert "derivation" not in [q.key for q in sol.derived]
        for q in (*sol.derived, *sol.derivation):
            assert q.text == tex_to_unicode(q.tex)


def test_bresenham_derivation_has_this_inputs_numbers():
    sol = api.line(2, 2, 10, 6, derive=True)
    text = "\n".join(q.text for q in sol.derivation)
    assert "8xₖ - 16yₖ + 16" in text and "2·4 - 8 = 0" in text


def test_midpoint_derivation_substitutes_r():
    text = "\n".join(q.text for q in api.circle(5, derive=True).derivation)
    assert "5/4 - 5 = -3.75" in text and "1 - r = -4" in text


def _code(sol):
    listing = next(c for c in sol.code if c.title.startswith("Algorithm"))
    return listing.title, list(listing.lines)


def test_pseudocode_is_the_variant_used():
    title, code = _code(api.line(2, 2, 5, 10, algo="dda", pseudocode=True))
    assert "|m| > 1" in title
    title, code = _code(api.line(2, 8, 10, 4, pseudocode=True))
    assert "negative slope" in title and any("y = y - 1" in c for c in code)
    title, code = _code(api.line(0, 0, 4, 2, tie="keep", pseudocode=True))
    assert any("if p <= 0" in c for c in code)
    title, code = _code(api.line(10, 6, 2, 2, pseudocode=True))
    assert code[0].startswith("swap the end points")
    title, code = _code(api.circle(5, convention="foley", pseudocode=True))
    assert "x = 0;  y = r;  p = 5/4 - r" in code and any("2*x + 3" in c for c in code)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("compare", "line", "2", "2", "10", "6", "--theory"), ("Bresenham", "floating point")),
        (("compare", "circle", "6", "--theory"), ("general method", "integer only")),
    ],
)
def test_comparison_theory_tables(args, words):  # Bezier vs B-spline: api.compare_curves()
    for fmt in ("plain", "markdown", "latex", "json"):
        r = run(*args, "-f", fmt)
        assert r.code == 0, r.err
        for w in words:
            assert w in r.out, (fmt, w)


def test_bezier_vs_bspline_theory():
    sol = api.compare_curves()
    rows = list(sol.tables[0].rows())
    assert rows[0][1].startswith("global") and rows[0][2].startswith("local")

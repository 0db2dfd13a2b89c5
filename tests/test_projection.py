"""Parallel and perspective projections, checked against published worked examples (cited) and
independent computations written here: the pinhole formula of each centre of projection, the
vanishing point as the limit of a receding line, the foreshortening of the axonometric
projections."""

from __future__ import annotations

import math
import re
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanconv
from scanconv.algorithms import projection as pj
from scanconv.algorithms.radical import Radical

from .helpers import run

R2, R3 = Radical(0, 1), Radical(0, 0, 1)

#: expertsmind's cube: A..D on z = 0, E(0, 1, 1), F(0, 0, 1), G(1, 0, 1), H(1, 1, 1)
EXPERTSMIND_CABINET_CUBE = "0 0 0 1 0 0 1 1 0 0 1 0 0 1 1 0 0 1 1 0 1 1 1 1"


def exact(v: object) -> object:
    """A JSON value back to an exact number: rationals as they are, texts as the radicals
    they name (only the few written here)."""
    table = {
        "sqrt(2)/2": R2 / 2,
        "sqrt(2)/4": R2 / 4,
        "sqrt(3)/4": R3 / 4,
        "1 + sqrt(3)/4": 1 + R3 / 4,
    }
    return table.get(v, v) if isinstance(v, str) else v


def test_cabinet_unit_cube_at_30_degrees_expertsmind() -> None:
    # https://expertsmind.com/questions/determine-the-transformation-matrix-for-cavalier-projection-30150152.aspx
    # cabinet projection with theta = 30 degrees: E' = (sqrt3/4, 5/4), F' = (sqrt3/4, 1/4),
    # G' = (1 + sqrt3/4, 1/4), H' = (1 + sqrt3/4, 5/4)
    sol = scanconv.project3d(EXPERTSMIND_CABINET_CUBE, parallel="cabinet", angle="30")
    got = [[exact(v) for v in p] for p in sol.data["projected"]]
    q = Fraction(1, 4)
    want = [
        [0, 0],
        [1, 0],
        [1, 1],
        [0, 1],
        [R3 / 4, 1 + q],
        [R3 / 4, q],
        [1 + R3 / 4, q],
        [1 + R3 / 4, 1 + q],
    ]
    assert got == want


def test_cavalier_unit_cube_at_45_degrees() -> None:
    # Hearn & Baker 12-3: x' = x + L1 z cos(phi), y' = y + L1 z sin(phi), L1 = 1 (cavalier)
    sol = scanconv.project3d(solid="unit-cube", parallel="cavalier")
    e = [exact(v) for v in sol.data["projected"][4]]  # E(0, 0, 1)
    assert e == [R2 / 2, R2 / 2]
    cab = scanconv.project3d(solid="unit-cube", parallel="cabinet")
    assert [exact(v) for v in cab.data["projected"][4]] == [R2 / 4, R2 / 4]
    # the projector's angle alpha = 45 degrees is the cavalier projection again
    alpha = scanconv.project3d(
        solid="unit-cube", parallel="oblique", angle="45", oblique="projector"
    )
    assert alpha.data["projected"] == sol.data["projected"]


def test_one_point_perspective_of_the_unit_cube_expertsmind() -> None:
    # https://expertsmind.com/questions/achieve-a-perspective-projection-on-the-plane-of-unit-cube-30150221.aspx
    # the centre at (0, 0, 10), the plane z = 0; A..D on z = 1: B' = (1.11, 0), C' = (1.11,
    # 1.11), D' = (0, 1.11); E..H on z = 0 unchanged. (The page writes the centre as
    # (0, 0, -d) with d = -10: Hearn & Baker's z_prp = 10.)
    cube = "0 0 1 1 0 1 1 1 1 0 1 1 0 0 0 1 0 0 1 1 0 0 1 0"
    sol = scanconv.project3d(cube, perspective="one-point", d=10, cop="plus-d")
    t = Fraction(10, 9)
    assert sol.data["projected"] == [[0, 0], [t, 0], [t, t], [0, t], [0, 0], [1, 0], [1, 1], [0, 1]]
    assert [round(float(t), 2)] == [1.11]
    assert sol.data["vanishing_points"] == [None, None, [0, 0]]


def test_the_one_point_matrix_with_the_centre_on_the_negative_z_axis() -> None:
    # http://www.cc.gatech.edu/gvu/multimedia/nsfmmedia/cware/graphics/notes/vue3d/projs/projs06.html
    # centre on the negative z axis, view plane through the origin: rows (1 0 0 0), (0 1 0 0),
    # (0 0 0 0), (0 0 1/d 1); x' = x d/(d + z)
    sol = scanconv.project3d("1 2 3", perspective="one-point", d=4, cop="minus-d")
    q = Fraction(1, 4)
    assert sol.data["matrix"] == [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, q, 1]]
    assert sol.data["projected"] == [[Fraction(4, 7), Fraction(8, 7)]]


PINHOLE = {
    "minus-d": lambda x, z, d: x * d / (z + d),
    "plus-d": lambda x, z, d: x * d / (d - z),
    "origin": lambda x, z, d: x * d / z,
}


@settings(deadline=None, max_examples=60)
@given(
    st.sampled_from(sorted(PINHOLE)),
    st.integers(-20, 20),
    st.integers(-20, 20),
    st.integers(1, 19),
    st.integers(1, 30),
)
def test_perspective_is_the_pinhole_formula(cop: str, x: int, y: int, z: int, d: int) -> None:
    # in front of the centre: 0 < z < d for plus-d, z > 0 for the others
    if cop == "plus-d" and z >= d:
        z = -z
    sol = scanconv.project3d(f"{x} {y} {z}", perspective="one-point", d=d, cop=cop)
    f = PINHOLE[cop]
    assert sol.data["projected"] == [[f(Fraction(x), z, d), f(Fraction(y), z, d)]]


@settings(deadline=None, max_examples=30)
@given(
    st.sampled_from(sorted(PINHOLE)), st.sampled_from([15, 30, 45, 60, 75, -30]), st.integers(2, 9)
)
def test_vanishing_points_are_limits_of_receding_lines(cop: str, phi: int, d: int) -> None:
    sol = scanconv.project3d(
        "0 0 1" if cop == "origin" else "0 0 0",
        perspective="two-point",
        angle=str(phi),
        d=d,
        cop=cop,
        convention="hearn-baker",
    )
    t = math.radians(phi)
    # Ry(phi) turns the x axis to (cos, 0, -sin) and the z axis to (sin, 0, cos)
    dirs = {"x": (math.cos(t), 0, -math.sin(t)), "z": (math.sin(t), 0, math.cos(t))}
    f = PINHOLE[cop]
    start = (0.5, 0.5, 1.0) if cop == "origin" else (0.5, 0.5, 0.0)
    for axis, vp in zip("xyz", sol.data["vanishing_points"], strict=True):
        if axis == "y":
            assert vp is None
            continue
        v = dirs[axis]
        # the far point of the line start + s·v, s large, on the side in front of the centre
        s = 1e7 * (1 if (v[2] > 0) != (cop == "plus-d") else -1)
        p = [start[i] + s * v[i] for i in range(3)]
        far = (f(p[0], p[2], d), f(p[1], p[2], d))
        got = [to_float(w) for w in vp]
        assert np.allclose(got, far, atol=1e-4), (axis, got, far)


_TERM = re.compile(r"([+-]?)(\d+(?:\.\d+)?)?\*?(?:sqrt\((\d+)\))?(?:/(\d+))?")


def to_float(v: object) -> float:
    """A JSON value as a float: a number, or an exact text (``-4*sqrt(3)``, ``1/2 + sqrt(3)/2``)
    read term by term here."""
    if not isinstance(v, str):
        return float(v)  # type: ignore[arg-type]
    total = 0.0
    for m in _TERM.finditer(v.replace(" ", "")):
        sign, num, root, den = m.groups()
        if not (num or root):
            continue
        term = float(num or 1) * (math.sqrt(int(root)) if root else 1) / int(den or 1)
        total += -term if sign == "-" else term
    return total


def test_isometric_foreshortens_every_axis_alike() -> None:
    sol = scanconv.project3d(solid="unit-cube", parallel="isometric")
    fore = next(q for q in sol.derived if q.key == "foreshortening").value
    assert fore == [Fraction(2, 3)] * 3  # sqrt(2/3) = 0.8165 on every axis


@settings(deadline=None, max_examples=20)
@given(st.fractions(min_value=Fraction(1, 10), max_value=1, max_denominator=12))
def test_dimetric_foreshortens_z_to_f_and_x_y_alike(f: Fraction) -> None:
    # Rogers & Adams 3-13: sin^2 theta = f^2/2, sin^2 phi = f^2/(2 - f^2) give f_x = f_y, f_z = f
    from scanconv.algorithms import space

    (cp, sp), (ct, st_) = pj.dimetric(f)
    m = space.compose([space.rotation("y", cp, sp), space.rotation("x", ct, st_), pj.onto_z0()])
    fx, fy, fz = pj.foreshortening(m)
    assert fx == fy and fz == f * f


def test_orthographic_views_drop_one_coordinate() -> None:
    for view, want in (("xy", [1, 2]), ("yz", [2, 3]), ("zx", [1, 3])):
        sol = scanconv.project3d("1 2 3", parallel="orthographic", view=view)
        assert sol.data["projected"] == [want]


def test_row_vectors_show_the_transposed_projection_matrix() -> None:
    col = scanconv.project3d("1 2 3", perspective="one-point", d=4, cop="minus-d")
    row = scanconv.project3d("1 2 3", perspective="one-point", d=4, convention="rogers")
    assert row.data["matrix"] == np.array(col.data["matrix"], dtype=object).T.tolist()
    assert row.data["projected"] == col.data["projected"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--solid", "cube", "--perspective", "one-point", "--d", "1"), "plane of the centre"),
        (("0", "0", "2", "--perspective", "one-point", "--d", "1"), "behind the centre"),
        (("--solid", "cube"), "choose one projection"),
        (("--solid", "cube", "--parallel", "cavalier", "--perspective", "one-point"), "choose one"),
        (("--solid", "cube", "--parallel", "cavalier", "--view", "yz"), "does not apply"),
        (("--solid", "cube", "--perspective", "one-point", "--d", "-2"), "must be positive"),
        (("--solid", "cube", "--parallel", "cavalier", "--angle", "20"), "multiple of 15"),
        (("--solid", "cube", "--parallel", "dimetric", "--ratio", "2"), "(0, 1]"),
        (("--solid", "cube", "--perspective", "two-point", "--angle", "90"), "multiple of 90"),
        (("--solid", "cube", "--parallel", "boxy"), "is not one of"),
        (("1", "2", "--parallel", "cavalier"), "triples"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    r = run("3d", "project", *args)
    assert r.code == 2 and r.out == ""
    assert message in r.err and r.err.count("\n") == 1, r.err

"""3D transformations in homogeneous coordinates, checked against independent computations
written here (floats: the rotation matrices of the textbook formulas, Rodrigues' formula) and
against worked results that hold whatever the source (a 120° turn about (1, 1, 1) permutes the
axes)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import scanconv
from scanconv.algorithms import space
from scanconv.algorithms.radical import approx
from scanconv.algorithms.transform import cos_sin

from .helpers import run

ANGLES = st.integers(-24, 24).map(lambda k: 15 * k)
SMALL = st.integers(-5, 5)


def floats(m: space.Matrix4) -> np.ndarray:
    return np.array([[float(approx(v)) for v in row] for row in m])


def exact_rotation(axis: str, deg: int) -> space.Matrix4:
    from fractions import Fraction

    c, s, _ = cos_sin(Fraction(deg))
    return space.rotation(axis, c, s)


@settings(deadline=None, max_examples=60)
@given(st.sampled_from("xyz"), ANGLES)
def test_rotations_are_orthogonal_with_determinant_one_exactly(axis: str, deg: int) -> None:
    r = exact_rotation(axis, deg)
    assert space.matmul(r, space.transpose(r)) == space.IDENTITY
    assert space.determinant(r) == 1


@settings(deadline=None, max_examples=40)
@given(st.sampled_from("xyz"), ANGLES)
def test_rotations_are_the_textbook_matrices(axis: str, deg: int) -> None:
    # Hearn & Baker 11-2: x' = x cos - y sin about z; y' = y cos - z sin about x;
    # z' = z cos - x sin about y (cyclic permutation x -> y -> z -> x)
    t = math.radians(deg)
    c, s = math.cos(t), math.sin(t)
    want = {
        "z": [[c, -s, 0], [s, c, 0], [0, 0, 1]],
        "x": [[1, 0, 0], [0, c, -s], [0, s, c]],
        "y": [[c, 0, s], [0, 1, 0], [-s, 0, c]],
    }[axis]
    assert np.allclose(floats(exact_rotation(axis, deg))[:3, :3], want)


def rodrigues(p1: np.ndarray, p2: np.ndarray, deg: int) -> np.ndarray:
    """Rodrigues' formula: R = cos θ I + sin θ [u]x + (1 - cos θ) u uᵀ, about the line
    through p1 and p2, as a 4 x 4 affine matrix."""
    u = (p2 - p1) / np.linalg.norm(p2 - p1)
    t = math.radians(deg)
    k = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    r = math.cos(t) * np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * np.outer(u, u)
    out = np.eye(4)
    out[:3, :3] = r
    out[:3, 3] = p1 - r @ p1
    return out


@settings(deadline=None, max_examples=60)
@given(st.tuples(SMALL, SMALL, SMALL), st.tuples(SMALL, SMALL, SMALL), ANGLES)
def test_arbitrary_axis_rotation_is_rodrigues(p1: tuple, p2: tuple, deg: int) -> None:
    if p1 == p2:
        return
    words = " ".join(map(str, (*p1, *p2, deg)))
    m = space.compose([f.matrix for f in _stage(f"--rotate-axis {words}").factors])
    assert np.allclose(
        floats(m), rodrigues(np.array(p1, float), np.array(p2, float), deg), atol=1e-9
    )
    # the answer applies that composite: each vertex where Rodrigues' formula puts it
    sol = scanconv.transform3d(f"1 2 3 --rotate-axis {words}")
    want = rodrigues(np.array(p1, float), np.array(p2, float), deg) @ np.array([1, 2, 3, 1.0])
    assert np.allclose([float(approx(v)) for v in space.apply(m, (1, 2, 3))], want[:3])
    assert len(sol.data["after"]) == 1
    rot = tuple(tuple(r[:3]) for r in m[:3])
    assert space.determinant(rot) == 1  # exactly, square roots and all
    assert space.matmul(rot, space.transpose(rot)) == ((1, 0, 0), (0, 1, 0), (0, 0, 1))


def _stage(words: str):  # type: ignore[no-untyped-def]
    from scanconv.answers.space.transform import parse

    return parse(words.split())[1][0]


def test_a_turn_of_120_about_the_diagonal_permutes_the_axes() -> None:
    # the rotation by 120° about (1, 1, 1) takes x to y, y to z, z to x (Rodrigues; a standard
    # exercise: Hearn & Baker, exercise 11-3)
    sol = scanconv.transform3d("1 0 0 0 1 0 0 0 1 --rotate-axis 0 0 0 1 1 1 120")
    assert sol.data["after"] == [[0, 1, 0], [0, 0, 1], [1, 0, 0]]


def test_rotation_about_an_axis_through_a_point_keeps_the_axis_fixed() -> None:
    sol = scanconv.transform3d("1 0 0 2 1 1 3 2 2 --rotate-axis 1 0 0 2 1 1 45")
    assert sol.data["after"] == [[1, 0, 0], [2, 1, 1], [3, 2, 2]]


def test_fixed_point_scaling_and_the_composite_order() -> None:
    # scale by 2 about (1, 1, 1), then translate: T(1, 0, 0)·T(1,1,1)·S(2)·T(-1,-1,-1)
    sol = scanconv.transform3d("0 0 0 1 1 1 --scale 2 --about 1 1 1 --translate 1 0 0")
    assert sol.data["after"] == [[0, -1, -1], [2, 1, 1]]
    # row vectors: the transposed composite
    row = scanconv.transform3d("0 0 0 --scale 2 --about 1 1 1 --translate 1 0 0", vectors="row")
    assert row.data["matrix"] == np.array(sol.data["matrix"]).T.tolist()


def test_reflection_about_a_plane() -> None:
    # the plane x + y + z - 3 = 0 through (1, 1, 1): the origin goes to (2, 2, 2)
    sol = scanconv.transform3d("0 0 0 1 1 1 --reflect plane 1 1 1 -3")
    assert sol.data["after"] == [[2, 2, 2], [1, 1, 1]]
    assert sol.data["determinant"] == -1
    xy = scanconv.transform3d("1 2 3 --reflect xy --reflect yz --reflect zx")
    assert xy.data["after"] == [[-1, -2, -3]]


def test_shear_and_reversed_sense() -> None:
    sol = scanconv.transform3d("1 1 1 --shear z 2 3")
    assert sol.data["after"] == [[3, 4, 1]]
    ccw = scanconv.transform3d("1 0 0 --rotate-z 90")
    cw = scanconv.transform3d("1 0 0 --rotate-z 90", sense="reversed")
    assert (ccw.data["after"], cw.data["after"]) == ([[0, 1, 0]], [[0, -1, 0]])


PRIMES = (
    "3d transform 1 2 3 --rotate-axis 0 0 0 1 2 0 30 --rotate-axis 0 0 0 1 2 3 15 "
    "--rotate-axis 0 0 0 1 1 3 15 --rotate-axis 0 0 0 1 1 4 15"
)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("3d", "transform", "1", "2", "--translate", "1", "1", "1"), "x y z triples"),
        (("3d", "transform", "1", "2", "3", "--translate", "1", "1"), "needs 3 numbers"),
        (("3d", "transform", "1", "2", "3", "--rotate-x", "north"), "not an angle"),
        (
            ("3d", "transform", "1", "2", "3", "--rotate-axis", "1", "1", "1", "1", "1", "1", "30"),
            "two different points",
        ),
        (("3d", "transform", "1", "2", "3", "--reflect", "plane", "0", "0", "0", "1"), "normal"),
        (("3d", "transform", "1", "2", "3"), "no transformation"),
        (("3d", "transform", "1", "2", "3", "--spin", "3"), "unknown transformation"),
        (("3d", "transform", "1", "2", "3", "--solid", "cube", "--rotate-x", "3"), "not both"),
        (("3d", "transform", *["1"] * 303, "--rotate-x", "3"), "at most 100 vertices"),
        (("3d", "transform", "0", "0", "0", *["--translate", "1", "1", "1"] * 21), "at most 20"),
        (
            # axes whose direction cosines need sqrt(5), sqrt(7), sqrt(11), sqrt(13), sqrt(17):
            # refused before the exact products grow
            tuple(PRIMES.split()),
            "different primes",
        ),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    r = run(*args)
    assert r.code == 2 and r.out == ""
    assert message in r.err and r.err.count("\n") == 1, r.err

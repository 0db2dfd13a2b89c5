"""Back-face detection (``scanconv 3d backface``): each face's normal from its vertices, the
view vector, the sign test and the table of faces, against a published worked example and
against the sign of the dot product computed here."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv import visible_backface
from scanconv.algorithms.visible import SOLIDS

from .helpers import run

# The worked example of expertsmind.com, "Back-Face Detection Method Naming Directions"
# (https://expertsmind.com/topic/algorithm-for-back-face-detection-methodvisual-realism/back-face-detection-method-naming-directions-916029.aspx):
# a tetrahedron PQRS whose outward normals, the cross products of two adjacent edges, are
# N_PQR = -4i + 2j + 6k, N_QSR = 2i + 4j + 2k, N_PRS = -3i - j - 3k, N_PSQ = 5i - 5j - 5k; the
# viewer on +z, so PQR and QSR (k > 0) are visible and PRS and PSQ hidden. The page's figure
# gives the vertices, its text only the normals: the edges follow from the normals (with
# a x b = N_PQR, b x c = N_PRS, c x a = N_PSQ and t = a . (b x c) = 10, a = ((c x a) x (a x b))/t),
# a = (2, 1, 1), b = (0, 3, -1), c = (1, 3, -2), and any tetrahedron with these normals is a
# translate of P, P + a, P + b, P + c. Here P = (1, 1, 1).
P, Q, R, S = (1, 1, 1), (3, 2, 2), (1, 4, 0), (2, 4, -1)
TETRA = {"PQR": (P, Q, R), "QSR": (Q, S, R), "PRS": (P, R, S), "PSQ": (P, S, Q)}
PUBLISHED = {"PQR": (-4, 2, 6), "QSR": (2, 4, 2), "PRS": (-3, -1, -3), "PSQ": (5, -5, -5)}


def _words(faces: dict[str, tuple[tuple[int, int, int], ...]]) -> list[str]:
    out: list[str] = []
    for face in faces.values():
        if out:
            out.append(":")
        out += [str(c) for v in face for c in v]
    return out


def test_the_published_tetrahedron_s_normals_and_verdicts() -> None:
    sol = visible_backface(
        [w if w == ":" else int(w) for w in _words(TETRA)], names=",".join(TETRA)
    )
    faces = sol.data["faces"]
    assert [f["name"] for f in faces] == list(TETRA)
    assert [tuple(f["normal"]) for f in faces] == list(PUBLISHED.values())
    assert [f["back"] for f in faces] == [False, False, True, True]


def test_the_cube_seen_from_plus_z_shows_its_front_face_only() -> None:
    # Hearn & Baker (C version, 2nd ed., section 13-2): viewing along -z, a face is a back
    # face when C <= 0; of the unit cube only the face z = 1 has C > 0
    faces = visible_backface(solid="cube").data["faces"]
    assert [f["name"] for f in faces if not f["back"]] == ["front"]
    visible = visible_backface(solid="cube", edge_on="visible").data["faces"]
    assert [f["name"] for f in visible if f["back"]] == ["back"]


@pytest.mark.parametrize("name", sorted(SOLIDS))
def test_the_named_solids_normals_point_outward(name: str) -> None:
    faces = SOLIDS[name]
    points = {v for f in faces.values() for v in f}
    centre = tuple(Fraction(sum(p[i] for p in points), len(points)) for i in range(3))
    for face in faces.values():
        a, b, c = face[:3]
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - a[i] for i in range(3)]
        n = (
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        )
        mid = [Fraction(sum(v[i] for v in face), len(face)) for i in range(3)]
        assert sum(n[i] * (mid[i] - centre[i]) for i in range(3)) > 0


small = st.integers(-6, 6)
point = st.tuples(small, small, small)


@pytest.mark.slow  # a property of many answers: over 50 ms
@settings(deadline=None)
@given(
    st.lists(st.tuples(point, point, point), min_size=1, max_size=5),
    point,
    st.sampled_from(["into-scene", "to-viewer"]),
    st.sampled_from(["hidden", "visible"]),
)
def test_a_verdict_is_the_sign_of_the_dot_product(
    triangles: list[tuple[tuple[int, int, int], ...]],
    view: tuple[int, int, int],
    direction: str,
    edge_on: str,
) -> None:
    def normal(t: tuple[tuple[int, int, int], ...]) -> tuple[int, int, int]:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t
        u, v = (bx - ax, by - ay, bz - az), (cx - ax, cy - ay, cz - az)
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])

    triangles = [t for t in triangles if normal(t) != (0, 0, 0)]
    if not triangles or view == (0, 0, 0):
        return
    flat: list[object] = []
    for t in triangles:
        flat += [":", *[c for p in t for c in p]]
    faces = visible_backface(flat, view=view, direction=direction, edge_on=edge_on).data["faces"]
    for t, f in zip(triangles, faces, strict=True):
        d = sum(a * b for a, b in zip(view, normal(t), strict=True))
        if d == 0:
            assert f["back"] == (edge_on == "hidden")
        else:
            assert f["back"] == ((d > 0) if direction == "into-scene" else (d < 0))
        assert f["dot"] == d


def test_the_eye_gives_each_face_its_own_view_vector() -> None:
    # the eye at (1/2, 1/2, 5) sees the cube's front face and no other; from (5, 1/2, 1/2) the
    # right face (x = 1) only: V = V1 - E into the scene
    for eye, seen in (
        ((Fraction(1, 2), Fraction(1, 2), 5), "front"),
        ((5, Fraction(1, 2), Fraction(1, 2)), "right"),
    ):
        faces = visible_backface(solid="cube", eye=eye).data["faces"]
        assert [f["name"] for f in faces if not f["back"]] == [seen]


def test_left_handed_axes_look_along_plus_z() -> None:
    faces = visible_backface(solid="cube", handed="left").data["faces"]
    assert [f["name"] for f in faces if not f["back"]] == ["back"]
    assert faces[0]["view"] == [0, 0, 1]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("0", "0", "0", "1", "0", "0", "2", "0", "0"), "lie on one line"),
        (("0", "0", "0", "1", "0", "0", "0", "1", "0", "1", "1", "1"), "not planar"),
        (("--solid", "cube", "0", "0", "0", "1", "0", "0", "0", "1", "0"), "not both"),
        (("--solid", "cube", "--view", "0", "0", "0"), "zero"),
        (("--solid", "cube", "--view", "0", "0", "1", "--eye", "0", "0", "5"), "not both"),
        ((), "give the faces"),
        (("--solid", "cube", "--names", "a,b"), "their own names"),
        (("0", "0", "0", "1", "0", "0", "0", "1", "0", "--names", "a,b"), "2 given for 1 faces"),
        (("0", "0", "0", "1", "0", "0", "0", "1", "0", "--names", "a b"), "up to 12 letters"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: tuple[str, ...], message: str) -> None:
    result = run("3d", "backface", *args)
    assert result.code == 2 and result.out == ""
    assert message in result.err and result.err.count("\n") == 1


def test_the_answer_states_its_conventions() -> None:
    out = run("3d", "backface", "--solid", "pyramid", "--direction", "to-viewer", "-f", "plain").out
    assert "direction = to-viewer" in out and "edge-on = hidden" in out and "handed = right" in out
    # the preset (Hearn & Baker's, the default) is named, and the value given that is not its
    assert "Conventions (preset hearn-baker: Hearn & Baker" in out
    assert "direction = to-viewer, not the preset's into-scene" in out


def test_check_marks_a_student_s_table_of_faces(tmp_path: Path) -> None:
    # the tetrahedron's xy face (N = (0, 0, -1), V.N = 1: hidden) written as visible with V.N = -1
    rows = [
        "face,normal,dot,verdict",
        'xy,"(0, 0, -1)",-1,visible',
        'yz,"(-1, 0, 0)",0,"edge-on, hidden (back face)"',
        'zx,"(0, -1, 0)",0,"edge-on, hidden (back face)"',
        'slant,"(1, 1, 1)",-1,visible',
    ]
    student = tmp_path / "faces.csv"
    student.write_text("\n".join(rows) + "\n", encoding="utf-8")
    result = run(
        "check", str(student), "--", "3d", "backface", "--solid", "tetrahedron", "-f", "plain"
    )
    assert result.code == 0, result.err
    marks = [
        line.split()[-1]
        for line in result.out.splitlines()
        if line.strip().endswith(("right", "wrong"))
    ]
    assert marks == ["wrong", "right", "right", "right"]

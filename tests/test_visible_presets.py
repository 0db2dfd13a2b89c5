"""The visible-surface presets (``--convention hearn-baker|foley|rogers`` of ``3d backface``,
``zbuffer``, ``scanline``, ``depth-sort``, ``warnock``): each answer names its preset and the
values it used, and where the texts differ the verdicts and frames differ as worked here by
hand from the texts' rules (docs/conventions.md, "Visible surfaces: the presets")."""

from __future__ import annotations

import json

import pytest

from scanconv import (
    visible_backface,
    visible_depth_sort,
    visible_scanline,
    visible_warnock,
    visible_zbuffer,
)

from .helpers import assert_refused, run
from .visible_oracle import frame_rows, nearest

#: Each text's values, written from the texts (not read from the library's table):
#: Hearn & Baker, C version, 2nd ed., ch. 13 (V.N > 0 a back face, C <= 0 along -z; the depth
#: buffer from 0, z > depth(x, y)); Foley et al., 2nd ed., 15.2.4 and 15.4 (a nonnegative dot
#: product; the z-buffer from 0, pz >= ReadZ); Rogers, Procedural Elements, 2nd ed., ch. 4
#: (E.[VT] < 0 strictly; the z-buffer from the minimum z, z > Zbuffer).
TEXTS = {
    "hearn-baker": {"direction": "into-scene", "edge-on": "hidden", "handed": "right",
                    "depth": "larger-nearer", "ties": "keep", "clear": "zero"},
    "foley": {"direction": "into-scene", "edge-on": "hidden", "handed": "right",
              "depth": "larger-nearer", "ties": "replace", "clear": "zero"},
    "rogers": {"direction": "into-scene", "edge-on": "visible", "handed": "right",
               "depth": "larger-nearer", "ties": "keep", "clear": "farthest"},
}  # fmt: skip
SOURCE = {"hearn-baker": "Hearn & Baker", "foley": "Foley", "rogers": "Rogers"}

#: A in z = 2 over x + y < 5; B in x + y + z = 6 (the z-buffer's worked example).
AB = [0, 0, 2, 5, 0, 2, 0, 5, 2, ":", 1, 1, 4, 5, 1, 0, 1, 5, 0]
#: Two triangles in one plane z = 1, B drawn second: they overlap at (1, 0), (2, 0), (3, 0)
#: and (2, 1) (A: x + y < 4; B: x >= 1 + y, x < 4; half-open), at equal depths.
COPLANAR = [0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 1, 0, 1, 4, 0, 1, 4, 3, 1]
OVERLAP = {(1, 0), (2, 0), (3, 0), (2, 1)}

ANSWERS = {
    "backface": lambda c: visible_backface(solid="cube", convention=c),
    "zbuffer": lambda c: visible_zbuffer(AB, size="5", convention=c),
    "scanline": lambda c: visible_scanline(AB, size="5", convention=c),
    "depth-sort": lambda c: visible_depth_sort(AB, size="5", convention=c),
    "warnock": lambda c: visible_warnock(AB, size="8", convention=c),
}
KNOBS_OF = {
    "backface": ("direction", "edge-on", "handed"),
    "zbuffer": ("depth", "ties", "clear"),
    "scanline": ("depth", "ties"),
    "depth-sort": ("depth",),
    "warnock": ("depth", "ties"),
}


@pytest.mark.parametrize("command", sorted(ANSWERS))
@pytest.mark.parametrize("preset", sorted(TEXTS))
def test_every_answer_states_its_preset_and_values(command: str, preset: str) -> None:
    sol = ANSWERS[command](preset)
    note = next(n for n in sol.notes if n.startswith("Conventions"))
    assert note.startswith(f"Conventions (preset {preset}: {SOURCE[preset]}")
    for knob in KNOBS_OF[command]:
        assert f"{knob} = {TEXTS[preset][knob]} (" in note, (knob, note)
    assert sol.data["conventions"] == {k: TEXTS[preset][k] for k in KNOBS_OF[command]}
    assert "not the preset's" not in note


def test_the_default_is_hearn_baker_s() -> None:
    for command, answer in ANSWERS.items():
        assert answer(None).notes == answer("hearn-baker").notes, command


def test_the_cube_s_side_faces_edge_on_hidden_or_kept() -> None:
    # The unit cube viewed along -z, V = (0, 0, -1): front N = (0, 0, 1), V.N = -1, visible;
    # back N = (0, 0, -1), V.N = 1, a back face; the four sides V.N = 0: C <= 0 hides them
    # (Hearn & Baker), a nonnegative dot product too (Foley); Rogers' strict test keeps them.
    def seen(preset: str) -> set[str]:
        faces = visible_backface(solid="cube", convention=preset).data["faces"]
        return {f["name"] for f in faces if not f["back"]}

    assert seen("hearn-baker") == seen("foley") == {"front"}
    assert seen("rogers") == {"front", "left", "right", "top", "bottom"}
    out = run("3d", "backface", "--solid", "cube", "--convention", "rogers", "-f", "plain").out
    assert "edge-on = visible (" in out and "edge-on, visible" in out


def test_a_polygon_in_z_0_by_each_text_s_z_buffer() -> None:
    # A: (0, 0, 0) (4, 0, 0) (0, 4, 0), pixels x + y < 4; B: (1, 1, 0) (3, 1, 0) (1, 3, 0),
    # pixels (1, 1), (2, 1), (1, 2); both in z = 0. Hearn & Baker: the buffer is 0 and 0 > 0
    # fails, nothing is drawn. Foley: 0 >= 0, A everywhere, then B replaces it on its three
    # pixels. Rogers: the buffer starts at the minimum, A is drawn, B's equal 0 keeps A.
    polys = [0, 0, 0, 4, 0, 0, 0, 4, 0, ":", 1, 1, 0, 3, 1, 0, 1, 3, 0]
    frames = {
        p: frame_rows(visible_zbuffer(polys, size="4", convention=p).data, 4, 4) for p in TEXTS
    }
    assert frames["hearn-baker"] == ["....", "....", "....", "...."]
    assert frames["foley"] == ["A...", "AB..", "ABB.", "AAAA"]
    assert frames["rogers"] == ["A...", "AA..", "AAA.", "AAAA"]
    hb = visible_zbuffer(polys, size="4")
    assert any("never written" in n for n in hb.notes)  # the answer says why the frame is empty


@pytest.mark.parametrize("answer", [visible_zbuffer, visible_scanline, visible_warnock])
def test_equal_depths_go_to_the_first_or_the_later_polygon(answer) -> None:  # type: ignore[no-untyped-def]
    # Hearn & Baker's and Rogers' strict comparison keeps A where the coplanar B overlaps it;
    # Foley's >= gives those four pixels to B. The rest is the brute-force nearest.
    tris = [((0, 0, 1), (4, 0, 1), (0, 4, 1)), ((1, 0, 1), (4, 0, 1), (4, 3, 1))]
    for preset, winner in (("hearn-baker", "A"), ("rogers", "A"), ("foley", "B")):
        frame = answer(COPLANAR, size="4", convention=preset).data["frame"]
        for p in OVERLAP:
            assert frame[f"{p[0]},{p[1]}"] == winner, (preset, p)
        brute = nearest(tris, 4, 4, "larger-nearer", TEXTS[preset]["ties"])
        assert {k: v for k, v in frame.items()} == {
            f"{x},{y}": "AB"[i] for (x, y), (i, _) in brute.items()
        }


def test_an_option_overrides_one_value_of_the_preset_and_says_so() -> None:
    out = run("3d", "zbuffer", *map(str, AB), "--size", "5", "--convention", "foley",
              "--ties", "keep", "-f", "json").out  # fmt: skip
    data = json.loads(out)
    assert data["conventions"] == {**{k: TEXTS["foley"][k] for k in KNOBS_OF["zbuffer"]},
                                   "ties": "keep"}  # fmt: skip
    note = next(n for n in data["notes"] if n.startswith("Conventions"))
    assert "preset foley" in note and "ties = keep, not the preset's replace" in note
    # with a smaller z nearer a preset's 0 is no back plane: the buffer starts at +inf
    sol = visible_zbuffer(AB, size="5", depth="smaller-nearer", convention="foley")
    assert sol.data["conventions"]["clear"] == "farthest"


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (("3d", "zbuffer", *map(str, AB), "--convention", "nope"), ("convention",)),
        (("3d", "backface", "--solid", "cube", "--convention", "hearn"), ("convention",)),
        (("3d", "zbuffer", *map(str, AB), "--depth", "smaller-nearer", "--clear", "zero"),
         ("clear zero",)),
        (("3d", "zbuffer", *map(str, AB), "--far", "1", "--clear", "zero"), ("far",)),
    ],
)  # fmt: skip
def test_bad_conventions_are_one_line_exit_2(args: tuple[str, ...], words: tuple[str, ...]) -> None:
    assert_refused(run(*args), *words)

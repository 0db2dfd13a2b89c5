"""Practice questions on clipping against a window of any shape and on a font's bytes
(scanconv.practice.windows, through ``practice("clip")`` and ``practice("characters")``):
every kind comes up, every question is answered over many seeds, and each answer is the
question it claims to be, judged by an independent computation: the clipped polygon's area
is the intersection shapely computes (and not 0, nor the whole polygon), a touching case's
polygons meet on their boundaries without only crossing there, a font table's address is
base + index x bytes a glyph worked here by hand, a glyph's bytes are its rows read as
binary numbers."""

from __future__ import annotations

import shlex

import pytest
from shapely.geometry import Point, Polygon

from scanconv import questions
from scanconv.algorithms import characters as ch
from scanconv.practice.beyond import KINDS
from scanconv.practice.notes import practice

NEW_CLIP = ("sutherland-hodgman triangle", "sutherland-hodgman hexagon", "weiler-atherton touching")
NEW_CHAR = ("font table", "glyph bytes")
SEEDS = range(25)


def _new(topic: str, kinds: tuple[str, ...], seed: int, difficulty: str) -> list:
    qs = practice(topic, len(KINDS[topic]), seed=seed, difficulty=difficulty)
    return [q for q in qs if q.features & set(kinds)]


def _flat_pairs(words: list[str]) -> list[tuple[int, int]]:
    values = [int(w) for w in words]
    return list(zip(values[::2], values[1::2], strict=True))


def _split(argv: tuple[str, ...]) -> tuple[list[tuple[int, int]], list[tuple[int, int]]]:
    at, end = argv.index("--window-vertices"), argv.index("--method")
    return _flat_pairs(list(argv[2:at])), _flat_pairs(list(argv[at + 1 : end]))


def test_the_new_kinds_are_in_the_rotation() -> None:
    assert set(NEW_CLIP) <= set(KINDS["clip"]) and set(NEW_CHAR) <= set(KINDS["characters"])
    shown = {f for q in practice("clip", len(KINDS["clip"]), seed=3) for f in q.features}
    assert set(NEW_CLIP) <= shown and {"triangular window", "hexagonal window"} <= shown
    shown = {
        f for q in practice("characters", len(KINDS["characters"]), seed=3) for f in q.features
    }
    assert set(NEW_CHAR) <= shown


@pytest.mark.slow  # 225 answers: outside the inner loop
@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_sutherland_hodgman_against_a_shaped_window_leaves_the_intersection(
    difficulty: str,
) -> None:
    """Over many seeds: the window is convex and counter-clockwise, and the clipped polygon's
    area is shapely's intersection area, more than 0 and less than the polygon's own."""
    for seed in SEEDS:
        for q in _new("clip", NEW_CLIP[:2], seed, difficulty):
            poly, window = _split(q.argv)
            w = Polygon(window)
            assert w.is_valid and w.exterior.is_ccw and w.convex_hull.area == w.area, q.argv
            sol = questions.answer(list(q.argv))
            want = Polygon(poly).intersection(w).area
            assert 0 < want < Polygon(poly).area, q.argv
            area = next(d.value for d in sol.derived if d.key == "area")
            assert float(area) == pytest.approx(want), q.argv


@pytest.mark.slow  # 75 answers: outside the inner loop
@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_weiler_atherton_touching_cases_touch_and_clip(difficulty: str) -> None:
    """The polygons' boundaries meet in a point or a segment where they do not cross (shapely:
    the boundaries' intersection includes a vertex of one lying on the other's edge, or a
    segment); the answer labels a point touch, and its output's area is shapely's."""
    for seed in SEEDS:
        for q in _new("clip", NEW_CLIP[2:], seed, difficulty):
            poly, clip = _split(q.argv)
            a, b = Polygon(poly), Polygon(clip)
            meet = a.boundary.intersection(b.boundary)
            on_edge = any(b.boundary.distance(Point(p)) == 0 for p in poly)
            assert on_edge or meet.length > 0, q.argv
            sol = questions.answer(list(q.argv))
            labels = " ".join(str(r) for t in sol.tables for r in t.rows())
            assert "touch" in labels, q.argv
            area = sum(abs(Polygon([(float(x), float(y)) for x, y in p]).area)
                       for p in sol.data["polygons"])  # fmt: skip
            assert area == pytest.approx(a.intersection(b).area) and area > 0, q.argv


def test_font_table_questions_give_base_plus_index_times_glyph_bytes() -> None:
    """A glyph of w x h in whole bytes per row takes h x ceil(w/8) bytes; the glyph of C
    starts at base + (code(C) - first) x that, worked here from the question's own words."""
    seen = 0
    for seed in SEEDS:
        for d in ("easy", "exam", "hard"):
            for q in _new("characters", ("font table",), seed, d):
                args = q.argv
                count, w, h = (int(v) for v in args[2:5])
                char = args[args.index("--char") + 1]
                first = int(args[args.index("--first") + 1])
                base = int(args[args.index("--base") + 1], 0)
                per = h * -(-w // 8)
                sol = questions.answer(list(args))
                address = next(x.value for x in sol.derived if x.key == "address")
                assert address == base + (ord(char) - first) * per, shlex.join(args)
                assert 0 <= ord(char) - first < count
                seen += 1
    assert seen > 20


def test_glyph_bytes_questions_give_each_row_read_as_a_binary_number() -> None:
    """Each row of the glyph, padded with 0 to 8 bits, read as a binary number (msb) or
    backwards (lsb): the byte the answer gives for that row."""
    seen = set()
    for seed in SEEDS:
        for q in _new("characters", ("glyph bytes",), seed, "exam"):
            char, order = q.argv[2], q.argv[q.argv.index("--bit-order") + 1]
            rows = ch.glyph(char, None)
            padded = [r.ljust(8, "0") for r in rows]
            want = [int(p if order == "msb" else p[::-1], 2) for p in padded]
            sol = questions.answer(list(q.argv))
            assert [b[0] for b in sol.data["bytes"]] == want, q.argv
            seen.add(order)
    assert seen == {"msb", "lsb"}


def test_a_touching_case_and_a_font_question_answer_on_the_command_line() -> None:
    from .helpers import run

    for topic, kind in (("clip", "weiler-atherton touching"), ("characters", "font table")):
        q = next(q for q in practice(topic, len(KINDS[topic]), seed=5) if kind in q.features)
        r = run(*q.argv, "--format", "plain")
        assert r.code == 0 and r.out and r.err == "", (q.argv, r.err)


def _with(topic: str, kind: str, seed: int, difficulty: str) -> list:
    qs = practice(topic, len(KINDS[topic]), seed=seed, difficulty=difficulty)
    return [q for q in qs if kind in q.features]


def _after(argv: tuple[str, ...], flag: str, n: int) -> list[int]:
    at = argv.index(flag) + 1
    return [int(v) for v in argv[at : at + n]]


@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_midpoint_edge_stop_questions_land_a_midpoint_on_the_edge(difficulty: str) -> None:
    """The line's ends are as far left and right of the window's left edge, so the first
    midpoint is on it (by hand: (x1 + x2) / 2 = x_min); the answer stops there, and the
    visible piece starts at that midpoint."""
    for seed in SEEDS:
        for q in _with("clip", "midpoint-subdivision edge stop", seed, difficulty):
            x1, x2 = int(q.argv[2]), int(q.argv[4])
            xmin = _after(q.argv, "--window", 4)[0]
            assert (x1 + x2) == 2 * xmin and x1 < xmin < x2, q.argv
            sol = questions.answer(list(q.argv))
            actions = [row[5] for row in sol.tables[0].rows()]
            assert "edge point" in actions, q.argv
            (start, _end), *_ = sol.data["visible"]
            assert start[0] == xmin, q.argv


@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_left_bottom_questions_put_points_on_the_boundary(difficulty: str) -> None:
    """A rectangle from (0, 0): a point with x = 0 or y = 0 is inside by the left-bottom rule,
    one with x = w or y = h outside, one strictly inside inside (worked here from the point
    alone); each question has one on each kind of edge and the answer says the same."""
    for seed in SEEDS:
        for q in _with("inside", "left-bottom", seed, difficulty):
            w, h = _after(q.argv, "inside", 8)[4:6]
            at = q.argv.index("--points") + 1
            points = _flat_pairs(list(q.argv[at : at + 6]))
            want = ["outside" if x == w or y == h else "inside" for x, y in points]
            assert sorted(want) == ["inside", "inside", "outside"], q.argv
            sol = questions.answer(list(q.argv))
            verdicts = next(t for t in sol.tables if t.title.startswith("Verdicts"))
            got = [str(row[3]).split()[0] for row in verdicts.rows()]
            assert got == want, q.argv


@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_mask_lsb_questions_apply_the_written_mask_backwards(difficulty: str) -> None:
    """Pixel k is drawn when bit k mod n of the mask as written is 1, bit 0 the rightmost
    character: the mask read from its right-hand end."""
    for seed in SEEDS:
        for q in _with("attributes", "mask lsb", seed, difficulty):
            mask = q.argv[q.argv.index("--mask") + 1]
            sol = questions.answer(list(q.argv))
            drawn = [s.extra[2] == "draw" for s in sol.steps()]
            want = [mask[::-1][k % len(mask)] == "1" for k in range(len(drawn))]
            assert drawn == want and any(drawn) and not all(drawn), q.argv

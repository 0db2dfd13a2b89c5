"""Practice on the topics beyond the notes' own (scanconv.practice.beyond): line
attributes, characters, the midpoint line, anti-aliasing and NLL clipping: the same seed gives the same
questions, every kind comes in as many questions, each is worded with its method and answered
by scanconv, and the CLI writes a worksheet and its key."""

from __future__ import annotations

import shlex

import pytest

from scanconv.practice.beyond import KINDS
from scanconv.practice.notes import TOPICS, practice

from .helpers import run

NEW = ("attributes", "characters", "midpoint-line", "antialias", "visible")


def test_the_topics_are_offered() -> None:
    assert set(NEW) <= set(TOPICS)
    assert "nicholl-lee-nicholl" in KINDS["clip"]


@pytest.mark.parametrize("topic", NEW)
@pytest.mark.parametrize("seed", [0, 5])
def test_deterministic_by_seed(topic: str, seed: int) -> None:
    assert practice(topic, 6, seed=seed) == practice(topic, 6, seed=seed)
    assert practice(topic, 6, seed=seed) != practice(topic, 6, seed=seed + 1)


@pytest.mark.parametrize("topic", NEW)
def test_every_kind_in_as_many_questions(topic: str) -> None:
    qs = practice(topic, len(KINDS[topic]), seed=2)
    shown = {f for q in qs for f in q.features}
    if topic == "midpoint-line":
        assert {f"octant {o}" for o in range(1, 9)} <= shown and "tie" in shown
    else:
        assert set(KINDS[topic]) <= shown


def test_the_wording_names_the_method() -> None:
    for q in practice("midpoint-line", 4, seed=1):
        assert q.argv[-2:] == ("--algo", "midpoint") and "midpoint line algorithm" in q.wording
    for q in practice("attributes", 4, seed=1):
        assert q.argv[0] in ("linestyle", "thickline")
        assert ("mask" in q.wording) == (q.argv[0] == "linestyle")
        assert ("brush" in q.wording) == ("--brush" in q.argv)
    for q in practice("antialias", 8, seed=1):
        wu, coverage = "wu" in q.argv, "coverage" in q.argv
        assert ("Wu's anti-aliased line algorithm" in q.wording) == wu
        assert ("weighted by the part of their column" in q.wording) == coverage
        assert ("3 x 3 sub-pixel grid (Hearn & Baker)" in q.wording) == ("subpixel" in q.argv)
        assert ("area sampling" in q.wording) == ("area" in q.argv)
    nll = [q for q in practice("clip", 6, seed=3) if "nicholl-lee-nicholl" in q.argv]
    assert nll and "Nicholl-Lee-Nicholl line clipping" in nll[0].wording


@pytest.mark.parametrize("topic", [*NEW, "clip"])
@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_every_question_is_answered(topic: str, difficulty: str) -> None:
    from scanconv import questions

    for q in practice(topic, len(KINDS[topic]), seed=7, difficulty=difficulty):
        sol = questions.answer(list(q.argv))
        assert sol.title, q.argv


def test_cli_worksheet_and_key(tmp_path) -> None:
    sheet, key = tmp_path / "w.md", tmp_path / "k.md"
    r = run("practice", "--topic", "characters", "--count", "3", "--seed", "4", "-o", str(sheet),
            "--key", str(key))  # fmt: skip
    assert r.code == 0, r.err
    first = practice("characters", 3, seed=4)[0]
    assert first.wording in sheet.read_text(encoding="utf-8")
    assert shlex.join(first.argv).split()[0] == "char"
    assert key.read_text(encoding="utf-8") != sheet.read_text(encoding="utf-8")

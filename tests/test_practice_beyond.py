"""Practice questions beyond the notes (scanconv.practice.beyond): seeded, every kind
shown, worded with the method's own name, and answered by scanconv itself."""

from __future__ import annotations

import pytest

from scanconv.answers.methods import method
from scanconv.practice.beyond import KINDS
from scanconv.practice.notes import practice

TOPICS = sorted(KINDS)


@pytest.mark.parametrize("topic", TOPICS)
def test_the_same_seed_gives_the_same_questions(topic: str) -> None:
    assert practice(topic, 6, seed=4) == practice(topic, 6, seed=4)


@pytest.mark.parametrize("topic", TOPICS)
def test_every_kind_comes_in_as_many_questions(topic: str) -> None:
    qs = practice(topic, len(KINDS[topic]), seed=11)
    shown = {f for q in qs for f in q.features}
    kinds = {str(k) for k in KINDS[topic]} if topic != "inside" else set()
    assert kinds <= shown


def test_clipping_questions_use_the_method_names() -> None:
    for q in practice("clip", 5, seed=2):
        name = q.argv[q.argv.index("--method") + 1]
        assert method("clip", name).title in q.wording


@pytest.mark.parametrize("topic", TOPICS)
@pytest.mark.parametrize("difficulty", ["easy", "exam", "hard"])
def test_every_question_is_answered(topic: str, difficulty: str) -> None:
    from scanconv import questions

    for q in practice(topic, len(KINDS[topic]), seed=7, difficulty=difficulty):
        sol = questions.answer(list(q.argv))
        assert sol.title

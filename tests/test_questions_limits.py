"""The question language's limits and work budget at its entry points (attack report N8, N2):
``scanconv.questions.parse``, ``answer`` and ``read_questions`` refuse a question longer than a
line of a question file, or a text larger than a question file, before any work, and
``check_budget`` refuses a question beyond a format's budget as the command line does. "Before
any work" is counted in calls (of Python functions and built-ins alike), never timed: parsing the
refused questions takes from tens of thousands to millions of calls; a refusal takes a few."""

from __future__ import annotations

import pytest

from scanconv import questions
from scanconv.questions.files import MAX_FILE_BYTES, MAX_LINE_CHARS
from scanconv.render import Format
from scanconv.render.budget import BudgetError

from .helpers import interpreter_calls, run

FEW = 2_000
"""Calls a refusal before any work may take (the length check is a handful; the margin is
for the exception's machinery)."""


def _refusal(fn, *args):  # type: ignore[no-untyped-def]
    try:
        fn(*args)
    except ValueError as err:
        return str(err)
    raise AssertionError(f"{fn.__name__} accepted it")


# the attack's questions (attack-report N8), cut to just over the limit: the same refusal,
# and the calls it took before the fix grow with the size (28 s at 400 KB)
LONG = {
    "answer: a polygon of 1,251 vertices": (questions.answer, "polygon " + "0 0 1 0 " * 1250),
    "parse: a question of 1,001 options": (questions.parse, "line 1 2 3 4 " + "--no-grid " * 1000),
    "parse: a list of words": (
        questions.parse,
        ["line", "1", "2", "3", "4"] + ["--no-grid"] * 1000,
    ),
}


@pytest.mark.parametrize("name", LONG)
def test_a_question_longer_than_a_line_is_refused_before_it_is_read(name: str) -> None:
    fn, question = LONG[name]
    refusal, calls = interpreter_calls(_refusal, fn, question, stop_after=FEW)
    assert refusal.startswith("a question of ") and refusal.endswith(
        f"characters; at most {MAX_LINE_CHARS:,} characters"
    )
    assert calls < FEW, calls


def test_a_question_as_long_as_a_line_is_read() -> None:
    question = "line 1 2 3 4 --no-grid"
    question += " " * (MAX_LINE_CHARS - len(question))
    assert questions.parse(question).display["grid"] is False
    assert questions.parse([*question.split(), "--no-grid"]).display["grid"] is False


TEXTS = {
    "a million and one line ends": "\r" * (MAX_FILE_BYTES + 1) + "circle 2",
    "comment lines": "# c\n" * (MAX_FILE_BYTES // 4) + "circle 2\n",
    "two-byte characters": "# " + "é" * (MAX_FILE_BYTES // 2) + "\ncircle 2\n",
}


@pytest.mark.parametrize("name", TEXTS)
def test_a_text_larger_than_a_question_file_is_refused_before_it_is_read(name: str) -> None:
    text = TEXTS[name]
    assert len(text.encode()) > MAX_FILE_BYTES
    refusal, calls = interpreter_calls(_refusal, questions.read_questions, text, stop_after=FEW)
    assert refusal == f"QUESTIONS is larger than {MAX_FILE_BYTES:,} bytes"
    assert calls < FEW, calls


def test_a_text_as_large_as_a_question_file_is_read() -> None:
    comment = "#" * 99 + "\n"
    text = "circle 2\n" + comment * ((MAX_FILE_BYTES - 9) // 100) + "#" * 90 + "\n"
    assert len(text.encode()) == MAX_FILE_BYTES
    assert [q.argv for q in questions.read_questions(text).questions] == [("circle", "2")]


# --- the budget -----------------------------------------------------------------------------

OVER = {  # question, format: refused by the command line in that format (attack-report N2)
    ("circle 2800000", "html"),
    ("circle 2800000", "json"),
    ("line 0 0 1999999 1", "html"),
    ("line 0 0 1000000 1 --algo wu", "markdown"),
    ("sample 'x + y' --size 4096 --levels 4", "latex"),
}


@pytest.mark.parametrize(("question", "fmt"), sorted(OVER))
def test_check_budget_refuses_what_the_cli_refuses_in_its_words(question: str, fmt: str) -> None:
    import shlex

    line = questions.parse(question)
    with pytest.raises(BudgetError) as caught:
        questions.check_budget(line, fmt)
    cli = run(*shlex.split(question), "--format", fmt)
    assert cli.code == 2 and cli.out == ""
    # the CLI's message is the library's, with its way out as its own options
    assert cli.err.startswith(f"scanconv: error: {caught.value}")
    assert "\n" not in str(caught.value)
    assert "--" not in str(caught.value)  # the library names formats, never a flag


def test_check_budget_passes_what_the_cli_prints() -> None:
    for question, fmt in (("circle 2800000", "csv"), ("line 0 0 1999999 1", "json")):
        assert questions.check_budget(questions.parse(question), fmt) is None
        assert questions.check_budget(questions.parse(question), Format(fmt)) is None


def test_answer_checks_the_budget_before_any_work() -> None:
    """A line no format prints: refused in a few calls (computing its billion rows would
    never end)."""
    refusal, calls = interpreter_calls(_refusal, questions.answer, "line 0 0 1000000000 1")
    assert refusal.startswith("the table has about 1,000,000,001 rows; no format prints")
    assert calls < 50_000, calls  # loading the grammar and the estimate: not a row


def test_check_budget_is_a_public_name_of_the_question_api() -> None:
    assert "check_budget" in questions.__all__
    assert questions.check_budget.__module__ == "scanconv.questions.budget"

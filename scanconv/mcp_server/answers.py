"""What each tool answers, computed by the library: no SDK here (:mod:`.server` wraps these).

Every question goes through the library's one question pipeline
(:func:`scanconv.questions.answered`: the command line's own words and messages, and the
budget of every format the answer is written in, before any work).
Bad input is a ``ValueError`` whose text is scanconv's one line; the server returns it as the
tool's error. Nothing here reads or writes a file: a question that names one (``-o``,
``--svg``, ``--png``) or a format (``--format``) has those words dropped, as the site's page
drops them (:func:`scanconv.site.page._words`): the answer comes as JSON and Markdown.
"""

from __future__ import annotations

import json
import shlex
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, NamedTuple

from .. import questions
from ..core import lazy
from ..core.records import Solution
from ..questions import limits
from ..questions.parser import CommandLine
from ..render import Format, Options, render
from ..site.page import _words

if TYPE_CHECKING:
    from ..marking import mark as answers_marking
    from ..marking import student_table
    from ..practice import notes as answers_practice
    from ..questions import marking as questions_marking
else:  # each only for the tool that needs it
    answers_marking = lazy.module("scanconv.marking.mark")
    answers_practice = lazy.module("scanconv.practice.notes")
    student_table = lazy.module("scanconv.marking.student_table")
    questions_marking = lazy.module("scanconv.questions.marking")

SHOWN = (Format.json, Format.markdown)
"""The formats every answer is written in (its budget is checked in each)."""

MAX_PRACTICE = 20
"""Most questions of one practice call: each comes with its whole key, which a chat reads."""

TABLE_NAME = "the table"
"""What a marked table is called in the marking's messages (it has no file name)."""


class Reply(NamedTuple):
    """A tool's answer: the structured content, the text for the model and the structured
    content's JSON text (for an answer, exactly what ``--format json`` writes)."""

    data: dict[str, Any]
    text: str
    data_text: str

    @classmethod
    def of(cls, data_text: str, text: str) -> Reply:
        """The reply whose structured content is ``data_text`` read."""
        return cls(json.loads(data_text), text, data_text)

    @classmethod
    def made(cls, data: dict[str, Any], text: str) -> Reply:
        """The reply whose structured content is ``data``, written as JSON."""
        return cls(data, text, json.dumps(data, ensure_ascii=False) + "\n")


def text_of(chunks: Iterable[object]) -> str:
    """The text a renderer yields (its notices left out)."""
    return "".join(c for c in chunks if isinstance(c, str))


def _question(question: str, where: str = "the server") -> tuple[CommandLine, Options]:
    """A question parsed, with the options it is shown with."""
    limits.check_question_size(question)  # before it is split into words
    line = questions.parse(_words(question))
    return line, questions.shown_with(line, where)


def _shown(solution: Solution, options: Options) -> tuple[str, str]:
    """The answer's stable JSON text (as ``--format json`` writes it) and its Markdown."""
    data = text_of(render(solution, Format.json, options))
    return data, text_of(render(solution, Format.markdown, options))


def solve(question: str) -> Reply:
    """The worked answer of ``question``: its stable JSON and its Markdown.

    >>> r = solve("line 5 5 13 9 --algo bresenham")
    >>> r.data["conventions"], [s["p"] for s in r.data["steps"]][:3]
    ({'tie': 'step', 'start': 'swap'}, [0, -8, 0])
    >>> solve("line 2 2 10")
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: Missing argument 'Y2'.
    """
    line, options = _question(question)
    data, text = _shown(questions.answered(line, SHOWN)[1], options)
    return Reply.of(data, text)


def page(question: str) -> str:
    """The step-through page (``--format html``, with its test-yourself mode) of
    ``question``: what the MCP App view shows."""
    line, options = _question(question)
    return text_of(render(questions.answered(line, [Format.html])[1], Format.html, options))


def check(question: str, table: str) -> Reply:
    """``table`` (a student's table as text: CSV, a Markdown pipe table, plain columns or
    JSON) marked against ``question``: the score, the first error, the diagnosis.

    >>> r = check("line 2 2 10 6", "k,p,pixel\\n0,0,(3,3)\\n")
    >>> r.data["score"], r.data["out_of"]
    (1, 8)
    """
    limits.check_question_size(question)
    line = questions_marking.marking_line(_words(question))
    solution = questions_marking.marking_answer(line, SHOWN)
    text = student_table.checked_text(table, TABLE_NAME)
    marked = answers_marking.mark_text(text, solution, TABLE_NAME)
    result = answers_marking.marking_solution(marked, solution, TABLE_NAME, shlex.join(line.words))
    data, shown = _shown(result, Options())
    return Reply.of(data, shown)


def practice(topic: str, count: int, seed: int, difficulty: str) -> Reply:
    """``count`` practice questions on ``topic`` from ``seed``, each with its key (the same
    arguments, the same questions: :func:`scanconv.practice.notes.practice`).

    >>> r = practice("line", 2, 7, "exam")
    >>> [q["question"] for q in r.data["questions"]] == [q["question"] for q in practice("line", 2, 7, "exam").data["questions"]]
    True
    """
    if not 1 <= count <= MAX_PRACTICE:
        raise ValueError(f"count must be 1 to {MAX_PRACTICE} (got {count})")
    if not 0 <= seed <= 10**9:
        raise ValueError(f"seed must be 0 to 1,000,000,000 (got {seed})")
    chosen = answers_practice.practice(topic, count, seed, difficulty)
    items: list[dict[str, Any]] = []
    lines = [f"# Practice: {topic}, {difficulty}, seed {seed}", ""]
    keys = ["", "## Key", ""]
    for n, q in enumerate(chosen, 1):
        words = shlex.join(q.argv)
        _, solution = questions.answered(list(q.argv), SHOWN)
        data, shown = _shown(solution, Options(brief=True))
        items.append(
            {
                "number": n,
                "wording": q.wording,
                "marks": q.marks,
                "question": words,
                "answer": json.loads(data),
            }
        )
        lines.append(f"{n}. {q.wording} [{q.marks} marks] (`{words}`)")
        keys += [f"### {n}. `{words}`", "", shown.strip(), ""]
    reply = {"topic": topic, "difficulty": difficulty, "seed": seed, "questions": items}
    return Reply.made(reply, "\n".join(lines + keys).rstrip() + "\n")


def theory(topic: str) -> Reply:
    """The model answer to a theory question (``scanconv theory TOPIC``).

    >>> theory("dda").data["title"]
    'Describe the DDA algorithm for line drawing'
    """
    return solve(shlex.join(["theory", topic]))

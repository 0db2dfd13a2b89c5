"""What the site runs in the browser: one question in, the worked answer out.

:func:`answer` takes a question as scanconv's own arguments (``line 2 2 10 6 --algo dda``,
read by the library's parser, :mod:`scanconv.questions`, the same one ``sheet`` uses) and
returns a JSON object: the answer's title, its HTML step-through page (``--format html``) and
its data (``--format json``), or the one-line error scanconv gives for that question. Before
any work the question goes through the library's checks, the ones the command line makes: its
length (:data:`~scanconv.questions.limits.MAX_LINE_CHARS`, before it is split into words) and
the work budget in html and in json (:func:`scanconv.questions.check_budget`), so a question
the command line refuses at once (``circle 2800000``) is refused here at once too. Nothing
here needs numpy, typer or rich (Pyodide has none of them).
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from ..core import lazy
from ..core.checks import InputError
from ..render import Format, Notice, render

if TYPE_CHECKING:
    from .. import questions
    from ..marking import mark as marking
    from ..questions import limits, parser
    from ..questions import marking as questions_marking
    from ..render.html import selftest_marks
else:
    questions = lazy.module("scanconv.questions")
    limits = lazy.module("scanconv.questions.limits")
    parser = lazy.module("scanconv.questions.parser")
    marking = lazy.module("scanconv.marking.mark")
    questions_marking = lazy.module("scanconv.questions.marking")
    selftest_marks = lazy.module("scanconv.render.html.selftest_marks")

EXAMPLES = (
    "line 2 2 10 6 --algo bresenham",
    "line 2 2 10 6 --algo dda",
    "circle 8 --method midpoint",
    "ellipse 8 6",
    "bezier 0 0 1 2 3 3 4 0",
    "bspline 0 0 1 2 3 3 4 0 5 2 --degree 2",
    "clip line 7 9 11 4 --window 4 4 10 8",
    "fill flood 2 0 4 2 2 4 0 2 --seed 2 2",
    "polygon 1 1 9 1 9 7 5 3 1 7",
    "compare line 2 2 8 5",
    "theory bresenham-line",
)
"""Questions the page offers to try, one click each."""

_DROPPED = ("--format", "-f", "--output", "-o", "--svg", "--png")


def _words(question: str) -> list[str]:
    """The question's words, without a leading ``scanconv`` (a line copied from the cheat
    sheet) and without the options that choose a format or a file (``--format``, ``-o``,
    ``--svg``, ``--png``) and their values: the page shows the answer in its own formats.

    >>> _words("scanconv line 2 2 10 6 -f json --svg=a.svg -o a.md")
    ['line', '2', '2', '10', '6']
    """
    words = parser.split(question)
    if words[:1] == ["scanconv"]:
        words = words[1:]
    out: list[str] = []
    skip = False
    for w in words:
        if skip:
            skip = False
        elif w in _DROPPED:
            skip = True
        elif not w.startswith(tuple(f"{o}=" for o in _DROPPED)):
            out.append(w)
    return out


def solve_page(question: str) -> dict[str, Any]:
    """The answer to ``question`` as the page shows it: ``{"ok": True, "title", "html",
    "json", "notes", "question"}`` (``notes``: what a large answer's page leaves out), or
    ``{"ok": False, "error"}`` with scanconv's one-line message.

    >>> r = solve_page("line 0 0 3 1 --algo dda")
    >>> r["ok"], r["title"], json.loads(r["json"])["algorithm"]
    (True, 'Simple DDA line algorithm: (0, 0) to (3, 1)', 'dda')
    >>> solve_page("line 2 2 10")["error"]
    "Missing argument 'Y2'."
    >>> solve_page("circle 2800000")["error"]  # doctest: +ELLIPSIS
    'the table has about 1,979,900 rows; circle/midpoint in html costs ...; scanconv on a computer prints it as csv'
    """
    try:
        limits.check_question_size(question)  # before it is split into words
        line = questions.parse(_words(question))
        options = questions.shown_with(line, "the page")
        # the library's one pipeline: the budget of the page's two formats before any work
        solution = _answered(line, (Format.html, Format.json))
        chunks = list(render(solution, Format.html, options))
        html = "".join(c for c in chunks if isinstance(c, str))
        notes = [c.message for c in chunks if isinstance(c, Notice)]  # what the page leaves out
        data = "".join(c for c in render(solution, Format.json, options) if isinstance(c, str))
    except ValueError as err:
        return {"ok": False, "error": " ".join(str(err).split())}
    except RecursionError:
        return {"ok": False, "error": "input too deeply nested"}
    except ImportError as err:  # numpy, for sample: Pyodide has none
        return {
            "ok": False,
            "error": f"this command needs {err.name or 'a package'}, which the browser's Python "
            "does not have: run it with scanconv on a computer",
        }
    return {
        "ok": True,
        "title": solution.title,
        "html": html,
        "json": data,
        "notes": notes,
        "question": question,
    }


def _answered(line: parser.CommandLine, formats: tuple[Format, ...]) -> Any:
    """:func:`scanconv.questions.answered` in ``formats``, a refusal by the budget ending
    with the formats of the command line that would print the answer (the page shows html
    and json only)."""
    try:
        return questions.answered(line, formats)[1]
    except ValueError as err:
        ways = [w for w in getattr(err, "ways", ()) if w not in ("html", "json", "raster")]
        if not ways:
            raise
        words = ways[0] if len(ways) == 1 else ", ".join(ways[:-1]) + " or " + ways[-1]
        raise ValueError(f"{err}; scanconv on a computer prints it as {words}") from None


def warm() -> None:
    """Answer a small question once, so that what every answer imports (the question
    language, the HTML and JSON renderers, the MathML of the working) is loaded while the page
    says it is loading, and the first answer takes what later ones do.

    >>> warm()
    """
    solve_page(EXAMPLES[0])


MAX_STEPS = 1000
"""Most steps of "Test yourself" :func:`judge` marks (the page asks at most
:data:`~scanconv.render.html.stepper.MAX_TABLE_ROWS`, 1,000; the site's script forwards as many)."""


def judge(question: str, steps: str) -> str:
    """The verdict on the last of the steps a student has typed into "Test yourself" on the
    answer to ``question`` (``steps``: a JSON list of ``{"p", "decision", "pixel"}``, the
    DDA's ``{"exact", "pixel"}``), judged by the library's marking, the follow-through of
    ``check`` (:func:`scanconv.marking.mark.mark_steps`), as JSON
    (:func:`scanconv.render.html.selftest_marks.feedback`), or ``{"error"}``.

    >>> steps = [{"p": "0", "decision": "NE", "pixel": "3, 3"},
    ...          {"p": "8", "decision": "NE", "pixel": "4, 4"}]
    >>> r = json.loads(judge("line 2 2 10 6", json.dumps(steps)))
    >>> r["mark"], r["expected"], r["score"]
    ('wrong', 'p = -8, NE, (4, 4)', [1, 2])
    >>> json.loads(judge("line 2 2 10 6", "[1]"))
    {'error': 'the steps are not a list of answers'}
    """
    try:
        limits.check_question_size(question)
        typed = json.loads(steps)
        if not isinstance(typed, list) or not all(
            isinstance(s, dict) and all(isinstance(v, str) for v in s.values()) for s in typed
        ):
            raise InputError("the steps are not a list of answers")
        solution = questions_marking.marking_question(_words(question))
        result = selftest_marks.feedback(marking.mark_steps(solution, typed[:MAX_STEPS]))
    except (ValueError, RecursionError) as err:  # InputError and JSON's errors are ValueErrors
        return json.dumps({"error": " ".join(str(err).split()) or "the steps are unreadable"})
    return json.dumps(result)


def answer(question: str) -> str:
    """:func:`solve_page` as JSON text (what the page's worker hands to JavaScript).

    >>> json.loads(answer("circle 0.5"))
    {'ok': False, 'error': 'radius must be an integer, got 0.500'}
    """
    return json.dumps(solve_page(question))

"""The "Test yourself" feedback of a step, in the words of ``check``'s own judgement.

The site's page hands the steps a student has typed so far to the library's marking
(:func:`scanconv.marking.mark.mark_steps`, the follow-through ``check`` marks a table
by); :func:`feedback` turns its verdict on the last step into what the page shows: each
answer right or wrong with the value it was judged against, the expected step as ``check``'s
expected column writes it, the first-error sentence's reason, and the score in steps, as
``check`` counts it. The page's script only lays these out.
"""

from __future__ import annotations

from typing import Any

from ...marking.rows import Marking
from ...marking.words import expected_text, explain, got_text


def _value(text: str) -> str:
    """``p = -8`` as its value, ``-8`` (a pixel or a move is its own value)."""
    return text.split(" = ", 1)[1] if text.startswith("p = ") else text


def feedback(marking: Marking) -> dict[str, Any]:
    """The verdict on ``marking``'s last step as the page shows it (``{}``: no step).

    >>> from scanconv.answers.primitives.line import line_solution
    >>> from scanconv.marking.mark import mark_steps
    >>> s = line_solution("bresenham", 2, 2, 10, 6)
    >>> f = feedback(mark_steps(s, [{"p": "0", "decision": "E", "pixel": "3, 3"}]))
    >>> f["mark"], f["parts"][1], f["expected"], f["score"]
    ('wrong', {'field': 'decision', 'ok': False, 'got': 'E', 'want': 'NE'}, 'p = 0, NE, (3, 3)', [0, 1])
    >>> f["why"]
    'the decision should be NE, not E (at (2, 2) with p = 0, p >= 0 chooses NE).'
    """
    if not marking.verdicts:
        return {}
    v = marking.verdicts[-1]
    fields = marking.fields
    judged = v.expected._replace(ruled=None) if v.expected is not None else None
    parts = [
        {
            "field": f,
            "ok": f not in v.wrong,
            "got": _value(got_text(v.got, (f,))),
            "want": _value(expected_text(judged, (f,))),
        }
        for f in fields
    ]
    why = "" if v.mark.startswith("right") else explain(v, fields).split(": ", 1)[-1]
    return {
        "mark": v.mark,
        "parts": parts,
        "expected": expected_text(v.expected, fields),
        "why": why,
        "score": [marking.right, marking.total],
    }

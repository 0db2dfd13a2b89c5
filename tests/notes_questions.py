"""The exam questions of the course notes, read from the notes themselves: each section's
TYPICAL EXAM QUESTIONS and the "Topic - N : NAME" topics that close the notes."""

from __future__ import annotations

import re
from pathlib import Path

NOTES = Path(__file__).resolve().parents[2] / "shared" / "seed" / "000_80ebdb5f8fa70d3f.txt"
"""Where the notes are when the repository sits beside ``shared/`` (``../shared/seed``)."""

_SKIP = {"TYPICAL EXAM QUESTIONS", "KEY TERMS", "IMPORTANT POINTS"}
_HEADING = re.compile(r"^[A-Z][A-Z' ]+$")
_ITEM = re.compile(r"^\s*(?:\d+\.|-)\s+(.+?)\s*$")
_TOPIC = re.compile(r"^Topic - (\d+) : (.+?)(?: \(14 Marks\))?$")


def notes_questions(text: str) -> list[tuple[str, str]]:
    """``(section heading, question)`` for every typical exam question, in order, then
    ``("14 MARKS", NAME)`` for each closing topic (7 to 13).

    >>> notes_questions("LINE DRAWING\\nTYPICAL EXAM QUESTIONS\\n1. Define line.\\nKEY TERMS\\n"
    ...                 "Topic - 12 : BEZIER METHOD (14 Marks)")
    [('LINE DRAWING', 'Define line.'), ('14 MARKS', 'BEZIER METHOD')]
    """
    found: list[tuple[str, str]] = []
    section, asking = "", False
    for line in text.splitlines():
        stripped = line.strip()
        topic = _TOPIC.match(stripped)
        if topic:
            found.append(("14 MARKS", topic.group(2)))
            asking = False
        elif stripped == "TYPICAL EXAM QUESTIONS":
            asking = True
        elif stripped in _SKIP:
            asking = False
        elif _HEADING.match(stripped) and len(stripped) > 3:
            section, asking = stripped, False
        elif asking and (item := _ITEM.match(line)):
            found.append((section, item.group(1)))
    return found

"""A decision cell of a student's table as a move: the compass letters (``NE``), the words
(``North-East``, ``right``), a relative word (``diagonal``) read against the two moves of its
step, and a cell that names no move kept as written (never read as blank)."""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

EMPTY = ("", "-", "\u2013", "\u2014", "none", "null", "n/a", "na")
"""What an empty cell of a student's table holds."""

_MOVE = re.compile(r"\b(NE|NW|SE|SW|N|E|S|W)\b")

_COMPASS = {"north": "N", "south": "S", "east": "E", "west": "W"}
_PLAIN_WORDS = {"right": "E", "left": "W", "up": "N", "down": "S"}
RELATIVE = ("diagonal", "straight", "horizontal", "vertical")
"""Decisions named by how they move rather than where: ``diagonal`` (both coordinates
change), ``straight`` (only the major one), ``horizontal`` (x only), ``vertical`` (y only);
:func:`resolve_move` reads them against the two moves a step chooses between."""

UNREADABLE = "?"
"""The prefix of a decision cell that names no move (``?keep``): marked wrong and shown as
written, never as blank."""


def _move_word(text: str) -> str | None:
    """A move written in words: ``East``, ``north-east``, ``North East``, ``right``,
    ``diagonal``; ``None`` if the text is not one."""
    words: list[str] = re.findall(r"[a-z]+", text.lower())
    if not words or len(words) > 3:
        return None
    if words[0] in RELATIVE and len(words) <= 2:  # "diagonal", "diagonal move"
        return words[0]
    if len(words) == 1 and words[0] in _PLAIN_WORDS:
        return _PLAIN_WORDS[words[0]]
    letters = [_COMPASS.get(w) for w in words]
    if None in letters or len(letters) > 2:
        joined = "".join(words)  # "northeast"
        for a in ("north", "south"):
            for b in ("east", "west"):
                if joined == a + b:
                    return _COMPASS[a] + _COMPASS[b]
        return None
    move = "".join(letters)  # type: ignore[arg-type]
    return move if move in ("N", "S", "E", "W", "NE", "NW", "SE", "SW") else None


def move_of(raw: Any) -> str | None:
    """A decision cell as a move: ``NE``, ``E (keep y)``, ``p < 0: E``, ``se``, ``East``,
    ``North-East``, ``north east``, ``right``, or a relative word (:data:`RELATIVE`);
    ``None``: the cell is empty; :data:`UNREADABLE` and the text: it names no move.

    >>> move_of(" ne "), move_of("E (x + 1)"), move_of("p < 0 -> E"), move_of("-")
    ('NE', 'E', 'E', None)
    >>> move_of("East"), move_of("North-East"), move_of("south east"), move_of("Diagonal")
    ('E', 'NE', 'SE', 'diagonal')
    >>> move_of("keep"), move_of("n/a")
    ('?keep', None)
    """
    if raw is None or isinstance(raw, (bool, int, float, list, dict)):
        return None
    text = str(raw).strip().strip("$*`").strip()
    if text.lower() in EMPTY:
        return None
    word = _move_word(text)
    if word is not None:
        return word
    m = _MOVE.search(text.upper())
    return m.group(1) if m else UNREADABLE + " ".join(text.split())[:30]


def resolve_move(said: str | None, moves: Sequence[str]) -> str | None:
    """The move of ``moves`` (the two a step chooses between) that a decision names: itself,
    or the one a relative word describes; ``None`` when it names neither.

    >>> resolve_move("diagonal", ("E", "NE")), resolve_move("straight", ("SE", "E"))
    ('NE', 'E')
    >>> resolve_move("horizontal", ("N", "NE")), resolve_move("?keep", ("E", "NE"))
    (None, None)
    """
    if said is None:
        return None
    if said in moves:
        return next(m for m in moves if m == said)
    fits = {
        "diagonal": lambda m: len(m) == 2,
        "straight": lambda m: len(m) == 1,
        "horizontal": lambda m: m in ("E", "W"),
        "vertical": lambda m: m in ("N", "S"),
    }.get(said)
    found = [m for m in moves if fits is not None and fits(str(m))]
    return found[0] if len(found) == 1 else None


def same_move(said: str | None, expected: str) -> bool:
    """Whether a student's decision names the expected move (a relative word naming it by
    how it moves: ``diagonal`` for NE, ``straight`` for E).

    >>> same_move("diagonal", "SE"), same_move("E", "E"), same_move("vertical", "E")
    (True, True, False)
    """
    if said is None or said.startswith(UNREADABLE):
        return False
    if said == expected:
        return True
    return resolve_move(said, (expected,)) == expected

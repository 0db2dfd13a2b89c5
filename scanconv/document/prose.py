"""Prose with math in it: a note's ``$...$`` formulas and the formulas written in text in the
ASCII notation (``x^2 + y^2 = r^2``), split into segments so that every format sets the math
as math (LaTeX math, MathML, Unicode, Markdown ``$...$``) and escapes only the text.
"""

from __future__ import annotations

import re


def note_segments(note: str) -> list[tuple[bool, str]]:
    """A note split into its text and its math: notes write formulas between ``$...$`` in
    TeX (``"$p_k < 0$ chooses E"``), so each format can set them as math.

    >>> note_segments("$p_k < 0$ chooses E")
    [(True, 'p_k < 0'), (False, ' chooses E')]
    >>> note_segments("costs $5 or more")  # an unpaired $ is text
    [(False, 'costs $5 or more')]
    """
    parts = note.split("$")
    if len(parts) % 2 == 0:  # an odd number of $: not markup
        return prose_math(note)
    out: list[tuple[bool, str]] = []
    for i, part in enumerate(parts):
        if part:
            out.extend([(True, part)] if i % 2 else prose_math(part))
    return out


_PROSE_MATH = None


def prose_math(text: str) -> list[tuple[bool, str]]:
    """Text split into prose and the formulas written in it in the ASCII notation
    (``x^2 + y^2 = r^2``, ``p_{k+1}``, ``x_inc``, ``2^-3``, ``(x - xc)^2``), each formula as TeX
    math, so every format sets it as math (LaTeX math, MathML, Unicode) instead of showing the
    markup. Only a name of one or two letters (or a number, or a bracketed group) with a
    sub- or superscript of a few letters or digits counts: a file name (``al_ice.csv``) does not.

    >>> prose_math("p = x^2 + y^2 - r^2 at (0, r)")
    [(False, 'p = '), (True, 'x^2'), (False, ' + '), (True, 'y^2'), (False, ' - '), (True, 'r^2'), (False, ' at (0, r)')]
    >>> prose_math("2x_{k+1} + 1, x_inc, 2^-3 and (x - xc)^2")
    [(False, '2'), (True, 'x_{k+1}'), (False, ' + 1, '), (True, 'x_{inc}'), (False, ', '), (True, '2^{-3}'), (False, ' and '), (True, '(x - xc)^2')]
    >>> prose_math("al_ice.csv, p_k. and a_b_c")
    [(False, 'al_ice.csv, '), (True, 'p_k'), (False, '. and a_b_c')]
    """
    global _PROSE_MATH
    if "_" not in text and "^" not in text:
        return [(False, text)] if text else []
    if _PROSE_MATH is None:
        sub = r"_(?:\{[A-Za-z0-9+\-, ]{1,12}\}|[A-Za-z0-9]{1,4})"
        sup = r"\^(?:\{[A-Za-z0-9+\-]{1,8}\}|-?[0-9]{1,3}|[A-Za-z])"
        base = (
            r"(?:(?<![A-Za-z_.\\])[A-Za-z]{1,2}[0-9]?|(?<![\w.\\])[0-9]+"
            r"|\([A-Za-z0-9 +\-*/.,]{1,30}\))"
        )
        _PROSE_MATH = re.compile(rf"{base}(?:{sub}(?:{sup})?|{sup})(?![\w^_{{]|\.\w)")
    out: list[tuple[bool, str]] = []
    at = 0
    for m in _PROSE_MATH.finditer(text):
        if m.start() > at:
            out.append((False, text[at : m.start()]))
        out.append((True, _braced(m.group())))
        at = m.end()
    if at < len(text):
        out.append((False, text[at:]))
    return out


def _braced(token: str) -> str:
    """A formula token with its multi-character scripts braced: ``x_inc`` as ``x_{inc}``."""
    body = r"(-[A-Za-z0-9]+|[A-Za-z0-9]{2,})"
    return re.sub(rf"([_^]){body}$|([_^]){body}(?=\^)", _brace, token)


def _brace(m: re.Match[str]) -> str:
    mark, body = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
    return f"{mark}{{{body}}}"

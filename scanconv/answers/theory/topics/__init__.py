"""Theory answers: a model answer to each define / explain / describe question of the course
notes, in the notes' terms and structure, each with a live example computed by scanconv.

One module per section of the notes (:mod:`.scan`, :mod:`.image`, :mod:`.lines`,
:mod:`.circles`, :mod:`.curves`); each lists its :class:`~._build.Topic` s. An answer is built
only when asked for (:func:`theory_solution`).

>>> [t.name for t in topics()][:2]
['scan-conversion', 'need-for-scan-conversion']
>>> theory_solution("raster-display").title
'What is raster display? Explain'
"""

from __future__ import annotations

from ....core import lazy
from ....core.checks import InputError
from ....core.records import Solution
from ._build import Topic

SECTIONS = (
    "scan",
    "image",
    "lines",
    "circles",
    "curves",
    "syllabus",
    "windows",
    "space",
    "visible",
)
"""The modules, in the notes' order; ``syllabus``, ``windows``, ``space`` and ``visible`` (the
topics the papers ask beyond the notes) last."""


def topics() -> list[Topic]:
    """Every topic, in the notes' order."""
    return [t for section in SECTIONS for t in lazy.load(f"{__name__}.{section}:TOPICS")]


def listed() -> list[tuple[str, str]]:
    """Every topic's name and question, in the notes' order (``scanconv theory --list``).

    >>> listed()[0]
    ('scan-conversion', 'Define scan conversion')
    """
    return [(t.name, t.title) for t in topics()]


def topic(name: str) -> Topic:
    """The topic called ``name``, or :class:`InputError` listing the names."""
    found = {t.name: t for t in topics()}
    if name not in found:
        raise InputError(f"unknown theory topic {name!r} (choose from {', '.join(found)})", "topic")
    return found[name]


def theory_solution(name: str) -> Solution:
    """The theory answer of the topic called ``name``."""
    return topic(name).build()

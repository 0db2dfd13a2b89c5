"""The structured content of each tool, declared so that the server lists a real output
schema (the SDK reads these types into JSON Schema, and checks each result against it).

:class:`Answer` is scanconv's stable JSON (``--format json``; docs/formats.md's "JSON output",
:mod:`scanconv.render.mappings.data`): every answer has its head (``primitive`` .. ``columns``) and
``steps``; ``pixels``, ``tables``, ``pseudocode`` and a command's own fields (``conventions``,
``layout``, a marking's ``score``) only where the answer has them. A step has ``k`` and its
``pixel`` always, ``p`` and ``decision`` where the method has them, and the method's own
columns under their own keys.

(``typing_extensions.TypedDict``: pydantic reads the standard one only from Python 3.12.)
"""

from __future__ import annotations

from typing import Any

from typing_extensions import NotRequired, TypedDict

Number = int | float
"""A JSON number: exact integers stay integers, other exact values are written as floats."""


class Step(TypedDict):
    """One row of the step table."""

    k: int | str
    """The step's number (a comparison's rows name their method)."""
    pixel: list[int]
    """The pixel the row plots, ``[x, y]``."""
    p: NotRequired[Number | str | None]
    """The decision parameter the row decides on."""
    decision: NotRequired[str | None]
    """The move it chooses (``E``, ``NE``, ``S``, ...)."""


class Table(TypedDict):
    """A further table (a clipping's region codes, a marking's rows, a comparison)."""

    title: str
    columns: list[str]
    rows: list[list[Any]]


class Listing(TypedDict):
    """Pseudocode (``--algorithm``): its title and its lines, indented by leading spaces."""

    title: str
    lines: list[str]


class Answer(TypedDict):
    """A worked answer, as ``scanconv COMMAND ... --format json`` writes it."""

    primitive: str | None
    """What was drawn or asked: ``line``, ``circle``, ``clip``, ``fill``, ``check``, ..."""
    algorithm: str | None
    """The method: ``bresenham``, ``dda``, ``midpoint``, ``cohen-sutherland``, ..."""
    title: str
    given: dict[str, Any]
    """The question's values (``P1``, ``P2``, ``r``, ``centre``)."""
    derived: dict[str, Any]
    """The working's values by name (``dx``, ``p0``, ``inc_keep``)."""
    working: list[str]
    """The working, a line each, in Unicode."""
    notes: list[str]
    """What the table means: which row plots which pixel, the tie rule, the conventions."""
    columns: list[str]
    """The step table's columns, in order: the keys of each step."""
    conventions: NotRequired[dict[str, str]]
    """The convention each knob took (``{"tie": "step", "start": "swap"}``): name them in
    any answer built on this one."""
    steps: list[Step]
    pixels: NotRequired[list[list[int]]]
    """Every pixel plotted, in order."""
    tables: NotRequired[list[Table]]
    pseudocode: NotRequired[list[Listing]]


class Marking(Answer):
    """A student's table marked (``scanconv check ... --format json``)."""

    question: str
    answer: str
    """The name the table is marked under."""
    score: int
    out_of: int
    first_error: str
    """The first step that is wrong and why (empty: none)."""
    diagnosis: str
    """The conventions or the mistake the table shows (``tie = keep``), if any."""
    follow_through: bool
    marked: list[str]
    """The columns marked."""


class PracticeQuestion(TypedDict):
    """One practice question and its key."""

    number: int
    wording: str
    """The question as an exam asks it."""
    marks: int
    question: str
    """The question in scanconv's question language: pass it to ``solve`` or ``check``."""
    answer: Answer


class Practice(TypedDict):
    """A seeded practice set: the same arguments give the same questions."""

    topic: str
    difficulty: str
    seed: int
    questions: list[PracticeQuestion]


class Option(TypedDict):
    """One option of a command."""

    flags: list[str]
    takes: str
    """What follows it: ``a choice``, ``a number``, ``N numbers``, ``nothing`` (a flag)."""
    choices: NotRequired[list[str]]
    default: NotRequired[Any]


class Command(TypedDict):
    """One command of the question language."""

    command: str
    """Its words: ``line``, ``clip line``, ``fill flood``."""
    usage: str
    """Its positional arguments in order (``X1 Y1 X2 Y2``), then ``[OPTIONS]``."""
    options: list[Option]


class Knob(TypedDict):
    """A convention: a variant rule on which textbooks differ."""

    name: str
    flag: str
    values: dict[str, str]
    """Each value and what it means."""
    default: str
    """The course notes' rule."""
    applies_to: list[str]
    """``primitive/method`` names."""


class Preset(TypedDict):
    """A published source's conventions (``--convention NAME``)."""

    name: str
    source: str
    values: dict[str, dict[str, str]]
    """Per primitive, the value of each knob."""


class Vocabulary(TypedDict):
    """What a valid question can say."""

    grammar: str
    """How a question is written."""
    examples: list[str]
    commands: list[Command]
    methods: dict[str, list[str]]
    """The methods of each command that has a choice of them."""
    conventions: list[Knob]
    presets: list[Preset]
    theory_topics: list[str]
    practice_topics: list[str]
    practice_difficulties: list[str]

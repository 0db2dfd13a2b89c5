"""The API of the colour and theory commands: :func:`color` (``scanconv color``) and
:func:`theory` (``scanconv theory``). Library modules are imported inside the functions
(start-up time)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated

from ..core import lazy
from ..core.checks import InputError, check_whole
from ..core.declare import Arg, Opt
from ..display import answers
from .values import NumberLike, _number

if TYPE_CHECKING:
    from ..answers.image import color as answers_color
    from ..answers.theory import topics as answers_topics
    from ..core.choices import (
        ColorModelName,
    )
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_color = lazy.module("scanconv.answers.image.color")
    answers_topics = lazy.module("scanconv.answers.theory.topics")

_MODELS = "rgb, cmy, hsv, hsi, grey"


@answers
def color(
    model: Annotated[ColorModelName, Arg(f"The model given: {_MODELS}.", "MODEL")],
    *values: Annotated[
        NumberLike,
        Arg(
            "Its components: R G B (0..255; 0..1 with --unit), C M Y (0..1), H S V or "
            "H S I (H in degrees, S, V, I in 0..1), or one grey level Y.",
            "VALUES...",
            kind="text",
        ),
    ],
    to: Annotated[
        str | Sequence[str],
        Opt(
            "--to",
            metavar="MODEL...",
            help=f"The models to convert to ({_MODELS}; several: --to cmy hsv hsi). "
            "Default: every other one.",
            multiple=True,
            show_default=False,
        ),
    ] = (),
    unit: Annotated[
        bool, Opt("--unit", help="RGB and grey are in 0..1 (default: 0..2^bits - 1).")
    ] = False,
    bits: Annotated[
        NumberLike,
        Opt(
            "--bits",
            help="Bits per RGB channel (default 8: 0..255, 24-bit colour).",
            show_default=False,
        ),
    ] = 8,
) -> Solution:
    """Convert a colour between models (``scanconv color``).

    Parameters
    ----------
    model : {"rgb", "cmy", "hsv", "hsi", "grey"}
        The model the values are in.
    *values : number
        The components: RGB and grey integers ``0 .. 2**bits - 1`` (or ``0 .. 1`` with
        ``unit``); C, M, Y, S, V and I in [0, 1]; hue in degrees. With ``to`` given, a
        model's name among them is one more target (``color rgb 1 2 3 --to cmy hsv``).
    to : str or sequence of str, default ()
        The models to convert to (names, or one string ``"cmy hsv"`` / ``"cmy,hsv"``); default
        every other model.
    unit : bool, default False
        RGB and grey given on the unit scale 0 .. 1.
    bits : int, default 8
        Bits a component for the integer scale.

    Returns
    -------
    Answer
        The conversion worked for each target and ``.data``: each model's components as exact
        fractions of their range (``"rgb"`` on the unit scale), the ``"hex"`` code, the
        ``"scale"`` used.

    Notes
    -----
    CMY is ``1 - RGB``; HSV is Smith's hexcone (Smith 1978), HSI Gonzalez & Woods' model (its
    hue from an arc cosine, a float unless exact), grey the average ``(R + G + B)/3`` and ITU-R
    BT.601 luma (:mod:`scanconv.algorithms.color`).

    Examples
    --------
    >>> color("rgb", 51, 102, 153, to="cmy").data["cmy"]
    [Fraction(4, 5), Fraction(3, 5), Fraction(2, 5)]
    >>> sol = color("hsv", 210, 0.5, 0.6, to="rgb")
    >>> sol.data["rgb"], sol.data["hex"]
    ([Fraction(3, 10), Fraction(9, 20), Fraction(3, 5)], '#4D7399')
    """
    targets = [to] if isinstance(to, str) else list(to)
    numbers = []
    for v in values:
        if not (isinstance(v, str) and v.isalpha()):
            numbers.append(v)
        elif targets:
            targets.append(v)
        else:
            raise InputError(
                f"a colour component must be a number, got {v!r} (the target models are "
                "given on their own, as to)",
                "to",
            )
    b = _number(bits, "bits")
    return answers_color.color_solution(
        model,
        [_number(v, "values") for v in numbers],
        [t for spec in targets for t in spec.replace(",", " ").split()],
        unit=unit,
        bits=check_whole(b, "bits", param="bits"),
    )


@answers
def theory(
    topic: Annotated[
        str,
        Arg(
            "The question's topic: scan-conversion, raster-display, rgb-model, dda, "
            "symmetry, bezier, ... (--list names them all).",
            "TOPIC",
        ),
    ],
    *,
    list_: Annotated[
        bool,
        Opt(
            "--list",
            help="List the topics, one a line (name, then the question), and stop.",
            lists="scanconv.answers.theory.topics:listed",
        ),
    ] = False,
) -> Solution:
    """The model answer to a theory question (``scanconv theory``).

    Parameters
    ----------
    topic : str
        The question's name, as ``scanconv theory --list`` lists them (``"symmetry"``,
        ``"scan-conversion"``, ``"raster-display"``, ...).
    list_ : bool, default False
        The command line's ``--list``, which lists the topics and stops before any answer
        (each topic's name and question: :func:`scanconv.answers.theory.topics.listed`); the
        answer is the topic's either way.

    Returns
    -------
    Answer
        The answer's text, its key points and tables (a worked example where the topic has one).

    Raises
    ------
    InputError
        An unknown topic.

    Examples
    --------
    >>> sol = theory("symmetry")
    >>> sol.title
    'Explain 8-way symmetry of a circle with diagram'
    >>> sol.tables[-1].title
    'The eight images of (2, 5) about the centre (0, 0)'
    """
    return answers_topics.theory_solution(topic)

"""The Python API: a bitmap font's storage (``scanconv char storage``). See
:mod:`scanconv._api`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .syllabus import _char
from .values import NumberLike, _choice, _whole

if TYPE_CHECKING:
    from ..answers.primitives import characters as answers_characters
    from ..core.choices import PackingName
    from ..core.records import Solution
else:  # the command's answer module, loaded by its first call
    answers_characters = lazy.module("scanconv.answers.primitives.characters")


@answers
def char_storage(
    count: Annotated[NumberLike, Arg("How many characters the font holds.", "COUNT")],
    width: Annotated[NumberLike, Arg("A glyph's width in pixels.", "WIDTH")],
    height: Annotated[NumberLike, Arg("A glyph's height in pixels.", "HEIGHT")],
    *,
    packing: Annotated[
        PackingName,
        Opt(
            "--packing",
            help="A glyph in whole bytes per row, per column, or packed bits.",
            choices=("rows", "columns", "bits"),
        ),
    ] = "rows",
    char: Annotated[
        str | None,
        Opt(
            "--char",
            metavar="C",
            help="A character whose glyph's number and address the font table gives.",
        ),
    ] = None,
    first: Annotated[
        NumberLike,
        Opt(
            "--first",
            metavar="CODE",
            help="The code of the font's first glyph (default 0).",
            show_default=False,
        ),
    ] = 0,
    base: Annotated[
        int | str,
        Opt(
            "--base",
            metavar="ADDRESS",
            help="The first glyph's byte address, decimal or 0x hexadecimal (default 0).",
            kind="text",
            show_default=False,
        ),
    ] = 0,
) -> Solution:
    """The storage of a bitmap font and its font table (``scanconv char storage``).

    Parameters
    ----------
    count : int
        The number of glyphs.
    width, height : int
        Each glyph's size in pixels.
    packing : {"rows", "columns", "bits"}, default "rows"
        Each row padded to whole bytes, each column padded to whole bytes, or the bits packed
        with no padding.
    char : str, optional
        A character whose glyph's address is asked: its glyph number (its code less
        ``first``) and start address.
    first : int, default 0
        The character code of the font's first glyph (32 for a font that starts at the space).
    base : int or str, default 0
        The byte address of the first glyph (a number, or text in decimal or ``0x``
        hexadecimal); each glyph follows the one before.

    Returns
    -------
    Answer
        The working and the font table (each glyph's start address); ``.data`` holds
        ``per_glyph`` and the total ``bits``.

    Examples
    --------
    >>> char_storage(128, 5, 7).data
    {'bits': 7168, 'per_glyph': 56, 'packing': 'rows'}
    >>> char_storage(128, 5, 7, packing="bits").data["bits"]
    4480
    >>> char_storage(128, 8, 8, char="A", base=0x1000).derived[-1].value  # 4096 + 65 x 8
    4616
    >>> char_storage(128, 8, 8, char="A", base="0x1000").derived[-1].value
    4616
    """
    return answers_characters.font_storage_solution(
        _whole(count, "count"),
        _whole(width, "width"),
        _whole(height, "height"),
        packing=_choice(packing, "packing"),
        char=None if char is None else _char(char),
        first=_whole(first, "first"),
        base=_address(base) if isinstance(base, str) else _whole(base, "base"),
    )


def _address(text: str) -> int:
    """A memory address as a user writes it: decimal (``4096``) or hexadecimal (``0x1000``).

    >>> _address("0x1000"), _address("4096")
    (4096, 4096)
    """
    s = text.strip().lower()
    try:
        return int(s[2:], 16) if s.startswith("0x") else int(s)
    except ValueError:
        raise InputError(
            f"an address is a whole number or 0x hexadecimal, got {text!r}", "base"
        ) from None

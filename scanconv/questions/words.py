"""The words of a question (and of a command line): what students type made into what the
commands take, the value parsers, and the usage errors worded as scanconv words them."""

from __future__ import annotations

import re
from fractions import Fraction

from ..core.checks import InputError, looks_like_option
from ..core.numeric import parse_number

MINUS = "\u2212"
_NUM = r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:/\d+)?"
# patterns, compiled by re on first use: a plain run never needs them (start-up time)
_POINT = rf"^\(?\s*({_NUM})\s*,\s*({_NUM})\s*\)?$"
_SIZE = r"^(\d+)\s*[xX\u00d7]\s*(\d+)$"
_FORMAT_NAMES = {"md": "markdown", "tex": "latex", "txt": "plain", "text": "plain"}
#: Options whose value is text the library parses itself (never split as a point).
TEXT_OPTIONS = {"--knots", "--at", "--t-range", "--domain", "--size", "-o", "--output"}
TEXT_OPTIONS |= {"--svg", "--png", "--x", "--y", "--formula"}
NONFINITE = ("-inf", "-infinity", "-nan")


class UsageError(InputError):
    """A question (or command line) that does not fit its command's parameters: the message
    is the whole of it, worded as the command line words it."""


def students(argv: list[str]) -> list[str]:
    """``argv`` with what students type made into what the commands take: a point written
    ``2,2`` or ``(2, 2)`` is two numbers, ``storage 1024x768`` is two sizes, ``-f md`` is
    markdown (``tex``: latex, ``txt``: plain).

    >>> students(["line", "(2,2)", "10,6", "-f", "md"])
    ['line', '2', '2', '10', '6', '-f', 'markdown']
    >>> students(["storage", "1024x768", "--knots", "0,1"])
    ['storage', '1024', '768', '--knots', '0,1']
    """
    out: list[str] = []
    for i, a in enumerate(argv):
        before = argv[i - 1] if i else ""
        # the patterns only where they can match: plain numbers and flags skip the regex engine
        point = re.match(_POINT, a) if "," in a else None
        size = re.match(_SIZE, a) if argv[:1] == ["storage"] and a[-1:].isdigit() else None
        if before in ("-f", "--format") and a.lower() in _FORMAT_NAMES:
            out.append(_FORMAT_NAMES[a.lower()])
        elif a.startswith("--format=") and a[9:].lower() in _FORMAT_NAMES:
            out.append("--format=" + _FORMAT_NAMES[a[9:].lower()])
        elif point and before not in TEXT_OPTIONS:
            out.extend(point.groups())
        elif size and argv[:1] == ["storage"] and before not in TEXT_OPTIONS:
            out.extend(size.groups())
        else:
            out.append(a)
    return out


def words_of(argv: list[str]) -> list[str]:
    """:func:`students`, and ``-inf``/``-nan`` kept as values (they would be read as bundled
    short options ``-i -n -f``), so the number parser names them.

    >>> words_of(["circle", "-inf"])
    ['circle', '\u2212inf']
    """
    return [MINUS + a[1:] if a.lower() in NONFINITE else a for a in students(argv)]


def usage_message(message: str) -> str:
    """A usage error in the words a student expects: an unknown flag is "No such option", a
    choice close to a valid one names it.

    >>> usage_message("Got unexpected extra argument(s) (-x 3)")
    'No such option: -x'
    >>> usage_message("Invalid value for '--tie': 'kep' is not one of 'step', 'keep'.")
    "Invalid value for '--tie': 'kep' is not one of 'step', 'keep'; did you mean 'keep'?"
    """
    message = " ".join(message.split()).replace("Value error, ", "")
    extra = re.match(r"Got unexpected extra argument(?:\(s\)|s)? \((-[^ )]*)[^)]*\)", message)
    if extra:
        return f"No such option: {extra.group(1)}"
    choice = re.search(r"'([^']*)' is not one of ((?:'[^']*'(?:, )?)+)", message)
    if choice:
        import difflib

        given, names = choice.group(1), re.findall(r"'([^']*)'", choice.group(2))
        close = [n for n in names if given.lower() in n.lower()]
        close = close or difflib.get_close_matches(given, names, n=1)
        if close:
            message = message.rstrip(".") + f"; did you mean '{close[0]}'?"
    return message


def no_such_option(name: str, possibilities: list[str] | None = None) -> UsageError:
    """The error of an unknown option (with the close ones, as click lists them)."""
    message = f"No such option: {name}"
    if possibilities:
        message += f" (Possible options: {', '.join(sorted(possibilities))})"
    return UsageError(message)


def number(text: str | Fraction | int) -> Fraction:
    """An exact number (integer, decimal or a/b); a default passes through. A word that
    looks like an option is "No such option"; any other bad word a ``ValueError``.

    >>> number("5/2"), number(Fraction(1))
    (Fraction(5, 2), Fraction(1, 1))
    """
    if isinstance(text, Fraction | int):
        return Fraction(text)
    try:
        return parse_number(text)
    except ValueError:
        if looks_like_option(text):
            raise no_such_option(text.strip()) from None
        raise


def integer(text: str | int) -> int:
    """A whole number (``16``, ``1e3``); the error names the bad word.

    >>> integer("1e3")
    1000
    """
    if isinstance(text, int):
        return text
    value = number(text)
    if value.denominator != 1:
        raise ValueError(f"{text!r} is not an integer")
    return value.numerator


def coordinate(text: str | Fraction) -> Fraction | str:
    """One value of ``continuity``'s points: a number, or the ``:`` between the segments."""
    return ":" if isinstance(text, str) and text.strip() == ":" else number(text)

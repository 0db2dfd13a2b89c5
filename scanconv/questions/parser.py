"""Parsing a question: scanconv's own arguments (``line 2 2 10 6 --algo dda``) read against
the command's grammar (:mod:`.grammar_table`) into a :class:`CommandLine`, without the
command line's parser, but as it reads them: the same words, the same defaults and the same
messages (``tests/test_questions_files.py`` holds the two side by side)."""

from __future__ import annotations

import shlex
from collections.abc import Sequence
from typing import Any

from .grammar import CommandLine, Param, Spec
from .grammar_table import NOT_QUESTIONS, SHARED, SPECS
from .limits import check_question_size
from .words import UsageError, coordinate, integer, no_such_option, number, usage_message
from .words import words_of as _words_of

__all__ = ["HELP", "CommandLine", "parse", "split"]

HELP = ("--help", "-h", "--version")
"""Words that ask the command line for something other than an answer."""


def split(question: str | Sequence[str]) -> list[str]:
    """The words of a question: a string split as a shell splits it, or the words given."""
    if isinstance(question, str):
        try:
            return shlex.split(question)
        except ValueError as err:
            raise UsageError(f"unbalanced quotes: {err}") from None
    return [str(w) for w in question]


def parse(question: str | Sequence[str]) -> CommandLine:
    """Read a question against its command's grammar.

    Bad words raise :class:`~scanconv.questions.words.UsageError` (an ``InputError``) worded
    as the command line words it; a question longer than a line of a question file
    (:data:`~scanconv.questions.limits.MAX_LINE_CHARS`) is refused before it is split.

    Parameters
    ----------
    question : str or sequence of str
        The question as scanconv's own arguments: one string, split as a shell splits it, or
        the list of words.

    Returns
    -------
    CommandLine
        The command (``path``, ``spec``), its ``arguments`` by the API's parameter names, with
        the defaults filled in and numbers exact, its ``display`` options, and the ``words``.

    Raises
    ------
    UsageError
        Bad words (an ``InputError``), worded as the command line words them.

    Examples
    --------
    >>> line = parse("line 2,2 10 6 --algo DDA --no-grid")
    >>> line.path, line.arguments["x1"], line.arguments["algo"], line.display["grid"]
    (('line',), Fraction(2, 1), 'dda', False)
    >>> parse("circle 5 -c 1 2").arguments["center"]
    (Fraction(1, 1), Fraction(2, 1))
    >>> parse("line 2 2 10")
    Traceback (most recent call last):
    ...
    scanconv.questions.words.UsageError: Missing argument 'Y2'.
    """
    check_question_size(question)
    given = split(question)
    args = _words_of(given)
    bad = next((a for a in args if a in HELP), None)
    if bad is not None:
        raise UsageError(f"{bad} is not a question")
    spec, rest = _command(args)
    try:
        values = _Reader(spec).read(rest)
    except UsageError as err:
        raise UsageError(usage_message(str(err)), err.param) from None
    own = set(spec.own)
    arguments = {name: value for name, value in values.items() if name in own}
    display = {name: value for name, value in values.items() if name in SHARED}
    return CommandLine(spec, arguments, display, tuple(given))


def _command(args: list[str]) -> tuple[Spec, list[str]]:
    """The command ``args`` name, and the words after its name."""
    import difflib

    top = args[0] if args else ""
    if not top or top.startswith("-"):
        raise UsageError("a question starts with a command name (line, circle, ...)")
    if top in NOT_QUESTIONS:
        raise UsageError(f"'{top}' cannot be a question of a sheet")
    if (top,) in SPECS:
        return SPECS[(top,)], args[1:]
    subs = sorted(p[1] for p in SPECS if len(p) == 2 and p[0] == top)
    if subs:
        if len(args) < 2 or args[1].startswith("-"):
            raise UsageError(f"'{top}' needs one of its commands: {', '.join(subs)}")
        if (top, args[1]) in SPECS:
            return SPECS[(top, args[1])], args[2:]
        name, known = args[1], subs
    else:
        name, known = top, sorted({p[0] for p in SPECS} | set(NOT_QUESTIONS))
    close = difflib.get_close_matches(name, known, n=1)
    hint = f"; did you mean '{close[0]}'?" if close else ""
    shown = name if len(name) <= 40 else name[:39] + "…"
    raise UsageError(f"No such command '{shown}'{hint}")


_CONVERT = {"number": number, "integer": integer, "coordinate": coordinate}


class _Reader:
    """click's reading of a command line, for one command: options first (anywhere among the
    arguments), then the arguments by position, then each value converted and checked in the
    order the words gave them."""

    def __init__(self, spec: Spec) -> None:
        self.spec = spec
        self.long: dict[str, tuple[Param, Any]] = {}
        self.short: dict[str, tuple[Param, Any]] = {}
        for p in spec.params:
            for opt, const in [*((o, True) for o in p.opts), *((o, False) for o in p.secondary)]:
                table = self.short if len(opt) == 2 and opt[1] != "-" else self.long
                table[opt] = (p, const)
        self.opts: dict[str, Any] = {}
        self.order: list[str] = []
        self.largs: list[str] = []
        self.rargs: list[str] = []

    def read(self, words: list[str]) -> dict[str, Any]:
        if not words and self.spec.no_args_is_help:
            first = next(p for p in self.spec.params if not p.opts)
            raise UsageError(f"Missing argument {first.hint}.", first.name)
        self.rargs = list(words)
        while self.rargs:
            arg = self.rargs.pop(0)
            if arg == "--":
                break
            if arg[:1] == "-" and len(arg) > 1:
                self._option(arg)
            else:
                self.largs.append(arg)
        rest = self._arguments(self.largs + self.rargs)
        values = {}
        for p in sorted(self.spec.params, key=self._processing_order):
            values[p.name] = self._value(p)
        if rest:
            raise UsageError(f"Got unexpected extra argument(s) ({' '.join(rest)})")
        return values

    # --- the words ----------------------------------------------------------------------------

    def _option(self, arg: str) -> None:
        name, eq, explicit = arg.partition("=")
        if name in self.long:
            self._take(name, self.long[name], explicit if eq else None)
        elif arg[:2] != "--":
            self._shorts(arg)
        elif not self.spec.ignore_unknown:
            import difflib

            close = difflib.get_close_matches(name, [*self.long, "--help"])
            raise no_such_option(name, close)
        else:
            self.largs.append(arg)

    def _shorts(self, arg: str) -> None:
        unknown = []
        for i, ch in enumerate(arg[1:], 2):
            entry = self.short.get(f"-{ch}")
            if entry is None:
                if not self.spec.ignore_unknown:
                    raise no_such_option(f"-{ch}")
                unknown.append(ch)
                continue
            param, _ = entry
            if param.kind != "flag" and i < len(arg):
                self.rargs.insert(0, arg[i:])
                self._take(f"-{ch}", entry, None)
                break
            self._take(f"-{ch}", entry, None)
        if unknown:
            self.largs.append("-" + "".join(unknown))

    def _take(self, opt: str, entry: tuple[Param, Any], explicit: str | None) -> None:
        param, const = entry
        if param.kind == "flag":
            if explicit is not None:
                raise UsageError(f"Option {opt!r} does not take a value.", param.name)
            self.opts[param.name] = const
        else:
            if explicit is not None:
                self.rargs.insert(0, explicit)
            if len(self.rargs) < param.nargs:
                need = "an argument" if param.nargs == 1 else f"{param.nargs} arguments"
                raise UsageError(f"Option {opt!r} requires {need}.", param.name)
            taken = self.rargs[: param.nargs]
            del self.rargs[: param.nargs]
            value = taken[0] if param.nargs == 1 else tuple(taken)
            if param.multiple:
                self.opts.setdefault(param.name, []).append(value)
            else:
                self.opts[param.name] = value
        self.order.append(param.name)

    def _arguments(self, words: list[str]) -> list[str]:
        """Give each positional argument its words (one, or all that are left to the one
        that takes any number); the words left over."""
        params = [p for p in self.spec.params if not p.opts]
        rest = list(words)
        many = next((i for i, p in enumerate(params) if p.nargs == -1), None)
        before = params if many is None else params[:many]
        after = [] if many is None else params[many + 1 :]
        for p in before:
            self.opts[p.name] = rest.pop(0) if rest else None
        for p in reversed(after):
            self.opts[p.name] = rest.pop() if rest else None
        if many is not None:
            self.opts[params[many].name] = tuple(rest) or None
            rest = []
        self.order.extend(p.name for p in params)
        return rest

    # --- the values ---------------------------------------------------------------------------

    def _processing_order(self, p: Param) -> float:
        return self.order.index(p.name) if p.name in self.order else float("inf")

    def _converted(self, p: Param, raw: Any) -> tuple[Any, bool]:
        """The parameter's value, converted, and whether it is missing."""
        if p.multiple or p.nargs == -1:
            value: Any = () if raw is None else tuple(self._convert(p, w) for w in raw)
            return value, value == ()
        if p.nargs > 1:
            value = None if raw is None else tuple(self._convert(p, w) for w in raw)
        else:
            value = None if raw is None else self._convert(p, raw)
        return value, value is None

    def _value(self, p: Param) -> Any:
        raw = self.opts.get(p.name)
        if raw is None:
            raw = p.default
        value, missing = self._converted(p, raw)
        if p.required and missing:
            kind = "option" if p.opts else "argument"
            raise UsageError(f"Missing {kind} {p.hint}.", p.name)
        if p.opts and p.kind == "flag" and p.name == "list_" and value:
            raise UsageError(f"{p.opts[0]} is not a question: it lists and stops", p.name)
        if p.multiple or p.nargs == -1:  # as the command line hands them over: a list or None
            return list(value) if value else (None if p.default is None else [])
        return value

    def _convert(self, p: Param, word: Any) -> Any:
        if p.kind == "flag":
            return bool(word)
        if p.kind == "choice":
            folded = str(word).casefold()
            for choice in p.choices:
                if choice.casefold() == folded:
                    return choice
            listed = ", ".join(repr(c) for c in p.choices)
            raise self._invalid(p, f"{word!r} is not one of {listed}.")
        convert = _CONVERT.get(p.kind)
        if convert is None:
            return word
        try:
            return convert(word)
        except UsageError:
            raise
        except ValueError as err:
            raise self._invalid(p, str(err)) from None

    @staticmethod
    def _invalid(p: Param, message: str) -> UsageError:
        return UsageError(f"Invalid value for {p.hint}: {message}", p.name)

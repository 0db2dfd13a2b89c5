"""A command's parameters, declared once, on the library function that answers it.

A function of :mod:`scanconv._api` is a command: each parameter the command takes carries,
in its ``Annotated`` type, an :class:`Arg` (a positional argument: its help and the name
messages call it) or an :class:`Opt` (an option: its flags and help). Nothing here knows a
command-line parser: the command line (:func:`scanconv.cli.options.typer_parameter`) turns
each into its parser's declaration, the question language (:mod:`scanconv.questions.grammar`)
into its grammar, and the site into its forms; the default is the function's, stated once.

:func:`declared` reads a function's declaration: each parameter's :class:`Declared` record,
with its kind (how a word becomes its value) worked out from its type. A command whose first
argument is a free list of words (``transform``'s points, then its transformations) declares it
with :func:`words`: the function's own reader turns the words into its arguments.

>>> from scanconv._api.shapes import ellipse
>>> [(d.name, d.kind, d.nargs) for d in declared(ellipse)][:3]
[('rx', 'number', 1), ('ry', 'number', 1), ('center', 'number', 2)]
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Sequence
from enum import Enum
from fractions import Fraction
from pathlib import Path
from typing import Annotated, Any, Union, get_args, get_origin

KINDS = ("number", "integer", "coordinate", "choice", "flag", "text")
"""How a word becomes a parameter's value: an exact number, a whole number, a number or the
``:`` between two point lists, one of an enum's values, a flag (no word), text."""


class Arg:
    """A positional argument: its help, and its name in messages (``X1``; default the
    parameter's name). ``kind`` overrides the kind the type gives."""

    __slots__ = ("help", "kind", "metavar")

    def __init__(self, help: str = "", metavar: str | None = None, kind: str | None = None):
        self.help, self.metavar, self.kind = help, metavar, kind

    def __repr__(self) -> str:
        return f"Arg({self.help!r}, {self.metavar!r})"


class Opt:
    """An option: its flags (``"--algo", "-a"``; ``"--grid/--no-grid"`` for a flag that has
    both), its help, and how its help shows it: ``metavar`` (``"XC YC"``), ``show_default``,
    ``hidden``. ``kind`` overrides the kind the type gives; ``choices``: the texts a choice
    takes, where its type is a ``Literal`` (an enum's values are its choices); ``multiple``:
    the option may be given again, each time adding a value; ``nargs``: the words it takes,
    where its type does not say (a window's four numbers typed as a sequence); ``lists``: a
    flag that, given, lists rows of ``(name, description)`` instead of answering and stops
    (``"module:function"`` of the rows, loaded when it is given: ``theory --list``).

    (A plain class, not a dataclass: reading one costs the command line's start-up nothing.)
    """

    __slots__ = (
        "choices",
        "help",
        "hidden",
        "kind",
        "lists",
        "metavar",
        "multiple",
        "names",
        "nargs",
        "show_default",
    )

    def __init__(
        self,
        *names: str,
        help: str,
        metavar: str | None = None,
        kind: str | None = None,
        show_default: bool = True,
        hidden: bool = False,
        multiple: bool = False,
        choices: tuple[str, ...] = (),
        nargs: int | None = None,
        lists: str = "",
    ) -> None:
        self.names, self.help, self.metavar, self.kind = names, help, metavar, kind
        self.show_default, self.hidden, self.multiple = show_default, hidden, multiple
        self.choices, self.nargs, self.lists = choices, nargs, lists

    def __repr__(self) -> str:
        return f"Opt({', '.join(map(repr, self.names))}, help={self.help!r})"

    @property
    def flags(self) -> tuple[str, ...]:
        """The flags that give the value (``--grid`` of ``--grid/--no-grid``)."""
        return tuple(n.split("/")[0] for n in self.names)

    @property
    def secondary(self) -> tuple[str, ...]:
        """The flags that set a flag false (``--no-grid``)."""
        return tuple(n.split("/")[1] for n in self.names if "/" in n)


WORDS = "__words__"
"""The attribute that holds a function's :class:`Words` (set by :func:`words`)."""


class Words:
    """A command's first argument, every word left (numbers, and flags only its reader
    knows: ``--points``, ``--rotate``), that the library function reads itself: its help, its
    name in messages, and ``read``, the function of the words and the command's other
    arguments that gives the library function's arguments. The command names it ``words``."""

    __slots__ = ("help", "metavar", "read")

    def __init__(
        self,
        help: str,
        metavar: str,
        read: Callable[[Sequence[str], dict[str, Any]], dict[str, Any]],
    ) -> None:
        self.help, self.metavar, self.read = help, metavar, read


def words(
    help: str, metavar: str, read: Callable[[Sequence[str], dict[str, Any]], dict[str, Any]]
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Declare that a library function's command takes a free list of words first, read by
    ``read`` (:class:`Words`); the function's parameters it fills carry no declaration.

    >>> @words("The numbers.", "X ...", lambda ws, given: {"xs": [int(w) for w in ws], **given})
    ... def total(xs, twice: Annotated[bool, Opt("--twice", help="Twice.")] = False):
    ...     return sum(xs) * (2 if twice else 1)
    >>> [(d.name, d.kind, d.nargs, d.required) for d in declared(total)]
    [('words', 'text', -1, True), ('twice', 'flag', 1, False)]
    >>> total(**getattr(total, WORDS).read(["1", "2"], {"twice": True}))
    6
    """

    def declare(fn: Callable[..., Any]) -> Callable[..., Any]:
        setattr(fn, WORDS, Words(help, metavar, read))
        return fn

    return declare


class Declared:
    """One parameter of a command, as its library function declares it: its ``name``, its
    ``meta`` (:class:`Arg` or :class:`Opt`; a :class:`Words` list an :class:`Arg`), its ``kind`` (one of :data:`KINDS`), ``nargs``
    (the words it takes; -1: all that are left), ``choices`` (a choice's enum, or its texts),
    ``optional`` (whether ``None`` is a value: the library's default for it), ``default``
    (the function's; ``inspect.Parameter.empty``: required; a ``*values`` parameter takes
    every word left and is required) and ``file`` (its type is a ``Path``: a file to write,
    never a folder). A plain class: reading a declaration at start-up builds no named-tuple
    class."""

    __slots__ = ("choices", "default", "file", "kind", "meta", "name", "nargs", "optional")

    def __init__(
        self,
        name: str,
        meta: Arg | Opt,
        kind: str,
        nargs: int,
        choices: type[Enum] | tuple[str, ...] | None,
        optional: bool,
        default: Any,
        file: bool = False,
    ) -> None:
        self.name, self.meta, self.kind, self.nargs = name, meta, kind, nargs
        self.choices, self.optional, self.default, self.file = choices, optional, default, file

    @property
    def required(self) -> bool:
        return self.default is inspect.Parameter.empty


class _Lenient(dict[str, Any]):
    """Names an annotation may use that are only imported for type checkers: the ``Literal``
    aliases of :mod:`scanconv.core.choices` (``LineAlgorithmName``), read as ``str`` (text;
    an enum beside one decides the kind, an ``Opt``'s ``choices`` its values), so their
    module is not imported to read a signature."""

    def __missing__(self, key: str) -> Any:
        if key.endswith("Name"):
            return str
        raise KeyError(key)


def _evaluate(annotation: Any, namespace: dict[str, Any]) -> Any:
    if isinstance(annotation, str):
        return eval(annotation, namespace, _Lenient())  # our own source
    return annotation


def _members(hint: Any) -> tuple[Any, ...]:
    origin = get_origin(hint)
    if origin is Union or type(hint).__name__ == "UnionType":
        return get_args(hint)
    return (hint,)


def _kind_of(hint: Any) -> tuple[str, int, type[Enum] | None]:
    """The kind, the word count and the enum of a parameter's type."""
    members = [m for m in _members(hint) if m is not type(None)]
    enums = [m for m in members if isinstance(m, type) and issubclass(m, Enum)]
    if enums:
        return "choice", 1, enums[0]
    first = members[0]  # the first type decides: str | Sequence[str] is text
    origin = get_origin(first)
    if origin is tuple:
        kind, _, _ = _kind_of(get_args(first)[0])
        return kind, len(get_args(first)), None
    if origin in (list, Sequence):
        kind, _, _ = _kind_of(get_args(first)[0])
        return kind, -1, None
    if members == [bool]:
        return "flag", 1, None
    if Fraction in members:
        return "number", 1, None
    if members == [int]:
        return "integer", 1, None
    if first in (str, Path):
        return "text", 1, None
    raise TypeError(f"no kind for {hint!r}")


DECLARATION = "__declaration__"
"""The attribute that keeps a function's annotations as written, when the ones ``help()``
shows are :func:`plain` (:func:`scanconv.display.answers`)."""


def plain(annotation: Any) -> Any:
    """An annotation without its declaration, as ``help()`` shows it.

    >>> plain('Annotated[PointLike, Opt("--center", help="The centre, (x, y).")]')
    'PointLike'
    >>> plain("bool")
    'bool'
    """
    if isinstance(annotation, str) and annotation.startswith("Annotated["):
        depth = 0
        for i, ch in enumerate(annotation[10:], 10):
            depth += (ch in "[(") - (ch in "])")
            if ch == "," and depth == 0:
                return annotation[10:i].strip()
    if get_origin(annotation) is Annotated:
        return get_args(annotation)[0]
    return annotation


def declared(fn: Callable[..., Any]) -> tuple[Declared, ...]:
    """The declared parameters of the library function ``fn``, in its order (a parameter
    with no :class:`Arg` or :class:`Opt` is the library's alone: no command takes it)."""
    fn = inspect.unwrap(fn)
    namespace = fn.__globals__
    written = getattr(fn, DECLARATION, fn.__annotations__)
    out = []
    said = getattr(fn, WORDS, None)
    if said is not None:  # the first argument: every word left, read by the function
        listed = Arg(said.help, said.metavar)
        out.append(Declared("words", listed, "text", -1, None, False, inspect.Parameter.empty))
    for name, p in inspect.signature(fn).parameters.items():
        hint = _evaluate(written.get(name, p.annotation), namespace)
        if get_origin(hint) is not Annotated:
            continue
        base, *extras = get_args(hint)
        meta = next((m for m in extras if isinstance(m, Arg | Opt)), None)
        if meta is None:
            continue
        choices: type[Enum] | tuple[str, ...] | None
        if isinstance(meta, Opt) and meta.choices:
            kind, nargs, choices = "choice", 1, meta.choices
        else:
            try:
                kind, nargs, choices = _kind_of(base)
            except TypeError:  # a type that says no kind: the declaration's own, one word
                if meta.kind is None:
                    raise
                kind, nargs, choices = meta.kind, 1, None
            nargs = getattr(meta, "nargs", None) or nargs
        if p.kind is p.VAR_POSITIONAL:  # ``*values``: every word left
            nargs = -1
        optional = type(None) in _members(base)
        file = Path in _members(base)
        out.append(
            Declared(name, meta, meta.kind or kind, nargs, choices, optional, p.default, file)
        )
    return tuple(out)

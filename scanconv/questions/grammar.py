"""The records of the question language: a command's parameters as the command line takes
them (:class:`Param`) and a command (:class:`Spec`). The table of every command is
:mod:`.grammar_table`, generated from the library's declarations (:mod:`.declared`, the
signatures of :mod:`scanconv._api`) by :mod:`.generate`::

    python -m scanconv.questions.generate > scanconv/questions/grammar_table.py
"""

from __future__ import annotations

from enum import Enum
from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    from ..core.declare import Declared
    from .declared import Command


class Param(NamedTuple):
    """One parameter of a command, as the command line takes it."""

    name: str
    """The command's name for it (``x1``, ``algo``, ``center``)."""
    opts: tuple[str, ...] = ()
    """Its flags (``--algo``, ``-a``); none for a positional argument."""
    kind: str = "text"
    """How a word becomes its value: ``number`` (exact), ``integer``, ``coordinate`` (a
    number or ``:``), ``choice``, ``flag`` or ``text``."""
    nargs: int = 1
    """How many words it takes (-1: all that are left)."""
    required: bool = False
    default: Any = None
    """Its value when the question leaves it out (a choice's by its text)."""
    choices: tuple[str, ...] = ()
    secondary: tuple[str, ...] = ()
    """A flag's flags that set it false (``--no-grid``)."""
    multiple: bool = False
    """An option that may be given several times (``color --to``): a tuple of values."""
    metavar: str = ""
    """A positional argument's name in messages (``X2``; empty: the name itself)."""
    help: str = ""
    """What it is, in the command line's own words (its ``--help`` text)."""

    @property
    def hint(self) -> str:
        """How a message names it: ``'X2'``, ``'--algo' / '-a'``."""
        return " / ".join(f"'{o}'" for o in self.opts or (self.metavar or self.name,))

    @property
    def flag(self) -> str | None:
        """The long flag a message about the value names (``--center``), or ``None`` for a
        positional argument, which a message names by its value."""
        if not self.opts:
            return None
        long = [o for o in self.opts if o.startswith("--")]
        return long[0] if long else "--" + self.name.replace("_", "-")


class Spec(NamedTuple):
    """One command of the question language."""

    path: tuple[str, ...]
    """Its words: ``("line",)``, ``("parametric", "circle")``."""
    function: str
    """The command's function name (``parametric_circle``): what the work budget knows it
    by."""
    params: tuple[Param, ...]
    own: tuple[str, ...]
    """The parameters the answer takes (the shared output options excluded, unless the command
    declares one itself, as ``sample`` its ``--origin``)."""
    ignore_unknown: bool = True
    """Whether a word that looks like an unknown option is kept as a value (``-3``)."""
    no_args_is_help: bool = False


class CommandLine(NamedTuple):
    """A parsed question: the command, its arguments and its display options."""

    spec: Spec
    arguments: dict[str, Any]
    """The answer's parameters by the command's names, their values converted (a choice as
    its text, a number as a Fraction, a list of points as a list)."""
    display: dict[str, Any]
    """The shared output options (grid, origin, brief, exact, format, output, svg, png), as
    given or by default: how the answer is shown, not what it is."""
    words: tuple[str, ...]
    """The question's words, as given."""

    @property
    def path(self) -> tuple[str, ...]:
        """The command's words: ``("parametric", "circle")``."""
        return self.spec.path

    @property
    def function(self) -> str:
        """The command's function name (``parametric_circle``), as the work budget knows it."""
        return self.spec.function


ALIASES = {
    "xc": "center",
    "yc": "center",
    "m": "size",
    "n": "size",
    "index": "move",
    "moved": "move",
    "integer": "kind",
}
"""Library parameters that a command takes under another name: ``--center XC YC`` holds
``xc`` and ``yc``, ``--size MxN`` holds ``m`` and ``n``, ``--move I X Y`` holds ``index`` and
``moved``, and ``--input`` sets ``integer``. (A command with a parameter of the library's own
name, such as ``storage M N``, keeps it.)"""


def flag_for(param: str | None, params: tuple[Param, ...]) -> str | None:
    """The command's option for the library parameter ``param``, or ``None`` (no parameter,
    or a positional argument, which the message already names by its value).

    >>> center = Param("center", ("--center", "-c"), "number", 2)
    >>> flag_for("xc", (center,)), flag_for("radius", (center,))
    ('--center', None)
    """
    if param is None:
        return None
    by_name = {p.name: p for p in params}
    found = by_name.get(param) or by_name.get(ALIASES.get(param, ""))
    return None if found is None else found.flag


def error_message(err: ValueError, params: tuple[Param, ...]) -> str:
    """The one-line message for bad input: the library's text, after the flag it concerns."""
    message = " ".join(str(err).split())
    flag = flag_for(getattr(err, "param", None), params)
    if flag is not None and not message.startswith(flag):
        message = f"{flag}: {message}"
    return message


# --- the table, generated from the declarations ----------------------------------------------


def default_text(value: Any) -> Any:
    """A default as the grammar holds it: a choice by its text, a list as a tuple."""
    if isinstance(value, Enum):
        return value.value
    if isinstance(value, list | tuple):
        return tuple(default_text(v) for v in value)
    return value


def values(enum: str) -> tuple[str, ...]:
    """The values of the enum ``"module:Class"``: the generated table's choices of a
    parameter the library types by an enum, read from it when the table is imported, so that
    a new member (a new line method) needs no regenerated table.

    >>> values("scanconv.algorithms.choices:Tie")
    ('step', 'keep')
    """
    from ..core import lazy

    return tuple(m.value for m in lazy.load(enum))


def _texts(choices: Any) -> tuple[str, ...]:
    if choices is None:
        return ()
    return tuple(c.value if isinstance(c, Enum) else c for c in choices)


def param_of(d: Declared) -> Param:
    """The grammar's parameter for a declared one (:func:`scanconv.core.declare.declared`)."""
    from ..core.declare import Opt

    meta = d.meta
    option = isinstance(meta, Opt)
    return Param(
        name=d.name,
        opts=meta.flags if isinstance(meta, Opt) else (),
        kind=d.kind,
        nargs=d.nargs,
        required=d.required,
        default=None if d.required or d.default is None else default_text(d.default),
        choices=_texts(d.choices),
        secondary=meta.secondary if isinstance(meta, Opt) else (),
        multiple=meta.multiple if isinstance(meta, Opt) else False,
        metavar="" if option else meta.metavar or d.name,
        help=" ".join(meta.help.split()),
    )


def spec_of(command: Command, shared: dict[str, Param]) -> Spec:
    """The grammar of a declared command, its output options those of ``shared``."""
    from .declared import OUTPUTS, PICTURE

    own = {d.name: param_of(d) for d in command.parameters()}
    params = [p for name, p in own.items() if name not in OUTPUTS]
    if command.picture:  # the same flag, shown as the picture
        shared = {**shared, "grid": shared["grid"]._replace(help=PICTURE)}
    params += [own.get(name) or shared[name] for name in command.outputs]
    return Spec(
        path=command.path,
        function=command.function,
        params=tuple(params),
        own=tuple(own),
        ignore_unknown=command.ignore_unknown,
        no_args_is_help=command.no_args_is_help,
    )

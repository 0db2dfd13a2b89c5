"""The records of the question language: a command's parameters as the command line takes
them (:class:`Param`) and a command (:class:`Spec`). The table of every command is
:mod:`.grammar_table`, generated from the command line's declarations."""

from typing import Any, NamedTuple


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

"""The ``scanconv`` command line: the only layer that parses flags and prints.

:mod:`.application` holds the typer app and its groups, :mod:`.options` the parsers and option
declarations, :mod:`.command` the ``@answers`` decorator (shared output options, bad input),
:mod:`.output` the writing, :mod:`.entry` the entry point ``main``; the commands are grouped
by topic in :mod:`.lines`, :mod:`.circles`, :mod:`.curves`, :mod:`.image` and :mod:`.compare`,
each a thin mapping from flags to a :mod:`scanconv._api` function.
"""

from typing import Any

from .application import register
from .entry import main

__all__ = ["app", "main"]


def __getattr__(name: str) -> Any:
    """``scanconv.cli.app``: the typer app with every command registered (``main`` registers
    only the command it runs)."""
    if name == "app":
        return register()
    raise AttributeError(f"module 'scanconv.cli' has no attribute {name!r}")

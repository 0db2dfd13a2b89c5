"""scanconv: scan-conversion algorithms as exam-style worked solutions.

The library is usable without the CLI. One function per question, each returning an
:class:`~scanconv.display.Answer` (a :class:`~scanconv.core.records.Solution` that shows
itself: ``.to("markdown")``, ``.rows()``, ``.pixels()``, and a table in Jupyter):

>>> import scanconv
>>> sol = scanconv.line(2, 2, 10, 6, algo="bresenham")
>>> [s.p for s in sol.steps()]
[0, -8, 0, -8, 0, -8, 0, -8, 0]
>>> list(sol.pixels())[:4]
[(2, 2), (3, 3), (4, 3), (5, 4)]
>>> scanconv.circle(5, method="midpoint").rows()[0]
{'k': 0, 'x_k': 0, 'y_k': 5, 'p': -4, 'decision': 'E', 'pixel': (0, 5)}

The algorithms themselves are generators of :class:`~scanconv.core.records.Step` records,
under unambiguous names:

>>> [s.pixel for s in scanconv.bresenham_line(0, 0, 3, 1)]
[(1, 0), (2, 1), (3, 1)]

A question written as scanconv's own arguments is answered by :mod:`scanconv.questions`
(``scanconv.questions.answer("line 2 2 10 6 --algo dda")``), and :func:`check` marks a
student's table against one.

Coordinates are ``(x, y)`` with y up. Every public name is listed once, in ``__init__.pyi``
(what type checkers read), and imported from there on first use, so ``import scanconv``
stays cheap for the command line.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

#: Names kept for old code, with what to use instead (a DeprecationWarning on use).
DEPRECATED = {
    "line_solution": "scanconv.line(x1, y1, x2, y2, algo=...), whose table is in the notes' "
    "layout unless layout='textbook' (line_solution's default)",
}


def _exports() -> dict[str, tuple[str, str | None]]:
    """Every public name -> (module, attribute; ``None``: the module itself), read from the
    stub ``__init__.pyi`` (its ``from X import a as b`` lines)."""
    import ast
    from pathlib import Path

    found: dict[str, tuple[str, str | None]] = {}
    tree = ast.parse(Path(__file__).with_suffix(".pyi").read_text(encoding="utf-8"))
    for node in tree.body:
        if not isinstance(node, ast.ImportFrom):
            continue
        for alias in node.names:
            public = alias.asname or alias.name
            if node.module is None:  # from . import raster
                found[public] = (f"{__name__}.{alias.name}", None)
            else:
                found[public] = (f"{__name__}.{node.module}", alias.name)
    return found


_EXPORTS: dict[str, tuple[str, str | None]] = {}


def __getattr__(name: str) -> Any:
    if not _EXPORTS:
        _EXPORTS.update(_exports())
    if name == "__all__":  # what is advertised: not the deprecated names
        return sorted([*(n for n in _EXPORTS if n not in DEPRECATED), "__version__"])
    if name not in _EXPORTS:
        raise AttributeError(f"module 'scanconv' has no attribute {name!r}")
    module, attr = _EXPORTS[name]
    value = importlib.import_module(module)
    if attr is not None:
        value = getattr(value, attr)
    if name in DEPRECATED:
        import warnings

        warnings.warn(
            f"scanconv.{name} is deprecated: use {DEPRECATED[name]}",
            DeprecationWarning,
            stacklevel=2,
        )
        return value  # not cached: every use warns
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return list(__getattr__("__all__"))

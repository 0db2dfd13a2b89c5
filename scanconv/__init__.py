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

Coordinates are ``(x, y)`` with y up. Everything is imported on first use (PEP 562), so
``import scanconv`` stays cheap for the command line.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

#: public name -> (module, attribute); an API function is wrapped to return an Answer.
_LAZY: dict[str, tuple[str, str]] = {
    # records
    "Answer": ("scanconv.display", "Answer"),
    "Column": ("scanconv.core.records", "Column"),
    "Move": ("scanconv.core.records", "Move"),
    "Quantity": ("scanconv.core.records", "Quantity"),
    "Solution": ("scanconv.core.records", "Solution"),
    "Step": ("scanconv.core.records", "Step"),
    "Table": ("scanconv.core.records", "Table"),
    "InputError": ("scanconv.core.checks", "InputError"),
    "round_half_up": ("scanconv.core.numeric", "round_half_up"),
    # the generators, by unambiguous names
    "bresenham_line": ("scanconv.algorithms.lines", "bresenham"),
    "dda_line": ("scanconv.algorithms.lines", "dda"),
    "basic_line": ("scanconv.algorithms.lines", "basic"),
    "midpoint_circle": ("scanconv.algorithms.circles", "midpoint"),
    "bresenham_circle": ("scanconv.algorithms.circles", "bresenham"),
    "midpoint_ellipse": ("scanconv.algorithms.ellipses", "midpoint_ellipse"),
    # earlier names, kept
    "bresenham": ("scanconv.algorithms.lines", "bresenham"),
    "dda": ("scanconv.algorithms.lines", "dda"),
    "basic": ("scanconv.algorithms.lines", "basic"),
    "line_solution": ("scanconv.answers.line", "line_solution"),
    # the question language: scanconv's own arguments as a question
    "check": ("scanconv.questions", "check"),
}


def _api_names() -> list[str]:
    """The API functions (one per command), from :mod:`scanconv._api`."""
    from . import _api

    return [n for n in _api.__all__ if n[0].islower()]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        module, attr = _LAZY[name]
        value = getattr(importlib.import_module(module), attr)
    elif name == "raster":
        value = importlib.import_module("scanconv.algorithms.raster")
    elif name == "__all__":
        value = sorted([*_LAZY, *_api_names(), "raster", "__version__"])
    elif not name.startswith("_") and name in _api_names():
        from .display import answering

        value = answering(name)
    else:
        raise AttributeError(f"module 'scanconv' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*_LAZY, *_api_names(), "raster", "__version__"])

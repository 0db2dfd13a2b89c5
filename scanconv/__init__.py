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
(what type checkers read), and imported from there on first use (as skimage's
``lazy.attach_stub`` does), by the package's one lazy-loading mechanism
(:mod:`scanconv.core.lazy`), so ``import scanconv`` stays cheap for the command line.
"""

from __future__ import annotations

from .core.lazy import attach_stub

__version__ = "0.1.0"

#: Names kept for old code, with what to use instead (a DeprecationWarning on use).
DEPRECATED = {
    "line_solution": "scanconv.line(x1, y1, x2, y2, algo=...), whose table is in the notes' "
    "layout unless layout='textbook' (line_solution's default)",
}


__getattr__, __dir__ = attach_stub(__name__, __file__, DEPRECATED)

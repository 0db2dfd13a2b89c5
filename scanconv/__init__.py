"""scanconv: scan-conversion algorithms as exam-style worked solutions.

The library is usable without the CLI: every algorithm is a generator of
:class:`~scanconv.core.records.Step` records, and every ``*_solution`` function returns a
:class:`~scanconv.core.records.Solution` that the renderers in :mod:`scanconv.render` turn into
text. Coordinates are ``(x, y)`` with y up (see :mod:`scanconv.core.records`).

>>> from scanconv import bresenham
>>> [s.pixel for s in bresenham(0, 0, 3, 1)]
[(1, 0), (2, 1), (3, 1)]
"""

from .algorithms.lines import basic, bresenham, dda
from .answers.line import line_solution
from .core.numeric import round_half_up
from .core.records import Column, Move, Quantity, Solution, Step, Table

__version__ = "0.1.0"

__all__ = [
    "Column",
    "Move",
    "Quantity",
    "Solution",
    "Step",
    "Table",
    "__version__",
    "basic",
    "bresenham",
    "dda",
    "line_solution",
    "round_half_up",
]

"""The Python API: one function per command of the command line, each returning an
:class:`~scanconv.display.Answer` (a :class:`~scanconv.core.records.Solution` that shows
itself).

The keywords are the library's parameter names; the choices are strings or the library's enums
(:class:`LineAlgorithm`, :class:`CircleMethod`, :class:`Rounding`). A number may be an ``int``,
a :class:`~fractions.Fraction`, a ``float`` (read as the decimal it prints as, so ``0.1`` is
exactly 1/10, as on the command line) or a string (``"5/2"``, ``"-3"``, ``"1e3"``); a formula
parameter (``t``, ``t_range``, ``domain``, ``value_range`` of :func:`sample`) also takes a
constant expression such as ``"2*pi"``. Bad input raises
:class:`~scanconv.core.checks.InputError` (a ``ValueError``) naming the parameter where this
module finds it, and the library's ``ValueError`` otherwise.

Render a solution with :func:`scanconv.render.render`, or read it directly:

>>> from scanconv._api import circle
>>> sol = circle(5, method="bresenham")
>>> [step.pixel for step in sol.steps()]
[(0, 5), (1, 5), (2, 5), (3, 4)]

Every name is listed once, in ``__init__.pyi`` (what type checkers read), and imported from
there on first use by the package's one lazy-loading mechanism (:func:`scanconv.core.lazy.attach_stub`),
so importing this module, or one command's function, stays cheap.
"""

from __future__ import annotations

from ..core.lazy import attach_stub

__getattr__, __dir__ = attach_stub(__name__, __file__)

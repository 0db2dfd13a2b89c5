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
``lazy.attach_stub`` does: :func:`_attach_stub`), so ``import scanconv`` stays cheap for the
command line.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping
    from typing import Any

__version__ = "0.1.0"

#: Names kept for old code, with what to use instead (a DeprecationWarning on use).
DEPRECATED = {
    "line_solution": "scanconv.line(x1, y1, x2, y2, algo=...), whose table is in the notes' "
    "layout unless layout='textbook' (line_solution's default)",
}


# --- the public names, loaded on first use from the stub (scanconv.questions uses this too) ---


def _stub_exports(
    package: str, init_file: str
) -> tuple[dict[str, tuple[str, str | None]], list[str]]:
    """Every name the stub beside ``init_file`` imports -> (module, attribute; ``None``: the
    module itself), from its ``from X import a as b`` lines; and the stub's ``__all__``."""
    import ast
    from pathlib import Path

    found: dict[str, tuple[str, str | None]] = {}
    listed: list[str] = []
    tree = ast.parse(Path(init_file).with_suffix(".pyi").read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "__all__":
            listed = list(ast.literal_eval(node.value))
        if not isinstance(node, ast.ImportFrom):
            continue
        base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
        for alias in node.names:
            public = alias.asname or alias.name
            if node.module is None:  # from . import raster
                found[public] = (f"{base}.{alias.name}", None)
            else:  # from .x import a, or from ..x import a (a level up)
                found[public] = (f"{base}.{node.module}", alias.name)
    return found, listed or sorted(found)


def _attach_stub(
    package: str, init_file: str, deprecated: Mapping[str, str] | None = None
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for the package ``package``: each public name of its
    stub, imported on first use and kept; a name in ``deprecated`` (name -> what to use
    instead) warns on every use and is left out of ``__all__`` and ``dir()``."""
    import sys

    exports: dict[str, tuple[str, str | None]] = {}
    listed: list[str] = []
    old = deprecated or {}

    def __getattr__(name: str) -> Any:
        if not exports:
            found, names = _stub_exports(package, init_file)
            exports.update(found)
            listed.extend(n for n in names if n not in old)
        if name == "__all__":
            return list(listed)
        if name not in exports:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        import importlib

        module, attr = exports[name]
        value = importlib.import_module(module)
        if attr is not None:
            value = getattr(value, attr)
        if name in old:
            import warnings

            message = f"{package}.{name} is deprecated: use {old[name]}"
            warnings.warn(message, DeprecationWarning, stacklevel=2)
            return value  # not kept: every use warns
        vars(sys.modules[package])[name] = value
        return value

    def __dir__() -> list[str]:
        return list(__getattr__("__all__"))

    return __getattr__, __dir__


__getattr__, __dir__ = _attach_stub(__name__, __file__, DEPRECATED)

"""scanconv's one lazy-loading mechanism: a module, or a name in it, imported on first use.

The command line answers one question per run, so it must not pay at start-up for the modules
of every other command, format or method (``docs/performance.md``: start-up within 1.3 times
``python -c "import typer"``). Everything scanconv loads later than its own import goes
through this module, in one of three forms:

- :func:`load` (``"package.module:attribute"``, or a module alone): the registries that name
  what they load, so that reading the table costs nothing: the method records
  (:meth:`scanconv.answers.methods.Method.load`), the renderer of each format
  (:func:`scanconv.render.render`), the command modules of the CLI
  (:func:`scanconv.cli.application.register`) and the theory sections
  (:func:`scanconv.answers.theory.topics.topics`).
- :func:`attach_stub` (PEP 562): a package's public names, listed once in its ``__init__.pyi``
  (what type checkers read) and imported when first used (``scanconv``, ``scanconv._api``,
  ``scanconv.questions``), as skimage's ``lazy.attach_stub`` does.
- :func:`module`: a module bound at the top of the module that uses it but imported when one
  of its names is first read, for a dependency that only some paths need (rich, the figure
  writer, the budget's tables). Written with its import for the type checkers and the layers
  contract, which then see it as an ordinary import::

      if TYPE_CHECKING:
          from ..render import budget
      else:
          budget = lazy.module("scanconv.render.budget")

- :func:`pattern`: a regular expression compiled when first used (compiling one costs as much
  as importing a small module, and most runs never need most of them).

A function-local import is kept only where the import itself is the point (a standard-library
module that one rare path needs, an optional dependency whose absence is the error to report).

>>> load("scanconv.core.numeric:parse_number")("5/2")
Fraction(5, 2)
>>> load("scanconv.core.numeric").__name__
'scanconv.core.numeric'
>>> numeric = module("scanconv.core.numeric")  # the module itself once it is imported
>>> numeric.parse_number("1/2")
Fraction(1, 2)
"""

from __future__ import annotations

import importlib
import sys

TYPE_CHECKING = False  # not typing's: ``import scanconv`` loads this module and no more
if TYPE_CHECKING:
    import re
    from collections.abc import Callable, Mapping
    from typing import Any

__all__ = ["attach_stub", "load", "module", "pattern", "stub_exports"]


def load(ref: str) -> Any:
    """The object ``ref`` names, imported now: ``"package.module:attribute"``, or
    ``"package.module"`` for the module itself.

    >>> load("scanconv.core.checks:InputError").__name__
    'InputError'
    """
    name, _, attr = ref.partition(":")
    found = importlib.import_module(name)
    return getattr(found, attr) if attr else found


class _LazyModule(type(sys)):  # type: ignore[misc]  # types.ModuleType
    """A stand-in for a module that imports it on the first attribute read and reads every
    attribute from it, live (a test's ``monkeypatch`` of the module is seen) (:func:`module`)."""

    _lazy_real: Any = None

    def __getattr__(self, attr: str) -> Any:
        if self._lazy_real is None:
            self._lazy_real = importlib.import_module(self.__name__)
        return getattr(self._lazy_real, attr)

    def __repr__(self) -> str:
        return f"<lazy module {self.__name__!r}>"


def module(name: str) -> Any:
    """The module ``name`` (absolute), imported when one of its names is first read.

    Typed ``Any``: bind it under ``TYPE_CHECKING``'s import of the same module (module
    docstring), so that the type checkers and import-linter see the real one.
    """
    loaded = sys.modules.get(name)
    return loaded if loaded is not None else _LazyModule(name)


class _LazyPattern:
    """A stand-in for a compiled regular expression, compiled on first use (:func:`pattern`)."""

    def __init__(self, regex: str, flags: int) -> None:
        self._args = (regex, flags)

    def __getattr__(self, attr: str) -> Any:
        value = getattr(re.compile(*self._args), attr)
        setattr(self, attr, value)  # later reads are plain attribute reads
        return value

    def __repr__(self) -> str:
        return f"lazy.pattern({self._args[0]!r})"


def pattern(regex: str, flags: int = 0) -> re.Pattern[str]:
    """``re.compile(regex, flags)``, compiled when one of its methods is first used.

    >>> digits = pattern("[0-9]+")
    >>> digits.findall("a1b22"), digits.pattern
    (['1', '22'], '[0-9]+')
    """
    return _LazyPattern(regex, flags)  # type: ignore[return-value]  # it stands in for one


if not TYPE_CHECKING:
    re = module("re")


# --- the public names of a package, from its stub ------------------------------------------------


def stub_exports(package: str, init_file: str) -> dict[str, tuple[str, str | None]]:
    """Every name the stub beside ``init_file`` imports -> (module, attribute; ``None``: the
    module itself), from its ``from X import a as b`` lines (one name a line, as ruff's isort
    writes them; anything else falls back to :mod:`ast`)."""
    text = _stub_text(init_file)
    found: dict[str, tuple[str, str | None]] = {}
    for line in text.splitlines():
        if not line.startswith("from "):
            continue
        words = line.split()  # from .x import a [as b]
        source, name, alias = words[1], words[3 % len(words)], words[-1]
        shape = words[2:3] == ["import"] and words[4:5] in ([], ["as"]) and len(words) in (4, 6)
        if not (shape and name.isidentifier() and alias.isidentifier()):
            return _stub_tree(package, text)[0]
        where = source.lstrip(".")
        dots = source[: len(source) - len(where)]
        base = package.rsplit(".", len(dots) - 1)[0] if len(dots) > 1 else package
        if not dots:  # from scanconv.x import a
            found[alias] = (where, name)
        elif where:  # from .x import a, or from ..x import a (a level up)
            found[alias] = (f"{base}.{where}", name)
        else:  # from . import raster
            found[alias] = (f"{base}.{name}", None)
    return found


def _stub_text(init_file: str) -> str:
    with open(init_file.removesuffix(".py") + ".pyi", encoding="utf-8") as stub:
        return stub.read()


def _stub_tree(package: str, text: str) -> tuple[dict[str, tuple[str, str | None]], list[str]]:
    """The stub's imports (as :func:`stub_exports`) and its ``__all__``, read with :mod:`ast`."""
    import ast  # the slow, general reader: __all__ and any import the fast one cannot read

    found: dict[str, tuple[str, str | None]] = {}
    listed: list[str] = []
    for node in ast.parse(text).body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "__all__":
            listed = list(ast.literal_eval(node.value))
        if not isinstance(node, ast.ImportFrom):
            continue
        base = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
        for alias in node.names:
            public = alias.asname or alias.name
            if node.level == 0:
                found[public] = (str(node.module), alias.name)
            elif node.module is None:
                found[public] = (f"{base}.{alias.name}", None)
            else:
                found[public] = (f"{base}.{node.module}", alias.name)
    return found, listed or sorted(found)


def attach_stub(
    package: str, init_file: str, deprecated: Mapping[str, str] | None = None
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for the package ``package``: each public name of its
    stub, imported on first use and kept; a name in ``deprecated`` (name -> what to use
    instead) warns on every use and is left out of ``__all__`` and ``dir()``.

    A private name (``_api``: a subpackage being imported, which ``from . import _api`` first
    looks up here) is not read from the stub."""
    exports: dict[str, tuple[str, str | None]] = {}
    old = deprecated or {}

    def __getattr__(name: str) -> Any:
        if name == "__all__":
            listed = _stub_tree(package, _stub_text(init_file))[1]
            return [n for n in listed if n not in old]
        if name.startswith("_") and name not in old:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        if not exports:
            exports.update(stub_exports(package, init_file))
        if name not in exports:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        where, attr = exports[name]
        value = load(where if attr is None else f"{where}:{attr}")
        if name in old:
            import warnings  # only a deprecated name warns

            message = f"{package}.{name} is deprecated: use {old[name]}"
            warnings.warn(message, DeprecationWarning, stacklevel=2)
            return value  # not kept: every use warns
        vars(sys.modules[package])[name] = value
        return value

    def __dir__() -> list[str]:
        return list(__getattr__("__all__"))

    return __getattr__, __dir__

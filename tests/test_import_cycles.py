"""No import cycle in the library: every module of scanconv can be read (and imported) after the
modules it imports, so each layer and each package stands on the ones below it.

The graph is built from the source with :mod:`ast`, not from a running interpreter: every
``import`` and ``from ... import`` of scanconv's own (relative ones resolved; those under
``if TYPE_CHECKING:`` too, since they name the same dependency the code reaches at run time),
plus the run-time imports written as strings, ``lazy.module("scanconv.x")`` and
``lazy.load("scanconv.x:name")`` (:mod:`scanconv.core.lazy`). A cycle is a strongly connected
component of more than one module (Tarjan's algorithm), and the test names each one with the
import that closes it.
"""

from __future__ import annotations

import ast
from collections.abc import Collection, Iterator, Mapping
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "scanconv"


def _name(path: Path, root: Path) -> str:
    parts = list(path.relative_to(root.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _lazy_target(node: ast.Call) -> str | None:
    """``lazy.module("a.b")`` -> ``a.b``; ``lazy.load("a.b:c")`` -> ``a.b``."""
    f = node.func
    if not (isinstance(f, ast.Attribute) and f.attr in ("module", "load")):
        return None
    if not (isinstance(f.value, ast.Name) and f.value.id == "lazy") or not node.args:
        return None
    arg = node.args[0]
    if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
        return arg.value.partition(":")[0]
    return None


def _imported(
    tree: ast.AST, name: str, is_package: bool, modules: Collection[str]
) -> Iterator[tuple[str, int]]:
    """The modules a module's source imports (statically or through ``lazy``), each with the
    line of the import: ``from .pkg import sub`` is the module ``pkg.sub`` when there is one,
    else the package ``pkg`` (a name in its ``__init__``)."""
    here = name.split(".") if is_package else name.split(".")[:-1]
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, node.lineno
        elif isinstance(node, ast.ImportFrom):
            parts = here[: len(here) - node.level + 1] if node.level else []
            base = ".".join([*parts, *([node.module] if node.module else [])])
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                yield (sub if sub in modules else base), node.lineno
        elif isinstance(node, ast.Call) and (target := _lazy_target(node)):
            yield target, node.lineno


def import_graph(root: Path) -> dict[str, dict[str, int]]:
    """Module -> {module of the same package it imports: the line of its first import}."""
    paths = {_name(p, root): p for p in sorted(root.rglob("*.py"))}
    graph: dict[str, dict[str, int]] = {}
    for name, path in paths.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        edges: dict[str, int] = {}
        for module, line in _imported(tree, name, path.name == "__init__.py", paths):
            if module in paths and module != name:
                edges.setdefault(module, line)
        graph[name] = edges
    return graph


def cycles(graph: Mapping[str, Mapping[str, int]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(found)


def _describe(component: list[str], graph: Mapping[str, Mapping[str, int]]) -> str:
    inside = set(component)
    links = [
        f"{a} imports {b} (line {line})"
        for a in component
        for b, line in sorted(graph[a].items())
        if b in inside
    ]
    return "; ".join(links)


def _write(root: Path, files: Mapping[str, str]) -> Path:
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root / "pkg"


def test_the_graph_sees_static_relative_and_lazy_imports(tmp_path: Path) -> None:
    """The measure itself, on a package written here: a cycle through a relative import and a
    ``lazy.module`` string, one through ``lazy.load`` and a ``TYPE_CHECKING`` import, and a
    package importing its own submodules (no cycle)."""
    root = _write(
        tmp_path,
        {
            "pkg/__init__.py": "from . import a, b\n",
            "pkg/a.py": "from .sub.c import X\n",
            "pkg/sub/__init__.py": "",
            "pkg/sub/c.py": "from ..core import lazy\nb = lazy.module('pkg.a')\nX = 1\n",
            "pkg/core/__init__.py": "",
            "pkg/core/lazy.py": "",
            "pkg/b.py": "if TYPE_CHECKING:\n    from pkg import d\n",
            "pkg/d.py": "from .core import lazy\nf = lazy.load('pkg.b:f')\n",
            "pkg/e.py": "import pkg.core.lazy\n",
        },
    )
    graph = import_graph(root)
    assert graph["pkg"] == {"pkg.a": 1, "pkg.b": 1}
    assert graph["pkg.sub.c"] == {"pkg.core.lazy": 1, "pkg.a": 2}
    assert graph["pkg.e"] == {"pkg.core.lazy": 1}
    assert cycles(graph) == [["pkg.a", "pkg.sub.c"], ["pkg.b", "pkg.d"]]


@pytest.mark.slow  # parses every module of the library: about a second
def test_the_library_has_no_import_cycle() -> None:
    graph = import_graph(PACKAGE)
    assert len(graph) > 150  # the whole library was read
    found = cycles(graph)
    assert not found, "import cycles: " + " | ".join(_describe(c, graph) for c in found)

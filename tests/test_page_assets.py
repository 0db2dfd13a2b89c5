"""The HTML page's style sheets and scripts are real files (``scanconv/render/html/static/``):
each is listed, shipped in the wheel and in the site's wheel, put on the page, and parses: the
scripts by node (``node --check``), the style sheets by a structural reader written here and by
css-tree, a CSS parser with the property grammar of MDN's data (the one csstree-validator uses),
installed into a temporary directory as tests/test_lms.py installs its GIFT parser."""

from __future__ import annotations

import fnmatch
import io
import json
import os
import re
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from scanconv.render.html import page_assets

from .external import npm_install

ROOT = Path(__file__).resolve().parent.parent
STATIC = ROOT / "scanconv" / "render" / "html" / "static"
SITE = ROOT / "scanconv" / "site" / "static"
SCRIPTS = sorted([*STATIC.glob("*.js"), SITE / "app.js", SITE / "worker.mjs"])
SHEETS = sorted([*STATIC.glob("*.css"), SITE / "site.css"])


def test_every_file_is_listed_and_on_the_page() -> None:
    assert sorted(p.name for p in STATIC.iterdir()) == sorted(page_assets.FILES)
    texts = (page_assets.CSS, page_assets.PAGE_CSS, page_assets.SHEET_CSS, page_assets.JS)
    for name in page_assets.FILES:
        body = (STATIC / name).read_text(encoding="utf-8")
        assert body and page_assets.read(name) == body
        assert any(body in t for t in texts), f"{name} is on no page"


def test_the_wheel_and_the_site_ship_them() -> None:
    tomllib = pytest.importorskip("tomllib")  # Python 3.11+
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = config["tool"]["setuptools"]["package-data"]["scanconv.render.html"]
    for name in page_assets.FILES:
        assert any(fnmatch.fnmatch(f"static/{name}", p) for p in patterns), name
    from scanconv.site.build import scanconv_wheel

    _, data = scanconv_wheel()
    shipped = set(zipfile.ZipFile(io.BytesIO(data)).namelist())
    assert {f"scanconv/render/html/static/{n}" for n in page_assets.FILES} <= shipped


def _node() -> str:
    found = shutil.which("node")
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("node missing in CI: the page's scripts are checked with node --check")
        pytest.skip("node is needed to check the page's scripts (apt-get install nodejs)")
    return found


def _node_check(node: str, path: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([node, "--check", str(path)], capture_output=True, text=True, timeout=60)


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: p.name)
def test_each_script_parses(path: Path) -> None:
    done = _node_check(_node(), path)
    assert done.returncode == 0, done.stderr


def test_a_broken_script_is_caught(tmp_path: Path) -> None:
    broken = tmp_path / "broken.js"
    broken.write_text((STATIC / "stepper.js").read_text(encoding="utf-8").replace(")", "", 1))
    assert _node_check(_node(), broken).returncode != 0


# --- the style sheets: a structural reader -----------------------------------------------------

_DECLARATION = re.compile(r"\s*(--[\w-]+|-?[a-z][a-z-]*)\s*:\s*\S")


def css_problems(text: str) -> list[str]:
    """What is wrong with a style sheet's structure: an unbalanced or stray brace, an
    unterminated comment or string, a rule without a selector, a declaration that is not
    ``property: value``. ``[]``: none. Strings and comments are read as such (a brace in
    ``content:"{"`` is not a block)."""
    problems: list[str] = []
    stack: list[str] = []  # the preludes of the open blocks
    buf, i = "", 0
    while i < len(text):
        c = text[i]
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            if end < 0:
                return [*problems, "an unterminated comment"]
            i = end + 2
            continue
        if c in "\"'":
            end = i + 1
            while end < len(text) and text[end] != c:
                end += 2 if text[end] == "\\" else 1
            if end >= len(text):
                return [*problems, "an unterminated string"]
            buf += text[i : end + 1]
            i = end + 1
            continue
        if c == "{":
            if not buf.strip():
                problems.append(f"a block without a selector at {i}")
            stack.append(buf.strip())
            buf = ""
        elif c == "}":
            if not stack:
                problems.append(f"a stray '}}' at {i}")
            else:
                problems += _declarations(buf, stack.pop())
            buf = ""
        else:
            buf += c
        i += 1
    if stack:
        problems.append(f"{len(stack)} block(s) left open: {stack[-1][:40]!r}")
    elif buf.strip():
        problems.append(f"text outside any rule: {buf.strip()[:40]!r}")
    return problems


def _declarations(body: str, prelude: str) -> list[str]:
    if prelude.startswith("@media") and not body.strip():
        return []  # a group of rules: its rules were read as blocks
    return [
        f"not a declaration in {prelude[:40]!r}: {d.strip()[:40]!r}"
        for d in body.split(";")
        if d.strip() and not _DECLARATION.match(d)
    ]


def test_the_reader_finds_what_is_wrong() -> None:
    assert css_problems('a{color:red}@media print{b{content:"{"}}') == []
    assert css_problems("a{color:red") == ["1 block(s) left open: 'a'"]
    assert css_problems("a{color:red}}") == ["a stray '}' at 12"]
    assert css_problems("{color:red}") == ["a block without a selector at 0"]
    assert css_problems("a{color red}") == ["not a declaration in 'a': 'color red'"]
    assert css_problems("a{content:'x}") == ["an unterminated string"]
    assert css_problems("a{} /* b") == ["an unterminated comment"]


@pytest.mark.parametrize("path", SHEETS, ids=lambda p: p.name)
def test_each_style_sheet_is_well_formed(path: Path) -> None:
    assert css_problems(path.read_text(encoding="utf-8")) == []


def test_the_page_s_whole_style_is_well_formed() -> None:
    for css in (page_assets.CSS, page_assets.PAGE_CSS, page_assets.PLAIN, page_assets.SHEET_CSS):
        assert css_problems(css) == []


# --- the style sheets: css-tree's parser and property grammar ----------------------------------

_LINT = """
const csstree = require(process.argv[2]);
const fs = require("fs");
const out = {};
for (const file of process.argv.slice(3)) {
  const errors = [];
  const ast = csstree.parse(fs.readFileSync(file, "utf8"), {
    positions: true, onParseError: (e) => errors.push(`${e.line}:${e.column} ${e.message}`),
  });
  csstree.walk(ast, {visit: "Declaration", enter(node) {
    if (node.property.startsWith("--")) { return; }
    const m = csstree.lexer.matchDeclaration(node);
    // css-tree cannot match a value holding var() (its value is known only at run time)
    if (m.error && !/var\\(\\) is not supported/.test(m.error.message)) {
      errors.push(`${node.loc.start.line}:${node.loc.start.column} ${node.property}: ${m.error.message}`);
    }
  }});
  out[file] = errors;
}
console.log(JSON.stringify(out));
"""


@pytest.fixture(scope="module")
def css_tree(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Path, Path]:
    """css-tree 3.x installed with npm into a temporary directory (needs node, npm and the
    registry: CI has them), and the script that reads style sheets with it."""
    node = _node()
    if shutil.which("npm") is None and os.environ.get("CI"):
        pytest.fail("npm missing in CI: the style sheets are checked with css-tree")
    module = npm_install(tmp_path_factory.mktemp("css-tree"), "css-tree@3")
    script = module.parent.parent / "lint.js"
    script.write_text(_LINT, encoding="utf-8")
    return node, script, module


def _css_tree(css_tree: tuple[str, Path, Path], paths: list[Path]) -> dict[str, list[str]]:
    node, script, module = css_tree
    done = subprocess.run(
        [node, str(script), str(module), *map(str, paths)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    found: dict[str, list[str]] = json.loads(done.stdout)
    return {Path(k).name: v for k, v in found.items()}


@pytest.mark.external
def test_every_style_sheet_is_valid_css(css_tree: tuple[str, Path, Path], tmp_path: Path) -> None:
    bad = tmp_path / "bad.css"
    bad.write_text("a{colr:red}b{width:wide}", encoding="utf-8")
    found = _css_tree(css_tree, [*SHEETS, bad])
    assert len(found.pop("bad.css")) == 2  # an unknown property, a value outside its grammar
    assert found == {p.name: [] for p in SHEETS}

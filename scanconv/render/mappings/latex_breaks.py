r"""Where a line of LaTeX may break inside a formula (issue 39, item 4: no overfull box).

TeX breaks an inline formula only after a relation (``=``) or a binary operator (``+``), and
never inside a ``\text{...}`` (a box) or after a comma. A working line such as
``\text{after the left edge (x = xmin = 1): } (1, 0), (6, 0), (6, 6), ...`` is one unbreakable
run wider than the page. :func:`breakable_math` writes the same formula as a line can break:
each ``\text{...}`` at the formula's top level is set as text between two formulas (its words
break as words do), and each comma at the top level (between two points, never inside one)
is followed by ``\allowbreak``. Nothing is shrunk: the type keeps its size.
"""

from __future__ import annotations

import re

from ...core.numeric import fmt_pixel
from ...document import Document, Pixels, StepTable, Table
from .. import Options
from ..cells import wrap_items
from ..figures.grid import too_large
from ..figures.tikz import grid_height

__all__ = ["breakable_math", "kept_with_grid"]

_TOKEN = re.compile(
    r"\\begin\{[^{}]*\}|\\end\{[^{}]*\}|\\left\b|\\right\b|\\text(?:bf)?\{|\\[a-zA-Z]+|\\.|.",
    re.DOTALL,
)


_ENVIRONMENT = {"\\begi": 1, "\\end{": -1}
"""How a token's first five characters change the depth of environments (``\\begin{...}``)."""


def _group(tex: str, start: int) -> int:
    """The index just past the brace group that opens at ``tex[start - 1]`` (a ``{``)."""
    depth = 1
    i = start
    while i < len(tex) and depth:
        c = tex[i]
        if c == "\\":
            i += 2
            continue
        depth += {"{": 1, "}": -1}.get(c, 0)
        i += 1
    return i


def _pieces(tex: str) -> list[tuple[bool, str]]:
    """The formula as (is math, TeX) pieces: its top-level ``\\text{...}`` as text, and
    ``\\allowbreak`` after each top-level comma of the math."""
    pieces: list[tuple[bool, str]] = []
    math: list[str] = []
    braces = parens = nested = 0  # brace depth, bracket depth, \left and \begin depth
    previous = ""
    i = 0
    while i < len(tex):
        token = _TOKEN.match(tex, i).group()  # type: ignore[union-attr]  # "." matches
        i += len(token)
        top = braces == 0 and nested == 0
        if token in ("\\text{", "\\textbf{") and top and previous not in ("_", "^"):
            end = _group(tex, i)
            words = tex[i : end - 1] if token == "\\text{" else f"\\textbf{{{tex[i : end - 1]}}}"
            pieces += [(True, "".join(math)), (False, words)]
            math, i, previous = [], end, "}"
            continue
        braces += 1 if token == "{" or token[2:].endswith("{") else -(token == "}")
        nested += {"\\left": 1, "\\right": -1}.get(token, 0) + _ENVIRONMENT.get(token[:5], 0)
        if top and token in "([":
            parens += 1
        elif top and token in ")]":
            parens = max(0, parens - 1)
        math.append(token)
        if token == "," and top and parens == 0:
            math.append("\\allowbreak")
        if not token.isspace():
            previous = token
    pieces.append((True, "".join(math)))
    return pieces


def breakable_math(tex: str) -> str:
    r"""An inline formula (without its ``$``) as LaTeX a line can break: ``$...$`` pieces and
    the words of its top-level ``\text{...}`` between them.

    >>> breakable_math(r"\text{clipped (2 vertices): } (1, 0), (6, 0)")
    'clipped (2 vertices): $(1, 0),\\allowbreak (6, 0)$'
    >>> breakable_math(r"x_{\text{max}} = 4 \quad (\text{r is the largest})")
    '$x_{\\text{max}} = 4 \\quad ($r is the largest$)$'
    >>> breakable_math(r"\text{area} = 4 \quad (\text{before: } 28)")
    'area $= 4 \\quad ($before: $28)$'
    >>> breakable_math(r"\textbf{3. draw the edges}")
    '\\textbf{3. draw the edges}'
    >>> breakable_math(r"\begin{bmatrix} 1 & 2 \end{bmatrix}, x_\text{a}")
    '$\\begin{bmatrix} 1 & 2 \\end{bmatrix},\\allowbreak x_\\text{a}$'
    """
    out = ""
    for math, piece in _pieces(tex):
        if not math:
            out += piece.lstrip() if out[-1:].isspace() else piece
            continue
        core = _EDGE_SPACE.sub("", piece)
        if core:
            lead, trail = _LEAD.match(piece), _TRAIL.search(piece)  # a space at either end
            before = " " if lead and lead.group() and out and not out[-1:].isspace() else ""
            after = " " if trail and trail.group() else ""
            out += f"{before}${core}${after}"
    return out.strip()


_LEAD = re.compile(r"^(?:\\ |\s)*")
_TRAIL = re.compile(r"(?:(?<!\\)\s|\\ )*$")
_EDGE_SPACE = re.compile(r"^(?:\\ |\s)+|(?:(?<!\\)\s|\\ )+$")
"""The spaces (``\\ `` too) at either end of a piece of math: a space between text and math."""


def kept_with_grid(doc: Document, options: Options) -> tuple[int, float]:
    """The index of the table set right above the pixel list and its grid, and how much room
    (points) they take: its heading makes room for the table, the list and the grid together,
    so that a page break never falls between a table's last rows and its grid (issue 39).
    ``(-1, 0)`` when there is no such table or no grid drawn."""
    blocks = doc.blocks
    at = next((i for i, b in enumerate(blocks) if isinstance(b, Pixels)), -1)
    table = at - 1
    if at < 1 or not isinstance(blocks[table], StepTable | Table) or not options.grid:
        return -1, 0
    pixels = blocks[at]
    assert isinstance(pixels, Pixels)
    tall = None if too_large(pixels.bbox) else grid_height(doc, options.origin)
    if tall is None:
        return -1, 0
    lines = sum(1 for _ in wrap_items(f"${fmt_pixel(p)}$" for p in pixels.pixels()))
    return table, tall + 12 * lines + 30

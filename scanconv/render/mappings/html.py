"""The ``html`` format: one self-contained page to step through an answer in a browser.

The page holds the full worked answer (given values, working, notes and conventions, the
tables, the pixels) beside a pixel grid drawn as SVG with the ideal primitive over it, and a
stepper: Next / Previous / Play-Pause / Reset buttons, a slider and the keyboard (right and
left arrows, space, Home, End). At step ``p`` the table row of step ``p`` is highlighted, the
pixels plotted so far are lit (a circle's or ellipse's mirror images in a lighter shade, the
ellipse's region 2 in another colour), the pixels the step plotted are outlined, and a
caption gives the decision with its numbers. Clicking a row jumps to its step; hovering a
pixel names it and the step that plotted it. Printing gives the plain worked answer (every
pixel shown, no controls).

**Positions.** Position 0 is the start: the pixels plotted before the first row (Bresenham's
start point, whose table rows plot ``(x_{k+1}, y_{k+1})``). Position ``p >= 1`` is the
``p``-th step record: its row is highlighted, and the pixels of the first ``p`` steps (each
step's point and, with 4- or 8-way symmetry, its mirror images) are lit. Pixels no step
reaches (the joining pixels of a curve) light with the next step that reaches a pixel after
them in plotting order. An answer with pixels but no step table (a fill, a polygon) steps
through its pixels in plotting order; an answer with neither has no stepper.

**Nothing from the network.** The math is MathML written by :mod:`latex2mathml` from the
working's TeX (imported only here, start-up time), which browsers typeset natively; the style
and the script are inline (:mod:`scanconv.render.html.page_assets`). Every text from the answer is
escaped; the step data sits in a ``<script type="application/json">`` with ``<``, ``>`` and
``&`` written as ``\\u003c`` escapes, so no text can close the script.

**Large answers.** The page steps through at most
:data:`~scanconv.render.html.stepper.MAX_STEPS` steps, draws at most
:data:`~scanconv.render.html.stepper.MAX_PIXELS` pixels, writes at most
:data:`~scanconv.render.html.stepper.MAX_TABLE_ROWS` rows of a table (fewer for wide tables) and
says on the page what it left out.

**Modules.** This one writes the page; :mod:`scanconv.render.html.stepper` works out the positions
and captions, :mod:`scanconv.render.html.stepgrid` draws the SVG, :mod:`scanconv.render.html.mathml`
turns TeX into MathML and escapes text, :mod:`scanconv.render.html.page_assets` holds the style
sheet and the script.

**For other documents** (the answer key of ``scanconv sheet``, a notebook):

* :func:`html_document` ``(answers, title)`` is a whole page of several answers, each a
  ``(heading, solution)`` pair, each with its own stepper;
* :func:`answer_section` is one answer's ``<section>`` (it needs the page's
  :func:`page_head` style and :data:`~scanconv.render.html.page_assets.JS` script, which
  :func:`page` adds around any body);
* :func:`notebook_html` is one answer as a self-contained fragment for Jupyter, with a unique
  id and its keyboard bound to the answer itself, so two answers never interfere.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from itertools import islice
from typing import TYPE_CHECKING, Any, NamedTuple

from ...core import lazy
from ...core.numeric import fmt_pixel
from ...core.records import Column, Solution, step_getter
from ...document import (
    Contents,
    Document,
    Drawing,
    Given,
    Notes,
    Pixels,
    Pseudocode,
    Question,
    StepTable,
    Table,
    Title,
    Working,
    as_document,
)
from .. import Notice, Options
from ..cells import cell, numeric_column
from ..html import stepper
from ..html.mathml import esc, json_script, note_html, prose_html, prose_segments_html, tex_math
from ..html.selftest import selftest_html
from ..html.stepgrid import figure_svg, legend, step_grid
from ..html.stepper import column_label, stepping

if TYPE_CHECKING:
    from ..html import page_assets
else:
    page_assets = lazy.module("scanconv.render.html.page_assets")

__all__ = [
    "answer_section",
    "esc",
    "html_document",
    "json_script",
    "note_html",
    "notebook_html",
    "page",
    "page_head",
    "render_html",
    "tex_math",
]

MAX_TABLE_CELLS = 30_000
"""Cells written of one table (a wide table gets fewer rows)."""

MAX_TABLE_COLUMNS = 64
"""Columns written of one table."""

MAX_PIXEL_LIST = 4_000
"""Pixels listed in words under the tables."""

"""A secondary table of this many columns or more (the circle's symmetry table) is split into
parts, as in the Markdown and LaTeX answers."""

CHUNK_ROWS = 40
"""A table of more rows is written in a scrolling box, in chunks of this many rows, each laid
out by the browser only when in view (CSS ``content-visibility``): a 1,000-row table opens
about as fast as a short one."""

PLAY_SECONDS = 20.0
"""Play takes about this long over the whole answer (at most 0.7 s, at least 15 ms a step)."""


Positions = dict[int, tuple[int, int]]
"""A table's rows that are stepper positions: ``{row index: (position, region)}``."""


def _table(
    title: str | None,
    columns: Sequence[Column],
    rows: Iterable[Sequence[Any]],
    exact: bool,
    positions: Positions | None = None,
    total: int | None = None,
    at: int = 0,
) -> str:
    """A table, capped (see the module); ``positions`` maps a row index to its stepper
    position and region; ``total`` is the number of rows if known (rows past the cap are not
    computed just to count them: a sampled matrix's rows are expensive)."""
    shown_cols = list(columns[:MAX_TABLE_COLUMNS])
    limit = max(1, min(stepper.MAX_TABLE_ROWS, MAX_TABLE_CELLS // max(1, len(shown_cols))))
    it = iter(rows)
    head = list(islice(it, limit))
    more = next(it, None) is not None
    heads = "".join(f"<th>{tex_math(c.tex)}</th>" for c in shown_cols)
    caption = f"<caption>{esc(title)}</caption>" if title else ""
    widths = [len(column_label(c.tex, None)) for c in shown_cols]
    lines = [_row(i, row, shown_cols, exact, positions, at, widths) for i, row in enumerate(head)]
    if len(lines) <= CHUNK_ROWS:
        body = f'<div class="sc-tablebox"><table class="sc-table">{caption}<thead><tr>{heads}'
        body += "</tr></thead><tbody>" + "".join(lines) + "</tbody></table></div>"
    else:
        body = _chunked(caption, heads, lines, widths)
    notes = []
    if more:
        of = f"of {total:,} rows" if total is not None else "rows of a longer table"
        notes.append(
            f"The table shows the first {len(head):,} {of}; csv or json output carries them all."
        )
    if len(columns) > len(shown_cols):
        notes.append(f"It shows the first {len(shown_cols)} of {len(columns)} columns.")
    if notes:
        body += '<p class="sc-more">' + " ".join(notes) + "</p>"
    return body


def _row(
    i: int,
    row: Sequence[Any],
    columns: Sequence[Column],
    exact: bool,
    positions: Positions | None,
    at: int,
    widths: list[int],
) -> str:
    """One ``<tr>``, with its stepper position if it has one; widens ``widths`` to its cells."""
    attrs = ""
    if positions is not None and i in positions:
        p, region = positions[i]
        classes = ("sc-r2 " if region > 1 else "") + ("sc-cur" if p == at else "")
        attrs = f' data-pos="{p}"' + (f' class="{classes.strip()}"' if classes.strip() else "")
    texts = [cell(v, c, exact) for v, c in zip(row, columns, strict=False)]
    for j, t in enumerate(texts):
        widths[j] = max(widths[j], len(t))
    tds = "".join(
        f'<td class="sc-num">{prose_html(t)}</td>'
        if numeric_column(c)
        else f"<td>{prose_html(t)}</td>"
        for t, c in zip(texts, columns, strict=False)
    )
    return f"<tr{attrs}>{tds}</tr>"


def _chunked(caption: str, heads: str, lines: list[str], widths: list[int]) -> str:
    """A long table: its header, then chunks of rows, each a table of the same fixed column
    widths that the browser lays out only when in view (content-visibility)."""
    cols = "".join(f'<col style="width:calc({w + 1}ch + 1.2em)">' for w in widths)
    total_width = f"calc({sum(widths) + len(widths)}ch + {1.2 * len(widths):.1f}em)"
    fixed = f'class="sc-table sc-fixed" style="width:{total_width}"'
    parts = [
        f'<div class="sc-scroll"><table {fixed} data-head="1">{caption}<colgroup>{cols}'
        f"</colgroup><thead><tr>{heads}</tr></thead></table>"
    ]
    for start in range(0, len(lines), CHUNK_ROWS):
        chunk = "".join(lines[start : start + CHUNK_ROWS])
        parts.append(
            f'<div class="sc-chunk"><table {fixed}><colgroup>{cols}</colgroup>'
            f"<tbody>{chunk}</tbody></table></div>"
        )
    parts.append("</div>")
    return "".join(parts)


def _step_rows(table: StepTable) -> Iterator[tuple[Any, ...]]:
    get = step_getter(table.columns, table.extra_keys)
    for step in table.steps():
        yield get(step)


def _mapped_tables(
    table: StepTable, tables: list[Table], count: int
) -> dict[int, dict[int, int]] | None:
    """When the step table is not shown (the ellipse's regions), which row of which further
    table is which step: ``{table index: {row index: step index}}``; ``None`` if the tables
    do not hold every step, in order."""
    if count == 0:
        return None
    keys = [c.key for c in table.columns]
    get = step_getter(table.columns, table.extra_keys)
    steps = islice(table.steps(), count)
    want = next(steps, None)
    s = 0
    found: dict[int, dict[int, int]] = {}
    for t, further in enumerate(tables):
        shared = [(j, keys.index(c.key)) for j, c in enumerate(further.columns) if c.key in keys]
        if not any(keys[i] == "pixel" for _, i in shared):
            continue
        for r, row in enumerate(islice(further.rows(), stepper.MAX_TABLE_ROWS)):
            if want is None:
                break
            cells = get(want)
            if all(row[j] == cells[i] for j, i in shared):
                found.setdefault(t, {})[r] = s
                s += 1
                want = next(steps, None)
    return found if want is None and s == count else None


class _Page(NamedTuple):
    """What the answer's blocks are written with: the options, the stepper's data (``None``:
    no stepper), the position shown, which further-table rows are steps."""

    options: Options
    st: stepper.Stepping | None
    at: int
    steps: Positions
    mapped: dict[int, dict[int, int]] | None
    tables: list[Table]


def _given(block: Given, page: _Page) -> str:
    return (
        '<p class="sc-given"><strong>Given:</strong> '
        + ", ".join(tex_math(q.tex) for q in block.quantities)
        + "</p>"
    )


def _working(block: Working, page: _Page) -> str:
    items = "".join(f"<li>{tex_math(q.tex, display=True)}</li>" for q in block.lines)
    return f'<h3>Working</h3><ul class="sc-working">{items}</ul>'


def _notes(block: Notes, page: _Page) -> str:
    items = "".join(f"<li>{prose_segments_html(n.segments)}</li>" for n in block.notes)
    return f'<h3>Notes</h3><ul class="sc-notes">{items}</ul>'


def _step_table(block: StepTable, page: _Page) -> str:
    if not block.columns or not (block.shown or page.mapped is None):
        return ""
    title = "Step table" if block.shown else "Step table (the tables below split it up)"
    total = page.st.total if page.st else None
    rows = _step_rows(block)
    return _table(
        title, block.columns, rows, page.options.exact, page.steps or None, total, page.at
    )


def _further_table(block: Table, page: _Page) -> str:
    t = next(i for i, table in enumerate(page.tables) if table is block)
    st, positions = page.st, None
    if st is not None and st.table == t:
        if st.table_rows is not None:
            positions = {r: (p, 1) for r, p in st.table_rows.items()}
        else:
            positions = {r: (r + 1, 1) for r in range(st.n)}
    if page.mapped is not None and t in page.mapped:
        positions = {r: page.steps[s] for r, s in page.mapped[t].items() if s in page.steps}
    # a table stays whole (the symmetry table, a comparison); its box scrolls sideways
    rows = block.rows()
    return _table(block.title, block.columns, rows, page.options.exact, positions, None, page.at)


def _code(block: Pseudocode, page: _Page) -> str:
    """The listing: its title, then the numbered lines in a ``<pre>``, escaped, in a box that
    scrolls sideways on a narrow screen (as a table's does).

    >>> _code(Pseudocode("a<b", ("x", "  y & z")), None)  # type: ignore[arg-type]
    '<h3>a&lt;b</h3><div class="sc-tablebox"><pre class="sc-code"><code>1  x\\n2    y &amp; z</code></pre></div>'
    """
    lines = "\n".join(esc(line) for line in block.numbered())
    code = f'<pre class="sc-code"><code>{lines}</code></pre>'
    return f'<h3>{esc(block.title)}</h3><div class="sc-tablebox">{code}</div>'


def _pixels(block: Pixels, page: _Page) -> str:
    st = page.st
    if st is None:
        return ""
    count = st.total_pixels
    listed = esc(", ".join(fmt_pixel(p) for p in st.pixels[:MAX_PIXEL_LIST]))
    more = esc(f", \u2026 ({count - MAX_PIXEL_LIST:,} more)" if count > MAX_PIXEL_LIST else "")
    text = f'<p class="sc-pixels">{listed}{more}</p>'
    if count > 200:
        text = f'<div class="sc-scroll sc-pixbox">{text}</div>'
    return f"<h3>Pixels plotted ({count:,})</h3>{text}"


def _nothing(block: Any, page: _Page) -> str:
    return ""


def question_html(block: Question, page: _Page | None = None) -> str:
    """A question's heading, its wording and its command line (a sheet's, above its answer's
    section)."""
    h = f"h{block.level}"
    out = f'<{h} class="sc-q">{esc(block.heading)}</{h}>\n'
    if block.wording:
        out += f'<p class="sc-wording">{esc(block.wording)}</p>\n'
    if block.command:
        out += f"<p><code>{esc(block.command)}</code></p>\n"
    return out


def contents_html(block: Contents, page: _Page | None = None) -> str:
    """The contents as a navigation list: each section, its questions numbered under it,
    each linked to its question's section (id ``q<number>``) when :attr:`Contents.linked`."""
    items = ['<nav class="sc-contents" aria-label="contents">', "<h2>Contents</h2>", "<ul>"]
    for section, entries in block.sections():
        items.append(f"<li>{esc(section)}<ol>" if section else "<li><ol>")
        for e in entries:
            text = (
                f'<a href="#q{e.number}">{esc(e.wording)}</a>' if block.linked else esc(e.wording)
            )
            items.append(f'<li value="{e.number}">{text}</li>')
        items.append("</ol></li>")
    return "\n".join([*items, "</ul>", "</nav>"]) + "\n"


HTML: dict[type, Callable[[Any, _Page], str]] = {
    Contents: contents_html,
    Question: question_html,
    Title: _nothing,  # the section's heading (answer_section)
    Given: _given,
    Working: _working,
    Notes: _notes,
    StepTable: _step_table,
    Table: _further_table,
    Pseudocode: _code,
    Pixels: _pixels,
    Drawing: _nothing,  # beside the stepper or under the answer (_figures)
}
"""The ``html`` format's answer column: one handler per block type."""


def _controls(st: stepper.Stepping, at: int) -> str:
    """The stepper's buttons, slider, caption and key help."""
    return (
        '<div class="sc-controls" role="group" aria-label="step through the answer">'
        '<button type="button" data-act="reset" title="Reset (Home)">Reset</button>'
        '<button type="button" data-act="prev" title="Previous (\u2190)">\u25c0 Prev</button>'
        '<button type="button" data-act="play" title="Play / Pause (space)" '
        'aria-pressed="false">\u25b6 Play</button>'
        '<button type="button" data-act="next" title="Next (\u2192)">Next \u25b6</button>'
        '<button type="button" data-act="end" title="End">End</button>'
        f'<input class="sc-slider" type="range" min="0" max="{st.n}" value="{at}" '
        'step="1" aria-label="step">'
        f'<output class="sc-pos">step {at} / {st.n}</output></div>'
        f'<p class="sc-caption" aria-live="polite">{esc(st.captions[at])}</p>'
        '<p class="sc-hover"></p>'
        '<p class="sc-keys">Keys: \u2192 next, \u2190 previous, space play / pause, '
        "Home reset, End last step. Click a table row to go to its step"
        + ("; hover a pixel to see which step plotted it." if st.pixels else ".")
        + "</p>"
    )


def _figures(doc: Document, options: Options) -> str:
    """The answer's own figures, drawn (``""``: none, or no grid wanted)."""
    drawings: list[Drawing] = doc.every(Drawing)
    if not options.grid or not drawings:
        return ""
    return (
        '<div class="sc-figures">'
        + "".join(figure_svg(d.figure, options.origin) for d in drawings)
        + "</div>"
    )


def _stepper_column(doc: Document, st: stepper.Stepping, page: _Page, said: list[str]) -> str:
    """The stepper beside the answer: its grid (or a comparison's figures), its controls,
    and what a large answer leaves out (into ``said``)."""
    out = ['<div class="sc-stepper">']
    if st.pixels:
        svg, numbered = step_grid(doc, st, page.options, page.at)
        out.append(svg)
        out.append(legend(doc, st, numbered))
    else:  # a comparison: its figures beside its table
        out.append(_figures(doc, page.options))
    out.append(_controls(st, page.at))
    out.append(selftest_html(doc.get(StepTable), st, page.options))  # "Test yourself": selftest.py
    if st.total > st.n and doc.get(StepTable) is not None and doc.get(StepTable).columns:
        said.append(f"the stepper goes through the first {st.n:,} of {st.total:,} steps")
    if st.total_pixels > len(st.pixels):
        said.append(f"the grid draws the first {len(st.pixels):,} of {st.total_pixels:,} pixels")
    if said:
        out.append('<p class="sc-more">Large answer: ' + "; ".join(said) + ".</p>")
    out.append("</div>")
    return "".join(out)


def _step_data(st: stepper.Stepping) -> str:
    """The stepper's data for the script."""
    play_ms = int(min(700, max(15, PLAY_SECONDS * 1000 / max(st.n, 1))))
    data = {
        "n": st.n,
        "pos": st.pos,
        "kind": st.kind,
        "captions": st.captions,
        "heads": st.heads,
        "ms": play_ms,
    }
    return json_script(data)


def _page_state(doc: Document, options: Options, at_end: bool) -> _Page:
    """The stepper's data and which table rows are its positions."""
    st = stepping(doc, options)
    at = st.n if (st is not None and at_end) else 0
    table: StepTable | None = doc.get(StepTable)
    tables: list[Table] = doc.every(Table)
    steps: Positions = {}
    mapped = None
    if st is not None and table is not None and table.columns:
        steps = {i: (i + 1, st.row_region[i]) for i in range(st.n)}
        mapped = None if table.shown else _mapped_tables(table, tables, st.n)
    return _Page(options, st, at, steps, mapped, tables)


def answer_section(
    answer: Solution | Document,
    uid: str,
    options: Options | None = None,
    *,
    heading: str = "",
    keys: str = "page",
    at_end: bool = False,
    level: int = 2,
    notices: list[str] | None = None,
) -> str:
    """One answer as a ``<section class="scanconv">`` with the id ``uid``: the worked answer
    beside its stepper, then the extra figures, then the stepper's data.

    ``heading`` is a plain-text line above the title (a question's number); ``keys`` is
    ``"page"`` (the arrow keys step the answer last clicked, or the first) or ``"root"`` (only
    while the answer has the focus: a notebook); ``at_end`` writes it at its last step (every
    pixel lit, as a notebook that runs no script shows it) instead of step 0; ``notices``
    collects what was left out.
    """
    doc = as_document(answer)
    options = options or Options()
    page = _page_state(doc, options, at_end)
    st, at = page.st, page.at
    said: list[str] = []
    h = f"h{level}"
    out = [
        f'<section class="scanconv" id="{esc(uid)}" data-keys="{esc(keys)}" tabindex="-1"'
        + (f' data-stepper data-pos="{at}"' if st else "")
        + ">"
    ]
    if heading:
        out.append(f'<p class="sc-heading">{esc(heading)}</p>')
    out.append(f'<{h} class="sc-title">{esc(doc.title)}</{h}>')
    out.append(f'<div class="sc-layout{"" if st else " sc-single"}"><div class="sc-answer">')
    out.extend(HTML[type(block)](block, page) for block in doc.blocks)
    out.append("</div>")
    if st is not None:
        out.append(_stepper_column(doc, st, page, said))
    out.append("</div>")
    if st is None or st.pixels:  # a comparison's figures are beside its table
        out.append(_figures(doc, options))
    if st is not None:
        out.append(_step_data(st))
    out.append("</section>")
    if notices is not None:
        notices.extend(said)
    return "".join(out)


def page_head(title: str) -> str:
    """The document's head: charset, title, the style sheet."""
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        '<meta name="generator" content="scanconv">\n'
        f"<title>{esc(title)}</title>\n<style>\n{page_assets.CSS}{page_assets.PAGE_CSS}</style>\n"
        f"<noscript><style>\n{page_assets.PLAIN}</style></noscript>\n</head>\n"
    )


def page(body: str, title: str) -> str:
    """A whole page around ``body`` (answer sections): head, body, the stepper's script."""
    return (
        f"{page_head(title)}<body>\n{body}\n<script>{page_assets.JS}</script>\n</body>\n</html>\n"
    )


def html_document(
    answers: Sequence[tuple[str, Solution]],
    title: str,
    options: Options | None = None,
    *,
    notices: list[str] | None = None,
    intro: str = "",
) -> str:
    """A page of several answers, each ``(heading, solution)`` (``heading`` plain text, may be
    empty), each with its own stepper. ``intro`` is plain text under the page's title.

    >>> from scanconv.answers.primitives.line import line_solution
    >>> doc = html_document([("Question 1", line_solution("dda", 0, 0, 2, 1))], "Key <1>")
    >>> doc.count('<section class="scanconv"'), "<title>Key &lt;1&gt;</title>" in doc
    (1, True)
    """
    body = [f'<h1 class="sc-doc-title">{esc(title)}</h1>'] if len(answers) != 1 else []
    if intro:
        body.append(f"<p>{esc(intro)}</p>")
    level = 2 if len(answers) == 1 else 3
    for i, (heading, solution) in enumerate(answers, 1):
        found: list[str] = []
        body.append(
            answer_section(solution, f"sc{i}", options, heading=heading, level=level, notices=found)
        )
        if notices is not None:
            notices.extend(f"{heading or solution.title}: {n}" for n in found)
    return page("\n".join(body), title)


def render_html(answer: Solution | Document, options: Options) -> Iterator[str | Notice]:
    """The ``html`` format: the whole page, then a notice for what it left out."""
    doc = as_document(answer)
    said: list[str] = []
    text = page(answer_section(doc, "sc1", options, notices=said), doc.title or "scanconv")
    yield text
    for n in said:
        yield Notice(f"the page shows part of a large answer: {n}")


_counter = iter(range(1, 1 << 62))


def notebook_html(solution: Solution | Document, options: Options | None = None) -> str:
    """One answer for a Jupyter cell: its style (scoped to ``.scanconv``), the section with a
    unique id, written at its last step (so an untrusted notebook, which runs no script, shows
    the whole answer), and the script, which starts only sections not started yet and binds
    the keys to the section itself (click it, then use the arrows)."""
    import secrets

    uid = f"scanconv-{next(_counter)}-{secrets.token_hex(4)}"
    section = answer_section(solution, uid, options, keys="root", at_end=True)
    return f'<div class="scanconv-cell"><style>{page_assets.CSS}</style>{section}<script>{page_assets.JS}</script></div>'

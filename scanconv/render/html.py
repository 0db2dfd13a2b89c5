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
and the script are inline (:mod:`scanconv.render.page_assets`). Every text from the answer is
escaped; the step data sits in a ``<script type="application/json">`` with ``<``, ``>`` and
``&`` written as ``\\u003c`` escapes, so no text can close the script.

**Large answers.** The page steps through at most
:data:`~scanconv.render.stepper.MAX_STEPS` steps, draws at most
:data:`~scanconv.render.stepper.MAX_PIXELS` pixels, writes at most
:data:`~scanconv.render.stepper.MAX_TABLE_ROWS` rows of a table (fewer for wide tables) and
says on the page what it left out.

**Modules.** This one writes the page; :mod:`scanconv.render.stepper` works out the positions
and captions, :mod:`scanconv.render.stepgrid` draws the SVG, :mod:`scanconv.render.mathml`
turns TeX into MathML and escapes text, :mod:`scanconv.render.page_assets` holds the style
sheet and the script.

**For other documents** (the answer key of ``scanconv sheet``, a notebook):

* :func:`html_document` ``(answers, title)`` is a whole page of several answers, each a
  ``(heading, solution)`` pair, each with its own stepper;
* :func:`answer_section` is one answer's ``<section>`` (it needs the page's
  :func:`page_head` style and :data:`~scanconv.render.page_assets.JS` script, which
  :func:`page` adds around any body);
* :func:`notebook_html` is one answer as a self-contained fragment for Jupyter, with a unique
  id and its keyboard bound to the answer itself, so two answers never interfere.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from itertools import islice
from typing import Any

from ..core.numeric import fmt_pixel
from ..core.records import Column, Solution, step_getter
from . import Notice, Options, stepper
from .cells import cell, numeric_column
from .mathml import esc, json_script, note_html, prose_html, tex_math
from .selftest import selftest_html
from .stepgrid import figure_svg, legend, step_grid
from .stepper import column_label, stepping

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


def _table(
    title: str | None,
    columns: Sequence[Column],
    rows: Iterable[Sequence[Any]],
    exact: bool,
    positions: dict[int, tuple[int, int]] | None = None,
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
    right = [numeric_column(c) for c in shown_cols]
    heads = "".join(f"<th>{tex_math(c.tex)}</th>" for c in shown_cols)
    caption = f"<caption>{esc(title)}</caption>" if title else ""
    lines: list[str] = []
    widths = [len(column_label(c.tex, None)) for c in shown_cols]
    for i, row in enumerate(head):
        attrs = ""
        if positions is not None and i in positions:
            p, region = positions[i]
            classes = ("sc-r2 " if region > 1 else "") + ("sc-cur" if p == at else "")
            attrs = f' data-pos="{p}"' + (f' class="{classes.strip()}"' if classes.strip() else "")
        texts = [cell(v, c, exact) for v, c in zip(row, shown_cols, strict=False)]
        for j, t in enumerate(texts):
            widths[j] = max(widths[j], len(t))
        tds = "".join(
            f'<td class="sc-num">{prose_html(t)}</td>' if r else f"<td>{prose_html(t)}</td>"
            for t, r in zip(texts, right, strict=False)
        )
        lines.append(f"<tr{attrs}>{tds}</tr>")
    if len(lines) <= CHUNK_ROWS:
        body = f'<div class="sc-tablebox"><table class="sc-table">{caption}<thead><tr>{heads}'
        body += "</tr></thead><tbody>" + "".join(lines) + "</tbody></table></div>"
    else:
        # A long table: its header, then chunks of rows, each a table of the same fixed column
        # widths that the browser lays out only when in view (content-visibility).
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
        body = "".join(parts)
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


def _step_rows(solution: Solution) -> Iterator[tuple[Any, ...]]:
    get = step_getter(solution.columns, solution.extra_keys)
    for step in solution.steps():
        yield get(step)


def _mapped_tables(solution: Solution, count: int) -> dict[int, dict[int, int]] | None:
    """When the step table is not shown (the ellipse's regions), which row of which secondary
    table is which step: ``{table index: {row index: step index}}``; ``None`` if the tables do
    not hold every step, in order."""
    if count == 0:
        return None
    keys = [c.key for c in solution.columns]
    get = step_getter(solution.columns, solution.extra_keys)
    steps = islice(solution.steps(), count)
    want = next(steps, None)
    s = 0
    found: dict[int, dict[int, int]] = {}
    for t, table in enumerate(solution.tables):
        shared = [(j, keys.index(c.key)) for j, c in enumerate(table.columns) if c.key in keys]
        if not any(keys[i] == "pixel" for _, i in shared):
            continue
        for r, row in enumerate(islice(table.rows(), stepper.MAX_TABLE_ROWS)):
            if want is None:
                break
            cells = get(want)
            if all(row[j] == cells[i] for j, i in shared):
                found.setdefault(t, {})[r] = s
                s += 1
                want = next(steps, None)
    return found if want is None and s == count else None


def answer_section(
    solution: Solution,
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
    options = options or Options()
    exact = options.exact
    st = stepping(solution, options)
    at = st.n if (st is not None and at_end) else 0
    said: list[str] = []
    h = f"h{level}"
    out = [
        f'<section class="scanconv" id="{esc(uid)}" data-keys="{esc(keys)}" tabindex="-1"'
        + (f' data-stepper data-pos="{at}"' if st else "")
        + ">"
    ]
    if heading:
        out.append(f'<p class="sc-heading">{esc(heading)}</p>')
    out.append(f'<{h} class="sc-title">{esc(solution.title)}</{h}>')
    out.append(f'<div class="sc-layout{"" if st else " sc-single"}"><div class="sc-answer">')
    if solution.given:
        out.append(
            '<p class="sc-given"><strong>Given:</strong> '
            + ", ".join(tex_math(q.tex) for q in solution.given)
            + "</p>"
        )
    if solution.derived:
        out.append('<h3>Working</h3><ul class="sc-working">')
        out.extend(f"<li>{tex_math(q.tex, display=True)}</li>" for q in solution.derived)
        out.append("</ul>")
    if solution.notes:
        out.append('<h3>Notes</h3><ul class="sc-notes">')
        out.extend(f"<li>{note_html(n)}</li>" for n in solution.notes)
        out.append("</ul>")
    n_steps = st.n if st and solution.columns else 0
    mapped = None if solution.show_steps else _mapped_tables(solution, n_steps)
    step_positions: dict[int, tuple[int, int]] = {}
    if st and solution.columns:
        step_positions = {i: (i + 1, st.row_region[i]) for i in range(st.n)}
    if solution.columns and (solution.show_steps or mapped is None):
        title = "Step table" if solution.show_steps else "Step table (the tables below split it up)"
        out.append(
            _table(
                title,
                solution.columns,
                _step_rows(solution),
                exact,
                step_positions or None,
                st.total if st else None,
                at,
            )
        )
    for t, table in enumerate(solution.tables):
        positions = None
        if st is not None and st.table == t:
            if st.table_rows is not None:
                positions = {r: (p, 1) for r, p in st.table_rows.items()}
            else:
                positions = {r: (r + 1, 1) for r in range(st.n)}
        if mapped is not None and t in mapped:
            positions = {r: step_positions[s] for r, s in mapped[t].items() if s in step_positions}
        # a table stays whole (the symmetry table, a comparison); its box scrolls sideways
        out.append(_table(table.title, table.columns, table.rows(), exact, positions, None, at))
    if solution.pixels is not None and st is not None:
        count = st.total_pixels
        listed = ", ".join(fmt_pixel(p) for p in st.pixels[:MAX_PIXEL_LIST])
        more = f", \u2026 ({count - MAX_PIXEL_LIST:,} more)" if count > MAX_PIXEL_LIST else ""
        out.append(
            f"<h3>Pixels plotted ({count:,})</h3>"
            + (
                f'<div class="sc-scroll sc-pixbox"><p class="sc-pixels">{esc(listed)}{esc(more)}'
                "</p></div>"
                if count > 200
                else f'<p class="sc-pixels">{esc(listed)}{esc(more)}</p>'
            )
        )
    out.append("</div>")
    if st is not None:
        out.append('<div class="sc-stepper">')
        if st.pixels:
            svg, numbered = step_grid(solution, st, options, at)
            out.append(svg)
            out.append(legend(solution, st, numbered))
        elif options.grid and solution.figures:  # a comparison: its figures beside its table
            out.append('<div class="sc-figures">')
            out.extend(figure_svg(fig, options.origin) for fig in solution.figures)
            out.append("</div>")
        out.append(
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
        )
        out.append(f'<p class="sc-caption" aria-live="polite">{esc(st.captions[at])}</p>')
        out.append('<p class="sc-hover"></p>')
        out.append(
            '<p class="sc-keys">Keys: \u2192 next, \u2190 previous, space play / pause, '
            "Home reset, End last step. Click a table row to go to its step"
            + ("; hover a pixel to see which step plotted it." if st.pixels else ".")
            + "</p>"
        )
        out.append(selftest_html(solution, st, options))  # "Test yourself" (issue 31): selftest.py
        if st.total > st.n and solution.columns:
            said.append(f"the stepper goes through the first {st.n:,} of {st.total:,} steps")
        if st.total_pixels > len(st.pixels):
            said.append(
                f"the grid draws the first {len(st.pixels):,} of {st.total_pixels:,} pixels"
            )
        if said:
            out.append('<p class="sc-more">Large answer: ' + "; ".join(said) + ".</p>")
        out.append("</div>")
    out.append("</div>")
    if options.grid and solution.figures and not (st is not None and not st.pixels):
        out.append('<div class="sc-figures">')
        out.extend(figure_svg(fig, options.origin) for fig in solution.figures)
        out.append("</div>")
    if st is not None:
        play_ms = int(min(700, max(15, PLAY_SECONDS * 1000 / max(st.n, 1))))
        data = {
            "n": st.n,
            "pos": st.pos,
            "kind": st.kind,
            "captions": st.captions,
            "heads": st.heads,
            "ms": play_ms,
        }
        out.append(json_script(data))
    out.append("</section>")
    if notices is not None:
        notices.extend(said)
    return "".join(out)


def page_head(title: str) -> str:
    """The document's head: charset, title, the style sheet."""
    from .page_assets import CSS, PAGE_CSS, PLAIN

    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        '<meta name="generator" content="scanconv">\n'
        f"<title>{esc(title)}</title>\n<style>\n{CSS}{PAGE_CSS}</style>\n"
        f"<noscript><style>\n{PLAIN}</style></noscript>\n</head>\n"
    )


def page(body: str, title: str) -> str:
    """A whole page around ``body`` (answer sections): head, body, the stepper's script."""
    from .page_assets import JS

    return f"{page_head(title)}<body>\n{body}\n<script>{JS}</script>\n</body>\n</html>\n"


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

    >>> from scanconv.answers.line import line_solution
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


def render_html(solution: Solution, options: Options) -> Iterator[str | Notice]:
    """The ``html`` format: the whole page, then a notice for what it left out."""
    said: list[str] = []
    text = page(
        answer_section(solution, "sc1", options, notices=said), solution.title or "scanconv"
    )
    yield text
    for n in said:
        yield Notice(f"the page shows part of a large answer: {n}")


_counter = iter(range(1, 1 << 62))


def notebook_html(solution: Solution, options: Options | None = None) -> str:
    """One answer for a Jupyter cell: its style (scoped to ``.scanconv``), the section with a
    unique id, written at its last step (so an untrusted notebook, which runs no script, shows
    the whole answer), and the script, which starts only sections not started yet and binds
    the keys to the section itself (click it, then use the arrows)."""
    import secrets

    from .page_assets import CSS, JS

    uid = f"scanconv-{next(_counter)}-{secrets.token_hex(4)}"
    section = answer_section(solution, uid, options, keys="root", at_end=True)
    return f'<div class="scanconv-cell"><style>{CSS}</style>{section}<script>{JS}</script></div>'

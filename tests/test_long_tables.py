"""Long step tables, every row in every format, against a Bresenham written here.

A LaTeX table over :data:`~scanconv.render.mappings.latex.KEEP_ROWS` rows is a ``longtable``; dropping
every row after its 16th passed the whole suite (mutation R10), as did a streamed (over
:data:`~scanconv.render.mappings.text.BUFFER_ROWS` rows) Markdown table written without escaping its
cells (R1: numeric cells have nothing to escape). Here ``line 0 0 50 10`` (51 rows) and
``line 0 0 1500 7`` (1,501 rows, streamed) are read back from each answer format (plain, rich
at a width, markdown, latex, html, csv, json) and each sheet format, and compared row by row
with :func:`bresenham`; the streamed Markdown writer gets hostile text cells.
"""

from __future__ import annotations

import csv
import html
import io
import json
import re
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pytest

from scanconv.render import formats
from scanconv.render.html import stepper
from scanconv.render.mappings import text as text_render
from tests.helpers import run

Row = tuple[str, str, str, str, str, str]
"""``(k, p_k, decision, x_k, y_k, p_{k+1})`` as the tables write them (``-``: none)."""


def bresenham(x0: int, y0: int, x1: int, y1: int) -> list[Row]:
    """The notes' Bresenham step table for a line with ``0 <= dy <= dx`` (tie steps y): row k
    plots (x_k, y_k) and decides on p_k; the last row is the end point, with no decision."""
    dx, dy = x1 - x0, y1 - y0
    assert 0 <= dy <= dx
    p, x, y = 2 * dy - dx, x0, y0
    rows: list[Row] = []
    for k in range(dx + 1):
        if k == dx:
            rows.append((str(k), str(p), "-", str(x), str(y), "-"))
            break
        if p < 0:
            decision, after, ny = "E", p + 2 * dy, y
        else:
            decision, after, ny = "NE", p + 2 * dy - 2 * dx, y + 1
        rows.append((str(k), str(p), decision, str(x), str(y), str(after)))
        p, x, y = after, x + 1, ny
    return rows


def test_bresenham_by_hand() -> None:
    """The reference against the table worked by hand for (0, 0) to (5, 2)."""
    assert bresenham(0, 0, 5, 2) == [
        ("0", "-1", "E", "0", "0", "3"),
        ("1", "3", "NE", "1", "0", "-3"),
        ("2", "-3", "E", "2", "1", "1"),
        ("3", "1", "NE", "3", "1", "-5"),
        ("4", "-5", "E", "4", "2", "-1"),
        ("5", "-1", "-", "5", "2", "-"),
    ]


def _dash(cell: Any) -> str:
    text = "" if cell is None else str(cell).strip().replace("\u2212", "-")
    return "-" if text in ("", "-", "--") else text


def _row(k: Any, p: Any, decision: Any, pixel: str, after: Any) -> Row:
    m = re.fullmatch(r"\((-?\d+), (-?\d+)\)", pixel.strip())
    assert m, pixel
    return (_dash(k), _dash(p), _dash(decision), m[1], m[2], _dash(after))


_TEXT_ROW = re.compile(r"^\s*(\d+)\s+(-?\d+)\s+(NE|E|-)\s+(\(-?\d+, -?\d+\))\s+(-?\d+|-)\s*$")


def rows_text(out: str) -> list[Row]:
    """A plain, rich or quiz-feedback table: one row a line, cells parted by spaces."""
    return [_row(*m.groups()) for line in out.splitlines() if (m := _TEXT_ROW.match(line))]


def rows_markdown(out: str) -> list[Row]:
    rows = []
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) == 5 and cells[0].isdigit():
            rows.append(_row(*cells))
    return rows


def rows_latex(out: str) -> list[Row]:
    rows = []
    for line in out.splitlines():
        if line.endswith(" \\\\") and line.count(" & ") == 4:
            cells = [c.strip().strip("$") for c in line[:-3].split(" & ")]
            if cells[0].isdigit():
                rows.append(_row(*cells))
    return rows


class _Cells(HTMLParser):
    """The text of each ``<td>`` of each ``<tr>``."""

    def __init__(self) -> None:
        super().__init__()
        self.rows: list[list[str]] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag: str, attrs: Any) -> None:
        if tag == "tr":
            self.rows.append([])
        elif tag == "td":
            self._cell = []

    def handle_endtag(self, tag: str) -> None:
        if tag == "td" and self._cell is not None:
            self.rows[-1].append("".join(self._cell))
            self._cell = None

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)


def rows_html(out: str) -> list[Row]:
    parser = _Cells()
    parser.feed(out)
    return [_row(*r) for r in parser.rows if len(r) == 5 and r[0].strip().isdigit()]


def rows_csv(out: str) -> list[Row]:
    return [
        _row(r["k"], r["p"], r["decision"], f"({r['x']}, {r['y']})", r["p_next"])
        for r in csv.DictReader(io.StringIO(out))
    ]


def _steps(data: Any) -> list[Any]:
    if isinstance(data, dict):
        if "steps" in data:
            return list(data["steps"])
        return [s for v in data.values() for s in _steps(v)]
    if isinstance(data, list):
        return [s for v in data for s in _steps(v)]
    return []


def rows_json(out: str) -> list[Row]:
    return [
        _row(s["k"], s["p"], s["decision"], f"({s['pixel'][0]}, {s['pixel'][1]})", s["p_next"])
        for s in _steps(json.loads(out))
    ]


def rows_moodle(out: str) -> list[Row]:
    return rows_text(html.unescape(out))


ANSWER_FORMATS = {
    "plain": rows_text,
    "rich": rows_text,
    "markdown": rows_markdown,
    "latex": rows_latex,
    "html": rows_html,
    "csv": rows_csv,
    "json": rows_json,
}
SHEET_FORMATS = {
    "plain": rows_text,
    "markdown": rows_markdown,
    "latex": rows_latex,
    "html": rows_html,
    "json": rows_json,
    "moodle": rows_moodle,
}
"""A GIFT quiz asks one row a question (its feedback is that row), so it holds no table."""


def test_every_format_has_a_reader_here() -> None:
    """A new format of the format table fails here until its table has a reader above."""
    assert set(ANSWER_FORMATS) == set(formats("answer"))
    assert set(SHEET_FORMATS) | {"gift"} == set(formats("document"))


LINES = {"51-rows": (0, 0, 50, 10), "1501-rows": (0, 0, 1500, 7)}


@pytest.mark.slow
@pytest.mark.parametrize("fmt", ANSWER_FORMATS)
@pytest.mark.parametrize("size", LINES)
def test_every_row_in_every_format(size: str, fmt: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Each answer format holds the whole step table, each row as the reference has it."""
    monkeypatch.setenv("COLUMNS", "72")  # rich at a width
    line = LINES[size]
    result = run("line", *map(str, line), "-f", fmt)
    assert result.code == 0, result.err
    check_rows(fmt, result.out, bresenham(*line))


def check_rows(fmt: str, out: str, want: list[Row]) -> None:
    """The rows of ``out`` are ``want``; an HTML page shows the first
    :data:`~scanconv.render.html.stepper.MAX_TABLE_ROWS` of a longer table, says so, and lists
    every pixel."""
    rows = ANSWER_FORMATS[fmt](out) if fmt in ANSWER_FORMATS else SHEET_FORMATS[fmt](out)
    if fmt == "html" and len(want) > stepper.MAX_TABLE_ROWS:
        assert rows == want[: stepper.MAX_TABLE_ROWS]
        shown = f"first {stepper.MAX_TABLE_ROWS:,} of {len(want):,} rows"
        assert shown in out
        pixels = re.search(r'<p class="sc-pixels">([^<]*)</p>', out)
        assert pixels is not None
        assert pixels[1] == ", ".join(f"({r[3]}, {r[4]})" for r in want)
    else:
        assert rows == want


@pytest.mark.slow
@pytest.mark.parametrize("fmt", SHEET_FORMATS)
@pytest.mark.parametrize("size", LINES)
def test_every_row_in_every_sheet_format(size: str, fmt: str, tmp_path: Path) -> None:
    """A sheet's key holds the whole table too (a Moodle quiz in its feedback)."""
    line = LINES[size]
    if fmt == "moodle" and size != "51-rows":
        pytest.skip("a quiz repeats its table in each part's feedback: the short table is enough")
    questions = tmp_path / "q.txt"
    questions.write_text("line " + " ".join(map(str, line)) + "\n", encoding="utf-8")
    result = run("sheet", str(questions), "-f", fmt)
    assert result.code == 0, result.err
    check_rows(fmt, result.out, bresenham(*line))


# --- the streamed Markdown writer's escaping (R1) ---------------------------------------------

HOSTILE = [
    "a|b",
    "<img src=x onerror=alert(1)>",
    "*em* and `code`",
    "[link](http://example.com)",
    "# not a heading",
    "$5 & ~6~ @me",
    "{braces} \\ back",
]
_SPECIAL = "|<>*`[]#$&~@{}\\"


def _unescape(cell: str) -> str:
    return re.sub(r"\\(.)", r"\1", cell)


def _split(line: str) -> list[str]:
    """A Markdown row's cells, parted at each ``|`` no backslash escapes."""
    assert line.startswith("| ") and line.endswith(" |"), line
    return [c.strip() for c in re.split(r"(?<!\\)\|", line[2:-2])]


@pytest.mark.parametrize("count", [5, text_render.BUFFER_ROWS + 5], ids=["buffered", "streamed"])
def test_markdown_cells_escaped_buffered_and_streamed(count: int) -> None:
    """Every text cell of a Markdown table, short (tabulated) or long (streamed), is escaped:
    no ``|`` splits a row, no markup character is left bare, and unescaped it is the text."""
    rows = [[str(k), HOSTILE[k % len(HOSTILE)]] for k in range(count)]
    lines = list(text_render.table_lines(["k", "note"], [True, False], rows, markdown=True))
    body = lines[2:]
    assert len(body) == count
    for (k, note), line in zip(rows, body, strict=True):
        cells = _split(line)
        assert len(cells) == 2, line
        assert cells[0] == k
        bare = re.sub(r"\\.", "", cells[1])
        assert not any(c in bare for c in _SPECIAL), line
        assert _unescape(cells[1]).replace("http\\://", "http://") == note

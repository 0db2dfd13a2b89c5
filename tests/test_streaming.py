"""Long answers stream: rows are rendered and written as the generator produces them.

Each test counts how many step records have been pulled from the algorithm when the first
rows come out; a renderer or writer that built a list first would have pulled them all.
(Peak memory of the real CLI is measured in ``benchmarks/bench.py``.)
"""

from __future__ import annotations

import io
from collections.abc import Iterator
from itertools import islice

import pytest

from scanconv.answers.primitives.line import line_solution
from scanconv.cli import output as cli
from scanconv.core.records import Solution, Step
from scanconv.render import Format, Options, render
from scanconv.render.mappings.text import BUFFER_ROWS

LENGTH = 1_000_000


def counted(solution: Solution) -> tuple[Solution, list[int]]:
    """The same solution, counting the step records its generators hand out."""
    pulled = [0]
    steps, pixels = solution.steps, solution.pixels

    def counting_steps() -> Iterator[Step]:
        for s in steps():
            pulled[0] += 1
            yield s

    def counting_pixels() -> Iterator[tuple[int, int]]:
        assert pixels is not None
        for p in pixels():
            pulled[0] += 1
            yield p

    walk = solution.walk._replace(steps=counting_steps)
    plot = solution.plot._replace(pixels=counting_pixels)
    return Solution(**{**solution.fields(), "walk": walk, "plot": plot}), pulled


@pytest.mark.parametrize("fmt", [Format.csv, Format.json])
def test_data_formats_stream_row_by_row(fmt):
    sol, pulled = counted(line_solution("bresenham", 0, 0, LENGTH, 1))
    chunks = render(sol, fmt, Options(grid=False))
    first = list(islice(chunks, 50))
    assert any("," in c for c in first[2:])  # step rows, not just the header
    assert pulled[0] <= 50


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("fmt", [Format.plain, Format.markdown])
def test_text_formats_buffer_only_the_padded_head(fmt):
    sol, pulled = counted(line_solution("bresenham", 0, 0, LENGTH, 1))
    chunks = render(sol, fmt, Options(grid=False))
    text = ""
    for chunk in chunks:
        text += chunk if isinstance(chunk, str) else ""
        if text.count("\n") > 60 + BUFFER_ROWS:
            break
    assert pulled[0] <= BUFFER_ROWS + 100


class ClosedAfter(io.StringIO):
    """A stdout that fails after a number of writes, like a pipe whose reader has gone."""

    def __init__(self, writes: int) -> None:
        super().__init__()
        self.left = writes

    def write(self, s: str) -> int:
        self.left -= 1
        if self.left < 0:
            raise BrokenPipeError
        return super().write(s)


@pytest.mark.parametrize("fmt", [Format.csv, Format.json])
def test_the_cli_writes_each_chunk_as_it_comes(fmt):
    sol, pulled = counted(line_solution("bresenham", 0, 0, LENGTH, 1))
    with pytest.raises(BrokenPipeError):
        cli._write(render(sol, fmt, Options(grid=False)), ClosedAfter(100))
    assert pulled[0] <= 100


@pytest.mark.slow  # a 1024 x 1024 matrix under tracemalloc
@pytest.mark.parametrize("fmt", [Format.csv, Format.json])
def test_a_wide_matrix_streams_a_few_rows_at_a_time(fmt):
    """``sample`` at 4096 x 4096 held 4,096 rows of 4,097 cells at once (415 MB); a batch is
    now a number of cells, so the peak is the matrix itself and a few rows' text."""
    import tracemalloc

    from scanconv.algorithms.sample import sample_levels
    from scanconv.answers.image.sample import sample_solution

    sol = sample_solution(sample_levels("x + y", 1024, 1024, 256))
    tracemalloc.start()
    try:
        size = sum(len(c) for c in render(sol, fmt, Options(grid=False)) if isinstance(c, str))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert size > 1024 * 1024 * 2  # every cell written
    assert peak < 3_000_000, peak  # the text alone is over 4 MB


@pytest.mark.parametrize("count", [BUFFER_ROWS, BUFFER_ROWS + 1])
def test_a_long_markdown_table_escapes_its_text_cells(count):
    # the padded table (at most BUFFER_ROWS rows) and the streamed one (one more) escape the
    # same: "E|NE *" is "E\|NE \*" in a Markdown cell, and "<b>" is "\<b\>"
    from scanconv.render.mappings.text import table_lines

    rows = [[str(k), "E|NE *", "<b>"] for k in range(count)]
    lines = list(table_lines(["k", "move", "tag"], [True, False, False], rows, markdown=True))
    assert len(lines) == 2 + count
    for k, line in enumerate(lines[2:]):
        cells = [c.strip() for c in line.strip("| ").split(" | ")]
        assert cells == [str(k), "E\\|NE \\*", "\\<b\\>"], line


def test_a_streamed_markdown_table_line_by_line():
    # over BUFFER_ROWS rows the table is streamed: cells unpadded between "| " and " |", the
    # rule sized by the widest cell of the buffered rows (k: "1000", 4; d: 1, at least 3):
    # "-----:" right-aligned, ":---:" centred
    from scanconv.render.mappings.text import table_lines

    rows = [[str(k), "E"] for k in range(BUFFER_ROWS + 1)]
    lines = list(table_lines(["k", "d"], [True, False], rows, markdown=True))
    assert lines[:3] == ["| k | d |", "|-----:|:---:|", "| 0 | E |"]
    assert lines[-1] == f"| {BUFFER_ROWS} | E |"


def test_a_markdown_heading_keeps_its_math_and_escapes_its_bar():
    # a heading is math scanconv wrote: kept as it is but for "|", which would end the cell
    from scanconv.render.mappings.text import _md_heading

    assert _md_heading("$|p_k|$") == "$\\|p_k\\|$"
    assert _md_heading("$x_k$") == "$x_k$"


def test_a_code_span_shows_control_characters_as_replacement():
    from scanconv.render.mappings.text import md_code

    assert md_code("a\x07b") == "`a\ufffdb`"
    assert md_code("``x") == "``` ``x ```"

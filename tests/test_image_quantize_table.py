"""The fast quantization table (2^24 rows at the limit) prints exactly what the exact per-row
formulas give.

The reference rows are computed here from the definitions, one row at a time with exact
fractions: level ``k`` of ``L = 2^B``, its code ``k`` in ``B`` binary digits, its name (the
notes' 3-bit names, their ends for 1 and 2 bits, ``Gray k/(L-1)`` beyond), and over a range
``[LO, HI]`` of width ``W`` its first and last integer input ``LO + ⌈kW/L⌉``,
``LO + ⌈(k+1)W/L⌉ - 1`` (real inputs: the cell ``LO + kW/L``, ``LO + (k+1)W/L``) and its
reconstruction value ``LO + (k + 1/2)W/L`` (or ``LO + kW/L``). The csv and json text of those
rows is written by the standard library's own ``csv.writer`` and ``json.dumps``, one row at a
time, as the renderers did before the fast path.
"""

from __future__ import annotations

import csv
import io
import json
import math
from fractions import Fraction
from itertools import islice

import pytest

from scanconv.algorithms.quantize import Quantizer
from scanconv.answers.image.quantize import quantization_rows
from scanconv.core.records import Move
from scanconv.render.mappings.data import _plain_csv, batch_rows

from .helpers import run

#: The notes' names of the 3-bit levels; 1 and 2 bits keep its ends and its dark/light gray.
NOTES_NAMES = {
    1: ("Black", "White"),
    2: ("Black", "Dark Gray", "Light Gray", "White"),
    3: (
        "Black",
        "Very Dark Gray",
        "Dark Gray",
        "Gray",
        "Light Gray",
        "Very Light Gray",
        "Almost White",
        "White",
    ),
}


def reference_row(bits: int, k: int) -> tuple:
    L = 2**bits
    code = "".join("1" if k >> (bits - 1 - i) & 1 else "0" for i in range(bits))
    if bits in NOTES_NAMES:
        name = NOTES_NAMES[bits][k]
    else:
        name = "Black" if k == 0 else "White" if k == L - 1 else f"Gray {k}/{L - 1}"
    return (k, code, name)


def exact(v: Fraction) -> int | Fraction:
    return v.numerator if v.denominator == 1 else v


def reference_cells(bits: int, lo, hi, integer: bool, recon: str, k: int) -> tuple:
    L = 2**bits
    lo, hi = Fraction(lo), Fraction(hi)
    W = hi - lo + (1 if integer else 0)
    if integer:
        cell = (exact(lo + math.ceil(k * W / L)), exact(lo + math.ceil((k + 1) * W / L) - 1))
    else:
        cell = (exact(lo + k * W / L), exact(lo + (k + 1) * W / L))
    offset = Fraction(1, 2) if recon == "midpoint" else 0
    return (*cell, exact(lo + (k + offset) * W / L))


def typed(rows) -> list[tuple]:
    """Rows with each cell's type: 2 and Fraction(2) print differently."""
    return [tuple((type(v), v) for v in row) for row in rows]


def reference_csv(bits: int) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["decimal", "binary", "gray_level"])
    for k in range(2**bits):
        writer.writerow(reference_row(bits, k))
    return buf.getvalue()


@pytest.mark.parametrize("bits", range(1, 13))
def test_csv_is_the_exact_table(bits):
    r = run("quantize", "--bits", str(bits), "-f", "csv")
    assert r.code == 0, r.err
    assert r.out == reference_csv(bits)


@pytest.mark.parametrize("bits", range(1, 13))
def test_json_rows_are_the_exact_table(bits):
    r = run("quantize", "--bits", str(bits), "-f", "json")
    assert r.code == 0, r.err
    rows = [reference_row(bits, k) for k in range(2**bits)]
    assert json.loads(r.out)["tables"][0]["rows"] == [list(row) for row in rows]
    text = ", ".join(json.dumps(row, ensure_ascii=False) for row in rows)
    assert f'"rows": [{text}]' in r.out  # the same bytes as one json.dumps per row


#: Ranges over which each level's inputs and reconstruction value are added.
RANGES = [
    (0, 255, True, "midpoint"),
    (0, 255, True, "lower"),
    (-7, 1000, True, "midpoint"),
    (3, 4098, True, "lower"),
    (0, 1, False, "midpoint"),
    (Fraction(-1, 3), Fraction(7, 5), False, "lower"),
    (Fraction(1, 10), 1000, False, "midpoint"),
]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("bits", [1, 2, 3, 5, 8, 10])
@pytest.mark.parametrize(("lo", "hi", "integer", "recon"), RANGES)
def test_rows_over_a_range_are_the_exact_formulas(bits, lo, hi, integer, recon):
    if integer and hi - lo + 1 < 2**bits:
        pytest.skip("fewer integer inputs than levels")
    q = Quantizer.make(lo, hi, 2**bits, integer=integer, recon=recon)
    expected = [
        reference_row(bits, k) + reference_cells(bits, lo, hi, integer, recon, k)
        for k in range(2**bits)
    ]
    assert typed(quantization_rows(bits, q)) == typed(expected)
    # and the quantizer's own per-level methods agree
    assert typed(q.cells()) == typed((*q.interval(k), q.reconstruction(k)) for k in range(q.levels))


# 13 and 14: one and two prefix digits before the 2^12 suffixes, and 8 and 16 whole thousands
# of gray names; 15 (was 17: 4 times the rows, no case the others miss) three digits.
# The 24-bit table is spot-checked below.
@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("bits", [13, 14, 15])
def test_rows_past_one_block_are_the_exact_table(bits):
    """Beyond 12 bits the codes are a prefix before 2^12 suffixes: every row checked."""
    assert list(quantization_rows(bits)) == [reference_row(bits, k) for k in range(2**bits)]


@pytest.mark.slow  # 2^24 rows are made (about 3 s)
def test_24_bit_rows_spot_checked():
    """Rows of the 2^24-row table at the ends, at thousands and 2^12 block boundaries."""
    bits, L = 24, 2**24
    ks = sorted(
        {0, 1, 2, 998, 999, 1000, 1001, 4095, 4096, 4097, 1_234_567, 8_388_607, 8_388_608}
        | {L - 1001, L - 1000, L - 999, L - 2, L - 1}
        | {1000 * h + j for h in (1, 4096, 16_776) for j in (-1, 0, 1)}
        | {4096 * h + j for h in (1, 2048, 4095) for j in (-1, 0, 1)}
    )
    rows = iter(quantization_rows(bits))
    seen, at = [], 0
    for k in ks:
        seen.append(next(islice(rows, k - at, None)))
        at = k + 1
    assert seen == [reference_row(bits, k) for k in ks]
    assert next(rows, None) is None  # exactly L rows


def _csv_writer_text(rows) -> str:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows)
    return buf.getvalue()


#: Batches the csv fast path must either write exactly as csv.writer does, or leave to it.
BATCHES = [
    [(1, "a b"), (2, "c")],
    [(0, "000", "Black"), (1, "001", "Gray 1/15")],
    [(1, "a,b")],
    [(1, 'say "hi"'), (2, "x")],
    [(1, "two\nlines")],
    [(1, "cr\rhere")],
    [("",)],
    [("", "")],
    [(1, "")],
    [(1,), (2,)],
    [(1, 2), (3,)],
    [(True, "x")],
    [(None, "x")],
    [(Fraction(1, 2), "x")],
    [(Move.NE, "x")],
    [(1.5, "x")],
    [(10**40, "ünïcode ✓")],
    [(-3, " lead and trail ")],
    [(1, "=SUM(A1)"), (2, "+1")],
]


@pytest.mark.parametrize("batch", BATCHES, ids=repr)
def test_csv_fast_path_writes_what_csv_writer_writes(batch):
    text = _plain_csv(batch)
    plain = all(type(v) in (int, str) for row in batch for v in row)
    if text is not None:
        assert plain
        assert text == _csv_writer_text(batch)


def test_csv_fast_path_is_taken_for_plain_cells():
    """The rows at the limit (int and plain text) do take it: otherwise nothing was sped up."""
    assert _plain_csv([(0, "000", "Black"), (1, "001", "Gray 1/7")]) == (
        "0,000,Black\n1,001,Gray 1/7\n"
    )


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_batches_larger_than_one_batch_keep_every_row():
    bits = 13  # 8192 rows: two whole batches of the renderer and more
    batch = batch_rows(5)  # a quantizer's table: k, code, and three more columns
    assert 2**bits > 2 * batch
    r = run("quantize", "--bits", str(bits), "--range", "0", "10000", "-f", "csv")
    assert r.code == 0, r.err
    rows = list(csv.reader(io.StringIO(r.out)))
    assert len(rows) == 2**bits + 1
    for k in (0, batch - 1, batch, 2**bits - 1):
        expected = reference_row(bits, k) + reference_cells(bits, 0, 10000, True, "midpoint", k)
        assert rows[k + 1][:5] == [str(v) for v in expected[:5]]

"""Marking models for step tables that are not a pixel walk: what each row of a student's
table should hold, judged from the student's own earlier rows (follow-through).

A pixel walk (:mod:`.models`) carries one state, the point and p. These tables carry other
things: Cyrus-Beck's ``tE`` and ``tL``, error diffusion's received errors, NLL's slopes used
again in later comparisons, midpoint subdivision's codes. Each model here says which columns
are marked and computes a row's expected cells from the answer's row and the student's own
earlier rows, with the method's own rule:

- a value the rule computes from other cells of the row (``t = N·(P0 - E) / -N·D``, an AND of
  two codes, a comparison's relation, a dither output) is expected from the student's own
  cells, so a slip in an input is charged once, where it is made;
- a value carried down the table (``tE = max(tE, t)``, an error received from earlier
  pixels, a slope compared again) is expected from the student's own earlier rows.

A cell equal to the answer's own is always right (a slip not carried on costs one row).
``tests/test_marking_tables.py`` marks a right table, a table with one slip and a table
that follows a slip through.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..core import lazy

if TYPE_CHECKING:
    from ..algorithms import dither
else:
    dither = lazy.module("scanconv.algorithms.dither")

Row = dict[str, Any]
"""A row's cells by column key: exact numbers (``Fraction``), pairs, or lower-case text."""


class TableModel:
    """The columns a table is marked on, and a row's expected cells (default: the answer's)."""

    table: str | None = None
    """The title of the answer's table that is marked (its start); ``None``: the step table."""
    marked: tuple[str, ...] = ()
    """The column keys marked, in the table's order."""
    rules: str = ""
    """The follow-through rule in words, for the marking's notes."""

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        """Row ``i``'s expected cells, from the answer's rows and the student's rows before
        it (``own[i]`` is the student's row ``i`` itself: its inputs)."""
        return dict(answer[i])

    def read(self, key: str, value: Any) -> Any:
        """The student's cell of column ``key`` in the spelling the answer's cells use
        (default: as written), before it is read as a number or text."""
        return value


def _num(v: Any) -> Fraction | None:
    return v if isinstance(v, Fraction) else None


def _given(row: Row, key: str, answer: Row) -> Any:
    """The student's own cell where it is a number, else the answer's."""
    v = row.get(key)
    return v if isinstance(v, Fraction) else answer.get(key)


class CyrusBeckTable(TableModel):
    """Cyrus-Beck's edge table: ``t`` from the student's own ``N·D`` and ``N·(P0 - E)``, the
    type from their own ``N·D``, ``tE`` and ``tL`` carried from their own rows above."""

    table = "Edges"
    marked = ("n_dot_d", "n_dot_w", "t", "kind", "t_enter", "t_leave")
    rules = (
        "t follows from the row's own N·D and N·(P0 - E), the type from its own N·D, and "
        "tE = max(tE, t), tL = min(tL, t) from the rows above as written."
    )

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        row = own[i]
        nd, nw = _given(row, "n_dot_d", exp), _given(row, "n_dot_w", exp)
        inward = _inward(answer)
        if isinstance(nd, Fraction) and isinstance(nw, Fraction) and nd != 0:
            exp["t"] = nw / -nd
            exp["kind"] = "entering" if (nd > 0) == inward else "leaving"
        prev = own[i - 1] if i else {}
        t_enter = _given(prev, "t_enter", answer[i - 1]) if i else Fraction(0)
        t_leave = _given(prev, "t_leave", answer[i - 1]) if i else Fraction(1)
        t = _given(row, "t", exp)
        kind = row.get("kind") if row.get("kind") in ("entering", "leaving") else exp["kind"]
        if isinstance(t, Fraction) and isinstance(t_enter, Fraction):
            exp["t_enter"] = max(t_enter, t) if kind == "entering" else t_enter
        if isinstance(t, Fraction) and isinstance(t_leave, Fraction):
            exp["t_leave"] = min(t_leave, t) if kind == "leaving" else t_leave
        return exp


def _inward(answer: Sequence[Row]) -> bool:
    """The answer's normals point inward: its entering rows have ``N·D > 0``."""
    return any(r.get("kind") == "entering" and (_num(r.get("n_dot_d")) or 0) > 0 for r in answer)


def _relation(a: Any, b: Any) -> str | None:
    if isinstance(a, Fraction) and isinstance(b, Fraction):
        return "<" if a < b else ">" if a > b else "="
    return None


class NLLTable(TableModel):
    """NLL's comparisons: a slope compared again keeps the value the student first wrote for
    it; the relation follows from the row's own two numbers."""

    table = "Comparisons"
    marked = ("left_value", "relation", "right_value")
    rules = (
        "A slope or coordinate compared again is expected as the student first wrote it, and "
        "each relation follows from the row's own two numbers."
    )

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        written: dict[str, Any] = {}
        for r, a in zip(own[:i], answer[:i], strict=False):
            for side in ("left", "right"):
                name, value = str(a.get(side)), r.get(f"{side}_value")
                if isinstance(value, Fraction):
                    written.setdefault(name, value)
        for side in ("left", "right"):
            if str(exp.get(side)) in written:
                exp[f"{side}_value"] = written[str(exp[side])]
        rel = _relation(_given(own[i], "left_value", exp), _given(own[i], "right_value", exp))
        if rel is not None:
            exp["relation"] = rel
        return exp


class MidpointClipTable(TableModel):
    """Midpoint subdivision's pieces: the AND from the row's own two codes, the action from
    them; the midpoint's code is not followed through (it needs the window)."""

    table = "Pieces"
    marked = ("code_a", "code_b", "and", "action", "mid", "code_mid")
    rules = (
        "The AND follows from the row's own two codes, and the action from them: both 0000 "
        "accept, AND not 0000 reject, else split."
    )

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        a, b = _code(own[i].get("code_a")), _code(own[i].get("code_b"))
        if a is None or b is None:
            return exp
        exp["and"] = f"{a & b:04b}"
        if a == b == 0:
            exp["action"] = "accept"
        elif a & b:
            exp["action"] = "reject"
        elif exp["action"] in ("accept", "reject"):
            exp["action"] = "split"
        return exp


def _code(v: Any) -> int | None:
    """A region code as written: ``1010`` (read as digits, not as the number 1010)."""
    text = str(v.numerator) if isinstance(v, Fraction) and v.denominator == 1 else str(v)
    text = text.zfill(4)
    return int(text, 2) if len(text) == 4 and set(text) <= {"0", "1"} else None


class DitherTable(TableModel):
    """Thresholding and ordered dither: the output from the row's own value and threshold."""

    marked = ("threshold", "output")
    rules = "The output follows from the row's own value and threshold, by the answer's comparison."

    def __init__(self, compare: str = ">") -> None:
        self.compare = compare

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        v, t = _given(own[i], "value", exp), _given(own[i], "threshold", exp)
        if isinstance(v, Fraction) and isinstance(t, Fraction):
            exp["output"] = Fraction(int(v > t or (self.compare == ">=" and v == t)))
        return exp


class DiffusionTable(TableModel):
    """Error diffusion: each pixel receives the shares of the errors the student wrote for
    the pixels before it; the output and the error follow from the row's own value."""

    marked = ("received", "value", "output", "error")
    rules = (
        "A pixel receives the kernel's shares of the errors as written in the rows above; its "
        "value is its gray level plus that, the output follows from the row's own value and "
        "the error is the row's own value less its own output."
    )

    def __init__(
        self, image: Sequence[Sequence[Any]], top: Any, data: dict[str, Any], compare: str
    ) -> None:
        self.image, self.top, self.data, self.compare = image, Fraction(top), data, compare
        self._got: dict[tuple[int, int], Fraction] = {}
        self._done = 0

    def _spread(self, row: Row, answer: Row) -> None:
        """Share the error the student wrote in ``row`` among the pixels it reaches."""
        err = _given(row, "error", answer)
        if not isinstance(err, Fraction) or (self.data.get("carry") == "clamped" and err < 0):
            return
        ai, aj = int(answer["i"]), int(answer["j"])
        direction = -1 if self.data.get("order") == "serpentine" and ai % 2 else 1
        for s in dither.KERNELS[self.data.get("kernel", "floyd-steinberg")].shares:
            to = (ai + s.di, aj + s.dj * direction)
            amount = dither._share(err, s.weight, self.data.get("arithmetic", "exact"))
            self._got[to] = self._got.get(to, Fraction(0)) + amount

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        if i < self._done or i == 0:
            self._got, self._done = {}, 0
        for n in range(self._done, i):  # the rows above, folded in once each, in order
            self._spread(own[n], answer[n])
        self._done = i
        at = (int(exp["i"]), int(exp["j"]))
        received = self._got.get(at, Fraction(0))
        exp["received"] = received
        exp["value"] = Fraction(self.image[at[0]][at[1]]) + _given(own[i], "received", exp)
        value = _given(own[i], "value", exp)
        if isinstance(value, Fraction):
            half = self.top / 2
            on = value > half or (self.compare == ">=" and value == half)
            exp["output"] = self.top if on else Fraction(0)
            out = _given(own[i], "output", exp)
            if isinstance(out, Fraction):
                exp["error"] = value - out
        return exp


class LineStyleTable(TableModel):
    """A styled line: the action follows from the row's own mask bit."""

    marked = ("bit_index", "bit", "action")
    rules = "The action follows from the row's own bit: 1 draws, 0 skips."

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        bit = own[i].get("bit")
        if isinstance(bit, Fraction) and bit in (0, 1):
            exp["action"] = "draw" if bit == 1 else "skip"
        return exp


class PlainRowsTable(TableModel):
    """Rows marked against the answer's row in the same place (each row stands alone: a
    thick line's added pixels, a character's bitmap rows)."""

    def __init__(self, table: str | None, marked: tuple[str, ...], rules: str) -> None:
        self.table, self.marked, self.rules = table, marked, rules


class FrameBufferTable(TableModel):
    """The frame-buffer sizes: each unit's size from the size above it as written (bits to
    bytes: / 8; bytes to KB: / 1000 or / 1024 as the answer's own ratio)."""

    table = "Frame-buffer size"
    marked = ("size",)
    rules = "Each size follows from the size above it as written, by the answer's own ratio."

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        if i:
            above, mine, theirs = (
                own[i - 1].get("size"),
                answer[i].get("size"),
                answer[i - 1].get("size"),
            )
            if isinstance(above, Fraction) and isinstance(mine, Fraction):
                if isinstance(theirs, Fraction) and theirs:
                    exp["size"] = above * mine / theirs
        return exp


class PixelAddressTable(TableModel):
    """A pixel's frame-buffer address: its bit offset from the student's own k (k b), its byte
    address from the student's own bit offset (base + offset / 8)."""

    table = "The pixel's address"
    marked = ("value",)
    rules = (
        "The bit offset follows from the row's k (k x b), the byte address and the bit in it "
        "from the offset (base + floor(offset / 8), offset mod 8)."
    )

    def __init__(self, bits: int, base: int) -> None:
        self.bits, self.base = bits, base

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        above = own[i - 1].get("value") if i else None
        if i == 1 and isinstance(above, Fraction):
            exp["value"] = above * self.bits
        elif i >= 2 and isinstance(offset := own[1].get("value"), Fraction):
            byte, bit = divmod(int(offset), 8)  # from the student's own bit offset
            exp["value"] = Fraction(self.base + byte if i == 2 else bit)
        return exp


class InsideVerdictsTable(TableModel):
    """The inside-outside verdicts: the even-odd verdict from the row's own crossing count,
    the nonzero verdict from its own winding number (a point on the boundary: the answer's)."""

    table = "Verdicts"
    marked = ("crossings", "even_odd", "winding", "nonzero")
    rules = (
        "The even-odd verdict follows from the row's own crossing count (odd: inside), the "
        "nonzero verdict from its own winding number (not 0: inside)."
    )

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        if exp.get("boundary") is not None:
            return exp
        crossings, winding = _given(own[i], "crossings", exp), _given(own[i], "winding", exp)
        if isinstance(crossings, Fraction) and crossings.denominator == 1:
            exp["even_odd"] = "inside" if crossings.numerator % 2 else "outside"
        if isinstance(winding, Fraction):
            exp["nonzero"] = "inside" if winding else "outside"
        return exp


class CoxDeBoorTable(TableModel):
    """The Cox-de Boor triangle at one t: each ``N_{i,d}`` from the student's own
    ``N_{i,d-1}`` and ``N_{i+1,d-1}`` (the rows above as written; a value not in the table is
    0, and ``N_{i,0}`` is 1 on the span of t only), by the knots' own weights."""

    table = "Cox–de Boor at t"
    marked = ("N",)
    rules = (
        "Each value of degree d follows by the Cox-de Boor recursion (the knots' weights, "
        "0/0 = 0) from the two values of degree d - 1 below it, as written in the rows above."
    )

    def __init__(self, knots: Sequence[Any], t: Any, span: int) -> None:
        self.u = [Fraction(v) for v in knots]
        self.t, self.span = Fraction(t), span

    def _weight(self, num: Fraction, lo: int, hi: int) -> Fraction:
        den = self.u[hi] - self.u[lo]
        return num / den if den else Fraction(0)

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        d, j = answer[i].get("d"), answer[i].get("i")
        if not isinstance(d, Fraction) or not isinstance(j, Fraction) or d < 1:
            return exp
        d, j = int(d), int(j)

        def lower(k: int) -> Fraction:
            if d == 1:
                return Fraction(int(k == self.span))
            for m in range(i):  # the row above that holds N_{k,d-1}, as the student wrote it
                if answer[m].get("d") == d - 1 and answer[m].get("i") == k:
                    mine = own[m].get("N")
                    return mine if isinstance(mine, Fraction) else Fraction(answer[m]["N"])
            return Fraction(0)

        left = self._weight(self.t - self.u[j], j, j + d) * lower(j)
        right = self._weight(self.u[j + d + 1] - self.t, j + 1, j + d + 1) * lower(j + 1)
        exp["N"] = left + right
        return exp


def _bytes_of(v: Any, base: int) -> list[int] | None:
    """A cell of bytes as written (``00011111``, ``0x1f 0x80``, ``31 128``), read in
    ``base``; ``None`` where it is not."""
    if isinstance(v, Fraction):
        text = str(v.numerator) if v.denominator == 1 and v >= 0 else ""
    else:
        text = str(v or "")
    try:
        values = [int(t, base) for t in text.replace("0x", "").split()]
    except ValueError:
        return None
    return values if values and all(0 <= b < 256 for b in values) else None


class GlyphBytesTable(TableModel):
    """A glyph packed into bytes row by row: each row's byte bits stand alone (from the
    glyph's row), its hexadecimal and decimal follow from the row's own bits as written."""

    table = "The glyph as bytes"
    marked = ("bits", "hex", "decimal")
    rules = (
        "Each row stands alone: its byte bits are the glyph's row padded to whole bytes in the "
        "answer's bit order, and its hexadecimal and decimal are the row's own bits as written."
    )

    def read(self, key: str, value: Any) -> Any:
        """A cell as written, in one spelling: hexadecimal as ``0x1f`` (``1F``, ``1Fh``,
        ``$1F`` and ``0x1F`` alike), bits grouped in whole bytes."""
        if not isinstance(value, str):
            return value
        text = " ".join(value.replace(",", " ").split())
        if key == "hex":
            tokens = [t.lower().removeprefix("0x").removeprefix("$").removesuffix("h")
                      for t in text.split()]  # fmt: skip
            try:
                return " ".join(f"0x{int(t, 16):02x}" for t in tokens) or value
            except ValueError:
                return value
        if key == "bits" and text and set(text) <= {"0", "1", " "}:
            bits = text.replace(" ", "")
            if len(bits) % 8 == 0:
                return " ".join(bits[n : n + 8] for n in range(0, len(bits), 8))
        return text if key == "decimal" else value

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        values = _bytes_of(own[i].get("bits"), 2)
        if values is not None:
            exp["hex"] = " ".join(f"0x{b:02x}" for b in values)
        else:
            values = _bytes_of(own[i].get("hex"), 16)
        if values is not None:
            exp["decimal"] = " ".join(str(b) for b in values)
        return exp


class FontTableTable(TableModel):
    """The font table: each glyph's address from the row's own glyph number as written
    (the first glyph's address plus the number times the bytes a glyph takes)."""

    table = "The font table"
    marked = ("glyph", "address")
    rules = (
        "Each row stands alone: a glyph's number is its code less the first glyph's, and its "
        "address the base plus the row's own number times the bytes a glyph takes."
    )

    def __init__(self, per_glyph: int) -> None:
        self.per_glyph = per_glyph

    def read(self, key: str, value: Any) -> Any:
        """An address written in hexadecimal alone (``0x10E7``) as the number it is."""
        text = value.strip().lower() if isinstance(value, str) else ""
        if key == "address" and text.startswith("0x"):
            try:
                return str(int(text, 16))
            except ValueError:
                return value
        return value

    def expect(self, i: int, answer: Sequence[Row], own: Sequence[Row]) -> Row:
        exp = dict(answer[i])
        glyph, theirs, at = (
            _num(own[i].get("glyph")),
            _num(exp.get("glyph")),
            _num(exp.get("address")),
        )
        if self.per_glyph % 8 == 0 and glyph is not None and theirs is not None and at is not None:
            exp["address"] = at + (glyph - theirs) * Fraction(self.per_glyph, 8)
        return exp

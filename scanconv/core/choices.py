"""The string choices of the public API as ``Literal`` types, each defined once here.

The Python API (:mod:`scanconv._api`, :mod:`scanconv.raster`) types every choice parameter as
one of these (or its enum, where the command line has one: ``algo: LineAlgorithm |
RoundingName``), so that a type checker rejects a misspelt choice
(``scanconv.line(2, 2, 10, 6, algo="bresenhm")`` is a mypy error) while the runtime still
validates the string with the same one-line :class:`~scanconv.core.checks.InputError`. Each
alias lists the values the library accepts, in the library's order; ``tests/test_api_typing.py``
checks each against the enum or the tuple the library validates with, so none can drift.
The API modules import these under ``TYPE_CHECKING`` only (their annotations are strings), so
building their ``Literal`` types costs the command line's start-up nothing (1.5 ms measured
with ``python -X importtime`` when imported).

>>> from typing import get_args
>>> get_args(RasterLineName)
('bresenham', 'dda', 'basic')

The line methods' own ``LineAlgorithmName`` sits beside their enum, in
:mod:`scanconv.algorithms.choices` (a new line method is named in one file).
"""

from __future__ import annotations

from typing import Literal

__all__ = [
    "AAMethodName",
    "AcrossName",
    "ArithmeticName",
    "BitOrderName",
    "BoundaryName",
    "CarryName",
    "CellOrderName",
    "CircleMethodName",
    "ClipEndsName",
    "ColorDepthName",
    "ColorModelName",
    "CompareName",
    "ConventionName",
    "DitherBaseName",
    "DitherCountName",
    "DitherScaleName",
    "DivideName",
    "EllipseP0Name",
    "FillMethodName",
    "FillRuleName",
    "InputKindName",
    "InsideRuleName",
    "KernelName",
    "LayoutName",
    "LevelCountName",
    "LineClipMethodName",
    "LineScaleName",
    "LoopName",
    "MajorName",
    "MidpointName",
    "MidpointStopName",
    "NormalsName",
    "OrderName",
    "OriginName",
    "P0Name",
    "PackingName",
    "PolygonClipMethodName",
    "PrinterDotsName",
    "RasterLineName",
    "ReconName",
    "RoundingName",
    "RowZeroName",
    "ScanOrderName",
    "StartName",
    "StrokeAlgorithmName",
    "SubgridName",
    "TieName",
    "UpdateName",
    "WuEndsName",
    "XStepName",
]

# --- lines and circles (the enums of scanconv.algorithms.choices and .circle_choices) ---------

RasterLineName = Literal["bresenham", "dda", "basic"]
"""``algo`` of :func:`scanconv.raster.line` (:data:`scanconv.algorithms.raster.LINE_ALGORITHMS`)."""
StrokeAlgorithmName = Literal["bresenham", "dda"]
"""``algo`` of :func:`scanconv.char_stroke`: the line drawing each stroke
(:data:`scanconv.algorithms.characters.STROKE_ALGORITHMS`)."""
RoundingName = Literal["half-up", "trunc", "half-even", "c-cast", "half-away"]
"""How a computed coordinate becomes a pixel (:class:`~scanconv.algorithms.choices.Rounding`)."""
TieName = Literal["step", "keep"]
"""What a decision parameter of exactly 0 chooses (:class:`~scanconv.algorithms.choices.Tie`)."""
StartName = Literal["swap", "given"]
"""Which end a line's walk starts from (:class:`~scanconv.algorithms.choices.Start`)."""
LineScaleName = Literal["integer", "half"]
"""The midpoint line's d: 2F(M) in integers or F(M) in halves (``LineScale``)."""
WuEndsName = Literal["full", "coverage"]
"""Wu's end points (:class:`~scanconv.algorithms.choices.WuEnds`)."""
LayoutName = Literal["notes", "textbook"]
"""The step table's rows (:class:`~scanconv.algorithms.choices.Layout`)."""
ConventionName = Literal["notes", "hearn-baker", "foley", "wikipedia"]
"""A named preset of conventions (:class:`~scanconv.algorithms.choices.Convention`)."""
CircleMethodName = Literal[
    "midpoint", "bresenham", "polynomial", "general", "trig", "symmetric-dda"
]
"""``method`` of :func:`scanconv.circle` (:class:`~scanconv.algorithms.circle_choices.CircleMethod`)."""
P0Name = Literal["1-r", "5/4-r"]
"""The midpoint circle's p0 as printed (:class:`~scanconv.algorithms.circle_choices.P0`)."""
EllipseP0Name = Literal["exact", "rounded"]
"""The midpoint ellipse's first decision parameters (``EllipseP0``)."""
LoopName = Literal["strict", "inclusive"]
"""The octant's loop: ``x < y`` or ``x <= y`` (:class:`~scanconv.algorithms.circle_choices.Loop`)."""
XStepName = Literal["last", "first"]
"""Bresenham's circle: d updated before or after ``x += 1`` (``XStep``)."""
UpdateName = Literal["new", "old"]
"""The midpoint circle's increments with the new or the old x (``Update``)."""

# --- clipping, filling, anti-aliasing (scanconv.algorithms.process_choices) -------------------

LineClipMethodName = Literal[
    "cohen-sutherland", "liang-barsky", "cyrus-beck", "midpoint-subdivision", "nicholl-lee-nicholl"
]
"""``method`` of :func:`scanconv.clip_line` (``LineClipMethod``)."""
PolygonClipMethodName = Literal["sutherland-hodgman", "weiler-atherton"]
"""``method`` of :func:`scanconv.clip_polygon` (``PolygonClipMethod``)."""
NormalsName = Literal["outward", "inward"]
"""Cyrus-Beck's edge normals (:data:`scanconv.algorithms.cyrus_beck.NORMALS`)."""
ClipEndsName = Literal["exact", "truncated"]
"""Cyrus-Beck's clipped end points (:data:`scanconv.algorithms.cyrus_beck.ENDS`)."""
MidpointName = Literal["rounded", "floor", "exact"]
"""Midpoint subdivision's midpoint (:data:`scanconv.algorithms.midpoint_clip.MIDPOINTS`)."""
MidpointStopName = Literal["length", "edge"]
"""Midpoint subdivision's stop rule (:data:`scanconv.algorithms.midpoint_clip.STOPS`)."""
AAMethodName = Literal["area", "supersample", "wu", "subpixel"]
"""``method`` of the anti-aliasing functions (``AAMethod``)."""
AcrossName = Literal["minor", "perpendicular"]
"""How a line's width is measured (``Across``)."""
SubgridName = Literal["span", "centre"]
"""Where the sub-pixel line runs (``Subgrid``)."""
DivideName = Literal["n", "n2"]
"""A sub-pixel count over n or n² (``Divide``)."""
FillRuleName = Literal["even-odd", "nonzero"]
"""The fill rule (``FillRule``)."""
OrderName = Literal["stack", "queue"]
"""A seed fill's pending pixels, last or first in first out (``Order``)."""
FillMethodName = Literal["boundary", "flood"]
"""The seed fill (:data:`scanconv.algorithms.seedfill.METHODS`)."""
InsideRuleName = Literal["both", "even-odd", "nonzero"]
"""The inside test's rule (:data:`scanconv.answers.process.fill.inside.RULES`)."""
BoundaryName = Literal["inside", "outside", "left-bottom"]
"""What a point on the boundary counts as (:data:`scanconv.algorithms.inside.BOUNDARY`)."""

# --- images, dithering, attributes, characters, colour ---------------------------------------

ColorDepthName = Literal["rgb24"]
"""``color`` of :func:`scanconv.storage`: 24-bit RGB."""
ReconName = Literal["midpoint", "lower"]
"""The quantizer's reconstruction level (:data:`scanconv.algorithms.quantize.RECON`)."""
InputKindName = Literal["integer", "real"]
"""What a quantizer's input range holds (:data:`scanconv.algorithms.quantize.INPUTS`)."""
OriginName = Literal["bottom-left", "top-left"]
"""Where a sampled image's row 0 is (:data:`scanconv.algorithms.sample.ORIGINS`)."""
CompareName = Literal[">", ">="]
"""A dither's comparison (:data:`scanconv.algorithms.dither.DITHER_KNOBS`, as the next five)."""
DitherScaleName = Literal["raw", "centered", "given"]
"""The ordered dither's thresholds: ``d·top/n²`` (``raw``), ``(d + 1/2)·top/n²`` (``centered``) or
the entries themselves, already in the image's units (``given``)."""
DitherBaseName = Literal["0", "1"]
"""The Bayer matrix's entries counted from 0 (``0 .. n² - 1``) or from 1."""
DitherCountName = Literal["0", "1"]
"""A pixel's screen position counted from 0 or from 1 (a threshold's lookup)."""
KernelName = Literal[
    "floyd-steinberg",
    "simple",
    "jarvis-judice-ninke",
    "stucki",
    "burkes",
    "sierra",
    "two-row-sierra",
    "sierra-lite",
    "one-dimensional",
]
"""The error-diffusion kernel (:data:`scanconv.algorithms.dither.KERNELS`)."""
ScanOrderName = Literal["raster", "serpentine"]
"""The error diffusion's scan: every row left to right, or alternate rows reversed."""
ArithmeticName = Literal["exact", "integer"]
"""The error diffusion's arithmetic: exact fractions, or each share truncated toward 0."""
CarryName = Literal["kept", "clamped"]
"""Negative errors ``kept``, or ``clamped`` at 0."""
LevelCountName = Literal["n2+1", "n2"]
"""An n x n halftone cell's levels: n² + 1 or n² (:data:`scanconv.answers.image.halftone.PRINTER_KNOBS`)."""
PrinterDotsName = Literal["whole", "exact"]
"""A printer's cell from dpi / lpi: whole dots, or the ratio itself."""
MajorName = Literal["row", "column"]
"""A frame buffer stores rows or columns one after another (:data:`scanconv.algorithms.framebuffer.ADDRESS_KNOBS`)."""
RowZeroName = Literal["top", "bottom"]
"""A frame buffer's y = 0: the top scan line or the bottom one."""
CellOrderName = Literal["bayer", "clustered"]
"""How a halftone cell fills (:data:`scanconv.algorithms.dither.CELL_ORDERS`)."""
BitOrderName = Literal["msb", "lsb"]
"""A line style's mask read from its most or least significant bit; a glyph row's leftmost pixel in a byte's most or least significant bit."""
PackingName = Literal["rows", "columns", "bits"]
"""A bitmap font's packing (:data:`scanconv.algorithms.characters.PACKINGS`)."""
ColorModelName = Literal["rgb", "cmy", "hsv", "hsi", "grey"]
"""A colour model (:data:`scanconv.algorithms.color.MODELS`)."""

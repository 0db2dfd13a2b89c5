"""TRANSITIONAL: the old ``scanconv.answers.image`` names, re-exported from their new modules.

Image representation was split by topic: the computations into
:mod:`scanconv.algorithms.image_limits`, :mod:`~scanconv.algorithms.storage`,
:mod:`~scanconv.algorithms.quantize`, :mod:`~scanconv.algorithms.ramp` and
:mod:`~scanconv.algorithms.sample`; the answers into :mod:`scanconv.answers.storage`,
:mod:`~scanconv.answers.quantize`, :mod:`~scanconv.answers.ramp` and
:mod:`~scanconv.answers.sample`. This module only keeps the command line (being rewritten)
importing while it moves to those modules; it is removed afterwards. Import from the new
modules.
"""

from __future__ import annotations

from ..algorithms.image_limits import (
    MAX_BITS,
    MAX_CELLS,
    MAX_LEVELS,
    MAX_SIDE,
    check_bits,
    check_cells,
    check_levels,
    parse_size,
)
from ..algorithms.quantize import RECON, Quantizer, level_dtype
from ..algorithms.ramp import ramp, ramp_row
from ..algorithms.sample import BLOCK_SAMPLES, Sampled, sample_levels
from ..algorithms.storage import UNITS, bits_per_pixel, storage_bits
from ..core.checks import check_positive as positive
from ._image import matrix_columns
from .quantize import GRAY_NAMES, gray_name, quantization_rows, quantize_solution
from .ramp import ramp_solution
from .sample import sample_solution
from .storage import size_text, storage_quantity, storage_solution

__all__ = [
    "BLOCK_SAMPLES",
    "GRAY_NAMES",
    "MAX_BITS",
    "MAX_CELLS",
    "MAX_LEVELS",
    "MAX_SIDE",
    "RECON",
    "UNITS",
    "Quantizer",
    "Sampled",
    "bits_per_pixel",
    "check_bits",
    "check_cells",
    "check_levels",
    "gray_name",
    "level_dtype",
    "matrix_columns",
    "parse_size",
    "positive",
    "quantization_rows",
    "quantize_solution",
    "ramp",
    "ramp_row",
    "ramp_solution",
    "sample_levels",
    "sample_solution",
    "size_text",
    "storage_bits",
    "storage_quantity",
    "storage_solution",
]

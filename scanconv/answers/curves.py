"""TRANSITIONAL: the old ``scanconv.answers.curves`` names, re-exported from their new modules.

The curves were split by topic: the algorithms into :mod:`scanconv.algorithms.curve_limits`,
:mod:`~scanconv.algorithms.sampling`, :mod:`~scanconv.algorithms.parametric`,
:mod:`~scanconv.algorithms.bezier`, :mod:`~scanconv.algorithms.bspline`,
:mod:`~scanconv.algorithms.continuity` and :mod:`~scanconv.algorithms.local_control`; the
answers into :mod:`scanconv.answers.parametric`, :mod:`~scanconv.answers.bezier`,
:mod:`~scanconv.answers.bspline`, :mod:`~scanconv.answers.continuity` and
:mod:`~scanconv.answers.local_control`. This module only keeps the command line (being
rewritten) importing while it moves to those modules; it is removed afterwards. Import from the
new modules.
"""

from __future__ import annotations

from ..algorithms.bezier import bernstein, bezier, de_casteljau
from ..algorithms.bspline import KNOTS, basis, basis_levels, bspline, knot_vector, parse_knots, span
from ..algorithms.continuity import continuity_level, end_derivatives
from ..algorithms.curve_limits import (
    DEFAULT_SAMPLES,
    MAX_CURVE_PIXELS,
    MAX_DEGREE,
    MAX_POINTS,
    MAX_SAMPLES,
    MAX_WEIGHTS,
    Point,
    Value,
    check_exact,
    check_path,
    check_points,
    check_samples,
    check_unit_t,
    check_weights,
    pairs,
)
from ..algorithms.local_control import local_control
from ..algorithms.parametric import parametric
from ..algorithms.sampling import coord, curve_pixel, curve_pixels, sample_ts
from .bezier import bezier_at_solution, bezier_solution
from .bspline import bspline_at_solution, bspline_solution
from .continuity import continuity_solution
from .local_control import local_control_solution
from .parametric import PARAMETRIC, parametric_solution

__all__ = [
    "DEFAULT_SAMPLES",
    "KNOTS",
    "MAX_CURVE_PIXELS",
    "MAX_DEGREE",
    "MAX_POINTS",
    "MAX_SAMPLES",
    "MAX_WEIGHTS",
    "PARAMETRIC",
    "Point",
    "Value",
    "basis",
    "basis_levels",
    "bernstein",
    "bezier",
    "bezier_at_solution",
    "bezier_solution",
    "bspline",
    "bspline_at_solution",
    "bspline_solution",
    "check_exact",
    "check_path",
    "check_points",
    "check_samples",
    "check_unit_t",
    "check_weights",
    "continuity_level",
    "continuity_solution",
    "coord",
    "curve_pixel",
    "curve_pixels",
    "de_casteljau",
    "end_derivatives",
    "knot_vector",
    "local_control",
    "local_control_solution",
    "pairs",
    "parametric",
    "parametric_solution",
    "parse_knots",
    "sample_ts",
    "span",
]

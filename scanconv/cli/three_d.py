"""The ``scanconv 3d`` group's command modules: each registers its commands on
:data:`scanconv.cli.application.three_d_app` when imported (one module per topic of the
group, so that each merges by a line here)."""

from __future__ import annotations

from . import space as space
from . import visible as visible

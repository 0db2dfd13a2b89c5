"""``scanconv.raster``: the public name of :mod:`scanconv.algorithms.raster` (the numpy bulk
rasterizers). Importing it gives that very module, so its constants are shared."""

import sys

from .algorithms import raster as _raster

sys.modules[__name__] = _raster

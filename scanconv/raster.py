"""``scanconv.raster``: every pixel of a primitive at once, as numpy arrays (the bulk
rasterizers of :mod:`scanconv.algorithms.raster` and :mod:`scanconv.algorithms.raster_conic`, re-exported).

Each function returns ``(xs, ys)``, two 1-D ``int64`` arrays, x first and y up:
``img[ys, xs] = 1`` draws into an image whose row index is y. Unlike ``skimage.draw``,
:func:`circle` and :func:`ellipse` are perimeters (skimage's ``circle_perimeter`` and
``ellipse_perimeter``), their size first and the centre after (``circle(r, xc, yc)``), and
nothing is clipped to a shape; :func:`polygon` is filled, as skimage's.

>>> from scanconv import raster
>>> xs, ys = raster.line(0, 0, 3, 1)
>>> list(zip(xs.tolist(), ys.tolist()))
[(0, 0), (1, 0), (2, 1), (3, 1)]
"""

from .algorithms.raster import LINE_ALGORITHMS, Coords, line
from .algorithms.raster_conic import circle, ellipse
from .algorithms.raster_fill import line_aa, polygon
from .core.numeric import COORD_LIMIT

__all__ = ["COORD_LIMIT", "LINE_ALGORITHMS", "Coords", "circle", "ellipse", "line", "line_aa"]
__all__ += ["polygon"]

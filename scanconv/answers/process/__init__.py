"""The answers of "The process: clip, transform, fill, anti-alias": 2D transformations,
the window-to-viewport mapping and the viewing pipeline here; clipping, filling and
anti-aliasing in the sub-packages; the process answers' shared text of values, points,
matrices and rectangles in `_shared`."""

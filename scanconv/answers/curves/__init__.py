"""The answers of "Curves": Bezier and B-spline curves (points, de Casteljau, the basis
functions), continuity and local control."""

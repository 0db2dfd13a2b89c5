"""The answers of "Lines, circles and ellipses" (`scanconv --help`'s first topic): the line
methods (basic, DDA, Bresenham, midpoint), the circle methods, the midpoint ellipse, the
parametric forms, line attributes (styles, thick lines) and characters."""

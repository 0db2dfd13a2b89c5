"""Figures: the drawn figure (:mod:`.figure`: SVG and PNG), its TikZ twin (:mod:`.tikz`), the
text pixel grid (:mod:`.grid`) and the shaded text picture of a matrix (:mod:`.shade`)."""

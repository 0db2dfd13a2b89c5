"""What the HTML page is made of: the stepper's positions (:mod:`.stepper`), its SVG grid
(:mod:`.stepgrid`), the "Test yourself" mode (:mod:`.selftest`, :mod:`.selftest_marks`), MathML
and escaping (:mod:`.mathml`), and the page's style sheets and scripts (:mod:`.page_assets`)."""

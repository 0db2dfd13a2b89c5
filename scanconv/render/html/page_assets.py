"""The style sheets and the scripts of the HTML page (:mod:`scanconv.render.mappings.html`), read
from the package's files in ``static/`` (package data, read through :mod:`importlib.resources`:
the page is still built from the installed package alone and stays one self-contained file).

Every CSS rule is scoped under ``.scanconv`` (one answer's root element), so the same rules
can sit in a Jupyter notebook next to other output without touching it. The script defines
``window.scanconvStepper`` once (a second answer in the same notebook or document reuses it)
and starts every answer root that is not started yet; each root keeps its own state and finds
its elements by class inside itself, never by a document-wide id.

The files (real CSS and JavaScript, so they can be linted: ``tests/test_page_assets.py``):

* ``page.css``: the answer's style; ``plain.css``: the answer without its stepper (printing, or
  no script); ``print.css``: the rest of the print rules; ``selftest.css``: the "Test yourself"
  mode's style (nothing of it prints); ``document.css``: a whole page only (never put into a
  notebook); ``sheet.css``: a sheet's page (:mod:`scanconv.render.documents.sheet_html`);
* ``stepper.js``: the stepper, one script for every answer on the page; ``clip.js``: marks the
  working formulas that are cut at the edge of their box; ``selftest.js``: the "Test
  yourself" mode (:mod:`scanconv.render.html.selftest`). That script knows no method: it reads
  each answer's ``script.sc-testdata`` (rows and rules, exact values as fraction strings) and
  compares with exact rationals (``BigInt``). It finds the answers through the stepper
  (``window.scanconvStepper.roots``) and its elements inside each answer's root; it drives the
  grid through the stepper's own slider (an ``input`` event), so the stepper needs no change.
"""

from __future__ import annotations

from importlib import resources

FILES = (
    "page.css",
    "plain.css",
    "print.css",
    "selftest.css",
    "document.css",
    "sheet.css",
    "stepper.js",
    "clip.js",
    "selftest.js",
)
"""The files of ``static/`` (a test lints each, and the wheel ships them)."""


def read(name: str) -> str:
    """The text of ``static/<name>``, one of :data:`FILES`."""
    return (resources.files(__package__) / "static" / name).read_text(encoding="utf-8")


PLAIN = read("plain.css")
"""The answer without its stepper: every pixel shown, no controls (printing; no script)."""

CSS = (
    read("page.css") + "@media print{\n" + PLAIN + read("print.css") + "}\n" + read("selftest.css")
)
"""The page's style sheet (every rule under ``.scanconv``), the print rules and the mode's."""

PAGE_CSS = read("document.css")
"""Rules for a whole page only (never put into a notebook)."""

SHEET_CSS = read("sheet.css")
"""A sheet's page (its title, questions and worksheet tables; a page break before each
question when printed)."""

JS = "".join("\n" + read(name) for name in ("stepper.js", "clip.js", "selftest.js"))
"""The scripts of every answer on the page: the stepper, the cut-formula marks and the mode."""

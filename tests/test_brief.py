"""``--brief`` leaves scanconv's own notes (the conventions it states, the table's layout, the
errata) out in every format, so homework keeps the student's working without the tool's
remarks; on a terminal it leaves the derivation out too."""

from __future__ import annotations

import pytest

from .helpers import run

LINE = ("line", "2", "2", "10", "6")


@pytest.mark.parametrize("fmt", ["markdown", "plain", "latex", "html", "json"])
def test_brief_drops_the_notes_in_every_format(fmt):
    full = run(*LINE, "-f", fmt).out
    brief = run(*LINE, "--brief", "-f", fmt).out
    assert "Conventions" in full and "erratum E1" in full
    assert "Conventions" not in brief and "erratum E1" not in brief
    if fmt == "html":  # the working stays: it is the student's answer (as MathML here)
        assert "<mi>x</mi><mo>=</mo>" in brief.replace(" ", "") or "<math" in brief
    elif fmt != "json":
        assert "10 - 2 = 8" in brief.replace("−", "-")
    assert "(10, 6)" in brief

"""The one LaTeX escaper, :func:`scanconv.core.tex_escape.tex_text`, symbol by symbol against a
table written by hand (each entry as LaTeX spells it in text mode)."""

from __future__ import annotations

import pytest

from scanconv.core.tex_escape import tex_text

UNICODE = {
    "Δ": r"$\Delta$",
    "≥": r"$\ge$",
    "≤": r"$\le$",
    "≠": r"$\ne$",
    "·": r"$\cdot$",
    "×": r"$\times$",
    "→": r"$\to$",
    "↑": r"$\uparrow$",
    "↓": r"$\downarrow$",
    "≈": r"$\approx$",
    "²": r"$^2$",
    "³": r"$^3$",
    "√": r"$\surd$",
    "ε": r"$\varepsilon$",
    "θ": r"$\theta$",
    "α": r"$\alpha$",
    "β": r"$\beta$",
    "γ": r"$\gamma$",
    "φ": r"$\phi$",
    "ϕ": r"$\phi$",
    "π": r"$\pi$",
    "°": r"$^\circ$",
    "−": "--",
    "…": r"\ldots{}",
    "–": "--",
    "—": "---",
    "⌈": r"$\lceil$",
    "⌉": r"$\rceil$",
    "⌊": r"$\lfloor$",
    "⌋": r"$\rfloor$",
    "∈": r"$\in$",
}
SPECIAL = {
    "\\": r"\textbackslash{}",
    "&": r"\&",
    "%": r"\%",
    "$": r"\$",
    "#": r"\#",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "~": r"\textasciitilde{}",
    "^": r"\textasciicircum{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
}


@pytest.mark.parametrize(("char", "tex"), [*UNICODE.items(), *SPECIAL.items()])
def test_each_symbol_as_latex_writes_it(char, tex):
    assert tex_text(f"a{char}b") == f"a{tex}b"


def test_hyphens_tabs_and_the_unknown():
    # a run of hyphens keeps each one; a tab or a line break is a space; a control character
    # or a letter the fonts lack is "?"
    assert tex_text("--x") == "-{}-x"
    assert tex_text("a-b") == "a-b"
    assert tex_text("a\tb\nc") == "a b c"
    assert tex_text("a\x07b\u4e2d") == "a?b?"

"""Unicode text into LaTeX text mode: the one LaTeX escaper of scanconv (:func:`tex_text`),
re-exported by :mod:`.working`."""

from __future__ import annotations

# --- Unicode -> LaTeX text mode ----------------------------------------------------------------

_TEX = {
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

_TEX_SPECIAL = {
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


def tex_text(s: str) -> str:
    """Escape text for LaTeX, turning known Unicode symbols into math.

    Every TeX special character is escaped (``^`` too, so no ``^^2f`` can spell a character),
    a run of hyphens keeps every hyphen (``--algo`` is never an en dash), and control
    characters become ``?`` as any character TeX's fonts lack does.

    >>> tex_text("p_k >= 0 chooses NE; 50% of Δx")
    'p\\\\_k \\\\textgreater{}= 0 chooses NE; 50\\\\% of $\\\\Delta$x'
    >>> tex_text("--algo dda ^^2f")
    '-{}-algo dda \\\\textasciicircum{}\\\\textasciicircum{}2f'
    """
    out = []
    for i, ch in enumerate(s):
        if ch == "-" and s[i + 1 : i + 2] == "-":
            out.append("-{}")
        elif ch in _TEX_SPECIAL:
            out.append(_TEX_SPECIAL[ch])
        elif ch in _TEX:
            out.append(_TEX[ch])
        elif ch.isascii() and ch.isprintable():
            out.append(ch)
        elif ch in "\t\n":
            out.append(" ")
        else:
            out.append("?")
    return "".join(out)

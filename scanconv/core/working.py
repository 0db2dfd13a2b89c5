"""The notation of the working: one place that knows how a line of working is written in
Unicode, in ASCII and in TeX.

``plain`` must be pure ASCII, so Unicode working (``Δx``, ``≥``, ``·``) is transliterated by
:func:`ascii_text`; LaTeX text mode gets its symbols as math through :func:`tex_text`.
"""

from __future__ import annotations

_ASCII = {
    "Δ": "d",
    "−": "-",
    "≥": ">=",
    "≤": "<=",
    "≠": "!=",
    "·": "*",
    "×": "x",
    "→": "->",
    "≈": "~",
    "²": "^2",
    "³": "^3",
    "√": "sqrt",
    "ε": "eps",
    "θ": "theta",
    "π": "pi",
    "°": " deg",
    "₀": "0",
    "₁": "1",
    "₂": "2",
    "ᵢ": "i",
    "…": "...",
    "–": "-",
    "—": "-",
    "’": "'",
    "⌈": "ceil(",
    "⌉": ")",
    "⌊": "floor(",
    "⌋": ")",
    "∈": "in",
}

_TEX = {
    "Δ": r"$\Delta$",
    "≥": r"$\ge$",
    "≤": r"$\le$",
    "≠": r"$\ne$",
    "·": r"$\cdot$",
    "×": r"$\times$",
    "→": r"$\to$",
    "≈": r"$\approx$",
    "²": r"$^2$",
    "³": r"$^3$",
    "√": r"$\surd$",
    "ε": r"$\varepsilon$",
    "θ": r"$\theta$",
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


def ascii_text(s: str) -> str:
    """Transliterate Unicode working to ASCII; anything unknown becomes ``?``.

    >>> ascii_text("p0 = 2Δy - Δx = 2·4 - 8 ≥ 0")
    'p0 = 2dy - dx = 2*4 - 8 >= 0'
    """
    if s.isascii():
        return s
    return "".join(ch if ch.isascii() else _ASCII.get(ch, "?") for ch in s)


def tex_text(s: str) -> str:
    """Escape text for LaTeX, turning known Unicode symbols into math.

    >>> tex_text("p_k >= 0 chooses NE; 50% of Δx")
    'p\\\\_k \\\\textgreater{}= 0 chooses NE; 50\\\\% of $\\\\Delta$x'
    """
    out = []
    for ch in s:
        if ch in _TEX_SPECIAL:
            out.append(_TEX_SPECIAL[ch])
        elif ch in _TEX:
            out.append(_TEX[ch])
        elif ch.isascii():
            out.append(ch)
        else:
            out.append("?")
    return "".join(out)

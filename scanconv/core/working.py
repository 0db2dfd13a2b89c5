"""The notation of the working: one place that knows how a line of working is written in
Unicode, in ASCII and in TeX.

The working of an answer is written **once**, as TeX math (:attr:`Quantity.tex
<scanconv.core.records.Quantity.tex>`, what markdown and LaTeX show); :func:`tex_to_unicode`
derives the Unicode text the terminal and JSON show, and ``plain`` transliterates that to pure
ASCII with :func:`ascii_text`. So the three can never say different things. LaTeX text mode
(titles, notes) gets its Unicode symbols as math through :func:`tex_text`.

Writing the one source
----------------------
The TeX is read as math, with two conventions that let one string serve both readers:

* **Spaces are kept** where the source has them (math mode would ignore them), so write the
  TeX spaced as the text should read: ``x \\le y`` gives ``x ≤ y``. A letter-like control
  word (``\\Delta``, ``\\theta``) eats the spaces between it and a letter or digit, as in
  TeX: ``\\Delta x`` gives ``Δx``. Runs of spaces become one.
* ``\\cdot`` is written tight (``2 \\cdot 4`` gives ``2·4``), ``\\quad`` is three spaces,
  ``\\ ``, ``\\;``, ``\\,``, ``\\:`` and ``~`` are one space; ``\\lceil``/``\\lfloor`` eat the
  spaces after them and ``\\rceil``/``\\rfloor`` the spaces before them.

Sub- and superscripts use Unicode's subscript and superscript characters where every
character of the script has one (``p_{k+1}`` gives ``pₖ₊₁``, ``2^{n-1}`` gives ``2ⁿ⁻¹``,
``^\\circ`` gives ``°``). A script with a character Unicode cannot lower (subscript ``b c d f g
q w y z``, capitals, ``,``) is written with ``_`` instead: ``x_c`` gives ``x_c``, ``r_y`` gives
``r_y``, ``x_{inc}`` gives ``x_inc`` and ``N_{i,3}`` gives ``N_{i,3}`` (braces when the script
is not a single word); a superscript falls back to ``^n`` or ``^(...)`` the same way. A minus
sign stays ``-`` (as in the numbers the tables print), so the ASCII is unchanged by it.

:func:`ascii_text` reads the scripts back: ``p₀`` gives ``p0`` (digits after a letter),
``p1₀`` gives ``p1_0``, ``pₖ`` gives ``p_k``, ``xₖ₊₁`` gives ``x_{k+1}``, ``r²`` gives ``r^2`` and
``2ⁿ⁻¹`` gives ``2^(n-1)``.
"""

from __future__ import annotations

from collections.abc import Callable

from . import lazy
from .tex_escape import tex_text as tex_text  # the LaTeX escaper, with the working

# --- Characters no output may carry as they are ----------------------------------------------

_UNSAFE_RANGES: tuple[tuple[int, int], ...] = ((0x00, 0x08), (0x0B, 0x1F), (0x7F, 0x9F))
_UNSAFE_RANGES += ((0x61C, 0x61C), (0x200E, 0x200F), (0x202A, 0x202E), (0x2066, 0x2069))

UNSAFE = lazy.pattern("[" + "".join(f"{chr(a)}-{chr(b)}" for a, b in _UNSAFE_RANGES) + "]")
"""Control characters (a terminal escape sequence, a bell) and the bidirectional controls
(U+202E RIGHT-TO-LEFT OVERRIDE and kin, which make text read differently from what it holds):
user text never carries them into any format. Tab and newline are left to each format."""

_UNSAFE_TO_ASK = {c: "?" for a, b in _UNSAFE_RANGES for c in range(a, b + 1)}
""":data:`UNSAFE` as a ``str.translate`` table to ``?`` (no pattern to compile on the way)."""


def visible(text: str) -> str:
    """``text`` with every :data:`UNSAFE` character shown as U+FFFD, and tabs and line breaks
    as spaces: a single-line text (a file name, a title) as every format shows it.

    >>> visible("a\x1b[2Jb\u202ecba\tz")
    'a\ufffd[2Jb\ufffdcba z'
    """
    if text.isascii() and text.isprintable():  # the common case: nothing to do
        return text
    return UNSAFE.sub("\ufffd", _BREAKS.sub(" ", text))


_BREAKS = lazy.pattern(r"\r\n|[\t\n\r]")


def json_visible(text: str) -> str:
    """JSON text with every :data:`UNSAFE` character in its strings written as a ``\\u``
    escape: the data round-trips unchanged, but the file never holds a raw bidirectional
    override or terminal control (``json.dumps`` escapes C0 controls, not U+202E or DEL).

    >>> import json
    >>> text = json_visible(json.dumps("a\u202eb\x7f", ensure_ascii=False))
    >>> text, json.loads(text) == "a\u202eb\x7f"
    ('"a\\\\u202eb\\\\u007f"', True)
    """
    if text.isascii() and "\x7f" not in text:
        return text
    return UNSAFE.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


# --- Unicode -> ASCII ------------------------------------------------------------------------

_GREEK = {
    **{
        name: chr(0x3B1 + i)
        for i, name in enumerate(
            "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi omicron "
            "pi rho varsigma sigma tau upsilon phi chi psi omega".split()
        )
    },
    **dict(zip("varepsilon epsilon vartheta varphi".split(), "εεϑφ", strict=True)),
    **dict(
        zip("Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega".split(), "ΓΔΘΛΞΠΣΦΨΩ", strict=True)
    ),
}

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
    "√": "sqrt",
    "ε": "eps",
    "θ": "theta",
    "π": "pi",
    "°": " deg",
    "…": "...",
    "–": "-",
    "—": "-",
    "’": "'",
    "′": "'",
    "⌈": "ceil(",
    "⌉": ")",
    "⌊": "floor(",
    "⌋": ")",
    "∈": "in",
    "±": "+/-",
    "∞": "inf",
    "‖": "||",
    "⟨": "<",
    "⟩": ">",
    "≡": "==",
}
for _name, _letter in _GREEK.items():  # the other Greek letters by name
    _ASCII.setdefault(_letter, _name)

_NAMES = {c: w for c, w in _ASCII.items() if len(w) > 1 and w.isalpha()}
"""The characters written as a name (``ε`` as ``eps``), which a letter after them is spaced
from (``eps y``)."""
_ASCII_TABLE = {ord(c): w for c, w in _ASCII.items() if not c.isascii()}
""":data:`_ASCII` as a ``str.translate`` table."""

_SUB = {
    **dict(zip("0123456789", "₀₁₂₃₄₅₆₇₈₉", strict=True)),
    **dict(zip("+-−=()", "₊₋₋₌₍₎", strict=True)),
    **dict(zip("aehijklmnoprstuvx", "ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ", strict=True)),
}
"""The characters Unicode can lower, with their subscript forms."""

_SUP = {
    **dict(zip("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹", strict=True)),
    **dict(zip("+-−=()", "⁺⁻⁻⁼⁽⁾", strict=True)),
    **dict(zip("abcdefghijklmnoprstuvwxyz", "ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖʳˢᵗᵘᵛʷˣʸᶻ", strict=True)),
}
"""The characters Unicode can raise (every lowercase letter but q), with their forms."""

_FROM_SUB = {v: k for k, v in _SUB.items() if k != "−"}
_FROM_SUP = {v: k for k, v in _SUP.items() if k != "−"}


def _runs(s: str, chars: dict[str, str], ascii: Callable[[str, str], str]) -> str:
    """``s`` with each run of the keys of ``chars`` replaced by ``ascii(run, before)``, where
    ``run`` is the run in ASCII and ``before`` the character before it (``""`` at the start)."""
    out: list[str] = []
    i, n = 0, len(s)
    while i < n:
        j = i
        while j < n and s[j] in chars:
            j += 1
        if j == i:
            out.append(s[i])
            i += 1
        else:
            out.append(ascii("".join(chars[c] for c in s[i:j]), s[i - 1 : i]))
            i = j
    return "".join(out)


def _sub_ascii(run: str, before: str) -> str:
    if run.isdigit() and before and not before.isdigit():
        return run  # p₀ -> p0, log₂ -> log2
    if run.isalnum():
        return "_" + run  # pₖ -> p_k, p1₀ -> p1_0
    return "_{" + run + "}"  # xₖ₊₁ -> x_{k+1}


def _sup_ascii(run: str, before: str) -> str:
    if run.isalnum() or (run[0] == "-" and run[1:].isalnum()):
        return "^" + run  # r² -> r^2, 2⁻ⁿ -> 2^-n
    if run[0] == "(" and run[-1] == ")" and "(" not in run[1:-1]:
        return "^" + run  # P⁽ʳ⁾ -> P^(r)
    return "^(" + run + ")"  # 2ⁿ⁻¹ -> 2^(n-1)


def ascii_text(s: str) -> str:
    """Transliterate Unicode working to ASCII; anything unknown, and any control character
    but tab and newline (:data:`UNSAFE`), becomes ``?``.

    >>> ascii_text("p₀ = 2Δy - Δx = 2·4 - 8 ≥ 0")
    'p0 = 2dy - dx = 2*4 - 8 >= 0'
    >>> ascii_text("pₖ₊₁ = pₖ + 2xₖ₊₁ + 1, p1₀ = rₓ²/4, 2ⁿ⁻¹ ≤ r < 2ⁿ, ε = 2⁻³, θₖ")
    'p_{k+1} = p_k + 2x_{k+1} + 1, p1_0 = r_x^2/4, 2^(n-1) <= r < 2^n, eps = 2^-3, theta_k'
    >>> ascii_text("xₖ + εyₖ, Δx")
    'x_k + eps y_k, dx'
    """
    if s.isascii():
        return s if s.isprintable() else s.translate(_UNSAFE_TO_ASK)
    if not _FROM_SUB.keys().isdisjoint(s):
        s = _runs(s, _FROM_SUB, _sub_ascii)
    if not _FROM_SUP.keys().isdisjoint(s):
        s = _runs(s, _FROM_SUP, _sup_ascii)
    if _NAMES.keys().isdisjoint(s):  # no name that may need a space after it: one table
        text = s.translate(_ASCII_TABLE)
        if not text.isascii():  # a character with no ASCII form
            text = "".join(c if c.isascii() else "?" for c in text)
        return text.translate(_UNSAFE_TO_ASK)
    out = []
    for i, ch in enumerate(s):
        word = ch if ch.isascii() else _ASCII.get(ch, "?")
        if len(word) > 1 and word.isalpha() and s[i + 1 : i + 2].isalpha():
            word += " "  # ε y as "eps y", never "epsy"
        out.append(word)
    return "".join(out).translate(_UNSAFE_TO_ASK)


# --- TeX -> Unicode --------------------------------------------------------------------------

_LETTERS = {**_GREEK, "ell": "ℓ", "infty": "∞", "partial": "∂", "circ": "°", "prime": "′"}
"""Letter-like control words: the spaces between them and a letter or digit are eaten
(``\\Delta x`` is ``Δx``, ``\\pi = 3`` keeps its spaces)."""

_SYMBOLS = {
    "le": "≤",
    "leq": "≤",
    "ge": "≥",
    "geq": "≥",
    "ne": "≠",
    "neq": "≠",
    "approx": "≈",
    "equiv": "≡",
    "times": "×",
    "pm": "±",
    "to": "→",
    "rightarrow": "→",
    "in": "∈",
    "mid": "|",
    "lvert": "|",
    "rvert": "|",
    "ldots": "…",
    "dots": "…",
    "cdots": "…",
    "bmod": "mod",
    "sum": "Σ",
}
"""Operators and relations: spaces around them are kept as written (``x \\le y``)."""

_TIGHT = {"cdot": "·"}
"""Written without the spaces around them (``2 \\cdot 4`` is ``2·4``)."""

_HARD = "\ue000"
"""A space that runs of spaces do not swallow (``\\quad``), replaced at the end."""

_QUADS = {"quad": 3, "qquad": 6}
_OPEN = {"lceil": "⌈", "lfloor": "⌊", "langle": "⟨"}
_CLOSE = {"rceil": "⌉", "rfloor": "⌋", "rangle": "⟩"}
_FUNCTIONS = {"max", "min", "sin", "cos", "tan", "log", "ln", "exp", "gcd", "lim", "det"}
_TEXT = {"text", "textrm", "textit", "textbf", "texttt", "textnormal", "mbox"}
_FONTS = {"mathrm", "mathit", "mathbf", "mathsf", "mathtt", "mathcal", "boldsymbol"}
_SIZES = {"big", "Big", "bigl", "bigr", "Bigl", "Bigr", "displaystyle"}
_FRACS = {"frac": " / ", "dfrac": " / ", "tfrac": "/"}
_ESCAPED = {"{": "{", "}": "}", "%": "%", "&": "&", "#": "#", "_": "_", "$": "$", "|": "‖"}
_TEXT_SYMBOLS = {
    "textbackslash": "\\",
    "textasciitilde": "~",
    "textasciicircum": "^",
    "textless": "<",
    "textgreater": ">",
    "textbar": "|",
    "ldots": "…",
}
"""Text-mode symbols (what :func:`tex_text` writes for ``\\ ~ ^ < > |``)."""
_SPACING = {" ": " ", ",": " ", ";": " ", ":": " ", ">": " ", "!": ""}
_ASCII_LETTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")
_PASS_SUP = ("°", "′", "″")
_OPERATORS = set(" +-−·×/=<>≤≥,;:")


def _operand(s: str) -> str:
    """A fraction's numerator or denominator, bracketed unless it is one term."""
    body = s[1:] if s[:1] in "-−" else s
    return f"({s})" if any(c in _OPERATORS for c in body) else s


def _script(arg: str, sup: bool) -> str:
    """A sub- or superscript in Unicode's forms, else with ``_``/``^`` (see the module)."""
    table, mark = (_SUP, "^") if sup else (_SUB, "_")
    compact = arg.replace(" ", "")
    if sup and compact in _PASS_SUP:
        return compact
    if compact and all(c in table for c in compact):
        return "".join(table[c] for c in compact)
    if compact.isalnum() or len(compact) == 1 or (sup and compact[:1] == "-"):
        return mark + compact
    return mark + ("(" + arg + ")" if sup else "{" + arg + "}")


class _Out:
    """The Unicode being written: runs of spaces collapse to one, hard spaces stay."""

    def __init__(self) -> None:
        self.chars: list[str] = []

    def add(self, text: str) -> None:
        for c in text:
            if c == " ":
                self.space()
            else:
                self.chars.append(c)

    def space(self) -> None:
        if self.chars and self.chars[-1] not in (" ", _HARD):
            self.chars.append(" ")

    def strip(self) -> None:
        while self.chars and self.chars[-1] == " ":
            self.chars.pop()

    def value(self) -> str:
        self.strip()
        return "".join(self.chars)


class _Reader:
    """A recursive-descent reader of the TeX math subset the answers write."""

    def __init__(self, tex: str) -> None:
        self.s = tex
        self.i = 0

    def error(self, what: str) -> ValueError:
        return ValueError(f"tex_to_unicode: {what} at {self.i} in {self.s!r}")

    def peek(self) -> str:
        return self.s[self.i : self.i + 1]

    def skip_spaces(self) -> None:
        while self.peek() in (" ", "\n", "\t"):
            self.i += 1

    def math(self, group: bool) -> str:
        """Read to the end (or to the ``}`` closing a group) and return the Unicode."""
        out = _Out()
        while self.i < len(self.s):
            c = self.s[self.i]
            if c == "}":
                if not group:
                    raise self.error("unbalanced '}'")
                self.i += 1
                return out.value()
            if c == "{":
                self.i += 1
                out.add(self.math(group=True))
            elif c == "\\":
                self.command(out)
            elif c in "^_":
                self.i += 1
                out.add(_script(self.argument(), sup=c == "^"))
            elif c in " \n\t~":
                self.i += 1
                out.space()
            else:
                self.i += 1
                out.add(c)
        if group:
            raise self.error("missing '}'")
        return out.value()

    def argument(self) -> str:
        """One argument: a ``{group}``, a control word or one character."""
        self.skip_spaces()
        c = self.peek()
        if not c or c == "}":
            raise self.error("missing argument")
        if c == "{":
            self.i += 1
            return self.math(group=True)
        if c == "\\":
            out = _Out()
            self.command(out)
            return out.value()
        self.i += 1
        return c

    def text_argument(self) -> str:
        """The ``{...}`` of ``\\text``: kept as written, with what :func:`tex_text` writes
        read back (``\\%``, ``\\textless{}``, ``$\\Delta$``), so ``\\texttt{tex_text(s)}``
        gives ``s`` back."""
        self.skip_spaces()
        if self.peek() != "{":
            raise self.error("\\text needs {...}")
        self.i += 1
        depth, chars = 0, []
        while self.i < len(self.s):
            c = self.s[self.i]
            self.i += 1
            if c == "\\" and self.peek() in _ESCAPED:
                chars.append(self.peek())
                self.i += 1
            elif c == "\\":
                name = self.word()
                if name not in _TEXT_SYMBOLS:
                    raise self.error(f"unknown text-mode macro \\{name}")
                chars.append(_TEXT_SYMBOLS[name])
                if self.s.startswith("{}", self.i):
                    self.i += 2
            elif c == "$":
                end = self.s.find("$", self.i)
                if end < 0:
                    raise self.error("missing '$'")
                chars.append(tex_to_unicode(self.s[self.i : end]))
                self.i = end + 1
            elif c == "{":
                depth += 1
            elif c == "}":
                if depth == 0:
                    return "".join(chars)
                depth -= 1
            else:
                chars.append(c)
        raise self.error("missing '}'")

    def word(self) -> str:
        start = self.i
        while self.peek().isalpha():
            self.i += 1
        return self.s[start : self.i]

    def command(self, out: _Out) -> None:
        self.i += 1  # the backslash
        c = self.peek()
        if not c:
            raise self.error("lone backslash")
        if not c.isalpha():
            self.i += 1
            if c in _ESCAPED:
                out.add(_ESCAPED[c])
            elif c in _SPACING:
                if _SPACING[c]:
                    out.space()
            else:
                raise self.error(f"unknown control symbol \\{c}")
            return
        name = self.word()
        if not (self._symbol(name, out) or self._structure(name, out)):
            raise self.error(f"unknown macro \\{name}")

    def _symbol(self, name: str, out: _Out) -> bool:
        """A macro that stands for a character or a space (``\\Delta``, ``\\le``, ``\\quad``)."""
        if name in _LETTERS:
            out.add(_LETTERS[name])
            if self.s[self.i :].lstrip()[:1].isalnum():  # \Delta x is Δx; \pi = 3 is π = 3
                self.skip_spaces()
        elif name in _SYMBOLS:
            out.add(_SYMBOLS[name])
        elif name in _TIGHT:
            out.strip()
            out.add(_TIGHT[name])
            self.skip_spaces()
        elif name in _QUADS:
            out.strip()
            out.add(_HARD * _QUADS[name])
            self.skip_spaces()
        elif name in _OPEN:
            out.add(_OPEN[name])
            self.skip_spaces()
        elif name in _CLOSE:
            out.strip()
            out.add(_CLOSE[name])
        elif name not in _SIZES:
            return False
        return True

    def _structure(self, name: str, out: _Out) -> bool:
        """A macro with arguments: functions, text, fonts, fractions, roots, delimiters and
        ``bmatrix``."""
        if name in _FUNCTIONS or name == "operatorname":
            out.add(name if name in _FUNCTIONS else self.argument())
            self.skip_spaces()
            if self.peek().isalnum() or self._letter_like_follows():
                out.space()
        elif name in _TEXT:
            out.add(self.text_argument())
        elif name in _FONTS:
            out.add(self.argument())
        elif name in _FRACS:
            a, b = _operand(self.argument()), _operand(self.argument())
            frac = a + _FRACS[name] + b
            out.add(f"({frac})" if self.s[self.i :].lstrip()[:1] == "(" else frac)
        elif name == "sqrt":
            out.add(self._root())
        elif name == "binom":
            out.add(f"C({self.argument()}, {self.argument()})")
        elif name in ("left", "right"):
            self._delimiter(name, out)
        elif name == "begin":
            out.add(self._matrix())
        else:
            return False
        return True

    def _root(self) -> str:
        index = ""
        if self.peek() == "[":
            end = self.s.index("]", self.i)
            index, self.i = _script(self.s[self.i + 1 : end], sup=True), end + 1
        a = self.argument()
        return index + "√" + (a if a.isalnum() else f"({a})")

    def _delimiter(self, name: str, out: _Out) -> None:
        if name == "left":  # the delimiter, then the spaces after it
            self.skip_spaces()
            if self.peek() == ".":  # \left. : no delimiter
                self.i += 1
            elif self.peek() == "\\":
                self.command(out)
            else:
                out.add(self.argument())
            self.skip_spaces()
            return
        out.strip()  # \right: the spaces before it, then the delimiter
        self.skip_spaces()
        if self.peek() == ".":
            self.i += 1

    def _matrix(self) -> str:
        """``\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}`` as ``[[a, b], [c, d]]``.

        >>> tex_to_unicode(r"D = \\begin{bmatrix} 0 & 2 \\\\ 3 & \\frac{1}{2} \\end{bmatrix}")
        'D = [[0, 2], [3, 1 / 2]]'
        """
        env = self.argument()
        if env != "bmatrix":
            raise self.error(f"unknown environment {env}")
        end = self.s.find("\\end{bmatrix}", self.i)
        if end < 0:
            raise self.error("missing \\end{bmatrix}")
        body, self.i = self.s[self.i : end], end + len("\\end{bmatrix}")
        rows = [r for r in body.split("\\\\") if r.strip()]
        return (
            "["
            + ", ".join(
                "[" + ", ".join(tex_to_unicode(c.strip()) for c in r.split("&")) + "]" for r in rows
            )
            + "]"
        )

    def _letter_like_follows(self) -> bool:
        """True if a letter-like control word or a function name comes next."""
        s, i = self.s, self.i
        if not s.startswith("\\", i):
            return False
        end = i + 1
        while end < len(s) and s[end] in _ASCII_LETTERS:
            end += 1
        word = s[i + 1 : end]  # the control word's name (\\([A-Za-z]+)), or empty
        return word != "" and (word in _LETTERS or word in _FUNCTIONS)


def tex_to_unicode(tex: str) -> str:
    """The Unicode working written by the TeX math ``tex`` (see the module for the rules).

    Raises ``ValueError`` for a macro it does not know or unbalanced braces, so a new macro is
    added to its tables rather than shown raw.

    >>> tex_to_unicode(r"\\Delta x = x_2 - x_1 = 10 - 2 = 8")
    'Δx = x₂ - x₁ = 10 - 2 = 8'
    >>> tex_to_unicode(r"m = \\frac{\\Delta y}{\\Delta x} = \\frac{4}{8} = 0.5")
    'm = Δy / Δx = 4 / 8 = 0.5'
    >>> tex_to_unicode(r"2\\Delta y = 2 \\cdot 4 = 8 \\quad (\\text{added when } p_k < 0)")
    '2Δy = 2·4 = 8   (added when pₖ < 0)'
    >>> tex_to_unicode(r"p_{k+1} = p_k + 2x_{k+1} + 1 - 2y_{k+1},\\ r_x^2 \\ge 0")
    'pₖ₊₁ = pₖ + 2xₖ₊₁ + 1 - 2yₖ₊₁, rₓ² ≥ 0'
    >>> tex_to_unicode(r"y = \\sqrt{r^2 - x^2},\\ r/\\sqrt{2} \\approx 3.536")
    'y = √(r² - x²), r/√2 ≈ 3.536'
    >>> tex_to_unicode(r"2^{n-1} \\le r < 2^n,\\ \\varepsilon = 2^{-n} \\ne 0")
    '2ⁿ⁻¹ ≤ r < 2ⁿ, ε = 2⁻ⁿ ≠ 0'
    >>> tex_to_unicode(r"\\theta_k = 90^\\circ - k \\cdot \\Delta\\theta,\\ x = r \\cos\\theta_k")
    'θₖ = 90° - k·Δθ, x = r cos θₖ'
    >>> tex_to_unicode(r"k = \\lceil \\log_2 L \\rceil = \\lceil 1.585 \\rceil \\times 1{,}024")
    'k = ⌈log₂ L⌉ = ⌈1.585⌉ × 1,024'
    >>> tex_to_unicode(r"\\text{steps} = \\max(|\\Delta x|, |\\Delta y|),\\ \\operatorname{round}(x_c)")
    'steps = max(|Δx|, |Δy|), round(x_c)'
    >>> tex_to_unicode(r"x = x_1 + \\frac{\\Delta x}{\\Delta y}(y - y_1),\\ p1_0 = \\tfrac{r_x^2}{4}")
    'x = x₁ + (Δx / Δy)(y - y₁), p1₀ = rₓ²/4'
    """
    return _Reader(tex).math(group=False).replace(_HARD, " ").strip()

"""TeX math as MathML for the HTML page, and the escaping every text on the page goes through.

:func:`tex_math` converts with :mod:`latex2mathml` (imported here only, on the path that
writes a page: its import costs about 55 ms of start-up) and then passes the result through
:func:`_safe_mathml`, since latex2mathml copies ``\\text{...}`` into ``<mtext>`` unescaped:
only MathML elements with MathML attributes, properly nested, survive; any other ``<``,
``>`` or ``&`` is escaped. :func:`esc` escapes plain text (and shows control characters as
U+FFFD); :func:`json_script` embeds data that no text in it can break out of.
"""

from __future__ import annotations

import html as htmlmod
import json
import re
from collections.abc import Iterable
from typing import Any

from ...core.working import UNSAFE as _CONTROLS
from ...core.working import tex_to_unicode
from ..cells import note_segments, prose_math


def esc(text: str) -> str:
    """Text for HTML content and quoted attributes: escaped, control characters (a terminal
    escape sequence in a title) and bidirectional overrides shown as U+FFFD.

    >>> esc('<b title="x">\x1b[2J & co')
    '&lt;b title=&quot;x&quot;&gt;\ufffd[2J &amp; co'
    """
    return htmlmod.escape(_CONTROLS.sub("\ufffd", text))


_MATHML_TAGS = frozenset(
    "math mrow mi mn mo mtext ms mspace msub msup msubsup mfrac msqrt mroot mstyle mtable mtr "
    "mtd mover munder munderover menclose mpadded mphantom semantics annotation merror".split()
)
_MATHML_ATTRS = frozenset(
    "xmlns display stretchy fence form mathvariant displaystyle scriptlevel width height depth "
    "linethickness columnalign rowalign columnspacing rowspacing separator lspace rspace accent "
    "accentunder notation minsize maxsize movablelimits symmetric largeop columnlines "
    "rowlines frame framespacing equalrows equalcolumns".split()
)
_TAG = re.compile(r"<(/?)([A-Za-z][A-Za-z0-9]*)((?:\s+[A-Za-z-]+=\"[^\"<>&]*\")*)\s*(/?)>")
_ATTR = re.compile(r"\s+([A-Za-z-]+)=\"([^\"<>&]*)\"")
_ENTITY = re.compile(r"&(#x[0-9A-Fa-f]+|#[0-9]+|[A-Za-z]+);")
_UPPER_GREEK = re.compile(r"<mi>(&#x0039[1-9A-Fa-f];|&#x003[Aa][0-9];)</mi>")


def _safe_mathml(markup: str) -> str:
    """``markup`` with every tag that is not a MathML element with MathML attributes, every
    end tag that does not close the open element, and every stray ``<``, ``>`` and ``&``
    escaped: :mod:`latex2mathml` copies ``\\text{...}`` into ``<mtext>`` unescaped, and no
    answer's text may become markup or close an element early.

    >>> _safe_mathml('<mtext></mtext><script>x</script>&<mi onclick="f">a</mi></mtext>')
    '<mtext></mtext>&lt;script&gt;x&lt;/script&gt;&amp;&lt;mi onclick="f"&gt;a&lt;/mi&gt;&lt;/mtext&gt;'
    """
    out: list[str] = []
    open_tags: list[str] = []
    i = 0
    while i < len(markup):
        ch = markup[i]
        if ch == "<":
            m = _TAG.match(markup, i)
            if m and m.group(2) in _MATHML_TAGS:
                closing, name, attrs, empty = m.group(1), m.group(2), m.group(3), m.group(4)
                fine = all(a in _MATHML_ATTRS for a, _ in _ATTR.findall(attrs))
                if closing and not attrs and open_tags and open_tags[-1] == name:
                    open_tags.pop()
                elif not closing and fine:
                    if not empty:
                        open_tags.append(name)
                else:
                    m = None
                if m is not None:
                    out.append(m.group(0))
                    i = m.end()
                    continue
            out.append("&lt;")
        elif ch == ">":
            out.append("&gt;")
        elif ch == "&":
            e = _ENTITY.match(markup, i)
            if e:
                out.append(e.group(0))
                i = e.end()
                continue
            out.append("&amp;")
        else:
            out.append(ch)
        i += 1
    out.extend(f"</{name}>" for name in reversed(open_tags))
    return _CONTROLS.sub("\ufffd", "".join(out))


def tex_math(tex: str, display: bool = False) -> str:
    """TeX math as MathML (safe to put in a page), or, if it cannot be converted, the same
    working in Unicode text, escaped.

    Upper-case Greek letters are set upright, as TeX sets them; ``display`` math is set in
    display style (fractions full size) but inline, left-aligned.

    >>> '<mi mathvariant="normal">&#x00394;</mi><mi>x</mi>' in tex_math(r"\\Delta x = 8")
    True
    >>> "&lt;b&gt;" in tex_math(r"\\text{<b>}")
    True
    """
    typed: list[str] = []
    try:
        from latex2mathml.converter import convert

        markup = convert(_TEXT_EDGES.sub(_keep_spaces, _typed_out(tex, typed)))
    except Exception:  # latex2mathml raises many kinds on TeX it does not know
        try:
            text = tex_to_unicode(tex)
        except ValueError:
            text = tex
        return f'<span class="sc-mathtext">{esc(text)}</span>'
    markup = _UPPER_GREEK.sub(r'<mi mathvariant="normal">\1</mi>', markup)
    markup = markup.replace("<mi>:</mi>", "<mo>:</mo>")  # a relation in TeX
    markup = markup.replace(  # |x| is set tight, as TeX sets it
        '<mo stretchy="false">&#x0007C;</mo>',
        '<mo stretchy="false" lspace="0em" rspace="0em">&#x0007C;</mo>',
    )
    if display:  # set like display math, but left-aligned in its list item
        markup = markup.replace(' display="inline">', ' display="inline" displaystyle="true">', 1)
    markup = _safe_mathml(markup)
    for n, text in enumerate(typed):  # each typed text back, escaped, as its own <mtext>
        typed_text = f'<mtext mathvariant="monospace">{esc(text)}</mtext>'
        markup = markup.replace(f"<mtext>{_TYPED}{n}</mtext>", typed_text, 1)
    return markup


_TYPED = "scTyped"
r"""The name a ``\texttt{...}`` group stands as while latex2mathml converts the rest (it
would close the group at the first ``}`` of an escape such as ``\textless{}``)."""


def _typed_out(tex: str, typed: list[str]) -> str:
    r"""``tex`` with each ``\texttt{...}`` group (a formula the user typed, escaped by
    :func:`~scanconv.core.working.tex_text`) replaced by a placeholder name; the group's
    text, read back (``\textless{}`` is ``<``), is appended to ``typed``.

    >>> typed = []
    >>> _typed_out(r"f = \texttt{t \# \textless{}b\textgreater{}} + 1", typed), typed
    ('f = \\text{scTyped0} + 1', ['t # <b>'])
    """
    out = []
    i = 0
    while (start := tex.find("\\texttt{", i)) >= 0:
        depth, j = 0, start + len("\\texttt")
        while j < len(tex):
            if tex[j - 1] != "\\":
                depth += {"{": 1, "}": -1}.get(tex[j], 0)
            j += 1
            if depth == 0:
                break
        out.append(tex[i:start] + f"\\text{{{_TYPED}{len(typed)}}}")
        typed.append(tex_to_unicode("\\text{" + tex[start + len("\\texttt{") : j - 1] + "}"))
        i = j
    return "".join(out) + tex[i:]


_TEXT_EDGES = re.compile(r"\\text\{([^{}]*)\}")
"""A ``\\text{...}`` group (its spaces taken apart in Python: ``( *)([^{}]*?)( *)`` tried
every split of a run of spaces, cubic in its length)."""


def _keep_spaces(m: re.Match[str]) -> str:
    """``\\text{ a }`` as ``\\ \\text{a}\\ ``: latex2mathml drops the spaces at a text's edges.

    >>> print(_TEXT_EDGES.sub(_keep_spaces, r"x \\text{ if } y \\text{  }"))
    x \\ \\text{if}\\  y \\ \\text{}
    """
    inner = m.group(1)
    text = inner.strip(" ")
    before = "\\ " if inner[:1] == " " else ""
    after = "\\ " if text and inner[-1:] == " " else ""
    return before + "\\text{" + text + "}" + after


def note_html(note: str) -> str:
    """A note: its text escaped, its ``$...$`` formulas as MathML.

    >>> note_html("if $p < 0$ & so on")[:12], note_html("if $p < 0$ & so on")[-12:]
    ('if <math xml', ' &amp; so on')
    """
    return prose_segments_html(note_segments(note))


def prose_segments_html(segments: Iterable[tuple[bool, str]]) -> str:
    """Prose segments (a :class:`~scanconv.document.Prose`'s): the text escaped, the math as
    MathML."""
    return "".join(tex_math(part) if is_math else esc(part) for is_math, part in segments)


def prose_html(text: str) -> str:
    """A text cell: escaped, the formulas written in it in the ASCII notation
    (:func:`~scanconv.render.cells.prose_math`) as MathML; a ``$`` is only text.

    >>> prose_html("x^2 < 1")[:5], prose_html("x^2 < 1")[-7:]
    ('<math', ' &lt; 1')
    """
    return "".join(tex_math(part) if is_math else esc(part) for is_math, part in prose_math(text))


def json_script(data: Any, cls: str = "sc-data") -> str:
    """``data`` as a ``<script type="application/json">`` that no text in it can close.

    >>> json_script({"t": "</script><b>&"})
    '<script type="application/json" class="sc-data">{"t": "\\\\u003c/script\\\\u003e\\\\u003cb\\\\u003e\\\\u0026"}</script>'
    """
    text = json.dumps(data, ensure_ascii=False, separators=(", ", ": "))
    text = text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")
    return f'<script type="application/json" class="{cls}">{text}</script>'

"""The colour models of a conversion, one record each (:class:`ColorModel`, named by its
method record: ``color/cmy``'s ``spec``): the numbers as the working writes them, the checks
of a given value, and each model's working to and from RGB, every formula written once (TeX)
with this colour's numbers substituted. :mod:`.color` builds the answer from them."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import NamedTuple

from ...algorithms import color as c
from ...algorithms.color import Value
from ...core.checks import InputError
from ...core.numeric import Number, fmt, fmt_short, normalize, paren
from ...core.records import Quantity, rule, worked

PLACES = 3
"""Decimals shown for an irrational value (HSI's hue and what follows from it)."""

# --- numbers as the working writes them --------------------------------------------------------


def num(v: Value) -> str:
    """A value substituted into a formula: a short decimal, else a fraction, else ``PLACES``
    decimals; negative ones bracketed.

    >>> num(Fraction(1, 5)), num(Fraction(-1, 5)), num(Fraction(2, 3)), num(61.5484)
    ('0.2', '(-0.2)', '2/3', '61.548')
    """
    if isinstance(v, float):
        return paren(fmt(v, PLACES))
    return paren(fmt_short(v))


def result(v: Value) -> str:
    """``= value`` at the end of a line: exact, with the decimal where it is a fraction, or
    ``≈`` and ``PLACES`` decimals for a float.

    >>> result(Fraction(2, 3)), result(Fraction(1, 2)), result(61.5484)
    ('= 2/3 \\\\approx 0.667', '= 0.5', '\\\\approx 61.548')
    """
    if isinstance(v, float):
        return rf"\approx {fmt(v, PLACES)}"
    s = fmt_short(v)
    if "/" in s:
        return rf"= {s} \approx {fmt(v, PLACES)}"
    return f"= {s}"


def cell(v: Value) -> str:
    """A table cell: a short decimal, or ``PLACES`` decimals (``~`` for a float)."""
    if isinstance(v, float):
        return "~" + fmt(v, PLACES)
    s = fmt_short(v)
    return fmt(v, PLACES) if "/" in s else s


def exact_cell(v: Value) -> str:
    """A table cell, exactly (``2/3``), or ``~`` and decimals for a float."""
    if isinstance(v, float):
        return "~" + fmt(v, PLACES)
    return str(normalize(v))


def _triple(vs: Sequence[Value], exact: bool = False) -> str:
    return "(" + ", ".join(exact_cell(v) if exact else cell(v) for v in vs) + ")"


def _deg(v: Value) -> str:
    return num(v) + r"^\circ"


def _deg_result(v: Value) -> str:
    """``= 210°``, ``= 10200/31 ≈ 329.032°`` or ``≈ 61.575°``."""
    return result(v) + r"^\circ"


# --- checks ---------------------------------------------------------------------------------------


def _unit(v: Number, what: str) -> Fraction:
    f = Fraction(v)
    if not 0 <= f <= 1:
        raise InputError(f"{what} = {fmt_short(f)} is out of range (0 <= {what} <= 1)", "values")
    return f


def _hue(v: Number) -> Fraction:
    f = Fraction(v)
    if not 0 <= f < 360:
        raise InputError(f"H = {fmt_short(f)} is out of range (0 <= H < 360 degrees)", "values")
    return f


def _level(v: Number, what: str, top: int, unit: bool) -> Fraction:
    f = Fraction(v)
    if unit:
        return _unit(f, what)
    if f.denominator != 1:
        raise InputError(
            f"{what} = {fmt_short(f)} must be an integer 0..{top} (or ask for the unit scale, values in 0..1)",
            "unit",
        )
    if not 0 <= f <= top:
        raise InputError(
            f"{what} = {fmt_short(f)} is out of range (0 <= {what} <= {top})", "values"
        )
    return f


# --- the working, model by model ------------------------------------------------------------------


class _Work:
    """The quantities of one answer, with unique keys, and its scale: RGB's top level and
    whether RGB is on the unit scale."""

    def __init__(self, top: int = 255, unit: bool = False) -> None:
        self.items: list[Quantity] = []
        self.top, self.unit = top, unit
        self.scale = "0..1" if unit else f"0..{top}"

    def add(self, key: str, value: object, tex: str) -> None:
        self.items.append(worked(key, value, tex))

    def say(self, key: str, tex: str) -> None:
        self.items.append(rule(key, tex))


def _to_cmy(w: _Work, rgb: tuple[Fraction, Fraction, Fraction]) -> tuple[Fraction, ...]:
    w.say("cmy", r"\text{RGB} \to \text{CMY (subtractive, the complement of RGB):}")
    out = c.rgb_to_cmy(*rgb)
    for name, low, v, o in zip("CMY", "rgb", rgb, out, strict=True):
        w.add(f"cmy_{name}", o, f"{name} = 1 - {low} = 1 - {num(v)} {result(o)}")
    return out


def _to_hsv(w: _Work, rgb: tuple[Fraction, Fraction, Fraction]) -> tuple[Value, ...]:
    r, g, b = rgb
    out = c.rgb_to_hsv(r, g, b)
    hi, lo = max(rgb), min(rgb)
    delta = hi - lo
    w.say("hsv", r"\text{RGB} \to \text{HSV (hexcone, Smith 1978):}")
    trip = f"{num(r)}, {num(g)}, {num(b)}"
    w.add("hsv_max", hi, rf"\text{{max}} = \max(r, g, b) = \max({trip}) {result(hi)}")
    w.add("hsv_min", lo, rf"\text{{min}} = \min(r, g, b) = \min({trip}) {result(lo)}")
    w.add(
        "hsv_delta",
        delta,
        rf"\Delta = \text{{max}} - \text{{min}} = {num(hi)} - {num(lo)} {result(delta)}",
    )
    w.add("hsv_V", out.v, rf"V = \text{{max}} {result(out.v)}")
    if hi == 0:
        w.add("hsv_S", out.s, r"S = 0 \quad (\text{max} = 0\text{: black})")
    else:
        w.add(
            "hsv_S",
            out.s,
            rf"S = \frac{{\Delta}}{{\text{{max}}}} = \frac{{{num(delta)}}}{{{num(hi)}}} {result(out.s)}",
        )
    if not out.largest:
        w.add(
            "hsv_H",
            out.h,
            r"H = 0^\circ \quad (\Delta = 0\text{: a grey, the hue is undefined; taken as } 0)",
        )
        return out.h, out.s, out.v
    formula, a, b_ = {
        "R": (r"60 \cdot \frac{g - b}{\Delta}", g, b),
        "G": (r"120 + 60 \cdot \frac{b - r}{\Delta}", b, r),
        "B": (r"240 + 60 \cdot \frac{r - g}{\Delta}", r, g),
    }[out.largest]
    base = {"R": 0, "G": 120, "B": 240}[out.largest]
    raw = base + 60 * (a - b_) / delta
    subst = (
        f"{base} + " if base else ""
    ) + rf"60 \cdot \frac{{{num(a)} - {num(b_)}}}{{{num(delta)}}}"
    wrap = rf" = {num(raw)} + 360" if raw < 0 else ""
    name = {"R": "r", "G": "g", "B": "b"}[out.largest]
    w.add(
        "hsv_H",
        out.h,
        rf"H = {formula} = {subst}{wrap} {_deg_result(out.h)} \quad (\text{{{name} is the largest}})",
    )
    return out.h, out.s, out.v


def _to_hsi(w: _Work, rgb: tuple[Fraction, Fraction, Fraction]) -> tuple[Value, ...]:
    r, g, b = rgb
    out = c.rgb_to_hsi(r, g, b)
    total = r + g + b
    w.say("hsi", r"\text{RGB} \to \text{HSI (Gonzalez and Woods):}")
    w.add(
        "hsi_I",
        out.i,
        rf"I = \frac{{r + g + b}}{{3}} = \frac{{{num(r)} + {num(g)} + {num(b)}}}{{3}} {result(out.i)}",
    )
    if total == 0:
        w.add("hsi_S", out.s, r"S = 0 \quad (r + g + b = 0\text{: black})")
    else:
        lo = min(rgb)
        w.add(
            "hsi_S",
            out.s,
            rf"S = 1 - \frac{{3 \min(r, g, b)}}{{r + g + b}} = 1 - \frac{{3 \cdot {num(lo)}}}{{{num(total)}}} {result(out.s)}",
        )
    w.add(
        "hsi_num",
        out.numerator,
        rf"\tfrac{{1}}{{2}}[(r - g) + (r - b)] = \tfrac{{1}}{{2}}[({num(r)} - {num(g)}) + ({num(r)} - {num(b)})] {result(out.numerator)}",
    )
    w.add(
        "hsi_den_sq",
        out.radicand,
        rf"(r - g)^2 + (r - b)(g - b) = {num(r - g)}^2 + {num(r - b)} \cdot {num(g - b)} {result(out.radicand)}",
    )
    if out.theta is None:
        w.add(
            "hsi_H",
            out.h,
            r"H = 0^\circ \quad (r = g = b\text{: a grey, the hue is undefined; taken as } 0)",
        )
        return out.h, out.s, out.i
    w.add(
        "hsi_theta",
        out.theta,
        rf"\theta = \operatorname{{arccos}}\left(\frac{{{fmt_short(out.numerator)}}}{{\sqrt{{{num(out.radicand)}}}}}\right) "
        + (
            f"= {_deg(out.theta)}"
            if isinstance(out.theta, Fraction)
            else rf"\approx {_deg(out.theta)}"
        ),
    )
    if b <= g:
        w.add("hsi_H", out.h, rf"H = \theta = {_deg(out.h)} \quad (b \le g)")
    else:
        eq = "=" if isinstance(out.h, Fraction) else r"\approx"
        w.add(
            "hsi_H",
            out.h,
            rf"H = 360^\circ - \theta = 360 - {num(out.theta)} {eq} {_deg(out.h)} \quad (b > g)",
        )
    return out.h, out.s, out.i


def _grey(w: _Work, rgb8: tuple[Fraction, ...], scale: str) -> tuple[Fraction, Fraction]:
    R, G, B = rgb8
    avg, luma = c.grey_average(R, G, B), c.grey_luma(R, G, B)
    w.say("grey", rf"\text{{RGB}} \to \text{{grey, on the RGB scale ({scale}):}}")
    w.add(
        "grey_average",
        avg,
        rf"Y_{{avg}} = \frac{{R + G + B}}{{3}} = \frac{{{num(R)} + {num(G)} + {num(B)}}}{{3}} {result(avg)} \quad (\text{{plain average}})",
    )
    w.add(
        "grey_luma601",
        luma,
        rf"Y_{{601}} = 0.299 R + 0.587 G + 0.114 B = 0.299 \cdot {num(R)} + 0.587 \cdot {num(G)} + 0.114 \cdot {num(B)} {result(luma)} \quad (\text{{ITU-R BT.601 luma}})",
    )
    return avg, luma


def _from_cmy(w: _Work, cmy: tuple[Fraction, ...]) -> tuple[Fraction, Fraction, Fraction]:
    w.say("to_rgb", r"\text{CMY} \to \text{RGB:}")
    rgb = c.cmy_to_rgb(*cmy)
    for low, name, v, o in zip("rgb", "CMY", cmy, rgb, strict=True):
        w.add(f"rgb_{low}", o, f"{low} = 1 - {name} = 1 - {num(v)} {result(o)}")
    return rgb


def _from_hsv(w: _Work, hsv: tuple[Fraction, ...]) -> tuple[Fraction, Fraction, Fraction]:
    h, s, v = hsv
    w.say("to_rgb", r"\text{HSV} \to \text{RGB:}")
    i = int(h // 60)
    f = h / 60 - i
    p, q, t = v * (1 - s), v * (1 - s * f), v * (1 - s * (1 - f))
    w.add("hsv_i", i, rf"i = \lfloor H / 60 \rfloor = \lfloor {num(h)} / 60 \rfloor = {i}")
    w.add("hsv_f", f, rf"f = H / 60 - i = {num(h)} / 60 - {i} {result(f)}")
    w.add("hsv_p", p, rf"p = V(1 - S) = {num(v)}(1 - {num(s)}) {result(p)}")
    w.add("hsv_q", q, rf"q = V(1 - S f) = {num(v)}(1 - {num(s)} \cdot {num(f)}) {result(q)}")
    w.add("hsv_t", t, rf"t = V(1 - S(1 - f)) = {num(v)}(1 - {num(s)}(1 - {num(f)})) {result(t)}")
    rgb = c.hsv_to_rgb(h, s, v)
    names = ["(V, t, p)", "(q, V, p)", "(p, V, t)", "(p, q, V)", "(t, p, V)", "(V, p, q)"][i]
    w.add("rgb", rgb, rf"(r, g, b) = {names} = {_triple(rgb)} \quad (\text{{sector }} i = {i})")
    return rgb


def _from_hsi(w: _Work, hsi: tuple[Fraction, ...]) -> tuple[Value, Value, Value]:
    h, s, i = hsi
    w.say("to_rgb", r"\text{HSI} \to \text{RGB:}")
    sector, hh = c.hsi_sector(h)
    name, first, nxt, low = [("RG", "r", "g", "b"), ("GB", "g", "b", "r"), ("BR", "b", "r", "g")][
        sector
    ]
    shift = f"H' = H - {120 * sector} = {_deg(hh)}" if sector else f"H' = H = {_deg(hh)}"
    w.say(
        "hsi_sector",
        rf"{120 * sector}^\circ \le H < {120 * sector + 120}^\circ\text{{: the {name} sector, }}{shift}",
    )
    out = c.hsi_to_rgb(h, s, i)
    by = dict(zip("rgb", out, strict=True))
    ratio = c.hsi_ratio(hh)
    w.add(f"rgb_{low}", by[low], rf"{low} = I(1 - S) = {num(i)}(1 - {num(s)}) {result(by[low])}")
    w.add(
        f"rgb_{first}",
        by[first],
        rf"{first} = I\left[1 + \frac{{S \cos H'}}{{\cos(60^\circ - H')}}\right] = {num(i)}[1 + {num(s)} \cdot {num(ratio)}] {result(by[first])}",
    )
    w.add(
        f"rgb_{nxt}",
        by[nxt],
        rf"{nxt} = 3I - ({low} + {first}) = 3 \cdot {num(i)} - ({num(by[low])} + {num(by[first])}) {result(by[nxt])}",
    )
    for v, what in zip(out, "rgb", strict=True):
        if not -1e-9 <= v <= 1 + 1e-9:
            raise InputError(
                f"HSI ({num(h)}, {num(s)}, {num(i)}) lies outside the RGB cube: {what} = {num(v)}",
                "values",
            )
    return out


Given = tuple[list[Quantity], tuple[Value, ...], tuple[int, int, int] | None]
"""A model's given values: their quantities, their RGB in [0, 1] and (from RGB) the channel
levels."""


def given_rgb(w: _Work, values: Sequence[Number]) -> Given:
    """RGB given: its channel levels, normalised to [0, 1] unless on the unit scale."""
    top, unit = w.top, w.unit
    rgb8 = tuple(_level(v, n, top, unit) for v, n in zip(values, "RGB", strict=True))
    given = [worked(n, normalize(v), f"{n} = {num(v)}") for n, v in zip("RGB", rgb8, strict=True)]
    if unit:
        return given, rgb8, None
    rgb = tuple(v / top for v in rgb8)
    for n, v8, v in zip("RGB", rgb8, rgb, strict=True):
        w.add(f"rgb_{n.lower()}", v, rf"{n.lower()} = {n} / {top} = {num(v8)} / {top} {result(v)}")
    return given, rgb, (int(rgb8[0]), int(rgb8[1]), int(rgb8[2]))


def given_grey(w: _Work, values: Sequence[Number]) -> Given:
    """A grey level given: r = g = b."""
    top, unit = w.top, w.unit
    y = _level(values[0], "Y", top, unit)
    v = y if unit else y / top
    w.say("to_rgb", r"\text{grey} \to \text{RGB: a grey has } r = g = b")
    w.add(
        "rgb",
        (v, v, v),
        (r"r = g = b = Y " if unit else rf"r = g = b = Y / {top} = {num(y)} / {top} ") + result(v),
    )
    return [worked("Y", normalize(y), f"Y = {num(y)}")], (v, v, v), None


def _given(
    names: str, parsed: tuple[Fraction, ...], to_rgb: Callable[..., tuple[Value, ...]], w: _Work
) -> Given:
    given = [worked(n, normalize(v), f"{n} = {num(v)}") for n, v in zip(names, parsed, strict=True)]
    return given, to_rgb(w, parsed), None


def given_cmy(w: _Work, values: Sequence[Number]) -> Given:
    """CMY given: each in [0, 1]."""
    parsed = tuple(_unit(Fraction(v), n) for v, n in zip(values, "CMY", strict=True))
    return _given("CMY", parsed, _from_cmy, w)


def _hue_given(names: str, values: Sequence[Number]) -> tuple[Fraction, ...]:
    """A hue in degrees, then two values in [0, 1]."""
    return (_hue(values[0]), _unit(values[1], names[1]), _unit(values[2], names[2]))


def given_hsv(w: _Work, values: Sequence[Number]) -> Given:
    """HSV given."""
    return _given("HSV", _hue_given("HSV", values), _from_hsv, w)


def given_hsi(w: _Work, values: Sequence[Number]) -> Given:
    """HSI given."""
    return _given("HSI", _hue_given("HSI", values), _from_hsi, w)


Rgb = tuple[Fraction, Fraction, Fraction]
"""RGB in [0, 1], exact from every model but HSI, whose RGB may be floats (the formulas take
either)."""


def _same(w: _Work, rgb: Rgb) -> tuple[Value, ...]:
    """RGB as a target: the hub every conversion goes through, nothing more to work."""
    return rgb


def _to_grey(w: _Work, rgb: Rgb) -> tuple[Value, ...]:
    """The grey levels on the RGB input scale."""
    return _grey(w, tuple(v if w.unit else v * w.top for v in rgb), w.scale)


class ColorModel(NamedTuple):
    """One colour model's part of a conversion, named by its method record (``color/cmy``'s
    ``spec``): its name in the working, its component count, its row label in the results,
    how its given values become RGB (:data:`Given`), how RGB becomes it, and the note an
    answer with it adds (``noted``: when it is given or a target, or only as a target)."""

    name: str
    components: int
    label: str
    given: Callable[[_Work, Sequence[Number]], Given]
    convert: Callable[[_Work, Rgb], tuple[Value, ...]]
    note: str = ""
    noted: str = "any"


RGB = ColorModel("RGB", 3, "RGB (r, g, b)", given_rgb, _same)
CMY = ColorModel("CMY", 3, "CMY", given_cmy, _to_cmy)
HSV = ColorModel("HSV", 3, "HSV (H deg, S, V)", given_hsv, _to_hsv)
HSI = ColorModel(
    "HSI",
    3,
    "HSI (H deg, S, I)",
    given_hsi,
    _to_hsi,
    f"HSI's hue is an arc cosine: it is given to {PLACES} decimals of a degree (~ in a table), "
    "exactly where the angle is a multiple of 30 degrees.",
)
GREY = ColorModel(
    "grey",
    1,
    "grey (average, BT.601)",
    given_grey,
    _to_grey,
    "Two grey levels: the plain average weighs R, G and B alike; BT.601 luma weighs them by "
    "how bright they look (green most, blue least).",
    noted="target",
)

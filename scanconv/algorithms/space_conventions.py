"""The conventions of 3D transformations, projections and visible-surface detection, named and
settable, with presets (the visible-surface ones: :data:`VISIBLE_PRESETS`).

Published answers differ on each, and each changes what is printed:

- ``vectors``: column vectors, ``P' = M·P`` and the composite ``Mn···M1`` (Hearn & Baker,
  Foley), or row vectors, ``P' = P·M`` with every matrix the transpose and the composite
  ``M1···Mn`` (Rogers & Adams);
- ``axes``: right- or left-handed axes (the numbers are the same; the words of a positive
  rotation, and where the viewer stands, are not);
- ``sense``: a positive angle turns y toward z about x, z toward x about y and x toward y about
  z (``standard``, the right-hand rule) or the other way (``reversed``: every matrix with -θ);
- ``oblique``: the ``--angle`` of an oblique projection is the receding angle φ, the angle the
  receding z axis makes with the x axis on the view plane (Hearn & Baker's φ), or the
  projector's angle α with the view plane (``L1 = cot α``, the receding axis then at 45°
  unless ``--receding`` says otherwise);
- ``cop``: the centre of projection at (0, 0, -d) and the view plane z = 0 (``x' = x·d/(z + d)``,
  Rogers & Adams), at (0, 0, d) and the view plane z = 0 (``x' = x·d/(d - z)``, Hearn & Baker's
  z_prp = d, z_vp = 0), or at the origin and the view plane z = d (``x' = x·d/z``, Foley).

>>> resolve(None, {})["cop"], resolve("rogers", {"cop": "origin"})
('plus-d', {'vectors': 'row', 'axes': 'right', 'sense': 'standard', 'oblique-angle': 'receding', 'cop': 'origin'})
"""

from __future__ import annotations

from collections.abc import Mapping

from ..core.checks import InputError

SPACE_KNOBS: dict[str, dict[str, str]] = {
    "vectors": {
        "column": "column vectors, P' = M·P: the composite is Mn···M2·M1",
        "row": "row vectors, P' = P·M: every matrix is the transpose, the composite M1·M2···Mn",
    },
    "axes": {
        "right": "right-handed axes: a positive rotation is counter-clockwise looking from the "
        "positive axis toward the origin",
        "left": "left-handed axes: a positive rotation is clockwise looking from the positive "
        "axis toward the origin (the same matrices)",
    },
    "sense": {
        "standard": "a positive angle turns y toward z about x, z toward x about y, x toward y "
        "about z",
        "reversed": "a positive angle turns z toward y about x, x toward z about y, y toward x "
        "about z (the matrices with -θ)",
    },
    "oblique-angle": {
        "receding": "the oblique angle is the receding angle φ of the z axis on the view plane, "
        "from the x axis",
        "projector": "the oblique angle is the angle α between the projectors and the view "
        "plane: L1 = cot α",
    },
    "cop": {
        "minus-d": "the centre of projection at (0, 0, -d), the view plane z = 0: x' = x·d/(z + d)",
        "plus-d": "the centre of projection at (0, 0, d), the view plane z = 0: x' = x·d/(d - z)",
        "origin": "the centre of projection at the origin, the view plane z = d: x' = x·d/z",
    },
}
"""Every 3D convention, by name: its values and what each means (the first: the default's
when no preset names it)."""

SPACE_PRESETS: dict[str, dict[str, str]] = {
    "hearn-baker": {
        "vectors": "column",
        "axes": "right",
        "sense": "standard",
        "oblique-angle": "receding",
        "cop": "plus-d",
    },
    "foley": {
        "vectors": "column",
        "axes": "right",
        "sense": "standard",
        "oblique-angle": "receding",
        "cop": "origin",
    },
    "rogers": {
        "vectors": "row",
        "axes": "right",
        "sense": "standard",
        "oblique-angle": "receding",
        "cop": "minus-d",
    },
}
"""The conventions of each source."""

SPACE_SOURCES = {
    "hearn-baker": "Hearn & Baker, Computer Graphics, C Version, 2nd ed., ch. 11-12 (column "
    "vectors; perspective with z_prp = d, z_vp = 0)",
    "foley": "Foley, van Dam, Feiner & Hughes, Computer Graphics, 2nd ed., 5.6-5.8 and 6.4 "
    "(column vectors; M_per with the centre at the origin, the plane z = d)",
    "rogers": "Rogers & Adams, Mathematical Elements for Computer Graphics, 2nd ed., ch. 3 "
    "(row vectors [x y z 1][T]; the centre at z = -1/r, the plane z = 0)",
}
"""What each preset's name stands for."""

DEFAULT = "hearn-baker"
"""The preset when none is named."""


# --- visible-surface detection ---------------------------------------------------------------

VISIBLE_PRESETS: dict[str, dict[str, str]] = {
    "hearn-baker": {
        "direction": "into-scene",
        "edge-on": "hidden",
        "handed": "right",
        "depth": "larger-nearer",
        "ties": "keep",
        "clear": "zero",
    },
    "foley": {
        "direction": "into-scene",
        "edge-on": "hidden",
        "handed": "right",
        "depth": "larger-nearer",
        "ties": "replace",
        "clear": "zero",
    },
    "rogers": {
        "direction": "into-scene",
        "edge-on": "visible",
        "handed": "right",
        "depth": "larger-nearer",
        "ties": "keep",
        "clear": "farthest",
    },
}
"""The visible-surface conventions of each source (the knobs of
:data:`scanconv.algorithms.conventions.KNOBS` that apply to ``3d``; ``docs/conventions.md``
says where each value is read and which are uncertain):

- Hearn & Baker: V the viewing direction, a back face when ``V . N > 0``, and with V along -z
  "any polygon ... a back face if ... C <= 0" (edge-on hidden); the depth buffer starts at 0
  (the back clipping plane) and a pixel is written when ``z > depth(x, y)`` (strict: ties keep);
- Foley et al.: back faces by "a nonnegative dot product" of the normal with the vector from
  the centre of projection (edge-on hidden); the z-buffer "initialized to zero" and written
  when ``pz >= ReadZ(x, y)`` ("not farther": ties replace);
- Rogers (*Procedural Elements*): the Roberts test ``E . [VT] < 0`` for a back plane, strict
  (edge-on kept: its edges may show); the z-buffer set to "the minimum z value" and written
  when ``z(x, y) > Zbuffer(x, y)`` (strict).
"""

VISIBLE_SOURCES = {
    "hearn-baker": "Hearn & Baker, Computer Graphics, C Version, 2nd ed., ch. 13",
    "foley": "Foley, van Dam, Feiner & Hughes, Computer Graphics, 2nd ed., 15.2.4 and 15.4",
    "rogers": "Rogers, Procedural Elements for Computer Graphics, 2nd ed., ch. 4",
}
"""What each visible-surface preset's name stands for."""


def visible_preset(convention: str | None) -> tuple[str, dict[str, str]]:
    """The visible-surface preset named ``convention`` (default :data:`DEFAULT`) and its
    values; :class:`InputError` for an unknown name.

    >>> visible_preset("foley")[1]["ties"], visible_preset(None)[0]
    ('replace', 'hearn-baker')
    """
    return _preset(VISIBLE_PRESETS, convention)


def _preset(
    presets: Mapping[str, dict[str, str]], convention: str | None
) -> tuple[str, dict[str, str]]:
    """The preset of ``presets`` named ``convention`` (default :data:`DEFAULT`) and its
    values, or :class:`InputError` naming the choices."""
    name = convention or DEFAULT
    if name not in presets:
        raise InputError(
            f"unknown convention {name!r} (choose from {', '.join(presets)})", "convention"
        )
    return name, presets[name]


def resolve(convention: str | None, given: Mapping[str, str | None]) -> dict[str, str]:
    """The conventions of one answer: an explicit value wins, then the preset's."""
    _, preset = _preset(SPACE_PRESETS, convention)
    out = {}
    for knob, values in SPACE_KNOBS.items():
        value = given.get(knob) or preset[knob]
        if value not in values:
            raise InputError(
                f"unknown {knob} convention {value!r} (choose from {', '.join(values)})", knob
            )
        out[knob] = value
    return out


def convention_notes(
    convention: str | None, used: Mapping[str, str], knobs: tuple[str, ...]
) -> str:
    """The note that names the conventions an answer used (``knobs``: the ones it states).

    >>> print(convention_notes(None, resolve(None, {}), ("vectors",)))
    Conventions (preset hearn-baker: Hearn & Baker, Computer Graphics, C Version, 2nd ed., ch. 11-12 (column vectors; perspective with z_prp = d, z_vp = 0)): vectors = column (column vectors, P' = M·P: the composite is Mn···M2·M1).
    """
    name = convention or DEFAULT
    parts = "; ".join(f"{k} = {used[k]} ({SPACE_KNOBS[k][used[k]]})" for k in knobs)
    return f"Conventions (preset {name}: {SPACE_SOURCES[name]}): {parts}."

"""The Python API: visible-surface detection (``scanconv 3d backface``, ``3d zbuffer``,
``3d warnock``). See :mod:`scanconv._api`.

Faces and polygons are given as numbers, ``x y z`` for each vertex, with the word ``:``
between two of them (as on the command line), or as a sequence of faces, each a sequence of
``(x, y, z)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, Any

from ..core import lazy
from ..core.checks import InputError
from ..core.declare import Arg, Opt
from ..display import answers
from .space import PRESETS
from .values import NumberLike, _choice, _maybe, _number

if TYPE_CHECKING:
    from ..answers.visible import backface as answers_backface
    from ..answers.visible import depthsort as answers_depthsort
    from ..answers.visible import scanline as answers_scanline
    from ..answers.visible import warnock as answers_warnock
    from ..answers.visible import zbuffer as answers_zbuffer
    from ..core.numeric import Number
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_backface = lazy.module("scanconv.answers.visible.backface")
    answers_zbuffer = lazy.module("scanconv.answers.visible.zbuffer")
    answers_depthsort = lazy.module("scanconv.answers.visible.depthsort")
    answers_scanline = lazy.module("scanconv.answers.visible.scanline")
    answers_warnock = lazy.module("scanconv.answers.visible.warnock")

FacesLike = Sequence[NumberLike] | Sequence[Sequence[tuple[NumberLike, NumberLike, NumberLike]]]
"""Faces: flat numbers with ``":"`` between faces, or faces of ``(x, y, z)`` points."""
Vec3Like = tuple[NumberLike, NumberLike, NumberLike]

POLYGONS = Arg(
    "The polygons: x y z of each vertex, ':' between polygons (named A, B, ... in order).",
    "X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3 ... [: ...]",
    kind="coordinate",
)
SIZE = Opt(
    "--size",
    help="The grid, W x H pixels (6x4, or 6 for square; default: the vertices' extent from 0).",
    show_default=False,
)
DEPTH = Opt(
    "--depth",
    help="larger-nearer: a larger z is nearer, z > depth(x, y) writes (Hearn & Baker, the "
    "default); smaller-nearer: z < depth(x, y) writes.",
    choices=("larger-nearer", "smaller-nearer"),
    show_default=False,
)
TIES = Opt(
    "--ties",
    help="Equal depths: keep (the polygon drawn first keeps the pixel: hearn-baker, rogers) or "
    "replace (foley).",
    choices=("keep", "replace"),
    show_default=False,
)
CONVENTION = Opt(
    "--convention",
    help="The conventions of a text: hearn-baker (default), foley or rogers; an option below "
    "overrides one of them.",
    choices=PRESETS,
    show_default=False,
)


def _vec(v: Vec3Like | None, param: str) -> tuple[Number, Number, Number] | None:
    if v is None:
        return None
    if isinstance(v, str) or len(v) != 3:
        raise InputError(f"{param} takes 3 numbers (x y z), got {v!r}", param)
    return (_number(v[0], param), _number(v[1], param), _number(v[2], param))


def _values(faces: FacesLike | None, param: str) -> list[Any]:
    """The faces' numbers exact (``":"`` kept), a face of points as a face of exact points."""
    out: list[Any] = []
    given: Sequence[Any] = faces or ()
    for v in given:
        if isinstance(v, str) and v.strip() == ":":
            out.append(":")
        elif isinstance(v, tuple | list) and v and isinstance(v[0], tuple | list):
            out.append([tuple(_number(c, param) for c in p) for p in v])
        elif isinstance(v, tuple | list):  # one point
            out.append(tuple(_number(c, param) for c in v))
        else:
            out.append(_number(v, param))
    return out


Direction = Annotated[
    str | None,
    Opt(
        "--direction",
        help="into-scene: V from the viewer into the scene, back face when V.N > 0 (Hearn & "
        "Baker, the default); to-viewer: V toward the viewer, back face when V.N < 0.",
        choices=("into-scene", "to-viewer"),
        show_default=False,
    ),
]

EdgeOn = Annotated[
    str | None,
    Opt(
        "--edge-on",
        help="A face with V.N = 0: hidden (hearn-baker's C <= 0, foley's V.N >= 0) or visible "
        "(rogers: a back plane only when V.N is strictly of the back sign).",
        choices=("hidden", "visible"),
        show_default=False,
    ),
]

Handed = Annotated[
    str | None,
    Opt(
        "--handed",
        help="right (the default): the viewer on +z looking along -z; left: looking along +z "
        "(Hearn & Baker's left-handed viewing system).",
        choices=("right", "left"),
        show_default=False,
    ),
]
"""The back-face conventions, as ``3d backface`` declares them."""


@answers
def visible_backface(
    faces: Annotated[
        FacesLike | None,
        Arg(
            "The faces: x y z of each vertex, ':' between faces (or give --solid).",
            "[X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3 ... : ...]",
            kind="coordinate",
        ),
    ] = None,
    *,
    solid: Annotated[
        str | None,
        Opt(
            "--solid",
            help="A named solid instead: cube (the unit cube), pyramid (base 0..2 on y = 0, "
            "apex (1, 2, 1)), tetrahedron (the origin and the unit points).",
            choices=("cube", "pyramid", "tetrahedron"),
            show_default=False,
        ),
    ] = None,
    view: Annotated[
        Vec3Like | None,
        Opt(
            "--view",
            metavar="VX VY VZ",
            help="The view vector V (default by --direction and --handed).",
            show_default=False,
        ),
    ] = None,
    eye: Annotated[
        Vec3Like | None,
        Opt(
            "--eye",
            metavar="X Y Z",
            help="The viewer's position instead: V per face, from the eye to V1.",
            show_default=False,
        ),
    ] = None,
    names: Annotated[
        str | None,
        Opt(
            "--names",
            help="The faces' names, separated by commas (default F1, F2, ...).",
            show_default=False,
        ),
    ] = None,
    direction: Direction = None,
    edge_on: EdgeOn = None,
    handed: Handed = None,
    convention: Annotated[str | None, CONVENTION] = None,
) -> Solution:
    """Back-face detection (``scanconv 3d backface``): each face's normal, the view vector, the
    sign of ``V . N`` and the verdict.

    Parameters
    ----------
    faces : numbers or sequence of faces, optional
        ``x y z`` of each vertex with ``":"`` between faces, or faces of ``(x, y, z)``; the
        vertices counter-clockwise seen from outside (right-handed axes).
    solid : {"cube", "pyramid", "tetrahedron"}, optional
        A named solid instead of the faces.
    view : (x, y, z), optional
        The view vector V for every face (default ``(0, 0, -1)`` into the scene,
        right-handed).
    eye : (x, y, z), optional
        The viewer's position: V is worked per face from its first vertex.
    names : str, optional
        The faces' names, separated by commas (``"PQR,QSR,PRS,PSQ"``; default F1, F2, ...).
    direction : {"into-scene", "to-viewer"}, optional
        Which way V points (default ``"into-scene"``: a back face has ``V . N > 0``).
    edge_on : {"hidden", "visible"}, optional
        A face with ``V . N = 0`` (default ``"hidden"``).
    handed : {"right", "left"}, optional
        The axes (default ``"right"``); the default V follows.
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's; ``rogers`` keeps an edge-on face).

    Returns
    -------
    Answer
        The normals worked with their numbers, the table of faces (``V2 - V1``, ``V3 - V1``,
        ``N``, ``V``, ``V . N``, the verdict); ``.data["faces"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-2: ``N = (V2 - V1) x (V3 - V1)``;
    a polygon is a back face when ``V . N > 0``; viewing along -z, when ``C <= 0``.

    Examples
    --------
    >>> sol = visible_backface(solid="cube")
    >>> [(f["name"], f["back"]) for f in sol.data["faces"]][:2]
    [('front', False), ('back', True)]
    >>> visible_backface([0, 0, 0, 1, 0, 0, 0, 1, 0], view=(0, 0, 1)).data["faces"][0]["dot"]
    1
    """
    return answers_backface.backface_solution(
        _values(faces, "faces"),
        solid=_maybe(solid, "solid"),
        view=_vec(view, "view"),
        eye=_vec(eye, "eye"),
        names=None if names is None else _choice(names, "names"),
        conventions={
            "direction": _maybe(direction, "direction"),
            "edge-on": _maybe(edge_on, "edge_on"),
            "handed": _maybe(handed, "handed"),
        },
        convention=_maybe(convention, "convention"),
    )


@answers
def visible_zbuffer(
    polygons: Annotated[FacesLike, POLYGONS],
    *,
    size: Annotated[str | None, SIZE] = None,
    far: Annotated[
        NumberLike | None,
        Opt(
            "--far",
            help="The depth buffer's first value, a number (default: as --clear says).",
            show_default=False,
        ),
    ] = None,
    depth: Annotated[str | None, DEPTH] = None,
    ties: Annotated[str | None, TIES] = None,
    clear: Annotated[
        str | None,
        Opt(
            "--clear",
            help="The depth buffer's first value: zero, the back clipping plane (hearn-baker, "
            "foley), or farthest, -inf (rogers; +inf with smaller-nearer).",
            choices=("zero", "farthest"),
            show_default=False,
        ),
    ] = None,
    convention: Annotated[str | None, CONVENTION] = None,
) -> Solution:
    """The depth-buffer (z-buffer) method on a small grid (``scanconv 3d zbuffer``).

    Parameters
    ----------
    polygons : numbers or sequence of polygons
        ``x y z`` of each vertex with ``":"`` between polygons (A, B, ... in drawing order),
        each planar and not seen edge-on; at most 8, with ``|x|, |y| <= 64``.
    size : str, optional
        The grid ``"WxH"`` (or ``"N"``), at most 32 x 32; default: from 0 to the largest
        vertex coordinates.
    far : number, optional
        The depth buffer's initial value (default: as ``clear`` says).
    depth : {"larger-nearer", "smaller-nearer"}, optional
        Which z is nearer (default ``"larger-nearer"``, Hearn & Baker).
    ties : {"keep", "replace"}, optional
        Equal depths (default ``"keep"``: the first polygon drawn keeps the pixel).
    clear : {"zero", "farthest"}, optional
        The depth buffer's first value: 0, the back clipping plane (default, Hearn & Baker's
        and Foley's), or farther than everything (Rogers'); with ``depth="smaller-nearer"``
        always the farthest.
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's; ``foley``: ties replace).

    Returns
    -------
    Answer
        Each polygon's plane ``Ax + By + Cz + D = 0`` and ``-A/C``; its scan lines from the
        top with the depth down the left edge; the step table of depth comparisons; the final
        frame and depth buffers; ``.data["frame"]``, ``.data["depth"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-3: ``z = (-Ax - By - D)/C``,
    ``z' = z - A/C`` along a scan line, ``z' = z + (A/m + B)/C`` down an edge.

    Examples
    --------
    >>> sol = visible_zbuffer([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 0, 0, 3, 2, 0, 3, 0, 2, 3])
    >>> sol.data["frame"]["0,0"], sol.data["depth"]["0,0"], sol.data["frame"]["2,1"]
    ('B', 3, 'A')
    """
    return answers_zbuffer.zbuffer_solution(
        _values(polygons, "polygons"),
        size=None if size is None else _choice(size, "size"),
        far=None if far is None else _number(far, "far"),
        conventions={
            "depth": _maybe(depth, "depth"),
            "ties": _maybe(ties, "ties"),
            "clear": _maybe(clear, "clear"),
        },
        convention=_maybe(convention, "convention"),
    )


@answers
def visible_warnock(
    polygons: Annotated[FacesLike, POLYGONS],
    *,
    size: Annotated[
        str | None,
        Opt(
            "--size",
            help="The grid's side, 2^n pixels (1 to 32; default: the smallest holding the vertices).",
            show_default=False,
        ),
    ] = None,
    depth: Annotated[str | None, DEPTH] = None,
    ties: Annotated[str | None, TIES] = None,
    convention: Annotated[str | None, CONVENTION] = None,
) -> Solution:
    """Warnock's area subdivision (``scanconv 3d warnock``).

    Parameters
    ----------
    polygons : numbers or sequence of polygons
        ``x y z`` of each vertex with ``":"`` between polygons (A, B, ...), each convex, planar
        and not seen edge-on; at most 8, with ``|x|, |y| <= 64``.
    size : str, optional
        The grid's side, a power of two up to 32 (default: the smallest holding the vertices).
    depth : {"larger-nearer", "smaller-nearer"}, optional
        Which z is nearer (default ``"larger-nearer"``).
    ties : {"keep", "replace"}, optional
        Equal depths at a pixel: the polygon given first (default) or last.
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's; ``foley``: ties replace).

    Returns
    -------
    Answer
        The windows depth first, each polygon's class against each, the decision; the final
        frame; ``.data["windows"]``, ``.data["frame"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-7 (area-subdivision method):
    surrounding, overlapping, inside and outside surfaces; a window is done when all surfaces
    are outside, one is inside, overlapping or surrounding, or a surrounding one obscures
    the others.

    Examples
    --------
    >>> sol = visible_warnock([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 0, 0, 2, 2, 0, 2, 0, 2, 2])
    >>> sol.data["windows"][0]["classes"], sol.data["frame"]["0,0"]
    (['contained', 'contained'], 'B')
    """
    return answers_warnock.warnock_solution(
        _values(polygons, "polygons"),
        size=None if size is None else _choice(size, "size"),
        conventions={"depth": _maybe(depth, "depth"), "ties": _maybe(ties, "ties")},
        convention=_maybe(convention, "convention"),
    )


@answers
def visible_scanline(
    polygons: Annotated[FacesLike, POLYGONS],
    *,
    size: Annotated[str | None, SIZE] = None,
    depth: Annotated[str | None, DEPTH] = None,
    ties: Annotated[str | None, TIES] = None,
    convention: Annotated[str | None, CONVENTION] = None,
) -> Solution:
    """The scan-line method of visible-surface detection (``scanconv 3d scanline``).

    Parameters
    ----------
    polygons : numbers or sequence of polygons
        ``x y z`` of each vertex with ``":"`` between polygons (A, B, ...), each planar and not
        seen edge-on; at most 8, with ``|x|, |y| <= 64``.
    size : str, optional
        The grid ``"WxH"`` (or ``"N"``), at most 32 x 32; default: from 0 to the largest
        vertex coordinates.
    depth : {"larger-nearer", "smaller-nearer"}, optional
        Which z is nearer (default ``"larger-nearer"``).
    ties : {"keep", "replace"}, optional
        Equal depths at a pixel: the polygon given first (default) or last.
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's; ``foley``: ties replace).

    Returns
    -------
    Answer
        The edge table, the polygon table (planes, flags), each scan line's active edges and
        intervals with the flags on and the depths compared; the frame; ``.data["frame"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-4: the edge table, the
    polygon table with an in/out flag per polygon, the active edge list of each scan line, and
    depth calculations only where more than one flag is on.

    Examples
    --------
    >>> sol = visible_scanline([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 1, 0, 2, 4, 0, 2, 4, 3, 2], size="5")
    >>> [sol.data["frame"][f"{x},1"] for x in range(4)]
    ['A', 'A', 'B', 'B']
    """
    return answers_scanline.scanline_solution(
        _values(polygons, "polygons"),
        size=None if size is None else _choice(size, "size"),
        conventions={"depth": _maybe(depth, "depth"), "ties": _maybe(ties, "ties")},
        convention=_maybe(convention, "convention"),
    )


@answers
def visible_depth_sort(
    polygons: Annotated[FacesLike, POLYGONS],
    *,
    size: Annotated[str | None, SIZE] = None,
    depth: Annotated[str | None, DEPTH] = None,
    convention: Annotated[str | None, CONVENTION] = None,
) -> Solution:
    """The depth-sort (painter's) method (``scanconv 3d depth-sort``).

    Parameters
    ----------
    polygons : numbers or sequence of polygons
        ``x y z`` of each vertex with ``":"`` between polygons (A, B, ...), each convex,
        planar and not seen edge-on; at most 8, with ``|x|, |y| <= 64``.
    size : str, optional
        The grid the frame is painted on, ``"WxH"`` (or ``"N"``), at most 32 x 32.
    depth : {"larger-nearer", "smaller-nearer"}, optional
        Which z is nearer (default ``"larger-nearer"``, the viewer on +z).
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's; the three agree on depth).

    Returns
    -------
    Answer
        The polygons by farthest depth, each pair's tests in order until one passes, the
        painting order (a cyclic overlap said), the frame; ``.data["painted"]``,
        ``.data["tests"]``, ``.data["frame"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C version*, 2nd ed., §13-5 (Newell, Newell and Sancha):
    a surface S is painted when no overlapping S' fails every test; one that fails them all
    is moved before S, and a surface moved twice means the two must be split.

    Examples
    --------
    >>> sol = visible_depth_sort([0, 0, 1, 4, 0, 1, 0, 4, 1, ":", 1, 1, 3, 5, 1, 3, 1, 5, 3], size="6")
    >>> sol.data["painted"], [t["passed"] for t in sol.data["tests"]]
    (['A', 'B'], ['z'])
    """
    return answers_depthsort.depth_sort_solution(
        _values(polygons, "polygons"),
        size=None if size is None else _choice(size, "size"),
        conventions={"depth": _maybe(depth, "depth")},
        convention=_maybe(convention, "convention"),
    )

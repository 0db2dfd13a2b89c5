"""The Python API: the 3D chapter (``scanconv 3d transform``, ``3d project``). See
:mod:`scanconv._api`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Annotated, Literal

from ..core import lazy
from ..core.declare import Arg, Opt
from ..display import answers
from .values import NumberLike, _number

if TYPE_CHECKING:
    from ..answers.space import project as answers_project
    from ..answers.space import transform as answers_transform3d
    from ..core.records import Solution
else:  # each command's answer module, loaded by its first call
    answers_project = lazy.module("scanconv.answers.space.project")
    answers_transform3d = lazy.module("scanconv.answers.space.transform")

SOLIDS = ("unit-cube", "cube", "pyramid", "tetrahedron")
PRESETS = ("hearn-baker", "foley", "rogers")

WORDS = Arg(
    "The vertices X1 Y1 Z1 ..., then the transformations in the order applied: --translate TX "
    "TY TZ, --scale S or SX SY SZ, --rotate-x/-y/-z A, --rotate-axis X1 Y1 Z1 X2 Y2 Z2 A, "
    "--reflect xy|yz|zx or --reflect plane A B C D (Ax + By + Cz + D = 0), --shear x|y|z A B "
    "(scale, rotate and shear may add --about X Y Z).",
    "X1 Y1 Z1 ... --TRANSFORMATION ARGS ...",
)
SOLID = Opt("--solid", help="A named solid instead of the vertices.", choices=SOLIDS)
CONVENTION = Opt(
    "--convention",
    help="The conventions of a text: hearn-baker (default), foley or rogers.",
    choices=PRESETS,
)
VECTORS = Opt(
    "--vectors",
    help="Column vectors, P' = M.P (default), or row vectors, P' = P.M (the transposes).",
    choices=("column", "row"),
)
AXES = Opt(
    "--axes",
    help="Right-handed axes (default) or left-handed (the same matrices; the words of a "
    "positive rotation change).",
    choices=("right", "left"),
)
SENSE = Opt(
    "--sense",
    help="A positive angle turns y toward z about x (standard, default) or the other way "
    "(reversed).",
    choices=("standard", "reversed"),
)


PARALLEL = Opt(
    "--parallel",
    help="A parallel projection: orthographic (onto --view), oblique, cavalier, cabinet, "
    "isometric, dimetric or trimetric.",
    choices=(
        "orthographic",
        "oblique",
        "cavalier",
        "cabinet",
        "isometric",
        "dimetric",
        "trimetric",
    ),
)
PERSPECTIVE = Opt(
    "--perspective",
    help="A perspective projection: one-point, two-point (turned about y by --angle) or "
    "three-point (turned about y, then x, by --angles).",
    choices=("one-point", "two-point", "three-point"),
)
VIEW = Opt(
    "--view", help="orthographic: the plane, xy (default), yz or zx.", choices=("xy", "yz", "zx")
)
ANGLE = Opt(
    "--angle",
    help="oblique: the receding angle phi (default 45), or the projectors' angle alpha with "
    "--oblique-angle projector; two-point: the turn about y (default 30).",
    metavar="A",
)
RECEDING = Opt(
    "--receding", help="oblique with --oblique-angle projector: phi (default 45).", metavar="PHI"
)
ANGLES = Opt(
    "--angles",
    help="trimetric, three-point: the turns about y and x (default 30 45; 30 30).",
    metavar="PHI THETA",
)
RATIO = Opt(
    "--ratio",
    help="oblique: L1 (default 1/2); dimetric: the z axis's foreshortening (default 1/2).",
)
D = Opt("--d", help="perspective: the distance d of the centre of projection (default 1).")
OBLIQUE = Opt(
    "--oblique-angle",
    help="oblique: --angle is the receding angle phi (default) or the projectors' angle alpha.",
    choices=("receding", "projector"),
)
COP = Opt(
    "--cop",
    help="perspective: the centre at (0, 0, -d) on the plane z = 0, at (0, 0, d) (hearn-baker), "
    "or at the origin with the plane z = d (foley).",
    choices=("minus-d", "plus-d", "origin"),
)


def _given(vectors: str | None, axes: str | None, sense: str | None) -> dict[str, str | None]:
    return {"vectors": vectors, "axes": axes, "sense": sense}


@answers
def transform3d(
    words: Annotated[Sequence[str], WORDS] = (),
    solid: Annotated[str | None, SOLID] = None,
    *,
    convention: Annotated[str | None, CONVENTION] = None,
    vectors: Annotated[Literal["column", "row"] | None, VECTORS] = None,
    axes: Annotated[Literal["right", "left"] | None, AXES] = None,
    sense: Annotated[Literal["standard", "reversed"] | None, SENSE] = None,
) -> Solution:
    """A composite 3D transformation in homogeneous coordinates (``scanconv 3d transform``).

    Parameters
    ----------
    words : str or sequence of str
        The vertices' coordinates ``x1 y1 z1 ...``, then the transformations in the order
        applied, as the command line words them (``"--rotate-z 90 --translate 1 0 0"``).
    solid : {"unit-cube", "cube", "pyramid", "tetrahedron"}, optional
        A named solid instead of the vertices.
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's).
    vectors : {"column", "row"}, optional
        Column vectors ``P' = M·P`` or row vectors ``P' = P·M``.
    axes : {"right", "left"}, optional
        Right- or left-handed axes.
    sense : {"standard", "reversed"}, optional
        The sense of a positive rotation.

    Returns
    -------
    Answer
        Each matrix with its numbers, the composite ``.data["matrix"]`` and the vertices
        after, ``.data["after"]``.

    Notes
    -----
    Hearn & Baker, *Computer Graphics, C Version*, 2nd ed., 11-1 to 11-5
    (:mod:`scanconv.answers.space.transform`).

    Examples
    --------
    >>> sol = transform3d("0 0 0 1 0 0 --rotate-z 90 --translate 0 0 2")
    >>> sol.data["after"]
    [[0, 0, 2], [0, 1, 2]]
    """
    split = words.split() if isinstance(words, str) else [str(w) for w in words]
    return answers_transform3d.transform_solution(
        split, solid, convention, **_given(vectors, axes, sense)
    )


@answers
def project3d(
    words: Annotated[Sequence[str], WORDS] = (),
    solid: Annotated[str | None, SOLID] = None,
    *,
    parallel: Annotated[str | None, PARALLEL] = None,
    perspective: Annotated[str | None, PERSPECTIVE] = None,
    view: Annotated[str | None, VIEW] = None,
    angle: Annotated[str | None, ANGLE] = None,
    receding: Annotated[str | None, RECEDING] = None,
    angles: Annotated[tuple[str, str] | None, ANGLES] = None,
    ratio: Annotated[NumberLike | None, RATIO] = None,
    d: Annotated[NumberLike | None, D] = None,
    convention: Annotated[str | None, CONVENTION] = None,
    vectors: Annotated[Literal["column", "row"] | None, VECTORS] = None,
    axes: Annotated[Literal["right", "left"] | None, AXES] = None,
    sense: Annotated[Literal["standard", "reversed"] | None, SENSE] = None,
    oblique: Annotated[Literal["receding", "projector"] | None, OBLIQUE] = None,
    cop: Annotated[Literal["minus-d", "plus-d", "origin"] | None, COP] = None,
) -> Solution:
    """A parallel or perspective projection of a solid (``scanconv 3d project``).

    Parameters
    ----------
    words : str or sequence of str
        The vertices' coordinates ``x1 y1 z1 ...``, then any transformations applied before
        the projection (as :func:`transform3d` takes them).
    solid : {"unit-cube", "cube", "pyramid", "tetrahedron"}, optional
        A named solid instead of the vertices (its edges are drawn).
    parallel : {"orthographic", "oblique", "cavalier", "cabinet", "isometric", "dimetric", "trimetric"}, optional
        A parallel projection (give it or ``perspective``).
    perspective : {"one-point", "two-point", "three-point"}, optional
        A perspective projection.
    view : {"xy", "yz", "zx"}, optional
        Orthographic only: the plane projected onto (default xy).
    angle : str, optional
        Oblique: the receding angle φ (default 45°), or the projectors' angle α; two-point:
        the turn about y (default 30°).
    receding : str, optional
        Oblique with ``oblique="projector"``: φ (default 45°).
    angles : (str, str), optional
        Trimetric and three-point: the turns about y and x.
    ratio : number, optional
        Oblique: L1; dimetric: the z axis's foreshortening f.
    d : number, optional
        Perspective: the distance of the centre of projection (default 1).
    convention : {"hearn-baker", "foley", "rogers"}, optional
        The conventions of a text (default Hearn & Baker's).
    vectors, axes, sense : str, optional
        As :func:`transform3d`.
    oblique : {"receding", "projector"}, optional
        What an oblique ``angle`` is.
    cop : {"minus-d", "plus-d", "origin"}, optional
        Where the centre of projection is.

    Returns
    -------
    Answer
        The projection matrix ``.data["matrix"]``, the projected vertices
        ``.data["projected"]``, a perspective's ``.data["vanishing_points"]``, and the
        figure of the projected edges.

    Notes
    -----
    Hearn & Baker, 2nd ed., 12-3; Rogers & Adams, *Mathematical Elements for Computer
    Graphics*, 2nd ed., 3-9 to 3-17 (:mod:`scanconv.answers.space.project`).

    Examples
    --------
    >>> sol = project3d(solid="unit-cube", perspective="one-point", d=2, cop="minus-d")
    >>> sol.data["projected"][6], sol.data["vanishing_points"][2]
    ([Fraction(2, 3), Fraction(2, 3)], [0, 0])
    """
    split = words.split() if isinstance(words, str) else [str(w) for w in words]
    return answers_project.project_solution(
        split,
        solid,
        parallel=parallel,
        perspective=perspective,
        view=view,
        angle=angle,
        receding=receding,
        angles=angles,
        ratio=None if ratio is None else _number(ratio, "ratio"),
        d=None if d is None else _number(d, "d"),
        convention=convention,
        cop=cop,
        **{"oblique-angle": oblique},
        **_given(vectors, axes, sense),
    )

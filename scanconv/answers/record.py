"""The method record: what one method of one command has, each piece named as
``"module:attribute"`` and imported on first use, or ``None`` with the reason it is missing
(:mod:`.methods` holds every record; this module, its type and its checks)."""

from typing import TYPE_CHECKING, Any, NamedTuple

from ..core import lazy
from ..core.checks import InputError

if TYPE_CHECKING:
    from ..algorithms import conventions
else:
    conventions = lazy.module("scanconv.algorithms.conventions")  # knobs only

PIECES = (
    "answer",
    "generator",
    "derivation",
    "pseudocode",
    "model",
    "raster",
    "errata",
    "practice",
    "rows",
)
"""The named pieces of a record, each ``"module:attribute"`` or ``None`` (with a reason)."""

STEPPED = ("line", "circle", "ellipse")
"""The commands whose step table is as long as the input makes it: each method of them has a
row estimate (``rows``) and a measured row cost (``cost``), or the record fails at import."""


class Method(NamedTuple):
    """One method of one command, with every piece the layers need (module docstring).

    Built by keyword, ``Method(command=..., name=..., title=..., answer=..., ...)``; every
    record passes :func:`checked` when :data:`METHODS` is built, so a record that lacks a
    piece without saying why fails at import.
    """

    command: str
    """The command (``line``, ``circle``, ``antialias``, ...)."""
    name: str
    """The method's name as ``--algo``/``--method`` and the API's ``method=`` take it."""
    title: str
    """The notes' name for it (what an answer, a practice question and the marking say)."""
    answer: str
    """The answer builder. A stepped command's takes the command's typed question
    (:mod:`.asked`): a line's returns the :class:`~scanconv.core.records.Solution`, a
    circle's the octant's parts (the circle answer adds the 8-way symmetry)."""
    generator: str | None = None
    derivation: str | None = None
    """``(question) -> tuple[Quantity, ...]``: the ``--derive`` working."""
    pseudocode: str | None = None
    """``(question) -> Code``: the ``--algorithm`` listing."""
    model: str | None = None
    """``(question) -> Model``: the follow-through marking model of :mod:`scanconv.marking`
    (a table model of :mod:`scanconv.marking.table_models` for the other commands)."""
    raster: str | None = None
    errata: str | None = None
    """``(question) -> str | None``: the note naming the course notes' mistake for this
    question (``docs/errata.md``), if they make one."""
    practice: str | None = None
    """``(question) -> str``: a practice question's wording (:mod:`scanconv.practice`)."""
    rows: str | None = None
    """``(question) -> int``: the step table's rows, estimated from the question alone (the
    work budget, :mod:`scanconv.render.work`); never much below the rows printed."""
    cost: float = 0.0
    """CPU microseconds of one csv row (the base cost); a format's row costs ``cost`` times
    its :attr:`~scanconv.render.Spec.row_factor` unless :attr:`costs` measures it."""
    costs: tuple[tuple[str, float], ...] = ()
    """CPU microseconds of one table row per output format (``csv``, ``json``, ``plain``,
    ``markdown``, ``latex``, ``html``, ``rich``), measured by ``benchmarks/bench_budget.py``;
    the work budget (:mod:`scanconv.render.work`) multiplies them by the rows. Empty: the
    budget costs the command as a whole (its function's estimate)."""
    missing: tuple[tuple[str, str], ...] = ()
    """``(piece, reason)`` for every piece that is ``None``."""
    answered_as: tuple[str, str] | tuple[()] = ()
    """Its answers' ``(primitive, algorithm)`` when not ``(command, name)``: :func:`answered_by`."""
    short: str = ""
    """The name in a comparison table's heading (``compare``); empty: not compared."""
    facts: tuple[tuple[str, str], ...] = ()
    """What ``compare`` says of it: ``tag`` (its name in a reason tag, ``SDDA twice``),
    ``work`` and ``arithmetic`` (a line method's row of the "Arithmetic per pixel" table,
    ``{maj}``, ``{mnr}`` and ``{d}`` standing for the axes and the minor difference; a line
    method's ``tag`` gives compare line's reason tags, ``SDDA off``/``SDDA repeats``); a
    DDA-family line's (its answer ``line:dda_answer``) ``heading`` (the answer's title) and
    ``steps`` (the TeX of its number of steps, of ``{adx}``, ``{ady}``, ``{longest}``, ``{n}``
    and ``{steps}``; the simple DDA's ``max(|Δx|, |Δy|)`` without one); and where a practice
    topic words its questions from the record (antialias, inside, thickline), ``practice`` (the
    method as the question names it), ``asks`` (what the question asks for) and ``words`` (the
    command-line words that choose it)."""

    spec: str | None = None
    """A command's own record of the method (``module:attribute``), where its answer reads
    more of it than one function: a colour model's name, components and conversions
    (:class:`scanconv.answers.image.color.ColorModel`)."""
    options: tuple[str, ...] = ()
    """The command's options that apply to this method alone (``clip/cyrus-beck``: normals,
    ends): given with another method of the command, they are refused."""
    stage: str | None = None
    """A line clipping method's working against a rectangle, ``(p1, p2, window) ->
    Clipped``: the pipeline's first stage; ``None``: the pipeline does not clip by it."""

    def fact(self, name: str) -> str:
        """One of :attr:`facts` (``""`` if the record states none)."""
        return dict(self.facts).get(name, "")

    @property
    def key(self) -> str:
        return f"{self.command}/{self.name}"

    @property
    def knobs(self) -> tuple[str, ...]:
        """The conventions that apply to this method, by knob name."""
        return tuple(
            n for n, k in conventions.KNOBS.items() if k.applies_to(self.command, self.name)
        )

    def reason(self, piece: str) -> str | None:
        """Why ``piece`` is absent (``None`` when it is there or unexplained)."""
        return dict(self.missing).get(piece)

    def load(self, piece: str) -> Any:
        """The object a piece names, imported now; :class:`InputError` if the method has none.

        >>> from scanconv.answers.methods import method
        >>> method("line", "bresenham").load("generator").__name__
        'bresenham'
        """
        ref = getattr(self, piece)
        if ref is None:
            why = self.reason(piece) or "not available"
            raise InputError(f"{self.command} {self.name} has no {piece}: {why}", "method")
        return lazy.load(ref)


def checked(m: Method) -> Method:
    """``m`` if every piece is there or says why not, each ``"module:attribute"``, and a
    stepped command's method has its row estimate and its base cost; else ``TypeError`` (at
    import: a record cannot be half written).

    >>> checked(Method(command="line", name="x", title="x", answer="m:f"))
    Traceback (most recent call last):
    ...
    TypeError: method record line/x: generator is None and missing gives no reason
    """
    for piece in PIECES:
        ref, why = getattr(m, piece), m.reason(piece)
        if ref is None and not why:
            raise TypeError(f"method record {m.key}: {piece} is None and missing gives no reason")
        if ref is not None and (why or ":" not in ref):
            raise TypeError(
                f"method record {m.key}: {piece} = {ref!r} (not module:attribute, or excused: {why!r})"
            )
    if m.command in STEPPED and (m.rows is None or m.cost <= 0):
        raise TypeError(f"method record {m.key}: a stepped command needs rows and a cost")
    return m


_NO_DERIVATION = "the notes derive no decision parameter for it"
_NO_MODEL = "marked on its pixels and values only (no decision parameter to follow through)"
_NO_RASTER = "no bulk form: the answer is the computation itself"
_NO_ERRATA = "the notes' worked examples of it print what the algorithm gives"
_NO_PRACTICE = "no practice topic draws it"


def plain_method(
    command: str,
    name: str,
    title: str,
    answer: str,
    generator: str | None,
    *,
    raster: str | None = None,
    no_generator: str = "",
    model: str | None = None,
    answered_as: tuple[str, str] | tuple[()] = (),
) -> Method:
    """A method with no derivation or pseudocode (each said why); ``model``: its table model's
    factory (:mod:`scanconv.marking.table_factories`), else why it has none."""
    missing = [
        ("derivation", _NO_DERIVATION),
        ("pseudocode", "the notes give it as prose steps, shown in the working"),
    ]
    if model is None:
        missing.append(("model", _NO_MODEL))
    if raster is None:
        missing.append(("raster", _NO_RASTER))
    if generator is None:
        missing.append(("generator", no_generator))
    missing += [
        ("errata", _NO_ERRATA),
        ("practice", "its practice topic, if any, words it (scanconv.practice.beyond)"),
        ("rows", "its command's work estimate or bound (scanconv.render.work)"),
    ]
    return Method(
        command=command,
        name=name,
        title=title,
        answer=answer,
        generator=generator,
        model=None if model is None else "scanconv.marking.table_factories:" + model,
        answered_as=answered_as,
        raster=raster,
        missing=tuple(missing),
    )

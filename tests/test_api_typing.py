"""The typed public API: the names a type checker sees, the signatures help()
shows, every library error an InputError with ``.param``, the numbers the API takes."""

from __future__ import annotations

import ast
import os
import pydoc
import shutil
import subprocess
import sys
import warnings
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import scanconv
from scanconv import _api
from scanconv.algorithms.choices import LineAlgorithmName
from scanconv.core.checks import InputError, check_integer

ROOT = Path(__file__).resolve().parent.parent

SNIPPET = """\
import scanconv
from scanconv import raster

reveal_type(scanconv.line(0, 0, 3, 1))
scanconv.line(0, 0, 3, 1, algoo="dda")
xs, ys = raster.line(0, 0, 3, 1)
reveal_type(scanconv.questions.answer("line 0 0 3 1"))
reveal_type(scanconv.check("a.csv", "line 0 0 3 1"))
scanconv.circle(np.int64(5), (np.float64(0.5), 0))
scanconv.line(2, 2, 10, 6, algo="bresenhm")
scanconv.line(2, 2, 10, 6, algo="bresenham")
raster.polygon([0, 4, 2], [0, 0, 3], rule="nonzero")
"""


@pytest.mark.slow
def test_mypy_sees_the_names_and_refuses_a_misspelt_keyword_or_choice(tmp_path: Path) -> None:
    found = _mypy(tmp_path, "import numpy as np\n" + SNIPPET)
    lines = [text for _, text in found]
    assert lines == [
        'note: Revealed type is "scanconv.display.Answer"',
        'error: Unexpected keyword argument "algoo" for "line"; did you mean "algo"?  [call-arg]',
        'note: "line" defined in "scanconv._api.shapes"',
        'note: Revealed type is "scanconv.display.Answer"',
        'note: Revealed type is "scanconv.display.Answer"',
        # a misspelt choice is a type error (core.choices), the right spelling is not
        'error: Argument "algo" to "line" has incompatible type "Literal[\'bresenhm\']"; '
        f'expected "LineAlgorithm | Literal[{_listed(LineAlgorithmName)}]"  [arg-type]',
    ], found


QUESTIONS = """\
from scanconv.answers.asked import (
    ClipLineQuestion, ClipPolygonQuestion, FillQuestion, ProjectionQuestion,
)

ClipLineQuestion("cohen-sutherland", (0, 0), (1, 1), (0, 0, 4, 4), normals="inward")
ClipPolygonQuestion("weiler-atherton", (0, 0, 4, 0, 0, 4), (1, 1, 3, 3))
FillQuestion("flood", (1, 1), connectivity=8, order="queue")
ProjectionQuestion("cavalier", "projector", "plus-d", -1)
ClipLineQuestion("cohen-sutherlnd", (0, 0), (1, 1), (0, 0, 4, 4))
ClipLineQuestion("cyrus-beck", (0, 0), (1, 1), (0, 0, 4, 4), normals="outwards")
ClipLineQuestion("midpoint-subdivision", (0, 0), (1, 1), (0, 0, 4, 4), stop="edges")
ClipPolygonQuestion("sutherland-hodgmann", (0, 0, 4, 0, 0, 4), (1, 1, 3, 3))
FillQuestion("flod", (1, 1))
FillQuestion("flood", (1, 1), connectivity=6)
FillQuestion("flood", (1, 1), order="heap")
ProjectionQuestion("cavalier", "projectors", "plus-d", 1)
ProjectionQuestion("one-point", "receding", "minus_d", 1)
"""
#: The misspelt choices of QUESTIONS, from its first misspelt line on, one a line.
MISSPELT = ("cohen-sutherlnd", "outwards", "edges", "sutherland-hodgmann", "flod", 6, "heap",
            "projectors", "minus_d")  # fmt: skip


def _mypy(tmp_path: Path, source: str) -> list[tuple[int, str]]:
    """mypy's messages on ``source`` (the project's config, a copy of its cache), each with
    its line number."""
    (tmp_path / "snippet.py").write_text(source, encoding="utf-8")
    # The README's test command runs `mypy` (the project's config) before pytest: a copy of its
    # cache, read with the same config, checks the snippet alone (under a second of CPU) where
    # a cold cache checks scanconv and numpy's stubs again (about 10 s). The config's stricter
    # flags apply to scanconv's own modules only, so the snippet sees what a user's mypy sees.
    # Without that cache (pytest run alone), the run is a cold one: the same result, slower.
    cache = tmp_path / ".mypy_cache"
    if (ROOT / ".mypy_cache").is_dir():
        shutil.copytree(ROOT / ".mypy_cache", cache)
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", str(ROOT / "pyproject.toml"),
         "--cache-dir", str(cache), "--no-error-summary", "snippet.py"],
        cwd=tmp_path, capture_output=True, text=True, timeout=600,
        env={**os.environ, "MYPYPATH": str(ROOT)},
    )  # fmt: skip
    found = []
    for x in done.stdout.splitlines():
        if x.startswith("snippet.py:"):
            _, line, text = x.split(":", 2)
            found.append((int(line), text.strip()))
    assert found or done.returncode == 0, done.stdout + done.stderr
    return found


@pytest.mark.slow
def test_mypy_refuses_a_misspelt_choice_in_each_commands_question(tmp_path: Path) -> None:
    """The questions of clip, fill and 3d project type their choices as Literals (the
    method, each convention, the connectivity): the right spellings pass, each misspelt one is
    an error on its own line naming the value."""
    found = _mypy(tmp_path, QUESTIONS)
    first = (
        QUESTIONS.splitlines().index(
            'ClipLineQuestion("cohen-sutherlnd", (0, 0), (1, 1), (0, 0, 4, 4))'
        )
        + 1
    )
    errors = [(line, text) for line, text in found if text.startswith("error:")]
    assert [line for line, _ in errors] == list(range(first, first + len(MISSPELT))), found
    for (_, text), value in zip(errors, MISSPELT, strict=True):
        assert f"Literal[{value!r}]" in text and "[arg-type]" in text, text


def test_the_questions_own_literals_list_what_the_library_accepts() -> None:
    """The question Literals not in :mod:`scanconv.core.choices` (no API parameter is typed
    by them) against the values the library checks."""
    from typing import get_args

    from scanconv.algorithms.seedfill import CONNECTIVITIES
    from scanconv.algorithms.space_conventions import SPACE_KNOBS
    from scanconv.answers import asked

    assert get_args(asked.Connectivity) == CONNECTIVITIES
    assert get_args(asked.ObliqueAngle) == tuple(SPACE_KNOBS["oblique-angle"])
    assert get_args(asked.CentreOfProjection) == tuple(SPACE_KNOBS["cop"])


def _listed(alias: object) -> str:
    """A ``Literal``'s values as mypy writes them: ``'bresenham', 'dda'``."""
    from typing import get_args

    return ", ".join(repr(v) for v in get_args(alias))


def test_the_line_methods_literal_is_their_enum() -> None:
    """The one choice named beside its enum (a new line method is named in one file): the
    same names in the same order, and each has its method record."""
    from typing import get_args

    from scanconv.algorithms.choices import LineAlgorithm
    from scanconv.answers.methods import methods_of

    assert get_args(LineAlgorithmName) == tuple(a.value for a in LineAlgorithm)
    assert set(get_args(LineAlgorithmName)) == set(methods_of("line"))


def test_the_package_says_it_is_typed_and_its_stub_lists_every_public_name() -> None:
    assert (ROOT / "scanconv" / "py.typed").is_file()
    stub = ast.parse((ROOT / "scanconv" / "__init__.pyi").read_text(encoding="utf-8"))
    listed = next(
        ast.literal_eval(n.value)
        for n in stub.body
        if isinstance(n, ast.Assign) and getattr(n.targets[0], "id", "") == "__all__"
    )
    imported = {a.asname for n in stub.body if isinstance(n, ast.ImportFrom) for a in n.names}
    assert set(listed) == imported | {"__version__"}
    assert set(_api.__all__) | {"check", "raster", "questions"} <= set(listed)
    assert sorted(scanconv.__all__) == sorted(set(listed) - set(scanconv.DEPRECATED))
    for name in scanconv.__all__:
        assert getattr(scanconv, name) is not None, name


def test_raster_is_a_plain_module() -> None:
    from scanconv import raster
    from scanconv.algorithms import raster as bulk

    assert raster.__name__ == "scanconv.raster" and sys.modules["scanconv.raster"] is raster
    assert raster.line is bulk.line and raster is not bulk
    xs, ys = raster.line(0, 0, 3, 1)
    assert list(zip(xs.tolist(), ys.tolist(), strict=True)) == [(0, 0), (1, 0), (2, 1), (3, 1)]


def test_help_says_the_api_returns_an_answer_with_numpydoc_sections() -> None:
    for fn in (scanconv.line, scanconv.circle, scanconv.ellipse):
        text = pydoc.render_doc(fn)
        assert "-> 'Answer'" in text and "-> 'Solution'" not in text
        assert "algoo" not in text and "Parameters\n    ----------" in text
        assert "Returns\n    -------\n    Answer" in text and ">>> " in text
    assert "x1: 'NumberLike'" in pydoc.render_doc(scanconv.line)


def test_every_library_error_is_an_input_error_with_a_param() -> None:
    with pytest.raises(InputError) as err:
        scanconv.circle(-1)
    assert "non-negative" in str(err.value) and hasattr(err.value, "param")
    with pytest.raises(InputError) as err:
        check_integer(Fraction(5, 2), "radius", param="r")
    assert err.value.param == "r"
    with pytest.raises(InputError) as err:
        scanconv.line(0, 0, 3, 1, algo="zzz")
    assert hasattr(err.value, "param")


@pytest.mark.parametrize(
    "value",
    [np.int64(3), np.int32(3), np.float64(3.0), np.float32(3.0), Fraction(3), Decimal("3"), 3.0],
)
def test_the_api_takes_numpy_scalars_fractions_and_decimals(value: object) -> None:
    assert scanconv.line(0, 0, value, 1).to("csv") == scanconv.line(0, 0, 3, 1).to("csv")  # type: ignore[arg-type]


def test_a_fractional_numpy_float_is_its_decimal() -> None:
    got = scanconv.line(0, 0, np.float64(2.5), 1, algo="dda").to("csv")
    assert got == scanconv.line(0, 0, "5/2", 1, algo="dda").to("csv")


@pytest.mark.parametrize(
    "value",
    [
        float("nan"),
        float("inf"),
        np.float64("nan"),
        np.float64("-inf"),
        Decimal("NaN"),
        Decimal("sNaN"),
        Decimal("Infinity"),
        10**12,
        2**63,
        np.int64(2**62),
        Fraction(10**12, 3),
        True,
    ],
)
def test_nan_infinities_and_huge_values_are_refused_naming_the_parameter(value: object) -> None:
    with pytest.raises(InputError) as err:
        scanconv.line(0, 0, value, 1)  # type: ignore[arg-type]
    assert err.value.param == "x2"


def test_decimal_nan_never_reaches_a_generator(monkeypatch: pytest.MonkeyPatch) -> None:
    from scanconv.algorithms import circles

    reached: list[object] = []
    monkeypatch.setattr(circles, "midpoint", lambda *a, **k: reached.append(a) or iter(()))
    with pytest.raises(InputError):
        scanconv.circle(Decimal("NaN"))
    assert reached == []


def test_line_and_the_retired_line_solution_give_the_same_table() -> None:
    with pytest.warns(DeprecationWarning, match="line_solution is deprecated"):
        old = scanconv.line_solution("bresenham", 2, 2, 10, 6)
    new = scanconv.line(2, 2, 10, 6, layout="textbook")
    assert scanconv.Answer.of(old).to("csv") == new.to("csv")
    assert "line_solution" not in dir(scanconv)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scanconv.line(2, 2, 10, 6)  # the current names never warn


def test_answers_pickle_by_the_api_function() -> None:
    import pickle

    sol = scanconv.line(0, 0, np.int64(5), 2, algo="dda")
    back = pickle.loads(pickle.dumps(sol))
    assert back.to("csv") == sol.to("csv") and back.recipe is not None


def _choice_sources() -> dict[str, tuple[str, ...]]:
    """Each Literal alias of :mod:`scanconv.core.choices` -> the values the library validates
    with: its enum, or the tuple its check reads."""
    from scanconv.algorithms import (
        characters,
        choices,
        circle_choices,
        color,
        coverage,
        cyrus_beck,
        dither,
        inside,
        midpoint_clip,
        process_choices,
        quantize,
        raster,
        sample,
        seedfill,
        subpixel,
        wu,
    )
    from scanconv.algorithms import framebuffer as algorithms_framebuffer
    from scanconv.answers.image import halftone as answers_halftone
    from scanconv.answers.process.antialias import subpixel as answers_subpixel
    from scanconv.answers.process.fill import inside as answers_inside

    enums = {
        "RoundingName": choices.Rounding,
        "TieName": choices.Tie, "StartName": choices.Start, "LineScaleName": choices.LineScale,
        "WuEndsName": choices.WuEnds, "LayoutName": choices.Layout,
        "ConventionName": choices.Convention, "CircleMethodName": circle_choices.CircleMethod,
        "P0Name": circle_choices.P0, "EllipseP0Name": circle_choices.EllipseP0,
        "LoopName": circle_choices.Loop, "XStepName": circle_choices.XStep,
        "UpdateName": circle_choices.Update,
        "LineClipMethodName": process_choices.LineClipMethod,
        "PolygonClipMethodName": process_choices.PolygonClipMethod,
        "AAMethodName": process_choices.AAMethod, "AcrossName": process_choices.Across,
        "SubgridName": process_choices.Subgrid, "DivideName": process_choices.Divide,
        "FillRuleName": process_choices.FillRule, "OrderName": process_choices.Order,
    }  # fmt: skip
    knobs = dither.DITHER_KNOBS
    tuples = {
        "RasterLineName": raster.LINE_ALGORITHMS, "NormalsName": cyrus_beck.NORMALS,
        "ClipEndsName": cyrus_beck.ENDS, "MidpointName": midpoint_clip.MIDPOINTS,
        "MidpointStopName": midpoint_clip.STOPS,
        "FillMethodName": seedfill.METHODS, "InsideRuleName": answers_inside.RULES,
        "BoundaryName": inside.BOUNDARY, "ReconName": quantize.RECON,
        "InputKindName": quantize.INPUTS,
        "OriginName": sample.ORIGINS, "PackingName": characters.PACKINGS,
        "StrokeAlgorithmName": characters.STROKE_ALGORITHMS,
        "ColorModelName": color.MODELS, "CompareName": knobs["compare"],
        "DitherScaleName": knobs["scale"], "DitherBaseName": knobs["base"],
        "DitherCountName": knobs["count"],
        "CellOrderName": dither.CELL_ORDERS,
        "MajorName": algorithms_framebuffer.ADDRESS_KNOBS["major"],
        "RowZeroName": algorithms_framebuffer.ADDRESS_KNOBS["row0"],
        "LevelCountName": answers_halftone.PRINTER_KNOBS["count"],
        "PrinterDotsName": answers_halftone.PRINTER_KNOBS["dots"],
        "KernelName": knobs["kernel"], "ScanOrderName": knobs["order"],
        "ArithmeticName": knobs["arithmetic"], "CarryName": knobs["carry"],
    }  # fmt: skip
    out = {name: tuple(m.value for m in enum) for name, enum in enums.items()}
    out |= {name: tuple(values) for name, values in tuples.items()}
    # the enums' and tables' siblings, checked against each other
    assert set(wu.ENDS) == set(out["WuEndsName"]) and set(coverage.ACROSS) == set(out["AcrossName"])
    assert set(subpixel.SUBGRIDS) == set(out["SubgridName"])
    assert set(answers_subpixel.DIVIDES) == set(out["DivideName"])
    return out


def test_each_literal_choice_lists_what_the_library_accepts() -> None:
    from typing import get_args

    from scanconv.core import choices

    sources = _choice_sources()
    # two choices the library checks inline: each value accepted, a misspelling refused
    inline = {
        "BitOrderName": lambda v: scanconv.line_style(0, 0, 7, 2, "110", bits=v),
        "ColorDepthName": lambda v: scanconv.storage(4, 4, color=v),
    }
    assert sorted(choices.__all__) == sorted(set(sources) | set(inline))
    for name, values in sources.items():
        assert sorted(get_args(getattr(choices, name))) == sorted(values), name
    for name, call in inline.items():
        for value in get_args(getattr(choices, name)):
            call(value)
        with pytest.raises(InputError):
            call("zzz")


STUBTEST = """\
import sys
from mypy import stubtest

# stubtest checks every submodule of each module named, and skips a re-exported name when the
# module defining it is checked: here only the stubs' packages are checked, so each of their
# lazy exports is verified as the runtime loads it (scanconv.line against scanconv._api.shapes)
find = stubtest.build_stubs


def build(modules, options, find_submodules=False):
    checked = find(modules, options)
    for name in [n for n in stubtest._all_stubs if n.startswith("scanconv.") and n not in checked]:
        del stubtest._all_stubs[name]
    return checked


stubtest.build_stubs = build
sys.exit(stubtest.test_stubs(stubtest.parse_options(sys.argv[1:])))
"""


@pytest.mark.slow
def test_the_stubs_agree_with_the_runtime_by_stubtest() -> None:
    # every public package's __init__.pyi against the objects its lazy __getattr__ loads:
    # each name present, each signature (parameters, kinds, defaults) and each __all__ equal;
    # tests/stubtest_allowlist.txt says why each of its entries is inherent to the lazy exports
    allow = ROOT / "tests" / "stubtest_allowlist.txt"
    done = subprocess.run(
        [sys.executable, "-c", STUBTEST, "--concise", "--mypy-config-file",
         str(ROOT / "pyproject.toml"), "--allowlist", str(allow),
         "scanconv", "scanconv._api", "scanconv.questions", "scanconv.raster"],
        cwd=ROOT, capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0 and not done.stdout.strip(), done.stdout + done.stderr


def _public_functions() -> list[tuple[str, object]]:
    """Every public function, by the names the stubs list (and ``scanconv.raster.__all__``)."""
    import importlib
    import inspect

    from scanconv.core.lazy import stub_exports

    found: dict[int, tuple[str, object]] = {}
    for package in ("scanconv", "scanconv._api", "scanconv.questions"):
        module = importlib.import_module(package)
        for name in sorted(stub_exports(package, str(module.__file__))):
            if package == "scanconv" and name in scanconv.DEPRECATED:
                continue
            obj = getattr(module, name)
            if inspect.isfunction(obj):
                found.setdefault(id(obj), (f"{package}.{name}", obj))
    from scanconv import raster

    for name in raster.__all__:
        if inspect.isfunction(obj := getattr(raster, name)):
            found.setdefault(id(obj), (f"scanconv.raster.{name}", obj))
    return sorted(found.values(), key=lambda item: item[0])


def _sections(doc: str) -> dict[str, list[str]]:
    """A numpydoc docstring's sections: title -> its lines."""
    import inspect

    lines = inspect.cleandoc(doc).splitlines()
    out: dict[str, list[str]] = {}
    title = ""
    for i, line in enumerate(lines):
        if i + 1 < len(lines) and lines[i + 1] and set(lines[i + 1]) == {"-"}:
            title = line.strip()
            out[title] = []
        elif title and not set(line) == {"-"}:
            out[title].append(line)
    return out


def test_the_public_functions_are_found_from_the_stubs() -> None:
    names = [name for name, _ in _public_functions()]
    assert len(names) >= 60 and "scanconv.line" in names and "scanconv.raster.line" in names
    assert "scanconv.questions.answer" in names and "scanconv.bresenham" in names
    assert not any("line_solution" in name for name in names)  # deprecated


@pytest.mark.parametrize(
    ("name", "fn"), [pytest.param(name, fn, id=name) for name, fn in _public_functions()]
)
def test_every_public_function_has_numpydoc_parameters_returns_and_examples(
    name: str, fn: object
) -> None:
    import inspect

    assert callable(fn)
    sections = _sections(fn.__doc__ or "")
    missing = {"Returns", "Examples"} - set(sections)
    params = [p.name for p in inspect.signature(fn).parameters.values()]
    if params:
        missing |= {"Parameters"} - set(sections)
    assert not missing, f"{name} has no {', '.join(sorted(missing))} section"
    assert any(line.lstrip().startswith(">>> ") for line in sections["Examples"]), name
    described = {
        word.strip().lstrip("*")
        for line in sections.get("Parameters", [])
        if line and not line[0].isspace() and " : " in line
        for word in line.split(" : ")[0].split(",")
    }
    assert set(params) <= described, f"{name}: {sorted(set(params) - described)} not described"

"""One typed public API (issue 26, item 3): the names a type checker sees, the signatures help()
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
"""


@pytest.mark.slow
def test_mypy_sees_the_public_names_and_refuses_a_misspelt_keyword(tmp_path: Path) -> None:
    (tmp_path / "snippet.py").write_text("import numpy as np\n" + SNIPPET, encoding="utf-8")
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
    lines = [x.split(": ", 1)[1] for x in done.stdout.splitlines() if x.startswith("snippet.py")]
    assert lines == [
        'note: Revealed type is "scanconv.display.Answer"',
        'error: Unexpected keyword argument "algoo" for "line"; did you mean "algo"?  [call-arg]',
        'note: "line" defined in "scanconv._api.shapes"',
        'note: Revealed type is "scanconv.display.Answer"',
        'note: Revealed type is "scanconv.display.Answer"',
    ], done.stdout + done.stderr


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

"""Shared test configuration: the ``--update-golden`` flag and a deterministic environment."""

from __future__ import annotations

import compileall
import os
import shutil
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import settings

# PYTHONDONTWRITEBYTECODE (set on this project's shared machine) made every pytest process,
# each xdist worker included, compile scanconv and rewrite the test modules' asserts anew (8 s
# of CPU a process), and every process a test starts compile scanconv again (0.6 s of CPU a
# ``python -m scanconv``). The tests write compiled files as Python does by default, in the
# ``__pycache__`` folders beside the sources (ignored by git; the site's wheel leaves them out):
# the xdist workers and the processes the tests start inherit the setting, and the first
# process compiles scanconv before any test (:func:`pytest_configure`). The dependencies' own
# compiled files, written by pip at install, are read as they are (a cache of compiled files
# apart, PYTHONPYCACHEPREFIX, made a fresh checkout compile 36 MB of them again: a minute of
# CPU).
ROOT = Path(__file__).resolve().parent.parent
if sys.dont_write_bytecode:
    sys.dont_write_bytecode = False
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)

# typer reads these at import time: plain, 80-column help, no terminal detection games.
os.environ.setdefault("TERM", "dumb")
os.environ["TERMINAL_WIDTH"] = "80"
os.environ["COLUMNS"] = "100"
os.environ.pop("FORCE_COLOR", None)


# No wall-clock deadline anywhere: on a shared machine a cold first call can take any time, and
# timings belong in benchmarks/. The dev profile (the inner loop) runs at most DEV_EXAMPLES
# examples of each property, even of one that asks for more; ci (the README's command) runs
# each test's own count.
DEV_EXAMPLES = 20
settings.register_profile("ci", deadline=None)
settings.register_profile("dev", max_examples=DEV_EXAMPLES, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_configure(config):
    """``pytest -m "not slow"`` (the inner loop) runs the dev profile unless
    ``HYPOTHESIS_PROFILE`` says otherwise. Before collection: the profile's settings are
    what an ``@given`` test without its own ``@settings`` takes when its module is imported.
    The first process (not an xdist worker) compiles scanconv beside its sources: under
    SlipCover no pytest process writes scanconv's compiled files (its importer compiles in
    memory), and every ``python -m scanconv`` a test starts would compile the package."""
    if not hasattr(config, "workerinput"):
        compileall.compile_dir(ROOT / "scanconv", quiet=2)
    if "HYPOTHESIS_PROFILE" not in os.environ and config.option.markexpr == "not slow":
        settings.load_profile("dev")


def pytest_collection_modifyitems(config, items):
    """A test that needs programs outside Python (``@pytest.mark.external``) is slow too, so
    ``pytest -m "not slow"`` is the inner loop. Every other mark is declared where its test
    is defined (``pytestmark`` in the file, a decorator on the test), never here by name
    (tests/test_markers.py). Under the dev profile, a property's own larger example count is
    capped at the profile's (hypothesis reads a test's settings when it runs)."""
    dev = settings.default.max_examples == DEV_EXAMPLES
    for item in items:
        if item.get_closest_marker("external") is not None:  # pdflatex, pandoc, chromium
            item.add_marker(pytest.mark.slow)
        own = getattr(getattr(item, "obj", None), "_hypothesis_internal_use_settings", None)
        if dev and own is not None and own.max_examples > DEV_EXAMPLES:
            item.obj._hypothesis_internal_use_settings = settings(own, max_examples=DEV_EXAMPLES)


def pytest_addoption(parser):
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="Rewrite golden/ files from the current output, then fail so the diff is reviewed.",
    )


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
"""Debian's chromium (the browser tests drive it through Playwright; no browser download)."""


@pytest.fixture(scope="session")
def browser() -> Iterator[Any]:
    """One headless Chromium for the whole session (Playwright's sync API allows one loop:
    every browser test shares it)."""
    if CHROMIUM is None:
        if os.environ.get("CI"):  # as tests/external.py does for pdflatex
            pytest.fail("chromium missing in CI: .ci/run installs Debian's chromium package")
        pytest.skip(
            "no chromium on PATH: the browser tests need Debian's chromium package "
            "(apt-get install chromium; .ci/run installs it)"
        )
    sync_api = pytest.importorskip(
        "playwright.sync_api", reason="playwright is not installed: pip install -e '.[test]'"
    )
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(
            executable_path=CHROMIUM,
            headless=True,
            # nothing could be fetched anyway, but from this machine (the site test serves on
            # 127.0.0.1: tests/test_site_browser.py)
            args=["--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"],
        )
        yield b
        b.close()

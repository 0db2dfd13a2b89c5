"""Shared test configuration: the ``--update-golden`` flag and a deterministic environment."""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from typing import Any

# typer reads these at import time: plain, 80-column help, no terminal detection games.
os.environ.setdefault("TERM", "dumb")
os.environ["TERMINAL_WIDTH"] = "80"
os.environ["COLUMNS"] = "100"
os.environ.pop("FORCE_COLOR", None)


import pytest
from hypothesis import settings

# HYPOTHESIS_PROFILE=dev for a quick inner loop; CI (and the default) keeps each test's own count.
settings.register_profile("ci", settings.default)
settings.register_profile("dev", max_examples=20)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

#: Whole files that are slow (large-input sweeps, subprocess-heavy) or need external programs.
SLOW_FILES = {
    "test_raster.py",
    "test_limits.py",
    "test_fuzz.py",
    "test_golden_flag.py",
    "test_signals.py",
    "test_escaping.py",
    "test_bad_input.py",  # every command x every way of being wrong: 1,700 runs
    "test_files.py",  # every command x every file fault
}
EXTERNAL_FILES = {"test_documents.py", "test_browser.py"}
#: Single slow tests elsewhere: radius sweeps and huge inputs.
SLOW_TESTS = {
    "test_midpoint_equals_bresenham_and_the_nearest_pixel_definition",
    "test_midpoint_equals_bresenham_for_large_radii",
    "test_midpoint_equals_skimage_bresenham",
    "test_a_huge_radius_streams_its_table",
    "test_the_whole_circle_is_closed_without_gaps",
    # exact clipping property tests with their own example counts (13 s together)
    "test_sutherland_hodgman_of_a_convex_polygon_is_the_intersection",
    "test_a_clipped_segment_is_inside_the_window_and_on_the_line",
    "test_sutherland_hodgman_keeps_a_polygon_inside_the_window",
    "test_cohen_sutherland_and_liang_barsky_agree_exactly",
    "test_region_codes_follow_the_tbrl_bits",
}


def pytest_collection_modifyitems(config, items):
    """Mark the slow and external tests, so ``pytest -m "not slow and not external"`` is the
    inner loop (under a minute on 2 cores) while CI runs everything."""
    import pytest

    for item in items:
        name = item.path.name
        if name in SLOW_FILES or getattr(item, "originalname", None) in SLOW_TESTS:
            item.add_marker(pytest.mark.slow)
        if name in EXTERNAL_FILES:
            item.add_marker(pytest.mark.external)
        if item.get_closest_marker("external") is not None:  # pdflatex, pandoc, chromium
            item.add_marker(pytest.mark.slow)


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
            args=["--host-resolver-rules=MAP * ~NOTFOUND"],  # nothing could be fetched anyway
        )
        yield b
        b.close()

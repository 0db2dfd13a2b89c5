"""Shared test configuration: the ``--update-golden`` flag and a deterministic environment."""

from __future__ import annotations

import os

# typer reads these at import time: plain, 80-column help, no terminal detection games.
os.environ.setdefault("TERM", "dumb")
os.environ["TERMINAL_WIDTH"] = "80"
os.environ["COLUMNS"] = "100"
os.environ.pop("FORCE_COLOR", None)


from hypothesis import settings

# HYPOTHESIS_PROFILE=dev for a quick inner loop; CI (and the default) keeps each test's own count.
settings.register_profile("ci", settings.default)
settings.register_profile("dev", max_examples=20)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))

#: Whole files that are slow (large-input sweeps, subprocess-heavy) or need external programs.
SLOW_FILES = {"test_raster.py", "test_limits.py", "test_fuzz.py", "test_golden_flag.py"}
EXTERNAL_FILES = {"test_documents.py", "test_browser.py"}
#: Single slow tests elsewhere: radius sweeps and huge inputs.
SLOW_TESTS = {
    "test_midpoint_equals_bresenham_and_the_nearest_pixel_definition",
    "test_midpoint_equals_bresenham_for_large_radii",
    "test_midpoint_equals_skimage_bresenham",
    "test_a_huge_radius_streams_its_table",
    "test_the_whole_circle_is_closed_without_gaps",
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
            item.add_marker(pytest.mark.slow)


def pytest_addoption(parser):
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="Rewrite golden/ files from the current output, then fail so the diff is reviewed.",
    )

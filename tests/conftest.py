"""Shared test configuration: the ``--update-golden`` flag and a deterministic environment."""

from __future__ import annotations

import os

# typer reads these at import time: plain, 80-column help, no terminal detection games.
os.environ.setdefault("TERM", "dumb")
os.environ["TERMINAL_WIDTH"] = "80"
os.environ["COLUMNS"] = "100"
os.environ.pop("FORCE_COLOR", None)


def pytest_addoption(parser):
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="Rewrite golden/ files from the current output, then fail so the diff is reviewed.",
    )

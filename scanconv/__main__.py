"""``python -m scanconv`` and the ``scanconv`` program (:func:`run`)."""

import gc
import signal
import sys


def run() -> int:
    """The program: :func:`scanconv.cli.main` with ``sys.argv``. A SIGINT that arrives while
    Python is still importing the CLI (before :func:`scanconv.cli.output.catch_signals`
    installs the one-line handlers) ends the process as the signal's default does, quietly,
    instead of printing a ``KeyboardInterrupt`` traceback from the middle of an import."""
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, signal.SIG_DFL)
    gc.disable()  # start-up makes only long-lived objects: main() freezes them, then collects
    from .cli import main

    return main()


if __name__ == "__main__":
    sys.exit(run())

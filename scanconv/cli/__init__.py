"""The ``scanconv`` command line: the only layer that parses flags and prints."""

from .commands import app, main

__all__ = ["app", "main"]

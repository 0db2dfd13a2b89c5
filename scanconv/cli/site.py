"""``scanconv site build DIR``: the static site that answers questions in the browser with
scanconv itself on Pyodide (:mod:`scanconv.site`; hosting it: docs/site.md).

Exit status 2 for a destination that cannot be one (a file, a folder of other files), 1 when
the runtime cannot be fetched or the folder cannot be written; either way no folder, or no
partial one, is left behind.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from ..core import lazy
from ..core.checks import InputError
from .application import app
from .output import fail, note

if TYPE_CHECKING:
    from ..site import build as site_build
    from . import exam
else:  # the site's builder and the exam book: only ``site build`` needs them
    site_build = lazy.module("scanconv.site.build")
    exam = lazy.module("scanconv.cli.exam")

site_app = typer.Typer(
    help="A static site that answers questions in the browser, with nothing to install.",
    add_completion=False,
    rich_markup_mode=None,
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(site_app, name="site")


@site_app.command()
def build(
    folder: Annotated[
        Path,
        typer.Argument(
            metavar="DIR",
            help="The folder to write (new, empty, or a site built before, which is replaced).",
        ),
    ],
    cache: Annotated[
        Path | None,
        typer.Option(
            "--cache",
            metavar="DIR",
            help="Where the Pyodide runtime is kept between builds "
            "(default: $SCANCONV_CACHE, else ~/.cache/scanconv).",
        ),
    ] = None,
) -> None:
    """Write a static site that answers scanconv's questions in the browser.

    The folder holds the pinned Pyodide runtime (fetched once from the npm registry, checked
    and cached), the wheels of scanconv and of the pure-Python packages it needs, the page
    (a question box, a form per command, a link to share a question) and the exam book.
    Serve it with any static host, or locally: python -m http.server -d DIR.
    Example: scanconv site build site
    """
    try:
        built = site_build.build_site(folder, lambda: exam.book(None, "html"), cache=cache)
    except InputError as err:
        fail(" ".join(str(err).split()))
    except site_build.FetchError as err:
        fail(str(err), 1)
    except OSError as err:
        fail(f"cannot write {folder}: {err.strerror or err}", 1)
    note(f"wrote {built.path}: {built.files} files, {built.size / 1e6:.1f} MB")

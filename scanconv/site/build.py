"""Writing the site: a self-contained folder any static host serves (``scanconv site build``).

The folder holds

* ``pyodide/``: the Pyodide runtime, the files of the npm package ``pyodide`` at
  :data:`PYODIDE_VERSION` that a page needs. The package is fetched once from the npm registry
  (:data:`PYODIDE_URL`), checked against :data:`PYODIDE_SHA256` and kept in the cache
  (:func:`cache_dir`); a later build reads the cache and needs no network;
* ``wheels/``: scanconv (the installed source, zipped as a wheel) and the pure-Python
  packages its question and HTML paths import (:data:`DEPENDENCIES`: zipped from the
  installed distributions, so the browser runs the very versions the command line does);
* ``index.html``, ``app.js``, ``worker.mjs``, ``site.css`` (:mod:`scanconv.site.static`),
  ``exam.html`` (the exam book, answered at build time) and ``site.json`` (the manifest:
  the versions and the wheels to load).

A later build replaces a folder only if a build wrote it (:func:`check_destination`): its
``site.json`` is a manifest a build writes and it holds no file a build does not write, so a
folder that merely holds a file named ``site.json``, or a site someone added a ``CNAME`` to, is
refused and left as it is. The folder is written beside its destination under a temporary
name and renamed into place only when complete, so a failure leaves no partial folder, no
temporary one, and an older site untouched.
"""

from __future__ import annotations

import base64
import contextlib
import hashlib
import io
import json
import os
import shutil
import tarfile
import tempfile
import zipfile
from collections.abc import Callable, Iterable
from html import escape
from importlib import metadata, resources
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from .. import __version__
from ..core import lazy
from ..core.checks import InputError

if TYPE_CHECKING:
    from . import forms as site_forms
    from . import page
else:
    site_forms = lazy.module("scanconv.site.forms")
    page = lazy.module("scanconv.site.page")

PYODIDE_VERSION = "314.0.7"
"""The Pyodide release the site runs (Python 3.14; the npm package ``pyodide``)."""

PYODIDE_URL = f"https://registry.npmjs.org/pyodide/-/pyodide-{PYODIDE_VERSION}.tgz"
"""Where the npm registry serves that release (``npm view pyodide@314.0.7 dist.tarball``)."""

PYODIDE_SHA256 = "66b7949e5a0cba2250b586d7e368bf12fb482800748d182c4618254b685ffaa0"
"""The SHA-256 of that tarball: a download that differs is refused."""

RUNTIME_FILES = (
    "pyodide.mjs",
    "pyodide.asm.mjs",
    "pyodide.asm.wasm",
    "python_stdlib.zip",
    "pyodide-lock.json",
)
"""The files of the npm package a page loads (its maps, types and consoles are left out)."""

DEPENDENCIES = ("tabulate", "latex2mathml")
"""The packages the page's Python imports besides scanconv (the question language and the
HTML and JSON renderers need no numpy, typer, rich or pygments)."""

STATIC = ("index.html", "app.js", "worker.mjs", "site.css")
"""The page's own files, in :mod:`scanconv.site.static`."""

MARKER = "site.json"
"""The manifest of a built site (:data:`MANIFEST_KEYS`)."""

MANIFEST_KEYS = ("scanconv", "pyodide", "wheels")
"""The keys of the manifest a build writes: scanconv's and Pyodide's versions (text) and the
wheels' file names (a list of text)."""

MANIFEST_BYTES = 100_000
"""The largest manifest read (a build writes a few hundred bytes)."""

_ZIP_DATE = (2020, 1, 1, 0, 0, 0)
"""The date of every member of a wheel: the same build gives the same bytes."""


class FetchError(Exception):
    """The runtime could not be fetched or did not match its checksum (exit status 1)."""


class Built(NamedTuple):
    """What a build wrote: the folder, its size in bytes and its number of files."""

    path: Path
    size: int
    files: int


def cache_dir() -> Path:
    """Where the fetched runtime is kept: ``$SCANCONV_CACHE``, else
    ``$XDG_CACHE_HOME/scanconv``, else ``~/.cache/scanconv``."""
    if os.environ.get("SCANCONV_CACHE"):
        return Path(os.environ["SCANCONV_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "scanconv"


def _download(url: str) -> bytes:
    import urllib.request

    with urllib.request.urlopen(url, timeout=120) as response:  # the pinned https URL only
        data: bytes = response.read()
    return data


def runtime_archive(cache: Path, fetch: Callable[[str], bytes] = _download) -> bytes:
    """The Pyodide tarball: from the cache if it is there and matches
    :data:`PYODIDE_SHA256`, else fetched from :data:`PYODIDE_URL`, checked and cached (a
    cache that cannot be written is skipped)."""
    cached = cache / f"pyodide-{PYODIDE_VERSION}.tgz"
    try:
        data = cached.read_bytes()
        if hashlib.sha256(data).hexdigest() == PYODIDE_SHA256:
            return data
    except OSError:
        pass
    try:
        data = fetch(PYODIDE_URL)
    except OSError as err:
        raise FetchError(
            f"cannot fetch Pyodide {PYODIDE_VERSION} from {PYODIDE_URL}: {err}"
        ) from None
    digest = hashlib.sha256(data).hexdigest()
    if digest != PYODIDE_SHA256:
        raise FetchError(
            f"{PYODIDE_URL} has SHA-256 {digest}, not the pinned {PYODIDE_SHA256}; refused"
        )
    try:
        cache.mkdir(parents=True, exist_ok=True)
        tmp = cached.with_name(cached.name + f".{os.getpid()}.tmp")
        tmp.write_bytes(data)
        os.replace(tmp, cached)
    except OSError:
        pass
    return data


def _runtime_files(archive: bytes) -> Iterable[tuple[str, bytes]]:
    """The :data:`RUNTIME_FILES` out of the npm tarball (members under ``package/``)."""
    with tarfile.open(fileobj=io.BytesIO(archive), mode="r:gz") as tar:
        for name in RUNTIME_FILES:
            member = tar.extractfile(f"package/{name}")
            if member is None:
                raise FetchError(f"the Pyodide package has no {name}")
            yield name, member.read()


# --- wheels -----------------------------------------------------------------------------------


def _record_hash(data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"sha256={digest}"


def wheel(name: str, version: str, files: Iterable[tuple[str, bytes]]) -> tuple[str, bytes]:
    """A pure-Python wheel of ``files`` (``(path in the wheel, bytes)``): its file name and
    its bytes, with the dist-info's ``METADATA``, ``WHEEL`` and ``RECORD`` added where
    ``files`` has none.

    >>> filename, data = wheel("demo-pkg", "1.0", [("demo/__init__.py", b"x = 1\\n")])
    >>> filename, sorted(zipfile.ZipFile(io.BytesIO(data)).namelist())
    ('demo_pkg-1.0-py3-none-any.whl', ['demo/__init__.py', 'demo_pkg-1.0.dist-info/METADATA', 'demo_pkg-1.0.dist-info/RECORD', 'demo_pkg-1.0.dist-info/WHEEL'])
    """
    stem = f"{name.replace('-', '_')}-{version}"
    info = f"{stem}.dist-info"
    members = dict(files)
    members.setdefault(
        f"{info}/METADATA", f"Metadata-Version: 2.1\nName: {name}\nVersion: {version}\n".encode()
    )
    members.setdefault(
        f"{info}/WHEEL",
        b"Wheel-Version: 1.0\nGenerator: scanconv site\nRoot-Is-Purelib: true\nTag: py3-none-any\n",
    )
    record = f"{info}/RECORD"
    members.pop(record, None)
    lines = [f"{path},{_record_hash(data)},{len(data)}" for path, data in sorted(members.items())]
    members[record] = ("\n".join([*lines, f"{record},,"]) + "\n").encode()
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(members):
            zf.writestr(zipfile.ZipInfo(path, _ZIP_DATE), members[path])
    return f"{stem}-py3-none-any.whl", out.getvalue()


def _kept(parts: tuple[str, ...]) -> bool:
    return "__pycache__" not in parts and not parts[-1].endswith((".pyc", ".pyo"))


def scanconv_wheel() -> tuple[str, bytes]:
    """scanconv's wheel, from the package as installed (its modules, stubs and data)."""
    root = Path(__file__).resolve().parent.parent
    files = [
        (str(Path("scanconv", *p.relative_to(root).parts).as_posix()), p.read_bytes())
        for p in sorted(root.rglob("*"))
        if p.is_file() and _kept(p.relative_to(root).parts)
    ]
    return wheel("scanconv", __version__, files)


def dependency_wheel(name: str) -> tuple[str, bytes]:
    """The wheel of an installed pure-Python distribution, from its installed files.

    Raises :class:`FetchError` if it is not installed or holds compiled code.
    """
    try:
        dist = metadata.distribution(name)
    except metadata.PackageNotFoundError:
        raise FetchError(f"{name} is not installed (pip install {name})") from None
    if dist.files is None:
        raise FetchError(f"{name}'s installed files are not listed (no RECORD); pip install it")
    files = []
    for entry in dist.files:
        parts = Path(entry).parts
        if not parts or parts[0] == ".." or not _kept(parts):
            continue  # scripts outside site-packages, caches
        if parts[-1].endswith((".so", ".pyd", ".dylib")):
            raise FetchError(f"{name} has compiled code ({entry}); the site needs pure Python")
        files.append((Path(entry).as_posix(), Path(str(dist.locate_file(entry))).read_bytes()))
    if not any(path.endswith(".py") for path, _ in files):
        raise FetchError(f"{name} has no Python modules among its installed files")
    return wheel(dist.metadata["Name"], dist.version, files)


# --- the page ---------------------------------------------------------------------------------


def index_html() -> str:
    """The page: the question box, the examples and a form per command."""
    template = (resources.files(__package__) / "static" / "index.html").read_text("utf-8")
    examples = " ".join(f'<a class="sc-example" href="#">{escape(q)}</a>' for q in page.EXAMPLES)
    fills = {
        "{version}": escape(__version__),
        "{pyodide}": PYODIDE_VERSION,
        "{examples}": examples,
        "{forms}": site_forms.forms(),
    }
    for key, value in fills.items():
        template = template.replace(key, value)
    return template


def site_files(exam_html: str, archive: bytes) -> Iterable[tuple[str, bytes]]:
    """Every file of the site, by its path in the folder."""
    wheels = [scanconv_wheel(), *(dependency_wheel(name) for name in DEPENDENCIES)]
    for name, data in _runtime_files(archive):
        yield f"pyodide/{name}", data
    for filename, data in wheels:
        yield f"wheels/{filename}", data
    static = resources.files(__package__) / "static"
    for name in STATIC:
        if name == "index.html":
            yield name, index_html().encode()
        else:
            yield name, (static / name).read_bytes()
    yield "exam.html", exam_html.encode()
    manifest = {
        "scanconv": __version__,
        "pyodide": PYODIDE_VERSION,
        "wheels": [filename for filename, _ in wheels],
    }
    yield MARKER, (json.dumps(manifest, indent=1) + "\n").encode()


def check_destination(dest: Path) -> None:
    """Refuse (:class:`~scanconv.core.checks.InputError`, exit 2) a destination that is a
    file, the current folder (or a folder holding it), or a folder with files in it that a
    build did not write (:func:`foreign_entries`)."""
    if dest.is_symlink():
        raise InputError(f"{dest}: is a symbolic link; give the folder it names")
    if dest.exists() and not dest.is_dir():
        raise InputError(f"{dest}: is a file; give a folder for the site")
    if not dest.is_dir():
        return
    here = Path.cwd().resolve()
    if dest.resolve() == here or dest.resolve() in here.parents:
        raise InputError(
            f"{dest}: is the current folder (or holds it), which a build would replace; "
            "run it from another folder"
        )
    if not any(dest.iterdir()):
        return
    wheels = manifest_wheels(dest)
    if wheels is None:
        raise InputError(
            f"{dest}: is a folder with files and not a scanconv site (no {MARKER} as a build "
            "writes it); give a new or empty folder"
        )
    extra = foreign_entries(dest, wheels)
    if extra:
        shown = ", ".join(extra[:5]) + (f" and {len(extra) - 5} more" if len(extra) > 5 else "")
        raise InputError(
            f"{dest}: a site scanconv built, with files a build does not write ({shown}), "
            "which a build would delete; move them out, or give a new or empty folder"
        )


def manifest_wheels(dest: Path) -> list[str] | None:
    """The wheels named in ``dest``'s manifest, if it is one a build writes (a JSON object
    of exactly :data:`MANIFEST_KEYS`, the versions as text, the wheels as plain file names),
    else ``None``."""
    path = dest / MARKER
    try:
        if path.is_symlink() or not path.is_file() or path.stat().st_size > MANIFEST_BYTES:
            return None
        manifest = json.loads(path.read_bytes())
    except (OSError, ValueError):
        return None
    if not isinstance(manifest, dict) or sorted(manifest) != sorted(MANIFEST_KEYS):
        return None
    wheels = manifest["wheels"]
    texts = (manifest["scanconv"], manifest["pyodide"])
    if not all(isinstance(v, str) for v in texts) or not isinstance(wheels, list):
        return None
    if not all(isinstance(w, str) and _plain_name(w) and w.endswith(".whl") for w in wheels):
        return None
    return wheels


def _plain_name(name: str) -> bool:
    return bool(name) and name not in (".", "..") and "/" not in name and "\\" not in name


def foreign_entries(dest: Path, wheels: Iterable[str]) -> list[str]:
    """The entries of the built site ``dest`` that no build writes (a ``CNAME``, an
    ``.htaccess``, a folder of one's own), by their paths in it, sorted: a build's files are
    :data:`STATIC`, ``exam.html``, :data:`MARKER`, ``pyodide/`` (:data:`RUNTIME_FILES`) and
    ``wheels/`` (the manifest's ``wheels``), each a plain file (not a link) and each folder a
    plain folder. A file of an older build's list that this build leaves out is no loss: the
    check is that nothing else is there."""
    files = {*STATIC, "exam.html", MARKER}
    folders = {"pyodide": set(RUNTIME_FILES), "wheels": set(wheels)}
    extra: list[str] = []
    for entry in sorted(os.scandir(dest), key=lambda e: e.name):
        if entry.name in folders and entry.is_dir(follow_symlinks=False):
            extra += (
                f"{entry.name}/{inner.name}"
                for inner in sorted(os.scandir(entry.path), key=lambda e: e.name)
                if inner.name not in folders[entry.name] or not inner.is_file(follow_symlinks=False)
            )
        elif entry.name not in files or not entry.is_file(follow_symlinks=False):
            extra.append(entry.name + ("/" if entry.is_dir(follow_symlinks=False) else ""))
    return extra


def build_site(
    dest: Path,
    exam_html: Callable[[], str],
    *,
    cache: Path | None = None,
    fetch: Callable[[str], bytes] = _download,
) -> Built:
    """Write the site to ``dest`` (see the module's docstring), all or nothing; ``exam_html``
    gives the exam book's page (called once the destination is known to be writable).

    Bad destination: :class:`~scanconv.core.checks.InputError`; the runtime not fetched:
    :class:`FetchError`; the folder not written: ``OSError``. In every case nothing is left
    at ``dest`` that was not there before.
    """
    check_destination(dest)
    given, dest = dest, Path(os.path.abspath(dest))  # its own name, even written "x/.."
    parent = dest.parent
    tmp = Path(tempfile.mkdtemp(prefix=f".{dest.name}.", suffix=".tmp", dir=parent))
    old: Path | None = None
    try:
        archive = runtime_archive(cache if cache is not None else cache_dir(), fetch)
        size = count = 0
        for path, data in site_files(exam_html(), archive):
            target = tmp / path
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
            size, count = size + len(data), count + 1
        os.chmod(tmp, 0o755)
        if dest.is_dir():
            old = Path(tempfile.mkdtemp(prefix=f".{dest.name}.", suffix=".old", dir=parent))
            os.replace(dest, old)
        os.replace(tmp, dest)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        if old is not None:
            if not dest.exists():
                os.replace(old, dest)  # the older site back in place
            else:
                with contextlib.suppress(OSError):
                    os.rmdir(old)  # the empty name made for it: the older site never moved
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
    return Built(given, size, count)

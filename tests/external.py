"""The programs outside Python that the tests read documents with (pdflatex, pdftotext, pandoc),
each run at most once per document in a pytest run.

Every result is kept under the run's temporary root, keyed by a hash of the program, its
arguments and the whole input: the same exam book typeset by two tests (or by two pytest-xdist
workers) is typeset once. The cache lives only as long as the run's temporary folder (a new
one each run, so never a stale result): ``scratch`` is any folder directly in the run's base
temporary folder (a test's ``tmp_path``, or a ``tmp_path_factory.mktemp`` folder); under xdist
the workers share the folder above theirs. A file lock per key makes a second worker wait for
the first instead of doing the same work.

:func:`typeset_each` compiles many small documents as one (each case on its own pages, in a
group) and only when that batch fails a check compiles the case alone, so that a failure still
names its case and shows its own log.
"""

from __future__ import annotations

import fcntl
import functools
import hashlib
import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import pytest

__all__ = [
    "Typeset",
    "batch",
    "npm_install",
    "overfull",
    "pandoc",
    "pandoc_with_warnings",
    "pdftotext",
    "tool",
    "typeset",
    "typeset_each",
]


def npm_install(where: Path, package: str) -> Path:
    """``package`` (``name@range``) installed with npm into the folder ``where`` (a test's
    temporary one), and its folder under ``node_modules``. Needs node, npm and the registry
    (CI has them): a skip without node or npm, a failure if npm fails."""
    if shutil.which("npm") is None or shutil.which("node") is None:
        pytest.skip(f"npm and node are needed to install and run {package}")
    done = subprocess.run(
        ["npm", "install", "--prefix", str(where), "--no-audit", "--no-fund", package],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, f"npm install {package} failed: {done.stderr[-2000:]}"
    return where / "node_modules" / package.rpartition("@")[0]


def tool(name: str) -> str:
    """The program on PATH; a skip without it (a failure in CI for pdflatex)."""
    found = shutil.which(name)
    if not found:
        if name == "pdflatex" and os.environ.get("CI"):
            pytest.fail("pdflatex missing in CI: .ci/run installs texlive-latex-base")
        pytest.skip(f"{name} not installed (apt-get install texlive-latex-base poppler-utils)")
    return found


@functools.cache
def _pandoc() -> tuple[str, str]:
    """pandoc's path, and its option that turns syntax highlighting off."""
    try:
        import pypandoc

        exe = str(pypandoc.get_pandoc_path())
    except (ImportError, OSError):
        found = shutil.which("pandoc")
        if not found:
            pytest.skip("pandoc not installed (pip install pypandoc_binary)")
        exe = found
    version = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True)
    major, minor = (int(n) for n in re.findall(r"\d+", version.stdout)[:2])
    return exe, "--syntax-highlighting=none" if (major, minor) >= (3, 8) else "--no-highlight"


def _root(scratch: Path) -> Path:
    """The cache folder of this pytest run (shared by its xdist workers)."""
    base = scratch.resolve().parent  # the run's (or this worker's) base temporary folder
    if os.environ.get("PYTEST_XDIST_WORKER") and base.name.startswith("popen-"):
        base = base.parent
    root = base / "external-cache"
    root.mkdir(exist_ok=True)
    return root


def _cached(scratch: Path, key: Sequence[str | bytes], make: Callable[[Path], None]) -> Path:
    """The folder holding what ``make(folder)`` wrote for ``key``, made once per run."""
    digest = hashlib.sha256()
    for part in key:
        data = part.encode("utf-8", "surrogatepass") if isinstance(part, str) else part
        digest.update(len(data).to_bytes(8, "big") + data)
    root = _root(scratch)
    done = root / digest.hexdigest()
    with open(root / f"{done.name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.is_dir():
            work = Path(tempfile.mkdtemp(dir=root, prefix="work-"))
            make(work)
            work.rename(done)  # whole or not at all
    return done


@dataclass(frozen=True)
class Typeset:
    """A pdflatex run: its exit code, the log of its last pass, its folder (``doc.pdf``,
    ``doc.toc``...) and the pages written (``None`` in draft mode)."""

    code: int
    log: str
    folder: Path

    @property
    def pdf(self) -> Path:
        return self.folder / "doc.pdf"

    @property
    def pages(self) -> int | None:
        found = re.search(r"Output written on doc\.pdf \((\d+) pages?", self.log)
        return int(found.group(1)) if found else None


def typeset(scratch: Path, tex: str, *, passes: int = 1, pdf: bool = True) -> Typeset:
    """``tex`` through pdflatex (``-halt-on-error``, batch mode: the log alone), in at most
    ``passes`` passes. A pass whose log asks for no rerun (longtable's widths settled, no
    label changed) in a document without contents ends the runs: one more would set the same
    pages. A pass that is not the last is a draft (no PDF written: it writes the ``.aux`` and
    ``.toc`` the next one reads) when the document has a longtable or contents; and every
    pass is a draft with ``pdf=False`` (no PDF read back)."""
    exe = tool("pdflatex")
    rerun_likely = "\\tableofcontents" in tex or "\\begin{longtable}" in tex

    def one(folder: Path, draft: bool) -> tuple[int, str]:
        proc = subprocess.run(
            [exe, "-halt-on-error", "-interaction=batchmode"]
            + (["-draftmode"] if draft else [])
            + ["doc.tex"],
            cwd=folder,
            capture_output=True,
            timeout=600,
            check=False,
        )
        (folder / "code").write_text(str(proc.returncode))
        return proc.returncode, (folder / "doc.log").read_text(encoding="utf-8", errors="replace")

    def make(folder: Path) -> None:
        (folder / "doc.tex").write_text(tex, encoding="utf-8")
        for n in range(passes):
            last = n == passes - 1
            draft = not pdf or (not last and rerun_likely)
            code, log = one(folder, draft)
            if code or last:
                return
            if "\\tableofcontents" not in tex and "Rerun" not in log:  # settled
                if draft and pdf:
                    one(folder, False)
                return

    folder = _cached(scratch, ["pdflatex", str(passes), str(pdf), tex], make)
    log = (folder / "doc.log").read_text(encoding="utf-8", errors="replace")
    return Typeset(int((folder / "code").read_text()), log, folder)


def overfull(log: str) -> list[float]:
    """How far (pt) each overfull line sticks out past the margin."""
    return [float(v) for v in re.findall(r"Overfull \\hbox \(([\d.]+)pt too wide\)", log)]


def batch(bodies: Sequence[str]) -> str:
    """The bodies one after another, each in a group from a new page (as if alone)."""
    return "\n".join(f"\\clearpage\\begingroup\n{b}\n\\endgroup" for b in bodies)


def typeset_each(
    scratch: Path,
    preamble: str,
    body: str,
    every: Sequence[str],
    check: Callable[[Typeset], None],
    *,
    passes: int = 1,
    pdf: bool = True,
) -> Typeset:
    """``preamble + body + \\end{document}`` checked by ``check`` (which asserts), the cheap
    way: all of ``every`` (the bodies of the cases of a test, ``body`` among them) are
    typeset as one document, each in a group from a new page, and when that compiles and
    passes ``check`` so does each of its cases. Otherwise ``body`` is typeset alone, must
    compile, and ``check`` judges its own log (the failure names the case)."""
    if body in every:
        whole = typeset(
            scratch, preamble + batch(every) + "\n\\end{document}\n", passes=passes, pdf=pdf
        )
        if whole.code == 0:
            try:
                check(whole)
            except AssertionError:
                pass
            else:
                return whole
    alone = typeset(scratch, preamble + body + "\n\\end{document}\n", passes=passes, pdf=pdf)
    assert alone.code == 0, alone.log[-3000:]
    check(alone)
    return alone


def pdftotext(scratch: Path, pdf: Path) -> str:
    """``pdftotext -layout`` of the PDF (table rows kept), pages split by form feeds."""
    exe = tool("pdftotext")
    data = pdf.read_bytes()

    def make(folder: Path) -> None:
        (folder / "in.pdf").write_bytes(data)
        subprocess.run([exe, "-layout", "in.pdf", "out.txt"], cwd=folder, check=True, timeout=120)

    folder = _cached(scratch, ["pdftotext -layout", data], make)
    return (folder / "out.txt").read_text(encoding="utf-8")


def pandoc(scratch: Path, text: str, source: str, target: str = "html", *args: str) -> str:
    """``text`` converted by pandoc from ``source`` to ``target``: its stdout (a failure of
    pandoc fails the test)."""
    return pandoc_with_warnings(scratch, text, source, target, *args)[0]


def pandoc_with_warnings(
    scratch: Path, text: str, source: str, target: str = "html", *args: str
) -> tuple[str, str]:
    """:func:`pandoc`'s stdout and its stderr (the warnings). Syntax highlighting is off:
    loading its definitions took 0.4 of the 0.45 s of CPU of a page, and the HTML is the same
    without it (every golden Markdown page, checked once: its only code blocks are ``text``;
    a code block from user text is still one)."""
    exe, plain_code = _pandoc()

    def make(folder: Path) -> None:
        proc = subprocess.run(
            [exe, "-f", source, "-t", target, plain_code, *args],
            input=text.encode("utf-8", "surrogatepass"),
            capture_output=True,
            timeout=120,
            check=False,
        )
        assert proc.returncode == 0, proc.stderr.decode(errors="replace")
        (folder / "out").write_bytes(proc.stdout)
        (folder / "err").write_bytes(proc.stderr)

    folder = _cached(scratch, ["pandoc", source, target, *args, text], make)
    return tuple(  # type: ignore[return-value]
        (folder / n).read_text(encoding="utf-8") for n in ("out", "err")
    )

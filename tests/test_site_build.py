"""``scanconv site build DIR`` without the network: its bad input (exit 2), its failures
(exit 1), the runtime's cache and checksum, the wheels, and all-or-nothing writing. The real
build and the site in a browser: tests/test_site_browser.py."""

from __future__ import annotations

import hashlib
import io
import json
import tarfile
import zipfile
from pathlib import Path

import pytest

from scanconv.site import build
from scanconv.site.build import FetchError, build_site, runtime_archive
from scanconv.site.page import solve_page

from .helpers import assert_refused, run


def _fake_runtime() -> bytes:
    """An npm-style tarball holding the runtime's files (their bytes are their names)."""
    out = io.BytesIO()
    with tarfile.open(fileobj=out, mode="w:gz") as tar:
        for name in build.RUNTIME_FILES:
            data = name.encode()
            info = tarfile.TarInfo(f"package/{name}")
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return out.getvalue()


@pytest.fixture
def fake_runtime(monkeypatch: pytest.MonkeyPatch) -> bytes:
    """The fake tarball, pinned as the runtime in place of the real one."""
    data = _fake_runtime()
    monkeypatch.setattr(build, "PYODIDE_SHA256", hashlib.sha256(data).hexdigest())
    return data


def _no_network(url: str) -> bytes:
    raise AssertionError(f"fetched {url}")


def _exam() -> str:
    return "<!DOCTYPE html><title>exam</title>"


def test_a_file_as_the_folder_is_refused(tmp_path: Path) -> None:
    target = tmp_path / "notes.txt"
    target.write_text("mine")
    r = run("site", "build", str(target))
    assert_refused(r, "is a file")
    assert target.read_text() == "mine"


def test_a_folder_of_other_files_is_refused_and_left_alone(tmp_path: Path) -> None:
    (tmp_path / "homework.md").write_text("mine")
    r = run("site", "build", str(tmp_path))
    assert_refused(r, "not a scanconv site")
    assert [p.name for p in tmp_path.iterdir()] == ["homework.md"]


def test_a_missing_parent_is_exit_1_and_writes_nothing(tmp_path: Path) -> None:
    r = run("site", "build", str(tmp_path / "missing" / "site"))
    assert r.code == 1 and r.out == ""
    assert r.err.startswith("scanconv: error: cannot write") and r.err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


def test_unknown_options_are_bad_input(tmp_path: Path) -> None:
    assert_refused(run("site", "build", str(tmp_path / "s"), "--bogus"), "--bogus")
    assert_refused(run("site", "build"), "DIR")


def test_the_runtime_is_read_from_the_cache_without_the_network(
    tmp_path: Path, fake_runtime: bytes
) -> None:
    (tmp_path / f"pyodide-{build.PYODIDE_VERSION}.tgz").write_bytes(fake_runtime)
    assert runtime_archive(tmp_path, _no_network) == fake_runtime


def test_a_fetched_runtime_is_checked_then_cached(tmp_path: Path, fake_runtime: bytes) -> None:
    fetched: list[str] = []

    def fetch(url: str) -> bytes:
        fetched.append(url)
        return fake_runtime

    assert runtime_archive(tmp_path / "cache", fetch) == fake_runtime
    assert fetched == [build.PYODIDE_URL]
    assert fetched[0].startswith("https://registry.npmjs.org/pyodide/-/pyodide-314.0.7.tgz")
    assert runtime_archive(tmp_path / "cache", _no_network) == fake_runtime


def test_a_runtime_with_another_checksum_is_refused_and_not_cached(
    tmp_path: Path, fake_runtime: bytes
) -> None:
    with pytest.raises(FetchError, match="not the pinned"):
        runtime_archive(tmp_path, lambda url: fake_runtime + b"tampered")
    assert list(tmp_path.iterdir()) == []
    # a damaged cache is fetched again
    (tmp_path / f"pyodide-{build.PYODIDE_VERSION}.tgz").write_bytes(b"damaged")
    assert runtime_archive(tmp_path, lambda url: fake_runtime) == fake_runtime


def test_a_failed_fetch_leaves_no_folder(tmp_path: Path) -> None:
    def offline(url: str) -> bytes:
        raise OSError("network is unreachable")

    with pytest.raises(FetchError, match="cannot fetch Pyodide"):
        build_site(tmp_path / "site", _exam, cache=tmp_path / "cache", fetch=offline)
    assert sorted(p.name for p in tmp_path.iterdir()) == []


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_site_from_a_fake_runtime(tmp_path: Path, fake_runtime: bytes) -> None:
    built = build_site(tmp_path / "site", _exam, cache=tmp_path, fetch=lambda url: fake_runtime)
    site = tmp_path / "site"
    names = {p.relative_to(site).as_posix() for p in site.rglob("*") if p.is_file()}
    manifest = json.loads((site / "site.json").read_text())
    assert names == {
        *(f"pyodide/{n}" for n in build.RUNTIME_FILES),
        *(f"wheels/{w}" for w in manifest["wheels"]),
        *build.STATIC,
        "exam.html",
        "site.json",
    }
    assert built.files == len(names)
    assert built.size == sum((site / n).stat().st_size for n in names)
    assert (site / "pyodide/pyodide.asm.wasm").read_bytes() == b"pyodide.asm.wasm"
    assert (site / "exam.html").read_text() == _exam()
    assert [w.split("-")[0] for w in manifest["wheels"]] == ["scanconv", "tabulate", "latex2mathml"]
    with zipfile.ZipFile(site / "wheels" / manifest["wheels"][0]) as wheel:
        members = set(wheel.namelist())
    assert {"scanconv/site/page.py", "scanconv/__init__.pyi", "scanconv/data/exam.txt"} <= members
    assert not any("__pycache__" in m for m in members)
    assert (site / "index.html").read_text().count('class="sc-form"') > 40


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_rebuild_replaces_the_site_and_a_failed_one_keeps_it(
    tmp_path: Path, fake_runtime: bytes, monkeypatch: pytest.MonkeyPatch
) -> None:
    site = tmp_path / "site"
    (tmp_path / f"pyodide-{build.PYODIDE_VERSION}.tgz").write_bytes(fake_runtime)
    build_site(site, _exam, cache=tmp_path, fetch=_no_network)
    (site / "index.html").unlink()  # a file a build writes, missing: no loss to replace it
    build_site(site, lambda: "<p>new</p>", cache=tmp_path, fetch=_no_network)
    assert (site / "exam.html").read_text() == "<p>new</p>"
    assert (site / "index.html").is_file()

    def broken(exam_html: str, archive: bytes):  # type: ignore[no-untyped-def]
        yield "index.html", b"half"
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(build, "site_files", broken)
    with pytest.raises(OSError):
        build_site(site, lambda: "<p>newer</p>", cache=tmp_path, fetch=_no_network)
    assert (site / "exam.html").read_text() == "<p>new</p>"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [site.name, f"pyodide-{build.PYODIDE_VERSION}.tgz"]
    )


# --- what a build may replace (attack report N3, N10) -----------------------------------------


def _tree(folder: Path) -> dict[str, bytes | None]:
    """Every entry under ``folder`` by its path: a file's bytes, a folder's ``None``."""
    return {
        p.relative_to(folder).as_posix(): (p.read_bytes() if p.is_file() else None)
        for p in sorted(folder.rglob("*"))
    }


@pytest.fixture
def cached(tmp_path: Path, fake_runtime: bytes) -> Path:
    """A cache holding the fake runtime (a build from it needs no network)."""
    cache = tmp_path / "cache"
    cache.mkdir()
    (cache / f"pyodide-{build.PYODIDE_VERSION}.tgz").write_bytes(fake_runtime)
    return cache


@pytest.fixture
def built(tmp_path: Path, cached: Path) -> Path:
    """A site a build wrote, from the fake runtime."""
    site = tmp_path / "site"
    build_site(site, _exam, cache=cached, fetch=_no_network)
    return site


MANIFESTS = {
    "an empty object": "{}\n",
    "another program's settings": '{"name": "my-thesis", "theme": "dark"}\n',
    "a build's keys and one more": '{"scanconv": "1", "pyodide": "2", "wheels": [], "x": 1}',
    "a wheel outside the folder": '{"scanconv": "1", "pyodide": "2", "wheels": ["../t.whl"]}',
    "not JSON": "site: yes\n",
}


@pytest.mark.parametrize("name", MANIFESTS)
def test_a_folder_with_a_site_json_a_build_did_not_write_is_refused_and_left_alone(
    tmp_path: Path, cached: Path, name: str
) -> None:
    """attack-report N3: a folder holding any file named site.json was emptied."""
    proj = tmp_path / "proj"
    (proj / "chapters").mkdir(parents=True)
    (proj / "site.json").write_text(MANIFESTS[name])
    (proj / "thesis.tex").write_text("my precious thesis")
    (proj / "chapters" / "1.tex").write_text("ch1")
    before = _tree(proj)
    r = run("site", "build", str(proj), "--cache", str(cached))
    assert_refused(r, "not a scanconv site")
    assert _tree(proj) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cache", "proj"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_built_site_is_rebuilt(tmp_path: Path, cached: Path, built: Path) -> None:
    (built / "exam.html").write_text("older")
    r = run("site", "build", str(built), "--cache", str(cached))
    assert r.code == 0, r.err
    assert r.err.startswith(f"scanconv: wrote {built}: ")
    assert (built / "exam.html").read_text() != "older"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cache", "site"]


ADDED = {  # what a user adds to a built site, and how the refusal names it
    "CNAME": ("CNAME", "CNAME"),
    ".htaccess": (".htaccess", ".htaccess"),
    "a folder of one's own": ("extra/notes.md", "extra/"),
    "a file among the wheels": ("wheels/mine.whl", "wheels/mine.whl"),
    "a file among the runtime's": ("pyodide/custom.js", "pyodide/custom.js"),
}


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("name", ADDED)
def test_a_built_site_with_a_file_a_build_does_not_write_is_refused_naming_it(
    tmp_path: Path, cached: Path, built: Path, name: str
) -> None:
    path, shown = ADDED[name]
    (built / path).parent.mkdir(exist_ok=True)
    (built / path).write_text("mine")
    before = _tree(built)
    r = run("site", "build", str(built), "--cache", str(cached))
    assert_refused(r, f"files a build does not write ({shown})", "would delete")
    assert _tree(built) == before


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_link_in_a_built_site_is_refused(tmp_path: Path, cached: Path, built: Path) -> None:
    """A build writes plain files: a link where one of them was is not the build's."""
    (built / "exam.html").unlink()
    (built / "exam.html").symlink_to(tmp_path / "cache")
    r = run("site", "build", str(built), "--cache", str(cached))
    assert_refused(r, "files a build does not write (exam.html)")
    linked = tmp_path / "linked"
    linked.symlink_to(built)
    assert_refused(run("site", "build", str(linked), "--cache", str(cached)), "symbolic link")
    assert (built / "exam.html").is_symlink() and (tmp_path / "cache").is_dir()


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_building_into_the_current_folder_is_refused_and_leaves_nothing(
    tmp_path: Path, cached: Path, built: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """attack-report N10: ``site build .`` left an empty ``..XXXXXXXX.old`` folder."""
    before = _tree(tmp_path)
    monkeypatch.chdir(built)
    assert_refused(run("site", "build", ".", "--cache", str(cached)), "current folder")
    monkeypatch.chdir(built / "wheels")
    assert_refused(run("site", "build", "..", "--cache", str(cached)), "current folder")
    assert _tree(tmp_path) == before


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_site_that_cannot_be_moved_aside_leaves_no_temporary_folder(
    tmp_path: Path, cached: Path, built: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import os

    before = _tree(tmp_path)
    real = os.replace

    def busy(src, dst):  # type: ignore[no-untyped-def]
        if Path(src) == built:
            raise OSError(16, "Device or resource busy")
        return real(src, dst)

    monkeypatch.setattr(os, "replace", busy)
    r = run("site", "build", str(built), "--cache", str(cached))
    assert r.code == 1 and r.out == ""
    assert r.err == f"scanconv: error: cannot write {built}: Device or resource busy\n"
    assert _tree(tmp_path) == before


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_page_answers_what_the_cli_answers() -> None:
    question = "ellipse 8 6 --no-grid"
    shown = solve_page("scanconv " + question + " --format json -o x.json")
    assert shown["ok"], shown
    cli = run(*question.split(), "--format", "json")
    assert cli.code == 0 and shown["json"] == cli.out
    html = run(*question.split(), "--format", "html")
    assert shown["html"] == html.out


def test_the_page_words_bad_input_as_the_cli_does() -> None:
    for question in ("line 2 2 10", "circle 0.5", "bezier 0 0 1", "clip line 1 2 3 4"):
        cli = run(*question.split())
        assert cli.code == 2
        shown = solve_page(question)
        assert not shown["ok"]
        assert cli.err == f"scanconv: error: {shown['error']}\n"


def test_a_command_that_needs_numpy_says_so_where_there_is_none(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import sys

    monkeypatch.setitem(sys.modules, "numpy", None)  # as in Pyodide
    shown = solve_page("sample 'x + y' --size 4x4 --levels 4")
    assert shown == {
        "ok": False,
        "error": "this command needs numpy, which the browser's Python does not have: run it "
        "with scanconv on a computer",
    }


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_a_dependency_that_is_not_installed_or_not_pure_python_is_refused(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    with pytest.raises(FetchError, match="is not installed"):
        build.dependency_wheel("no-such-package-scanconv")
    with pytest.raises(FetchError, match="compiled code"):
        build.dependency_wheel("numpy")
    filename, data = build.dependency_wheel("tabulate")
    with zipfile.ZipFile(io.BytesIO(data)) as wheel:
        names = wheel.namelist()
    assert filename.startswith("tabulate-") and "tabulate/__init__.py" in names
    assert not any(n.startswith("../") or "__pycache__" in n for n in names)


def test_a_question_longer_than_a_sheet_line_is_refused_by_the_page() -> None:
    from scanconv.questions.files import MAX_LINE_CHARS
    from scanconv.site.page import solve_page

    got = solve_page("line 2 2 10 6 " + "x" * MAX_LINE_CHARS)
    assert got["ok"] is False and f"at most {MAX_LINE_CHARS:,} characters" in got["error"]


# --- the page's budget (attack report N2) ------------------------------------------------------

BEYOND = {  # refused by the command line in the page's formats: 288 s and 108 s on the page
    "circle 2800000": "csv",
    "line 0 0 1999999 1": "plain or csv",
    "line 0 0 1000000000 1": None,  # no format prints it: the library's words alone
}


@pytest.mark.parametrize("question", BEYOND)
def test_the_page_refuses_beyond_the_budget_before_any_work(question: str) -> None:
    """Counted in calls, with a guard that stops the work (computing the rows is millions of
    calls): the CLI's refusal in html, the library's words, then what prints it."""
    from scanconv import questions

    from .helpers import interpreter_calls

    shown, calls = interpreter_calls(solve_page, question, stop_after=200_000)
    assert calls < 100_000, calls  # the grammar and the estimate, not a row
    assert shown["ok"] is False
    cli = run(*question.split(), "--format", "html")
    assert cli.code == 2 and cli.out == ""
    with pytest.raises(ValueError) as library:
        questions.check_budget(questions.parse(question), "html")
    assert cli.err.startswith(f"scanconv: error: {library.value}")
    ways = BEYOND[question]
    tail = "" if ways is None else f"; scanconv on a computer prints it as {ways}"
    assert shown["error"] == f"{library.value}{tail}"


def test_the_page_checks_json_too() -> None:
    """A question html prints at once but json beyond its budget (the page holds both)."""
    from scanconv import questions

    question = "polygon 0 0 1 0 0 300000"  # html costs 83 us a scan line, json 192
    line = questions.parse(question)
    with pytest.raises(ValueError) as refused:
        questions.check_budget(line, "json")
    questions.check_budget(line, "html")
    assert solve_page(question)["error"].startswith(str(refused.value))

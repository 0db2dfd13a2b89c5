"""The site in a real browser (issue 31, item 1): built once per session with
``scanconv.site.build``, served by a local ``http.server`` thread on 127.0.0.1, and driven in
Debian's headless Chromium through Playwright (the session's ``browser``: tests/conftest.py).

Questions typed into the box (a line, a circle, an ellipse, a Bezier curve, a clipping and a
fill) give the very JSON the command line gives (``--format json``); a form gives the JSON of
the question it stands for; a shared link opens a new page at the same answer (the module's
page is opened at one); the page fits a 390 px phone screen. Every page routes each request:
one outside the site's origin is aborted and recorded, and none may be.

The build needs the Pyodide runtime: from the cache (``~/.cache/scanconv``) or, the first time,
from the npm registry; without either the tests skip and say why.
"""

from __future__ import annotations

import functools
import shlex
import threading
import urllib.parse
from collections.abc import Iterator
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import pytest

from .helpers import run

pytestmark = [pytest.mark.slow, pytest.mark.external]  # chromium, Pyodide

QUESTIONS = (
    "line 2 2 10 6 --algo bresenham",
    "circle 8 --method midpoint",
    "ellipse 8 6",
    "bezier 0 0 1 2 3 3 4 0",
    "clip line 7 9 11 4 --window 4 4 10 8",
    "fill flood 2 0 4 2 2 4 0 2 --seed 2 2",
)

ANSWERED = (
    "(n) => window.scanconvTimings.answers.length >= n && document.body.dataset.state !== 'working'"
)
"""True once the page has shown its n-th answer (or error)."""

LOAD = 600_000
"""Milliseconds a cold page may take to its first answer on a loaded machine (not a timing
check: only how long to wait before calling it broken)."""


@pytest.fixture(scope="session")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site, built once for the session."""
    from scanconv.cli.exam import book
    from scanconv.site.build import FetchError, build_site

    folder = tmp_path_factory.mktemp("site") / "site"
    try:
        build_site(folder, lambda: book(None, "html"))
    except FetchError as err:
        pytest.skip(f"no Pyodide runtime in the cache and none fetched: {err}")
    return folder


class _Quiet(SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


@pytest.fixture(scope="session")
def origin(site: Path) -> Iterator[str]:
    """The site served on 127.0.0.1 by a thread, as ``http://127.0.0.1:PORT/``."""
    server = ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=site))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_port}/"
    server.shutdown()
    server.server_close()


class Site:
    """A page of the site, with every request it made and every one aborted."""

    def __init__(self, browser: Any, origin: str, hash: str = "", width: int = 1280) -> None:
        self.origin = origin
        self.page = browser.new_page(viewport={"width": width, "height": 900})
        self.requests: list[str] = []
        self.outside: list[str] = []
        self.errors: list[str] = []
        self.first: tuple[str, str, str | None] = ("", "", None)
        self.page.route("**/*", self._route)
        self.page.on("request", lambda r: self.requests.append(r.url))
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.goto(origin + hash)

    def _route(self, route: Any) -> None:
        url = route.request.url
        if url.startswith(self.origin) or url.startswith(("data:", "blob:", "about:")):
            route.continue_()
        else:
            self.outside.append(url)
            route.abort()

    def answers(self) -> int:
        return int(self.page.evaluate("window.scanconvTimings.answers.length"))

    def wait(self, n: int) -> None:
        self.page.wait_for_function(ANSWERED, arg=n, timeout=LOAD)

    def ask(self, question: str) -> str:
        """Type ``question`` into the box, answer it, and return the JSON shown."""
        n = self.answers()
        self.page.fill("#q", question)
        self.page.click("#go")
        self.wait(n + 1)
        return self.shown()

    def shown(self) -> str:
        assert self.page.evaluate("document.body.dataset.state") == "answered", self.error()
        return str(self.page.text_content("#json"))

    def error(self) -> str:
        return str(self.page.text_content("#error"))

    def close(self) -> None:
        """Check what every page must: nothing outside the origin, no script error."""
        self.page.close()
        assert self.outside == []
        assert all(u.startswith((self.origin, "data:", "blob:", "about:")) for u in self.requests)
        assert self.errors == []


SHARED = "bezier 0 0 1 2 3 3 4 0 --at 0.5"
"""The question of the shared link the module's page is opened at."""


def _link(question: str) -> str:
    """The page's link to ``question`` (``#q=`` and the question as encodeURIComponent has it)."""
    return "#q=" + urllib.parse.quote(question, safe="!~*'()")


@pytest.fixture(scope="module")
def page(browser: Any, origin: str) -> Iterator[Site]:
    """One page for the module's questions (one cold start of Pyodide; a second page for the
    shared link cost another), opened as a shared link is: at :data:`SHARED`'s link, whose
    answer it shows first (kept in ``first``: the question box, the JSON, the link shown)."""
    opened = Site(browser, origin, _link(SHARED))
    opened.wait(1)
    opened.first = (
        opened.page.input_value("#q"),
        opened.shown(),
        opened.page.get_attribute("#share", "href"),
    )
    yield opened
    opened.close()


def _cli_json(question: str) -> str:
    r = run(*shlex.split(question), "--format", "json")
    assert r.code == 0, r.err
    return r.out


@pytest.mark.parametrize("question", QUESTIONS)
def test_a_question_typed_in_the_box_gives_the_cli_json(page: Site, question: str) -> None:
    assert page.ask(question) == _cli_json(question)
    frame = page.page.frame_locator("#answer")
    # the answer's page, its stepper started where it has one
    ready = "section.scanconv[data-ready], section.scanconv:not([data-stepper])"
    frame.locator(ready).first.wait_for()
    assert frame.locator("section.scanconv h2").first.text_content()
    assert page.outside == []


def test_a_form_gives_the_json_of_its_question(page: Site) -> None:
    n = page.answers()
    page.page.click("#forms summary")
    page.page.select_option("#sc-command", "circle")
    form = page.page.locator('.sc-form[data-command="circle"]')
    form.locator('input[name="r"]').fill("8")
    form.locator('select[name="method"]').select_option("bresenham")
    form.locator('input[name="grid"]').uncheck()
    page.page.click("#form-go")
    page.wait(n + 1)
    assert page.page.input_value("#q") == "circle 8 --method bresenham --no-grid"
    assert page.shown() == _cli_json("circle 8 --method bresenham --no-grid")


def test_bad_input_shows_the_cli_message(page: Site) -> None:
    n = page.answers()
    page.page.fill("#q", "line 2 2 10")
    page.page.click("#go")
    page.wait(n + 1)
    cli = run("line", "2", "2", "10")
    assert cli.code == 2
    assert cli.err == f"scanconv: error: {page.error()}\n"
    assert page.page.is_hidden("#answer")


def test_the_exam_book_is_browsable(browser: Any, origin: str, page: Site) -> None:
    assert page.page.get_attribute("text=The exam book, answered", "href") == "exam.html"
    book = Site(browser, origin, "exam.html", width=390)
    try:
        contents = book.page.locator("nav.sc-contents a")
        assert contents.count() > 30
        contents.nth(5).click()
        assert book.page.evaluate("location.hash") == "#q6"
        assert book.page.locator("#q6").is_visible()
    finally:
        book.close()


def test_the_shared_link_reopens_the_same_answer(page: Site) -> None:
    """The link the page gives for a question, opened in a new page, shows the same answer:
    the module's page was opened at that link (``page``), before any question was typed."""
    expected = page.ask(SHARED)
    link = page.page.get_attribute("#share", "href")
    assert link == _link(SHARED)
    assert page.page.evaluate("location.hash") == link
    assert page.first == (SHARED, expected, link)
    assert expected == _cli_json(SHARED)
    # a phone's screen: the page itself never scrolls sideways
    page.page.set_viewport_size({"width": 390, "height": 900})
    try:
        assert page.page.evaluate("document.documentElement.scrollWidth") <= 390
    finally:
        page.page.set_viewport_size({"width": 1280, "height": 900})


def test_a_long_question_can_be_stopped_and_the_page_answers_again(page: Site) -> None:
    """On the module's page (its Pyodide already loaded: the stop starts a new one), last in
    the module."""
    idle = "['ready', 'answered', 'error'].includes(document.body.dataset.state)"
    page.page.wait_for_function(idle, timeout=LOAD)
    n = page.answers()
    page.page.fill("#q", "circle 100000")  # seconds natively, far longer in WebAssembly
    page.page.click("#go")
    assert page.page.evaluate("document.body.dataset.state") == "working"
    page.page.click("#stop")
    assert page.page.evaluate("document.body.dataset.state") == "loading"
    assert page.page.is_hidden("#stop")
    assert page.ask("line 0 0 3 1 --algo dda") == _cli_json("line 0 0 3 1 --algo dda")
    assert page.answers() == n + 1  # the stopped question never answered

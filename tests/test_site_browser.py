"""The site in a real browser: built once per session with
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


def _open_link(page: Site, hash: str) -> None:
    """Open the link ``hash`` on the page, as a click on a shared link does (a hash change:
    the same code as a page opened at it), and wait for its answer or its error."""
    n = page.answers()
    page.page.evaluate("(h) => { location.hash = h; }", hash)
    page.wait(n + 1)


def test_a_shared_link_beyond_the_budget_is_refused_with_the_cli_message(page: Site) -> None:
    """attack-report N2: ``#q=circle%202800000`` tied up the tab for two minutes and ended in
    an empty "scanconv failed:". The refusal is the library's, before any work (the wait is
    a hang guard, not a timing)."""
    from scanconv import questions
    from scanconv.site.page import solve_page

    _open_link(page, "#q=circle%202800000")
    assert page.page.evaluate("document.body.dataset.state") == "error"
    with pytest.raises(ValueError) as refused:
        questions.check_budget(questions.parse("circle 2800000"), "html")
    shown = page.error()
    assert shown.startswith(f"{refused.value}; scanconv on a computer prints it as csv")
    assert shown == solve_page("circle 2800000")["error"]
    cli = run("circle", "2800000", "--format", "html")
    assert cli.code == 2 and cli.err.startswith(f"scanconv: error: {refused.value}")
    assert page.page.is_hidden("#answer")


def test_a_malformed_share_link_says_so(page: Site) -> None:
    """attack-report N12: an uncaught URIError and no message (``Site.close`` checks that
    no script error happened)."""
    page.page.evaluate("() => { location.hash = '#q=%E0%A4%A'; }")
    page.page.wait_for_selector("#error:not([hidden])")
    assert "This link is malformed" in page.error()
    assert page.page.evaluate("document.body.dataset.state") == "error"
    assert page.errors == []
    assert page.ask("line 0 0 3 1 --algo dda") == _cli_json("line 0 0 3 1 --algo dda")


def test_the_answer_frame_is_sandboxed_and_its_stepper_works(page: Site) -> None:
    """attack-report N14: the answer's page ran with the site's origin. In the sandbox its
    scripts run (the stepper, test yourself) but cannot reach the site's page. After an error
    first: a sandboxed frame hidden for an error and shown again was left blank."""
    _open_link(page, "#q=line%202%202%2010")
    assert page.page.is_hidden("#answer")
    page.ask("line 2 2 10 6")
    assert page.page.get_attribute("#answer", "sandbox") == "allow-scripts"
    frame = page.page.frame_locator("#answer")
    stepper = frame.locator("section.scanconv[data-ready]")
    stepper.wait_for()
    body = frame.locator("body")
    blocked = "() => { try { return parent.document.title; } catch (e) { return e.name; } }"
    assert body.evaluate(blocked) == "SecurityError"
    assert body.evaluate("() => window.origin") == "null"
    start = int(stepper.get_attribute("data-pos") or "0")
    frame.locator("button[data-act=next]").click()
    frame.locator("button[data-act=next]").click()
    assert stepper.get_attribute("data-pos") == str(start + 2)
    assert frame.locator(".sc-stepper output, .sc-stepper [aria-live]").first.text_content()
    frame.locator("button[data-act=end]").click()
    end = int(stepper.get_attribute("data-pos") or "0")
    assert end == 10 - 2 + 1  # the line (2, 2) to (10, 6): a pixel a column, each a step
    frame.locator("button[data-act=reset]").click()
    assert stepper.get_attribute("data-pos") == "0"
    # test yourself: the first step typed and checked in the frame
    frame.locator("[data-selftest]").click()
    frame.locator(".sc-testpanel").wait_for()
    assert frame.locator("[data-selftest]").get_attribute("aria-expanded") == "true"
    # the frame reports its height (this page cannot read it): the whole answer shows
    height = page.page.evaluate("document.getElementById('answer').getBoundingClientRect().height")
    inner = body.evaluate("() => [document.documentElement.scrollHeight, innerHeight]")
    assert height >= inner[0] > 300 and inner[0] <= inner[1]  # no scroll bar of its own


def test_an_error_without_a_last_line_is_not_an_empty_message(page: Site) -> None:
    """attack-report N2: the worker showed "scanconv failed:" and nothing, a Python error's
    text ending with a line end. A worker of the site's own is sent what the page never
    sends (a number for a question), which Python refuses with a TypeError."""
    script = """async () => {
      const worker = new Worker("worker.mjs", { type: "module" });
      const answer = await new Promise((resolve) => {
        worker.onmessage = (event) => {
          if (event.data.type === "ready") worker.postMessage({ id: 1, question: 42 });
          else if (event.data.type === "answer" || event.data.type === "failed") resolve(event.data);
        };
      });
      worker.terminate();
      return answer;
    }"""
    answer = page.page.evaluate(script)
    assert answer["type"] == "answer" and answer["ok"] is False
    assert answer["error"].startswith("scanconv failed: TypeError: ")
    assert len(answer["error"]) > len("scanconv failed: TypeError: ")


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


def test_no_console_error_on_load_and_no_share_link_for_an_error(browser: Any, origin: str) -> None:
    """A load logs no console error (a favicon.ico 404 was one on every load); a question
    with an error offers no link to share; a shared link leaves out the words that choose a
    format or a file (the page shows its own formats)."""
    opened = Site(browser, origin, _link("line 2 2 10 6"))
    console: list[str] = []
    opened.page.on("console", lambda m: console.append(m.text) if m.type == "error" else None)
    opened.wait(1)
    try:
        assert console == []
        assert not any(u.endswith("favicon.ico") for u in opened.requests)
        n = opened.answers()
        opened.page.fill("#q", "line 2 2 10")
        opened.page.click("#go")
        opened.wait(n + 1)
        assert opened.page.is_hidden("#share-row")
        opened.ask("scanconv line 2 2 10 6 --algo dda -f json -o a.md --svg=b.svg")
        assert opened.page.get_attribute("#share", "href") == _link("line 2 2 10 6 --algo dda")
        assert opened.page.is_visible("#share-row")
    finally:
        opened.close()

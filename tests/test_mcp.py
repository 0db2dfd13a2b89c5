"""``scanconv mcp``: the Model Context Protocol server, driven as a separate process over stdio
by the SDK's own client, and by an independent one, the MCP Inspector's command line from npm.

Each answer is held to the command line's (``python -m scanconv ... --format json``, byte for
byte), each marking to ``scanconv check``'s score and to a hand-worked table, each refusal to
the command line's one line; the structured content of every tool to the output schema the
server lists (jsonschema, an independent validator). Without the SDK (the ``mcp`` extra, which
the ``test`` extra installs) the tests that drive the server are skipped, saying so, and the
command's one-line message is tested instead. (Timings: benchmarks/bench_mcp.py.)
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import importlib.util
import json
import shlex
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .helpers import run_process

HAS_SDK = importlib.util.find_spec("mcp") is not None
needs_sdk = pytest.mark.skipif(
    not HAS_SDK,
    reason="the MCP SDK is the optional extra mcp: pip install -e '.[mcp]' (or '.[test]')",
)
pytestmark = pytest.mark.slow  # each test talks to a server process

URI = "ui://scanconv/stepper.html"

#: One question of each kind the server is asked for: a line, a circle, an ellipse, a clipping, a
#: fill and a Bezier curve.
QUESTIONS = (
    "line 5 5 13 9 --algo bresenham",
    "circle 8 --method midpoint",
    "ellipse 8 6",
    "clip line 7 9 11 4 --window 4 4 10 8",
    "fill flood 2 0 4 2 2 4 0 2 --seed 2 2",
    "bezier 0 0 1 2 3 3 4 0",
)

#: The VTU line (5, 5) to (13, 9) worked by hand: dx = 8, dy = 4, p0 = 2dy - dx = 0, p += 8
#: after E and -8 after NE, a tie (p = 0) stepping y; each row the pixel it reaches.
VTU_RIGHT = """k,p_k,(x_{k+1}, y_{k+1})
0,0,"(6, 6)"
1,-8,"(7, 6)"
2,0,"(8, 7)"
3,-8,"(9, 7)"
4,0,"(10, 8)"
5,-8,"(11, 8)"
6,0,"(12, 9)"
7,-8,"(13, 9)"
"""

#: The same line with the tie the other way (p = 0 keeps y), as a chat answer
#: plots it, and a slip in row 5.
VTU_SLIPPED = """k,p_k,(x_{k+1}, y_{k+1})
0,0,"(6, 5)"
1,8,"(7, 6)"
2,0,"(8, 6)"
3,8,"(9, 7)"
4,0,"(10, 7)"
5,4,"(11, 8)"
6,0,"(12, 8)"
7,8,"(13, 9)"
"""


def cli_json(question: str) -> str:
    """What ``python -m scanconv QUESTION --format json`` prints."""
    r = run_process(*shlex.split(question), "--format", "json")
    assert r.code == 0, r.err
    return r.out


def cli_error(*args: str) -> str:
    """The command line's one-line reason for refusing ``args`` (after ``error:``)."""
    r = run_process(*args)
    assert r.code == 2 and r.out == "", (r.code, r.out)
    (line,) = r.err.strip().splitlines()
    return line.split("error: ", 1)[1]


class Server:
    """``scanconv mcp`` as a separate process, with the SDK's client connected over stdio,
    on an event loop of its own thread so that plain (and hypothesis) tests can call it."""

    def __init__(self) -> None:
        from mcp import Client, StdioServerParameters

        self.loop = asyncio.new_event_loop()
        self.thread = threading.Thread(target=self.loop.run_forever, daemon=True)
        self.thread.start()
        self.ready: concurrent.futures.Future[Any] = concurrent.futures.Future()
        params = StdioServerParameters(command=sys.executable, args=["-m", "scanconv", "mcp"])
        self.done = asyncio.Event()

        async def hold() -> None:
            try:
                async with Client(params) as client:
                    self.ready.set_result(client)
                    await self.done.wait()
            except BaseException as err:  # reported to the test that waits for it
                if not self.ready.done():
                    self.ready.set_exception(err)
                raise

        self.held = asyncio.run_coroutine_threadsafe(hold(), self.loop)
        self.client = self.ready.result(timeout=300)

    def run(self, coroutine: Any) -> Any:
        return asyncio.run_coroutine_threadsafe(coroutine, self.loop).result(timeout=300)

    def call(self, tool: str, **arguments: Any) -> Any:
        return self.run(self.client.call_tool(tool, arguments))

    def close(self) -> None:
        self.loop.call_soon_threadsafe(self.done.set)
        self.held.result(timeout=300)
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join()


@pytest.fixture(scope="module")
def server() -> Iterator[Server]:
    if not HAS_SDK:
        pytest.skip("the MCP SDK is the optional extra mcp: pip install -e '.[mcp]'")
    s = Server()
    yield s
    s.close()


@pytest.fixture(scope="module")
def tools(server: Server) -> dict[str, Any]:
    return {t.name: t for t in server.run(server.client.list_tools()).tools}


def texts(result: Any) -> list[str]:
    return [c.text for c in result.content]


# --- the tools and their schemas ----------------------------------------------------------


@needs_sdk
def test_docs_mcp_md_lists_the_tools_the_model_sees_with_their_arguments(tools):
    """docs/mcp.md's table of tools is the server's: every tool but the view's own
    (``answer_page``, for the app), each with the arguments it takes, and ``practice``'s count
    limit (1 to 20) is the one it enforces."""
    import re

    from scanconv.mcp_server.answers import MAX_PRACTICE
    from scanconv.mcp_server.view import PAGE_TOOL

    doc = (Path(__file__).resolve().parent.parent / "docs" / "mcp.md").read_text("utf-8")
    rows = dict(re.findall(r"^\| `([a-z_]+)` \| ([^|]*) \|", doc, flags=re.M))
    assert set(rows) == set(tools) - {PAGE_TOOL}
    for name, arguments in rows.items():
        said = set(re.findall(r"`([a-z_]+)`", arguments))
        assert said == set(tools[name].input_schema.get("properties", {})), name
    assert f"`count` (1 to {MAX_PRACTICE})" in rows["practice"]


@needs_sdk
def test_the_tools_are_listed_read_only_with_real_output_schemas(tools):
    assert set(tools) >= {"solve", "check", "practice", "theory", "vocabulary"}
    for name in ("solve", "check", "practice", "theory", "vocabulary"):
        tool = tools[name]
        a = tool.annotations
        assert (a.read_only_hint, a.idempotent_hint, a.open_world_hint) == (True, True, False)
        assert a.destructive_hint is False
        schema = tool.output_schema
        assert schema is not None and schema["type"] == "object", name
        assert schema.get("properties"), f"{name}: an open object is no schema"
        assert "path" not in json.dumps(tool.input_schema).lower(), "no tool takes a file"
    steps = tools["solve"].output_schema
    answer = steps["properties"]
    assert {"primitive", "algorithm", "steps", "conventions", "working"} <= set(answer)
    step = steps["$defs"]["Step"]["properties"]
    assert {"k", "p", "decision", "pixel"} <= set(step)
    assert "instead of computing" in tools["solve"].description
    assert tools["solve"].meta["ui"]["resourceUri"] == URI


# --- solve: the command line's JSON ---------------------------------------------------------


@needs_sdk
@pytest.mark.parametrize("question", QUESTIONS)
def test_solve_returns_the_command_lines_json_byte_for_byte(server, question):
    result = server.call("solve", question=question)
    assert not result.is_error, texts(result)
    expected = cli_json(question)
    markdown, data = texts(result)
    assert data == expected  # the JSON text block: the bytes --format json writes
    assert result.structured_content == json.loads(expected)
    assert list(result.structured_content) == list(json.loads(expected))  # the keys' order
    shown = run_process(*shlex.split(question), "--format", "markdown")
    assert markdown == shown.out


@needs_sdk
def test_solve_names_the_vtu_lines_conventions(server):
    data = server.call("solve", question="line 5 5 13 9").structured_content
    assert data["conventions"] == {"tie": "step", "start": "swap"}
    assert [s["p"] for s in data["steps"]][:4] == [0, -8, 0, -8]  # by hand: p0 = 2dy - dx
    assert data["pixels"][-1] == [13, 9]


@needs_sdk
def test_a_question_naming_a_file_or_format_has_those_words_dropped(server, tmp_path):
    target = tmp_path / "answer.svg"
    question = f"line 5 5 13 9 -f latex -o {tmp_path / 'a.tex'} --svg {target}"
    result = server.call("solve", question=question)
    assert texts(result)[1] == cli_json("line 5 5 13 9")
    assert list(tmp_path.iterdir()) == []  # nothing written


# --- refusals: isError with scanconv's one line -----------------------------------------------


@needs_sdk
@pytest.mark.parametrize(
    "question",
    [
        "line 2 2 10",  # bad input
        "line 2 2 10 6 --algo zzz",  # an unknown method
        "line 0 0 1000000000 1",  # over the work budget
        "circle 0.5",
        "ellipse 8 6 --method zzz",
    ],
)
def test_bad_input_is_an_error_result_with_the_command_lines_reason(server, question):
    result = server.call("solve", question=question)
    assert result.is_error and result.structured_content is None
    (text,) = texts(result)
    cli = cli_error(*shlex.split(question), "--format", "json")
    # the command line adds its way out of a budget refusal (scanconv.raster for the pixels)
    assert text == cli or ("rows" in text and cli.startswith(text + "; for the pixels alone"))
    assert "Error executing tool" not in text and "Traceback" not in text


@needs_sdk
def test_a_question_too_long_and_a_bad_practice_set_are_refused(server):
    long = server.call("solve", question="line " + "1 " * 5000)
    assert texts(long) == ["a question of 10,005 characters; at most 10,000 characters"]
    bad = server.call("practice", topic="lines", count=2, seed=1)
    assert bad.is_error and texts(bad)[0].startswith("unknown topic 'lines'")
    many = server.call("practice", topic="line", count=500, seed=1)
    assert many.is_error and texts(many) == ["count must be 1 to 20 (got 500)"]
    theory = server.call("theory", topic="zzz")
    assert theory.is_error and texts(theory)[0].startswith("unknown theory topic 'zzz' (choose")
    command = server.call("solve", question="lines 2 2 10 6")
    assert command.is_error and texts(command) == ["No such command 'lines'; did you mean 'line'?"]


# --- check: the marks ---------------------------------------------------------------------------


@needs_sdk
def test_check_gives_a_hand_worked_right_table_full_marks(server):
    result = server.call("check", question="line 5 5 13 9 --algo bresenham", table=VTU_RIGHT)
    data = result.structured_content
    assert (data["score"], data["out_of"], data["first_error"]) == (8, 8, "")


@needs_sdk
@pytest.mark.parametrize(
    "table,question",
    [
        (VTU_SLIPPED, "line 5 5 13 9"),
        (Path("tests/data/check/slip.csv").read_text(), "line 2 2 10 6"),
        (Path("tests/data/check/ellipse-slip.csv").read_text(), "ellipse 8 6"),
    ],
)
def test_check_gives_a_slipped_table_the_command_lines_score(server, tmp_path, table, question):
    answer = tmp_path / "answer.csv"
    answer.write_text(table)
    r = run_process("check", str(answer), "--", *shlex.split(question), "-f", "json")
    assert r.code == 0, r.err
    cli = json.loads(r.out)
    data = server.call("check", question=question, table=table).structured_content
    for key in ("score", "out_of", "first_error", "diagnosis", "marked"):
        assert data[key] == cli[key], key
    assert data["score"] < data["out_of"]


@needs_sdk
def test_check_refuses_a_question_without_a_table_and_a_table_that_is_no_table(server):
    theory = server.call("check", question="theory dda", table=VTU_RIGHT)
    assert theory.is_error
    assert texts(theory) == [cli_error("check", "tests/data/check/slip.csv", "--", "theory", "dda")]
    empty = server.call("check", question="line 5 5 13 9", table="  ")
    assert empty.is_error and texts(empty) == ["the table: the file is empty"]


# --- practice, theory, vocabulary, the view ---------------------------------------------------


@needs_sdk
def test_practice_repeats_per_seed_and_its_key_is_the_questions_answer(server, tmp_path):
    first = server.call("practice", topic="circle", count=3, seed=11, difficulty="easy")
    again = server.call("practice", topic="circle", count=3, seed=11, difficulty="easy")
    other = server.call("practice", topic="circle", count=3, seed=12, difficulty="easy")
    assert first.structured_content == again.structured_content
    asked = [q["question"] for q in first.structured_content["questions"]]
    assert asked != [q["question"] for q in other.structured_content["questions"]]
    file = tmp_path / "questions.txt"
    cli = run_process(
        "practice", "--topic", "circle", "-n", "3", "--seed", "11", "-d", "easy",
        "--questions", str(file),
    )  # fmt: skip
    assert cli.code == 0, cli.err
    lines = file.read_text().splitlines()[2:]  # the command line's question file
    wording = [q["wording"] for q in first.structured_content["questions"]]
    marks = [q["marks"] for q in first.structured_content["questions"]]
    assert lines[0::2] == [f"> {w}" for w in wording]
    assert lines[1::2] == [f"[{m}] {q}" for m, q in zip(marks, asked, strict=True)]
    for q in first.structured_content["questions"]:
        assert q["answer"] == json.loads(cli_json(q["question"] + " --brief"))


@needs_sdk
def test_theory_and_vocabulary(server):
    theory = server.call("theory", topic="dda")
    assert texts(theory)[1] == cli_json("theory dda")
    v = server.call("vocabulary").structured_content
    assert (
        v["methods"]["circle"][:2] == ["midpoint", "bresenham"]
        or "midpoint" in v["methods"]["circle"]
    )
    assert {p["name"] for p in v["presets"]} == {"notes", "hearn-baker", "foley", "wikipedia"}
    tie = next(k for k in v["conventions"] if k["name"] == "tie")
    assert tie["default"] == "step" and set(tie["values"]) == {"step", "keep"}
    assert all(server.call("solve", question=e).is_error is False for e in v["examples"])


@needs_sdk
def test_the_ui_view_is_the_step_through_page(server):
    resources = server.run(server.client.list_resources()).resources
    (view,) = [r for r in resources if str(r.uri) == URI]
    assert view.mime_type == "text/html;profile=mcp-app"
    (content,) = server.run(server.client.read_resource(URI)).contents
    assert content.mime_type == "text/html;profile=mcp-app"
    page = run_process("line", "5", "5", "13", "9", "--algo", "bresenham", "-f", "html").out
    from scanconv.mcp_server.view import BRIDGE

    head, _, tail = page.rpartition("</body>")
    assert content.text == head + BRIDGE + "</body>" + tail  # the --format html page, bridged
    bridge = BRIDGE
    assert "Test yourself" in page and "ui/initialize" in bridge
    assert "tools/call" in bridge and "answer_page" in bridge
    for outside in ('src="http', "src='http", 'href="http', "<link", "@import", "url(http"):
        assert outside not in content.text  # nothing fetched from outside the page
    assert "fetch(" not in content.text and "XMLHttpRequest" not in content.text
    shown = server.call("answer_page", question="circle 8")
    assert texts(shown) == [run_process("circle", "8", "-f", "html").out]


HOST = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>test host</title></head><body>
<iframe id="view" sandbox="allow-scripts" style="width:1200px;height:900px"></iframe>
<script>
/* a minimal MCP Apps host: it answers the view's ui/initialize, sends the tool input of a solve
   call, and passes the view's tools/call to the real server (window.callTool, from Python) */
const frame = document.getElementById("view");
window.seen = [];
function reply(message) { frame.contentWindow.postMessage(message, "*"); }
window.addEventListener("message", async (event) => {
  if (event.source !== frame.contentWindow) { return; }
  const m = event.data;
  window.seen.push(m.method);
  if (m.method === "ui/initialize") {
    reply({jsonrpc: "2.0", id: m.id, result: {protocolVersion: m.params.protocolVersion,
      hostInfo: {name: "test host", version: "1"}, hostCapabilities: {}, hostContext: {}}});
  } else if (m.method === "ui/notifications/initialized") {
    reply({jsonrpc: "2.0", method: "ui/notifications/tool-input",
           params: {arguments: {question: window.QUESTION}}});
  } else if (m.method === "tools/call") {
    const result = await window.callTool(m.params.name, JSON.stringify(m.params.arguments));
    reply({jsonrpc: "2.0", id: m.id, result: JSON.parse(result)});
  }
});
</script></body></html>
"""


@needs_sdk
@pytest.mark.external  # chromium
def test_in_a_host_the_view_shows_the_page_of_the_question_solved(server, browser, tmp_path):
    """The view in a sandboxed iframe of a host page, in Debian's chromium: it introduces
    itself, learns the question of the solve call, gets that question's page from the server
    through the host and shows it, stepper and test yourself working; nothing is fetched."""
    host = tmp_path / "host.html"
    host.write_text(HOST, encoding="utf-8")
    (view,) = server.run(server.client.read_resource(URI)).contents
    tab = browser.new_page()
    requests: list[str] = []
    tab.on("request", lambda r: requests.append(r.url))

    def call_tool(name: str, arguments: str) -> str:
        result = server.call(name, **json.loads(arguments))
        return json.dumps(result.model_dump(mode="json", by_alias=True, exclude_none=True))

    try:
        tab.expose_function("callTool", call_tool)
        tab.goto(host.as_uri())
        tab.evaluate("window.QUESTION = 'circle 8'")
        tab.evaluate("(html) => { document.getElementById('view').srcdoc = html; }", view.text)
        tab.wait_for_function("window.seen.includes('tools/call')")
        frame = tab.frames[1]
        frame.wait_for_function("document.title.startsWith('Midpoint circle')")
        assert frame.evaluate("document.title") == "Midpoint circle algorithm: r = 8, centre (0, 0)"
        frame.wait_for_function("document.querySelector('section.scanconv[data-pos]') !== null")
        frame.click("button[data-act=reset]")  # the stepper runs
        frame.click("button[data-act=next]")
        frame.click("button[data-act=next]")
        pos = "+document.querySelector('section.scanconv').getAttribute('data-pos')"
        assert frame.evaluate(pos) == 2
        assert frame.locator("button.sc-testbtn").count() == 1  # test yourself
        seen = tab.evaluate("window.seen")
        assert seen[:3] == [
            "ui/initialize",
            "ui/notifications/initialized",
            "ui/notifications/size-changed",
        ]
        assert all(u.startswith(("file:", "data:", "about:")) for u in requests), requests
    finally:
        tab.close()


# --- the structured content against the declared schemas --------------------------------------

THEORY_TOPICS = ("dda", "bresenham-line", "midpoint-circle", "raster-display", "clipping")
_points = st.integers(-20, 20)
_QUESTIONS = st.one_of(
    st.builds(
        "line {} {} {} {} --algo {}".format,
        _points,
        _points,
        _points,
        _points,
        st.sampled_from(["bresenham", "dda", "basic", "midpoint", "wu"]),
    ),
    st.builds(
        "circle {} --method {}".format,
        st.integers(1, 12),
        st.sampled_from(["midpoint", "bresenham", "polynomial", "trig"]),
    ),
    st.builds("ellipse {} {}".format, st.integers(1, 9), st.integers(1, 9)),
    st.builds(
        "bezier {} {} {} {} {} {}".format, _points, _points, _points, _points, _points, _points
    ),
    st.builds(
        "clip line {} {} {} {} --window 0 0 10 10".format, _points, _points, _points, _points
    ),
    st.sampled_from(
        [
            "polygon 1 1 9 1 9 7 5 3 1 7",
            "compare line 2 2 8 5",
            "theory dda",
            "fill flood 2 0 4 2 2 4 0 2 --seed 2 2",
            "ellipse 6 4 --center 2 -1",
        ]
    ),
)


@needs_sdk
@settings(
    max_examples=15,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(question=_QUESTIONS, seed=st.integers(0, 10**6), topic=st.sampled_from(["line", "all"]))
def test_structured_content_validates_against_the_declared_schema(
    server, tools, question, seed, topic
):
    import jsonschema

    def valid(tool: str, result: Any) -> None:
        if not result.is_error:
            jsonschema.validate(result.structured_content, tools[tool].output_schema)

    solved = server.call("solve", question=question)
    valid("solve", solved)
    if not solved.is_error and solved.structured_content["steps"]:
        csv = run_process(*shlex.split(question), "--format", "csv").out
        marked = server.call("check", question=question, table=csv)
        valid("check", marked)
        if not marked.is_error:  # scanconv's own table, as the command line writes it
            assert marked.structured_content["score"] == marked.structured_content["out_of"]
    valid("practice", server.call("practice", topic=topic, count=2, seed=seed))
    valid("theory", server.call("theory", topic=THEORY_TOPICS[seed % len(THEORY_TOPICS)]))
    valid("vocabulary", server.call("vocabulary"))


# --- the independent client: the MCP Inspector's command line ---------------------------------


PACKAGE = "@modelcontextprotocol/inspector@2"
"""The MCP Inspector (2.12.0 when this was written; its --cli drives a server over stdio)."""


@pytest.fixture(scope="module")
def inspector(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """@modelcontextprotocol/inspector 2.x installed with npm into a temporary directory
    (needs node, npm and the registry; .ci/run installs node and npm), as tests/test_lms.py
    installs gift-pegjs."""
    if shutil.which("npm") is None or shutil.which("node") is None:
        pytest.skip("npm and node are needed to install and run the MCP Inspector")
    where = tmp_path_factory.mktemp("inspector")
    done = subprocess.run(
        [*("npm", "install", "--prefix", str(where), "--no-audit", "--no-fund"), PACKAGE],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, f"npm install of the MCP Inspector failed: {done.stderr[-2000:]}"
    return where / "node_modules" / ".bin" / "mcp-inspector"


def inspect(inspector: Path, *args: str, refused: bool = False) -> Any:
    """The Inspector's JSON for one request to ``scanconv mcp`` (it exits 5 for a tool result
    with ``isError``)."""
    done = subprocess.run(
        # a generous connect timeout (the Inspector's default, 15 s, is a hang guard that a
        # loaded machine's Python start-up can exceed: not a timing of scanconv)
        [
            str(inspector),
            "--cli",
            sys.executable,
            "-m",
            "scanconv",
            "mcp",
            *args,
            "--connect-timeout",
            "120000",
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == (5 if refused else 0), done.stderr[-2000:]
    return json.loads(done.stdout)


@needs_sdk
@pytest.mark.external
def test_the_mcp_inspector_lists_the_tools_and_calls_solve(inspector):
    listed = inspect(inspector, "--method", "tools/list")
    names = {t["name"] for t in listed["tools"]}
    assert {"solve", "check", "practice", "theory", "vocabulary"} <= names
    called = inspect(
        inspector,
        "--method",
        "tools/call",
        "--tool-name",
        "solve",
        "--tool-arg",
        "question=circle 4",
    )
    assert called["structuredContent"] == json.loads(cli_json("circle 4"))
    refused = inspect(
        inspector,
        *("--method", "tools/call", "--tool-name", "solve", "--tool-arg", "question=circle"),
        refused=True,
    )
    assert refused["isError"] is True
    assert refused["content"][0]["text"] == cli_error("circle", "-f", "json")


@needs_sdk
def test_http_serves_the_same_answers_bound_to_this_machine_only():
    import socket
    import time

    from mcp import Client

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen(
        [sys.executable, "-m", "scanconv", "mcp", "--http", str(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    try:
        listening = f"0100007F:{port:04X}"  # 127.0.0.1 in /proc/net/tcp
        for _ in range(600):  # until it listens (or has died)
            table = Path("/proc/net/tcp").read_text()
            if any(f" {listening} 00000000:0000 0A " in ln for ln in table.splitlines()):
                break
            assert proc.poll() is None, proc.stderr.read() if proc.stderr else ""
            time.sleep(0.05)
        else:
            pytest.fail("the server did not listen on 127.0.0.1")

        async def solve() -> Any:
            async with Client(f"http://127.0.0.1:{port}/mcp") as client:
                return await client.call_tool("solve", {"question": "circle 4"})

        # on a thread of its own: a session's browser tests keep an event loop in this one
        with concurrent.futures.ThreadPoolExecutor(1) as pool:
            result = pool.submit(lambda: asyncio.run(solve())).result(timeout=300)
        assert texts(result)[1] == cli_json("circle 4")
    finally:
        proc.terminate()
        proc.communicate(timeout=60)


# --- the command and the core without the SDK ---------------------------------------------------

PROBE = """
import sys
{hide}
from scanconv.cli import main
code = main({args!r})
sdk = {{"mcp", "mcp_types", "pydantic", "pydantic_core", "starlette", "sse_starlette",
        "uvicorn", "httpx", "httpx2", "anyio", "jsonschema"}}
print("LOADED", ",".join(sorted({{m.split(".")[0] for m in sys.modules}} & sdk)) or "-", code,
      file=sys.stderr)
"""


def probe(*args: str, hide_sdk: bool = False) -> tuple[set[str], str, str]:
    """The SDK's modules a run of ``scanconv ARGS`` loaded, its status, and its stderr."""
    hide = "sys.modules['mcp'] = None  # as if the extra were not installed" if hide_sdk else ""
    proc = subprocess.run(
        [sys.executable, "-c", PROBE.format(args=list(args), hide=hide)],
        capture_output=True,
        text=True,
        timeout=120,
        stdin=subprocess.DEVNULL,
    )
    last = proc.stderr.strip().splitlines()[-1]
    _, names, code = last.split(" ")
    return set(names.split(",")) - {"-"}, code, proc.stderr


@pytest.mark.parametrize(
    "args",
    [
        ("line", "2", "2", "10", "6", "--algo", "bresenham"),
        ("line", "2", "2", "10", "6", "--format", "json"),
        ("--help",),  # every command module imported, scanconv mcp's too
        ("mcp", "--help"),
    ],
)
def test_a_plain_run_imports_no_module_of_the_sdk(args):
    loaded, code, err = probe(*args)
    assert code == "0", err
    assert loaded == set()


def test_without_the_extra_scanconv_mcp_says_how_to_install_it_in_one_line():
    _, code, err = probe("mcp", hide_sdk=True)
    assert code == "2"
    message = err.strip().splitlines()[:-1]
    assert message == [
        "scanconv: error: scanconv mcp needs the MCP SDK, an optional extra: "
        "pip install 'scanconv[mcp]'"
    ]


@pytest.mark.parametrize("bad", ["http", "0", "65536", "host:", "a b:80"])
def test_a_bad_http_address_is_refused_in_one_line(bad):
    r = run_process("mcp", "--http", bad)
    assert r.code == 2 and r.out == ""
    assert (
        r.err.strip()
        == f"scanconv: error: --http: {bad!r} is not [HOST:]PORT (a port is 1 to 65535)"
    )

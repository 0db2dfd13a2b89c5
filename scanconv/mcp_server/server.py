"""The MCP server: scanconv's tools over the official Python SDK (``mcp``, the
``scanconv[mcp]`` extra), on stdio or streamable HTTP (``scanconv mcp``; docs/mcp.md).

The tools are few and thin: each calls :mod:`.answers` (the library, one budget check before
any work) and returns its structured content, declared by :mod:`.schema` (the output schema
the server lists), with the Markdown answer as the text for hosts that read only text. Every
tool is read-only, idempotent and closed-world (it computes; it reads no file and reaches
nothing outside). Bad input, an unknown method or a question over the work budget is a tool
result with ``isError`` and scanconv's one-line reason as its text, so the model can correct
its call; no tool takes a file path.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Annotated, Any

from mcp.server import MCPServer
from mcp.server.apps import APP_MIME_TYPE, Apps
from mcp.server.mcpserver.resources import FunctionResource
from mcp_types import CallToolResult, TextContent, ToolAnnotations

from .. import __version__
from . import answers, schema
from .view import PAGE_TOOL, URI, view_html
from .vocabulary import vocabulary as language
from .vocabulary import vocabulary_text

NAME = "scanconv"

INSTRUCTIONS = (
    "scanconv computes the scan-conversion chapter of computer graphics exactly: step tables "
    "of line, circle and ellipse algorithms (DDA, Bresenham, midpoint), curves, clipping, "
    "filling, anti-aliasing, and marks a student's table. Never compute a decision "
    "parameter, a pixel or a table yourself: call solve and copy its table, and name the "
    "conventions it reports (tie, start, rounding, p0, loop), since textbooks differ exactly "
    "there. Call vocabulary to see how to write a question."
)

READ_ONLY = ToolAnnotations(
    read_only_hint=True,
    destructive_hint=False,
    idempotent_hint=True,
    open_world_hint=False,
)

SOLVE = (
    "Solve a scan-conversion question exactly: the derivation, the step table (k, p, "
    "decision, pixel), the pixels, and the conventions used. Call this instead of computing a "
    "decision-parameter table, DDA increments or pixels yourself; copy its table as it is and "
    "name its conventions (for example 'tie = step: p = 0 steps y'). The question is "
    "scanconv's own command line without 'scanconv', for example 'line 5 5 13 9 --algo "
    "bresenham', 'circle 8 --method midpoint', 'ellipse 8 6', 'clip line 7 9 11 4 --window 4 "
    "4 10 8', 'fill flood 2 0 4 2 2 4 0 2 --seed 2 2', 'bezier 0 0 1 2 3 3 4 0' (call "
    "vocabulary for every command and option). A bad question returns scanconv's one-line "
    "reason: fix the question and call again."
)
CHECK = (
    "Mark a student's (or another assistant's, or a website's) step table against a "
    "question, row by row with follow-through: the score, the first wrong step and why, and "
    "the conventions or the mistake the table shows. Call this before trusting or repeating "
    "any table you did not get from solve. The table is text: CSV, a Markdown pipe table, "
    "whitespace columns or JSON, with headings such as k, p_k, (x, y) or x and y."
)
PRACTICE = (
    "Practice questions with their answer key, the same for the same seed: call this to "
    "set a student exercises (topic: line, circle, ellipse, bezier, bspline, clip, ... or all; "
    "difficulty: easy, exam or hard; count 1 to 20). Each question comes in the question "
    "language, ready for solve and check."
)
THEORY = (
    "The model answer to a theory question of the chapter (definition, key points, "
    "advantages and limitations, with a worked example): call this for 'explain', 'define' "
    "or 'compare' questions instead of answering from memory. The topics are listed by "
    "vocabulary (theory_topics), e.g. dda, bresenham-line, midpoint-circle, raster-display."
)
VOCABULARY = (
    "The question language: every command with its arguments and options, the methods, the "
    "conventions (the rules textbooks differ on, with their meanings and defaults) and the "
    "presets of published sources (--convention hearn-baker, foley, ...). Call this to form a "
    "valid question for solve, check or practice."
)
PAGE = "The step-through page of a question (HTML), for the scanconv view only."

AnswerResult = Annotated[CallToolResult, schema.Answer]
MarkingResult = Annotated[CallToolResult, schema.Marking]
PracticeResult = Annotated[CallToolResult, schema.Practice]
VocabularyResult = Annotated[CallToolResult, schema.Vocabulary]


def _refusal(reason: str) -> CallToolResult:
    """A tool result with ``isError`` and scanconv's one-line reason as its text, nothing
    before it (the SDK's own errors start "Error executing tool")."""
    return CallToolResult(content=[TextContent(type="text", text=reason)], is_error=True)


def _reason(call: Callable[[], Any]) -> tuple[Any, str | None]:
    """``call()``'s value, or the one line that says why it refused (``ValueError``: bad
    input, an unknown method, a question over the work budget)."""
    try:
        return call(), None
    except ValueError as err:
        return None, " ".join(str(err).split())
    except RecursionError:
        return None, "input too deeply nested"


def _reply(call: Callable[[], answers.Reply]) -> CallToolResult:
    """A tool's result: the text for the model (Markdown), the structured content and, as
    the protocol asks of a tool with structured content, its JSON as a second text (for an
    answer, the bytes ``--format json`` writes); or the refusal."""
    reply, reason = _reason(call)
    if reason is not None:
        return _refusal(reason)
    return CallToolResult(
        content=[
            TextContent(type="text", text=reply.text),
            TextContent(type="text", text=reply.data_text),
        ],
        structured_content=reply.data,
    )


def build() -> MCPServer[Any]:
    """The server with its tools and its view (not yet running)."""
    apps = Apps()

    @apps.tool(resource_uri=URI, name="solve", description=SOLVE, annotations=READ_ONLY)
    async def solve(question: str) -> AnswerResult:
        return _reply(lambda: answers.solve(question))

    @apps.tool(
        resource_uri=URI,
        visibility=["app"],
        name=PAGE_TOOL,
        description=PAGE,
        annotations=READ_ONLY,
    )
    async def answer_page(question: str) -> CallToolResult:
        html, reason = _reason(lambda: answers.page(question))
        if reason is not None:
            return _refusal(reason)
        return CallToolResult(content=[TextContent(type="text", text=html)])

    apps.add_resource(  # the page written when a host first reads it, not at start-up
        FunctionResource(
            uri=URI,
            name="scanconv stepper",
            title="Step through the answer",
            description="The step-through page of the question solve answered, with test yourself.",
            mime_type=APP_MIME_TYPE,
            meta={"ui": {"prefersBorder": True}},
            fn=functools.cache(view_html),
        )
    )
    server: MCPServer[Any] = MCPServer(
        NAME,
        title="scanconv",
        version=__version__,
        instructions=INSTRUCTIONS,
        log_level="WARNING",
        extensions=[apps],
    )

    @server.tool(name="check", description=CHECK, annotations=READ_ONLY)
    async def check(question: str, table: str) -> MarkingResult:
        return _reply(lambda: answers.check(question, table))

    @server.tool(name="practice", description=PRACTICE, annotations=READ_ONLY)
    async def practice(
        topic: str = "all", count: int = 5, seed: int = 0, difficulty: str = "exam"
    ) -> PracticeResult:
        return _reply(lambda: answers.practice(topic, count, seed, difficulty))

    @server.tool(name="theory", description=THEORY, annotations=READ_ONLY)
    async def theory(topic: str) -> AnswerResult:
        return _reply(lambda: answers.theory(topic))

    @server.tool(name="vocabulary", description=VOCABULARY, annotations=READ_ONLY)
    async def vocabulary() -> VocabularyResult:
        words = language()
        return _reply(lambda: answers.Reply.made(words, vocabulary_text(words)))

    return server


def run(http: tuple[str, int] | None = None) -> None:
    """Serve until the client goes away: over stdio, or streamable HTTP on ``(host, port)``."""
    server = build()
    if http is None:
        server.run("stdio")
    else:
        host, port = http
        server.run("streamable-http", host=host, port=port)

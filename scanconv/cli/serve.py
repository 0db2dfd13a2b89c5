"""``scanconv mcp``: scanconv's tools for AI assistants, as a Model Context Protocol server
(:mod:`scanconv.mcp_server`; docs/mcp.md).

The server needs the optional extra (``pip install 'scanconv[mcp]'``, the official SDK); this
module only reads the flags and starts it, importing the SDK when the command runs, never when
the CLI starts. Without the extra the command says how to install it, in one line (exit 2).
"""

from __future__ import annotations

from typing import Annotated

import typer

from .application import app
from .output import fail

DEFAULT_HOST = "127.0.0.1"
"""Where ``--http PORT`` listens: this machine only, unless a host is given."""

INSTALL = "scanconv mcp needs the MCP SDK, an optional extra: pip install 'scanconv[mcp]'"


def address(text: str) -> tuple[str, int]:
    """``--http [HOST:]PORT`` read: the host (:data:`DEFAULT_HOST` if none) and the port.

    >>> address("8000"), address("0.0.0.0:8000"), address("[::1]:9000")
    (('127.0.0.1', 8000), ('0.0.0.0', 8000), ('::1', 9000))
    >>> address("host:http")
    Traceback (most recent call last):
    ...
    ValueError: --http: 'host:http' is not [HOST:]PORT (a port is 1 to 65535)
    """
    host, _, port = text.rpartition(":")
    host = host.strip("[]") or DEFAULT_HOST
    if not port.isdecimal() or not 1 <= int(port) <= 65535 or any(c.isspace() for c in host):
        raise ValueError(f"--http: {text!r} is not [HOST:]PORT (a port is 1 to 65535)")
    return host, int(port)


@app.command(name="mcp")
def mcp_server(
    http: Annotated[
        str | None,
        typer.Option(
            "--http",
            metavar="[HOST:]PORT",
            help="Serve streamable HTTP on PORT (at http://HOST:PORT/mcp), bound to "
            f"{DEFAULT_HOST} unless HOST is given, instead of stdio.",
            show_default=False,
        ),
    ] = None,
) -> None:
    """Serve scanconv's tools to an AI assistant over the Model Context Protocol.

    Over stdio (what Claude Desktop, VS Code and other hosts launch) unless --http is given.
    The tools: solve, check, practice, theory and vocabulary, each computed by scanconv
    (docs/mcp.md). Needs the extra: pip install 'scanconv[mcp]'.
    Example: scanconv mcp --http 8000
    """
    try:
        where = None if http is None else address(http)
    except ValueError as err:
        fail(str(err))
    try:
        from ..mcp_server import server
    except ImportError:
        fail(INSTALL)
    server.run(where)

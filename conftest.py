"""The doctests of scanconv's modules: the MCP server's SDK glue only with the SDK (the
``mcp`` extra, which the ``test`` extra installs; tests/test_mcp.py says when it is missing)."""

import importlib.util

collect_ignore = [] if importlib.util.find_spec("mcp") else ["scanconv/mcp_server/server.py"]

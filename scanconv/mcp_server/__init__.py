"""scanconv as a Model Context Protocol server: a chat assistant calls scanconv's exact
engine instead of predicting a table's digits (``scanconv mcp``; docs/mcp.md).

* :mod:`.answers` answers each tool's call with the library (the question language, the
  marking, the practice generator), one budget check before any work; no SDK here;
* :mod:`.schema` declares the structured content each tool returns (the stable JSON);
* :mod:`.view` is the MCP App view, the step-through page the ``solve`` tool points to;
* :mod:`.server` is the SDK's server around them (``pip install 'scanconv[mcp]'``), the only
  module that imports ``mcp``.

Nothing else in scanconv imports this package but ``scanconv mcp``, which imports it only
when it runs (start-up of the other commands, and a core without the SDK).
"""

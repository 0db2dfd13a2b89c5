"""The MCP server's speed and memory: ``python benchmarks/bench_mcp.py`` (needs the mcp extra).

Measures, with the SDK's own client driving ``scanconv mcp`` over stdio (a separate process,
as a desktop host runs it):

* ``solve`` through a warm server against the same question answered in-process
  (:func:`scanconv.mcp_server.answers.solve`: the JSON and the Markdown), median of the calls,
  and the difference (the issue's bound: at most 50 ms);
* the first answer after launch: from starting the process to the first ``solve`` result,
  the protocol's handshake included (bound: 2 s), median of a few launches;
* the server's resident memory at rest (after the first answer) and after 1,000 and 2,000
  calls (no growth).

``--transcript`` prints instead a real session in Markdown (the calls and their results, as
docs/mcp.md shows it): the VTU line answered, its conventions named, and a chat answer's table
with the tie the other way marked.

Options: ``--calls N`` (default 1,000), ``--launches N`` (default 5).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import statistics
import sys
import time
from pathlib import Path
from typing import Any

from mcp import Client, StdioServerParameters

from scanconv.mcp_server import answers

QUESTION = "line 5 5 13 9 --algo bresenham"
REFUSED = ("line 0 0 1000000000 1", "circle 2800000", "line 2 2 10")
"""Questions refused: two over the work budget, one bad."""
MIX = (QUESTION, "circle 8 --method midpoint", "ellipse 8 6", "bezier 0 0 1 2 3 3 4 0")


def _params() -> StdioServerParameters:
    return StdioServerParameters(command=sys.executable, args=["-m", "scanconv", "mcp"])


def _server_pid() -> int:
    """The ``scanconv mcp`` process this one started (a child, by its command line)."""
    me = str(os.getpid())
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            cmdline = (entry / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if stat[1] == me and b"mcp" in cmdline and b"scanconv" in cmdline:
            return int(entry.name)
    raise RuntimeError("the server process was not found")


def _rss_mb(pid: int) -> float:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    raise RuntimeError("no VmRSS")


def _cpu_s(pid: int) -> float:
    """The CPU time (user and system) process ``pid`` has used: unlike the wall clock, not
    stretched by the other processes of a loaded machine."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


async def _first_answer() -> tuple[float, float]:
    """The wall time from launch to the first answer, and the server's CPU time by then."""
    start = time.perf_counter()
    async with Client(_params()) as client:
        result = await client.call_tool("solve", {"question": QUESTION})
        elapsed = time.perf_counter() - start
        assert not result.is_error
        cpu = _cpu_s(_server_pid())
    return elapsed, cpu


def _in_process(question: str, n: int) -> list[float]:
    times = []
    for _ in range(n):
        t = time.perf_counter()
        answers.solve(question)
        times.append(time.perf_counter() - t)
    return times


async def measure(calls: int, launches: int) -> dict[str, Any]:
    runs = [await _first_answer() for _ in range(launches)]
    firsts = [wall for wall, _ in runs]
    out: dict[str, Any] = {"first_answer_s": statistics.median(firsts), "firsts": firsts}
    out["first_cpu_s"] = statistics.median(cpu for _, cpu in runs)
    out["load"] = os.getloadavg()[0]
    async with Client(_params()) as client:
        await client.call_tool("solve", {"question": QUESTION})
        pid = _server_pid()
        out["rss_at_rest_mb"] = _rss_mb(pid)
        for question in MIX:
            answers.solve(question)  # warm in-process too
            served = []
            for _ in range(50):
                t = time.perf_counter()
                await client.call_tool("solve", {"question": question})
                served.append(time.perf_counter() - t)
            local = _in_process(question, 50)
            out[question] = (statistics.median(served), statistics.median(local))
        for question in REFUSED:
            refusals = []
            for _ in range(20):
                t = time.perf_counter()
                result = await client.call_tool("solve", {"question": question})
                refusals.append(time.perf_counter() - t)
                assert result.is_error
            out[f"refused {question}"] = statistics.median(refusals)
        for round_ in (1, 2):
            for i in range(calls):
                await client.call_tool("solve", {"question": MIX[i % len(MIX)]})
            out[f"rss_after_{round_ * calls}_mb"] = _rss_mb(pid)
    return out


def report(m: dict[str, Any], calls: int) -> str:
    lines = [
        "| measure | figure |",
        "|---|---|",
        f"| first answer after launch (median of {len(m['firsts'])}) | "
        f"{m['first_answer_s']:.2f} s (each: {', '.join(f'{t:.2f}' for t in m['firsts'])}) |",
        f"| the server's CPU time by its first answer (median) | {m['first_cpu_s']:.2f} s |",
        f"| load average (1 min) at the start, {os.cpu_count()} cores | {m['load']:.1f} |",
    ]
    for question in MIX:
        served, local = m[question]
        lines.append(
            f"| `solve {question}`: warm server / in-process / difference | "
            f"{served * 1000:.1f} ms / {local * 1000:.1f} ms / {(served - local) * 1000:+.1f} ms |"
        )
    for question in REFUSED:
        lines.append(
            f"| `solve {question}` refused (isError), warm server | "
            f"{m[f'refused {question}'] * 1000:.1f} ms |"
        )
    lines.append(f"| server RSS at rest (after the first answer) | {m['rss_at_rest_mb']:.1f} MB |")
    for n in (calls, 2 * calls):
        lines.append(f"| server RSS after {n:,} more calls | {m[f'rss_after_{n}_mb']:.1f} MB |")
    return "\n".join(lines)


# --- the transcript of docs/mcp.md ---------------------------------------------------------------

CHAT_TABLE = """k,p_k,(x_{k+1}, y_{k+1})
0,0,"(6, 5)"
1,8,"(7, 6)"
2,0,"(8, 6)"
3,8,"(9, 7)"
4,0,"(10, 7)"
5,8,"(11, 8)"
6,0,"(12, 8)"
7,8,"(13, 9)"
"""
"""The VTU line as a chat answer plots it: p >= 0 steps y, but a tie (p = 0) keeps it."""


def _shown(value: dict[str, Any]) -> str:
    """Some fields of a result, a field a line (a list's items a line each)."""
    d = json.dumps
    lines = []
    for key, v in value.items():
        if isinstance(v, list) and v and isinstance(v[0], dict):
            items = ",\n  ".join(d(i, ensure_ascii=False) for i in v)
            lines.append(f" {d(key)}: [\n  {items}\n ]")
        else:
            lines.append(f" {d(key)}: {d(v, ensure_ascii=False)}")
    return "{\n" + ",\n".join(lines) + "\n}"


def _first_sentence(text: str) -> str:
    return re.split(r"(?<!\.)\.\s", text)[0]


async def transcript() -> str:
    out: list[str] = []
    async with Client(_params()) as client:
        tools = (await client.list_tools()).tools
        out += ["**tools/list** →", ""]
        out += [f"- `{t.name}`: {_first_sentence(t.description or '')}." for t in tools]
        calls: list[tuple[str, dict[str, Any]]] = [
            ("solve", {"question": QUESTION}),
            ("check", {"question": "line 5 5 13 9", "table": CHAT_TABLE}),
            ("solve", {"question": "line 5 5 13 9 --algo bresenham --tie keep"}),
            ("solve", {"question": "line 5 5 13"}),
            ("solve", {"question": "line 0 0 1000000000 1"}),
        ]
        for name, arguments in calls:
            result = await client.call_tool(name, arguments)
            out += ["", f"**tools/call** `{name}` `{json.dumps(arguments, ensure_ascii=False)}` →"]
            out += [""]
            if result.is_error:
                out += [f"`isError: true`, text: `{result.content[0].text}`"]
                continue
            data = result.structured_content or {}
            keep = (
                ("primitive", "algorithm", "conventions", "steps", "pixels")
                if name == "solve"
                else ("score", "out_of", "first_error", "diagnosis", "marked")
            )
            out += ["structuredContent (some fields):", "", "```json"]
            out += [_shown({k: data[k] for k in keep if k in data}), "```"]
            if name == "solve" and arguments["question"] == QUESTION:
                table = [ln for ln in result.content[0].text.splitlines() if ln.startswith("|")]
                out += ["", "text (the Markdown answer; its step table):", "", *table]
    return "\n".join(out) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=1000)
    parser.add_argument("--launches", type=int, default=5)
    parser.add_argument("--transcript", action="store_true")
    args = parser.parse_args()
    if args.transcript:
        print(asyncio.run(transcript()), end="")
        return
    print(report(asyncio.run(measure(args.calls, args.launches)), args.calls))


if __name__ == "__main__":
    main()

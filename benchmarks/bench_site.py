"""The static site (``scanconv site build``) in headless Chromium: ``python
benchmarks/bench_site.py [--site DIR] [--repeat N]`` (issue 31: size ≤ 30 MB, cold load to
the first answer ≤ 15 s, a later answer ≤ 1 s).

Builds the site (or takes ``--site DIR``), serves it on 127.0.0.1 from a thread and, in
Debian's chromium driven by Playwright, measures for each run in a **fresh browser context**
(no HTTP or compiled-code cache): **cold**, from ``page.goto(SITE#q=line ...)`` until the
answer is shown; the worker's phases (Python up, wheels in, scanconv imported and warm);
then **later**, a question typed into the box until its answer is shown (a Bezier curve, a
circle, a clipping). Prints one Markdown table of medians. Benchmarks never run in the tests.

``--screenshots DIR`` writes docs/figures/site-1280.png and site-390.png instead.
"""

from __future__ import annotations

import argparse
import functools
import shutil
import statistics
import sys
import tempfile
import threading
import time
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

FIRST = "line 2 2 10 6 --algo bresenham"
LATER = (
    "bezier 0 0 1 2 3 3 4 0",
    "circle 8 --method midpoint",
    "clip line 7 9 11 4 --window 4 4 10 8",
)
ANSWERED = "(n) => window.scanconvTimings.answers.length >= n && document.body.dataset.state === 'answered'"


class _Quiet(SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


def serve(folder: Path) -> str:
    server = ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=folder))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return f"http://127.0.0.1:{server.server_port}/"


def build(folder: Path) -> None:
    from scanconv.cli.exam import book
    from scanconv.site.build import build_site

    build_site(folder, lambda: book(None, "html"))


def size(folder: Path) -> tuple[int, int]:
    files = [p for p in folder.rglob("*") if p.is_file()]
    return sum(p.stat().st_size for p in files), len(files)


def one_run(browser: Any, origin: str) -> dict[str, float]:
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    outside: list[str] = []
    page.route(
        "**/*",
        lambda r: (
            r.continue_()
            if r.request.url.startswith(origin)
            else (outside.append(r.request.url), r.abort())
        ),
    )
    t0 = time.perf_counter()
    page.goto(origin + "#q=" + FIRST.replace(" ", "%20"))
    page.wait_for_function(ANSWERED, arg=1, timeout=600_000)
    cold = time.perf_counter() - t0
    timings = page.evaluate("window.scanconvTimings")
    later = []
    for i, q in enumerate(LATER):
        page.fill("#q", q)
        t1 = time.perf_counter()
        page.click("#go")
        page.wait_for_function(ANSWERED, arg=i + 2, timeout=600_000)
        later.append(time.perf_counter() - t1)
    context.close()
    assert not outside, outside
    return {
        "cold": cold,
        "python": timings["phases"]["python"] / 1000,
        "wheels": timings["phases"]["wheels"] / 1000,
        "scanconv": timings["phases"]["scanconv"] / 1000,
        "later": statistics.median(later),
    }


def screenshots(browser: Any, origin: str, out: Path) -> None:
    for width, name in ((1280, "site-1280.png"), (390, "site-390.png")):
        page = browser.new_page(viewport={"width": width, "height": 1000 if width > 400 else 844})
        page.goto(origin + "#q=" + FIRST.replace(" ", "%20"))
        page.wait_for_function(ANSWERED, arg=1, timeout=600_000)
        page.wait_for_timeout(500)
        page.screenshot(path=str(out / name))
        page.close()
        print(f"wrote {out / name}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", type=Path, help="a site built before (default: build one)")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--screenshots", type=Path, metavar="DIR")
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    with tempfile.TemporaryDirectory() as tmp:
        folder = args.site
        if folder is None:
            folder = Path(tmp) / "site"
            t0 = time.perf_counter()
            build(folder)
            print(f"built in {time.perf_counter() - t0:.1f} s", file=sys.stderr)
        origin = serve(folder)
        with sync_playwright() as p:
            browser = p.chromium.launch(
                executable_path=shutil.which("chromium"),
                headless=True,
                args=["--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"],
            )
            if args.screenshots:
                screenshots(browser, origin, args.screenshots)
                return
            runs = [one_run(browser, origin) for _ in range(args.repeat)]
            browser.close()
        total, count = size(folder)
    med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
    print(f"| site | {total / 1e6:.1f} MB in {count} files |")
    print("|---|---|")
    print(f"| cold load to the first answer (median of {len(runs)}) | {med['cold']:.1f} s |")
    print(f"| of which: Python up | {med['python']:.1f} s |")
    print(f"| wheels unpacked (since the worker started) | {med['wheels']:.1f} s |")
    print(f"| scanconv imported and warm | {med['scanconv']:.1f} s |")
    print(f"| a later answer (median) | {med['later'] * 1000:.0f} ms |")
    print(
        "| every run, cold / later | "
        + ", ".join(f"{r['cold']:.1f} s / {r['later'] * 1000:.0f} ms" for r in runs)
        + " |"
    )


if __name__ == "__main__":
    main()

"""Large answers as HTML pages, opened in headless Chromium: ``python benchmarks/bench_html.py``
(issue 16: a 10,000-step line and an r = 1,000 circle open in under a second).

For each answer: the time ``scanconv ... -o page.html`` takes (a real process), the page's
size, then in Debian's chromium driven by Playwright (one browser for the whole run, a fresh
page each time): **open**, from ``page.goto(file://...)`` until the stepper has started (the
answer's section has ``data-ready`` and its first step drawn); **to the end** and **back to
the start**, a key press (End, Home) until the DOM shows it. Medians of ``--repeat`` runs;
prints one Markdown table. Benchmarks never run in the tests.

``--screenshots DIR`` writes the four screenshots of docs/html.md and the README instead.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

SCANCONV = [sys.executable, "-m", "scanconv"]

CASES = [
    ("10,000-step line", ["line", "0", "0", "9999", "4000"]),
    ("r = 1,000 circle", ["circle", "1000"]),
    ("10,000-step DDA line", ["line", "0", "0", "9999", "4000", "--algo", "dda"]),
    ("rx = 600, ry = 400 ellipse", ["ellipse", "600", "400"]),
]

SHOTS = [
    ("html-line.png", ["line", "2", "2", "10", "6"], 5, 1400),
    ("html-circle.png", ["circle", "5"], 3, 1400),
    ("html-ellipse.png", ["ellipse", "8", "6"], 9, 1400),
    (
        "html-bezier.png",
        ["bezier", "0", "0", "1", "2", "3", "3", "4", "0", "--samples", "8"],
        6,
        1400,
    ),
]

READY = "() => document.querySelector('section.scanconv[data-ready]') !== null"
AT = "(p) => document.querySelector('section.scanconv').getAttribute('data-pos') === String(p)"


def _launch(p: Any) -> Any:
    chromium = shutil.which("chromium")
    if chromium is None:
        sys.exit("no chromium on PATH (Debian: apt-get install chromium)")
    return p.chromium.launch(
        executable_path=chromium, headless=True, args=["--host-resolver-rules=MAP * ~NOTFOUND"]
    )


def _open(browser: Any, path: Path) -> tuple[Any, float]:
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    start = time.perf_counter()
    page.goto(path.as_uri())
    page.wait_for_function(READY)
    return page, time.perf_counter() - start


def _key(page: Any, key: str, pos: int) -> float:
    start = time.perf_counter()
    page.keyboard.press(key)
    page.wait_for_function(AT, arg=pos)
    return time.perf_counter() - start


def bench(repeat: int) -> None:
    from playwright.sync_api import sync_playwright

    rows = []
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        browser = _launch(p)
        for name, argv in CASES:
            target = Path(tmp) / "page.html"
            start = time.perf_counter()
            subprocess.run([*SCANCONV, *argv, "-o", str(target)], check=True)
            write = time.perf_counter() - start
            size = target.stat().st_size
            opens, ends, homes = [], [], []
            for _ in range(repeat):
                page, opened = _open(browser, target)
                n = int(page.get_attribute("section.scanconv input.sc-slider", "max") or 0)
                opens.append(opened)
                ends.append(_key(page, "End", n))
                homes.append(_key(page, "Home", 0))
                page.close()
            rows.append(
                f"| {name} | `scanconv {' '.join(argv)}` | {n:,} | {write:.2f} s "
                f"| {size / 1e6:.1f} MB | {statistics.median(opens):.2f} s "
                f"| {statistics.median(ends) * 1000:.0f} ms | {statistics.median(homes) * 1000:.0f} ms |"
            )
        browser.close()
    print("| answer | command | steps | write the page | size | open | End | Home |")
    print("|---|---|--:|--:|--:|--:|--:|--:|")
    print("\n".join(rows))


def screenshots(directory: Path) -> None:
    from playwright.sync_api import sync_playwright

    directory.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        browser = _launch(p)
        for name, argv, step, width in SHOTS:
            target = Path(tmp) / "page.html"
            subprocess.run([*SCANCONV, *argv, "-o", str(target)], check=True)
            page = browser.new_page(viewport={"width": width, "height": 900})
            page.goto(target.as_uri())
            page.wait_for_function(READY)
            page.keyboard.press("ArrowRight")
            for _ in range(step - 1):
                page.keyboard.press("ArrowRight")
            page.wait_for_function(AT, arg=step)
            page.mouse.move(0, 0)
            page.screenshot(path=str(directory / name), full_page=True)
            page.close()
            print(directory / name)
        browser.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--screenshots", type=Path, default=None, metavar="DIR")
    args = parser.parse_args()
    if args.screenshots is not None:
        screenshots(args.screenshots)
    else:
        bench(args.repeat)


if __name__ == "__main__":
    main()

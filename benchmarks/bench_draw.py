"""``scanconv.raster`` against what a programmer would use instead: ``python benchmarks/bench_draw.py``.

For each shape (line, circle, ellipse, filled polygon, Wu's anti-aliased line) the bulk
rasterizer of :mod:`scanconv.raster` is timed beside ``skimage.draw``, OpenCV (``cv2.line``,
``cv2.circle``, ``cv2.ellipse``, ``cv2.fillPoly``) and Pillow's ``ImageDraw`` (the ``bench``
extra), all in one run, each contestant in turn (round robin), the best of the repeats.

OpenCV and Pillow draw into an image; scanconv and skimage return coordinate arrays. So the
array libraries draw into a preallocated 8-bit numpy image (``img[ys, xs] = 255``;
``img[ys, xs] = 255 * v`` for the anti-aliased line), OpenCV into the same image and Pillow
into an ``L`` image of the same size, each cleared between rounds outside the timing. The
ratio is the other library's time over scanconv's (above 1: scanconv is faster). The
workload is a batch of shapes that fit in a 4096 × 4096 image (fixed seed), as one would draw
them. The last column says whether each library drew exactly scanconv's pixels.

Options: ``--repeat N`` (default 7), ``--size`` (the image's side, default 4096), ``--count``
(shapes per batch, default 200; polygons: a tenth of it).
"""

from __future__ import annotations

import argparse
import platform
import random
import time
from collections.abc import Callable
from importlib.metadata import version
from typing import Any

import numpy as np

from scanconv import raster

Image = np.ndarray
Draw = Callable[[Image], Any]


def race(contestants: dict[str, Draw], image: Image, repeat: int) -> dict[str, float]:
    """The best time of each contestant drawing into a cleared image, run in turn ``repeat``
    times after a warm-up. The best rather than the median: on a shared machine the other
    jobs only ever add time."""
    for draw in contestants.values():
        _clear(draw, image)
        draw(image)
    times: dict[str, list[float]] = {name: [] for name in contestants}
    for _ in range(repeat):
        for name, draw in contestants.items():
            _clear(draw, image)
            t0 = time.perf_counter()
            draw(image)
            times[name].append(time.perf_counter() - t0)
    return {name: min(ts) for name, ts in times.items()}


def _clear(draw: Draw, image: Image) -> None:
    image.fill(0)
    clear = getattr(draw, "clear", None)
    if clear is not None:
        clear()


def drawn(draw: Draw, image: Image) -> Image:
    """The pixels ``draw`` sets, as a boolean image."""
    _clear(draw, image)
    draw(image)
    result = getattr(draw, "result", None)
    return (result() if result is not None else image) != 0


class _Pillow:
    """Pillow draws into its own image (it cannot draw into a numpy array): one ``L`` image
    of the same size, cleared between rounds outside the timing like the numpy one."""

    def __init__(self, draw: Callable[[Any], None], size: int) -> None:
        from PIL import Image as PILImage
        from PIL import ImageDraw

        self.canvas = PILImage.new("L", (size, size))
        self.pen = ImageDraw.Draw(self.canvas)
        self.paint = draw

    def __call__(self, image: Image) -> None:
        self.paint(self.pen)

    def clear(self) -> None:
        self.canvas.paste(0, (0, 0, *self.canvas.size))

    def result(self) -> Image:
        return np.asarray(self.canvas)


# --- the shapes ------------------------------------------------------------------------------------


def lines(rng: random.Random, size: int, count: int) -> dict[str, Draw]:
    import cv2
    import skimage.draw

    ends = [tuple(rng.randrange(size) for _ in range(4)) for _ in range(count)]

    def ours(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            xs, ys = raster.line(x1, y1, x2, y2)
            img[ys, xs] = 255

    def sk(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            rr, cc = skimage.draw.line(y1, x1, y2, x2)
            img[rr, cc] = 255

    def cv(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            cv2.line(img, (x1, y1), (x2, y2), 255, 1, cv2.LINE_8)

    def pil(d: Any) -> None:
        for x1, y1, x2, y2 in ends:
            d.line((x1, y1, x2, y2), fill=255)

    return {"scanconv": ours, "skimage": sk, "OpenCV": cv, "Pillow": _Pillow(pil, size)}


def circles(rng: random.Random, size: int, count: int) -> dict[str, Draw]:
    import cv2
    import skimage.draw

    shapes = []
    for _ in range(count):
        r = rng.randrange(1, size // 2)
        shapes.append((rng.randrange(r, size - r), rng.randrange(r, size - r), r))

    def ours(img: Image) -> None:
        for xc, yc, r in shapes:
            xs, ys = raster.circle(r, xc, yc)
            img[ys, xs] = 255

    def sk(img: Image) -> None:
        for xc, yc, r in shapes:
            rr, cc = skimage.draw.circle_perimeter(yc, xc, r, method="bresenham")
            img[rr, cc] = 255

    def cv(img: Image) -> None:
        for xc, yc, r in shapes:
            cv2.circle(img, (xc, yc), r, 255, 1, cv2.LINE_8)

    def pil(d: Any) -> None:
        for xc, yc, r in shapes:
            d.ellipse((xc - r, yc - r, xc + r, yc + r), outline=255)

    return {"scanconv": ours, "skimage": sk, "OpenCV": cv, "Pillow": _Pillow(pil, size)}


def ellipses(rng: random.Random, size: int, count: int) -> dict[str, Draw]:
    import cv2
    import skimage.draw

    shapes = []
    for _ in range(count):
        rx, ry = rng.randrange(1, size // 2), rng.randrange(1, size // 2)
        shapes.append((rng.randrange(rx, size - rx), rng.randrange(ry, size - ry), rx, ry))

    def ours(img: Image) -> None:
        for xc, yc, rx, ry in shapes:
            xs, ys = raster.ellipse(rx, ry, xc, yc)
            img[ys, xs] = 255

    def sk(img: Image) -> None:
        for xc, yc, rx, ry in shapes:
            rr, cc = skimage.draw.ellipse_perimeter(yc, xc, ry, rx)
            img[rr, cc] = 255

    def cv(img: Image) -> None:
        for xc, yc, rx, ry in shapes:
            cv2.ellipse(img, (xc, yc), (rx, ry), 0, 0, 360, 255, 1, cv2.LINE_8)

    def pil(d: Any) -> None:
        for xc, yc, rx, ry in shapes:
            d.ellipse((xc - rx, yc - ry, xc + rx, yc + ry), outline=255)

    return {"scanconv": ours, "skimage": sk, "OpenCV": cv, "Pillow": _Pillow(pil, size)}


def polygons(rng: random.Random, size: int, count: int) -> dict[str, Draw]:
    """Star-shaped polygons of 50 vertices each (concave, never self-crossing), up to a
    quarter of the image across."""
    import cv2
    import skimage.draw

    shapes = []
    for _ in range(max(1, count // 10)):
        r = rng.randrange(size // 16, size // 8)
        xc, yc = rng.randrange(r, size - r), rng.randrange(r, size - r)
        angles = sorted(rng.uniform(0, 2 * np.pi) for _ in range(50))
        radii = [rng.uniform(0.3, 1.0) * (r - 1) for _ in angles]
        xs = np.array([round(xc + q * np.cos(a)) for a, q in zip(angles, radii, strict=True)])
        ys = np.array([round(yc + q * np.sin(a)) for a, q in zip(angles, radii, strict=True)])
        shapes.append((xs.astype(np.int64), ys.astype(np.int64)))

    def ours(img: Image) -> None:
        for xs, ys in shapes:
            px, py = raster.polygon(xs, ys)
            img[py, px] = 255

    def sk(img: Image) -> None:
        for xs, ys in shapes:
            rr, cc = skimage.draw.polygon(ys, xs, img.shape)
            img[rr, cc] = 255

    def cv(img: Image) -> None:
        for xs, ys in shapes:
            cv2.fillPoly(img, [np.stack((xs, ys), axis=1).astype(np.int32)], 255, cv2.LINE_8)

    def pil(d: Any) -> None:
        for xs, ys in shapes:
            d.polygon(list(zip(xs.tolist(), ys.tolist(), strict=True)), fill=255)

    return {"scanconv": ours, "skimage": sk, "OpenCV": cv, "Pillow": _Pillow(pil, size)}


def lines_aa(rng: random.Random, size: int, count: int) -> dict[str, Draw]:
    """Pillow's ImageDraw has no anti-aliased line."""
    import cv2
    import skimage.draw

    ends = [tuple(rng.randrange(1, size - 1) for _ in range(4)) for _ in range(count)]

    def ours(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            xs, ys, v = raster.line_aa(x1, y1, x2, y2)
            img[ys, xs] = np.round(255 * v)

    def sk(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            rr, cc, v = skimage.draw.line_aa(y1, x1, y2, x2)
            img[rr, cc] = np.round(255 * v)

    def cv(img: Image) -> None:
        for x1, y1, x2, y2 in ends:
            cv2.line(img, (x1, y1), (x2, y2), 255, 1, cv2.LINE_AA)

    return {"scanconv": ours, "skimage": sk, "OpenCV": cv}


SHAPES: dict[str, tuple[Callable[[random.Random, int, int], dict[str, Draw]], str]] = {
    "line": (lines, "`raster.line` (Bresenham)"),
    "circle": (circles, "`raster.circle` (midpoint)"),
    "ellipse": (ellipses, "`raster.ellipse` (midpoint)"),
    "polygon": (polygons, "`raster.polygon` (scan-line fill, even-odd)"),
    "line_aa": (lines_aa, "`raster.line_aa` (Wu)"),
}
OTHERS = ("skimage", "OpenCV", "Pillow")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--size", type=int, default=4096)
    parser.add_argument("--count", type=int, default=200)
    args = parser.parse_args()
    image = np.zeros((args.size, args.size), dtype=np.uint8)
    print(
        f"Python {platform.python_version()}, numpy {version('numpy')}, scikit-image "
        f"{version('scikit-image')}, opencv-python-headless {version('opencv-python-headless')}, "
        f"Pillow {version('pillow')}; {args.size} x {args.size} image, best of {args.repeat}\n"
    )
    print("| shape (batch) | scanconv | skimage | OpenCV | Pillow | same pixels as scanconv |")
    print("|---|--:|--:|--:|--:|---|")
    for name, (make, label) in SHAPES.items():
        contestants = make(random.Random(name), args.size, args.count)
        t = race(contestants, image, args.repeat)
        ours = drawn(contestants["scanconv"], image).copy()
        same = []
        for other in OTHERS:
            if other in contestants:
                agree = np.array_equal(drawn(contestants[other], image), ours)
                same.append(f"{other}: {'yes' if agree else 'no'}")
        cells = [f"{t['scanconv'] * 1e3:.1f} ms"]
        for other in OTHERS:
            cells.append(
                f"{t[other] * 1e3:.1f} ms ({t[other] / t['scanconv']:.2f})" if other in t else "n/a"
            )
        n = args.count if name != "polygon" else max(1, args.count // 10)
        print(f"| {label}, {n} | {' | '.join(cells)} | {', '.join(same)} |")


if __name__ == "__main__":
    main()

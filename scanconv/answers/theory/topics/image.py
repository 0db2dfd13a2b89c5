"""Theory answers of the notes' image-representation section: the image, its types, sampling
and quantization, the storage formula and the RGB colour model."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ....algorithms.storage import bits_per_pixel, storage_bits
from ....core import lazy
from ....core.records import Solution
from ._build import Topic, answer, embed, text_table

if TYPE_CHECKING:
    from ...image import color, quantize, ramp
    from ...image import storage as answers_storage
else:
    color = lazy.module("scanconv.answers.image.color")
    quantize = lazy.module("scanconv.answers.image.quantize")
    ramp = lazy.module("scanconv.answers.image.ramp")
    answers_storage = lazy.module("scanconv.answers.image.storage")

SECTION = "image-representation"

_PARAMETERS = text_table(
    "Image representation parameters (the notes' list)",
    ["parameter", "meaning"],
    [
        ("Resolution (spatial)", "pixels in rows (M) and columns (N)"),
        ("Intensity resolution", "number of intensity levels L"),
        ("Pixel", "the smallest element of an image"),
        ("Aspect ratio", "width / height"),
        ("Storage", "M x N x log2 L bits"),
    ],
)


def image() -> Solution:
    return answer(
        "image",
        "Define image and image representation",
        definition=(
            "an image is a two-dimensional function $f(x, y)$, where x and y are spatial (plane) "
            "coordinates and the value of f at (x, y) is the intensity, or gray level, of the "
            "image at that point. Image representation is the digital form a computer keeps it "
            "in: a matrix of M rows and N columns of pixels, each holding one of L intensity "
            "levels."
        ),
        paragraphs=(
            "A continuous image becomes digital by two processes: sampling (a finite grid of "
            "points) and quantization (a finite set of levels).",
        ),
        points=(
            "An image is a 2D function f(x, y).",
            "Needed to store, process, analyse and transmit images in a computer.",
            "Needed to show images on raster display devices.",
            "The basis of computer graphics, CAD and medical imaging.",
        ),
        tables=(_PARAMETERS,),
        examples=(
            embed(
                "the notes' 8 × 8 image of L = 8 gray levels (scanconv image ramp)",
                ramp.ramp_solution(8, 8, 8),
                working=False,
            ),
        ),
    )


def types() -> Solution:
    rgb = (51, 102, 153)
    colour = color.color_solution("rgb", list(rgb), ["grey"])
    one = text_table(
        "One pixel of each type, and its bits",
        ["image", "pixel value", "bits", "bits per pixel"],
        [
            ("Binary", "1 (white)", "1", 1),
            ("Grayscale, L = 8", "5 (very light gray)", "101", 3),
            ("Colour, 24-bit", str(rgb), " ".join(f"{v:08b}" for v in rgb), 24),
        ],
    )
    sizes = text_table(
        "Storage of a 640 × 480 image of each type",
        ["image", "bits per pixel", "bits", "bytes"],
        [
            (name, k, storage_bits(640, 480, k), storage_bits(640, 480, k) // 8)
            for name, k in (
                ("Binary", 1),
                ("Grayscale, L = 256", bits_per_pixel(256)),
                ("Colour, 24-bit", 24),
            )
        ],
    )
    kinds = text_table(
        "The three types (the notes)",
        ["type", "values", "bits per pixel"],
        [
            ("Binary (monochrome)", "0 (black), 1 (white)", "1"),
            ("Grayscale", "0 .. L - 1 gray levels", "log2 L"),
            ("Colour", "(R, G, B), each 0 .. 255", "24 (true colour)"),
        ],
    )
    return answer(
        "image-types",
        "Explain binary, grayscale and color images",
        definition=(
            "images are classed by what a pixel can hold. A binary (monochrome) image has two "
            "values, 0 (black) and 1 (white), so each pixel needs 1 bit. A grayscale image has "
            "L gray levels 0 .. L - 1 and needs $\\log_2 L$ bits a pixel (L = 8: 3 bits). A "
            "colour image combines red, green and blue components in each pixel; in 24-bit "
            "true colour each component has 8 bits, 24 bits a pixel."
        ),
        paragraphs=(
            "The common colour models are RGB, CMY, HSV and HSI (scanconv color converts "
            "between them). The colour pixel below is worked in full: each channel's bits and "
            "the hex code.",
        ),
        tables=(kinds, one, sizes),
        examples=(
            embed(
                "the colour pixel (51, 102, 153) in bits (scanconv color rgb 51 102 153)",
                colour,
            ),
        ),
    )


def sampling() -> Solution:
    return answer(
        "sampling-quantization",
        "What are sampling and quantization? Explain",
        definition=(
            "sampling is the process of converting a continuous image into a set of discrete "
            "points (the pixel grid); quantization is the process of assigning each sampled "
            "point one of a finite set of intensity values (the gray levels). Together they "
            "make a continuous image digital."
        ),
        paragraphs=(
            "Sampling fixes the spatial resolution: a denser grid keeps more detail. "
            "Quantization fixes the intensity resolution: more gray levels give a better "
            "picture but need more storage, $\\log_2 L$ bits a pixel. Sampling digitises the "
            "coordinates, quantization the amplitude.",
            "scanconv sample 'x + y' --size 8x8 --levels 8 samples and quantizes a function; "
            "below is the notes' 3-bit quantization table.",
        ),
        points=(
            "Sampling converts a continuous image to discrete points.",
            "Quantization converts infinite intensities to finite levels.",
            "Sampling density decides the level of detail.",
            "More gray levels: better quality, more storage.",
        ),
        examples=(
            embed(
                "3-bit quantization, 8 gray levels (scanconv quantize --bits 3)",
                quantize.quantize_solution(3),
            ),
        ),
    )


def storage() -> Solution:
    return answer(
        "storage-formula",
        "Write the storage requirement formula for an image",
        definition=(
            "an image of M rows and N columns with L intensity levels needs "
            "$M \\times N \\times \\log_2 L$ bits, since each of its $M \\times N$ pixels holds "
            "$k = \\log_2 L$ bits (rounded up to a whole number of bits when L is not a power "
            "of two). Dividing by 8 gives bytes."
        ),
        paragraphs=(
            "Special cases: a binary image needs $M \\times N$ bits (k = 1); a 24-bit colour "
            "image $24 M N$ bits.",
        ),
        examples=(
            embed(
                "a 1024 × 768 image with L = 256 (scanconv storage 1024 768 --levels 256)",
                answers_storage.storage_solution(1024, 768, levels=256),
            ),
        ),
    )


_PRIMARIES = text_table(
    "The corners of the RGB cube",
    ["colour", "(R, G, B)", "hex"],
    [
        ("black", "(0, 0, 0)", "#000000"),
        ("red", "(255, 0, 0)", "#FF0000"),
        ("green", "(0, 255, 0)", "#00FF00"),
        ("blue", "(0, 0, 255)", "#0000FF"),
        ("yellow", "(255, 255, 0)", "#FFFF00"),
        ("cyan", "(0, 255, 255)", "#00FFFF"),
        ("magenta", "(255, 0, 255)", "#FF00FF"),
        ("white", "(255, 255, 255)", "#FFFFFF"),
    ],
)


def rgb() -> Solution:
    return answer(
        "rgb-model",
        "Explain RGB color model with example",
        definition=(
            "the RGB colour model describes each colour as a mixture of the three additive "
            "primaries red, green and blue, written as the triple (R, G, B). It is the model "
            "of displays, which emit light: adding all three at full strength gives white, "
            "none gives black."
        ),
        paragraphs=(
            "Geometrically the colours form a cube with black at the origin, red, green and "
            "blue on the axes, their sums cyan, magenta and yellow at the other corners, and "
            "white opposite black; the diagonal from black to white holds the grays "
            "(R = G = B).",
            "In a 24-bit true-colour image each component has 8 bits (0 .. 255), so a pixel "
            "needs 24 bits and there are $2^{24} = 16{,}777{,}216$ colours. CMY is RGB's "
            "subtractive complement (C = 1 - R, M = 1 - G, Y = 1 - B), used for printing.",
        ),
        points=(
            "Each pixel = (R, G, B).",
            "Each component = 8 bits (0 .. 255).",
            "Total = 24 bits per pixel.",
            "Additive: R + G + B at full strength is white.",
        ),
        tables=(_PRIMARIES,),
        examples=(
            embed(
                "the colour (51, 102, 153) (scanconv color rgb 51 102 153 --to cmy)",
                color.color_solution("rgb", [51, 102, 153], ["cmy"]),
            ),
        ),
    )


TOPICS = (
    Topic(
        "image",
        SECTION,
        "Define image and image representation",
        ("Define image and image representation.",),
        image,
    ),
    Topic(
        "image-types",
        SECTION,
        "Explain binary, grayscale and color images",
        ("Explain binary, grayscale and color images.",),
        types,
    ),
    Topic(
        "sampling-quantization",
        SECTION,
        "What are sampling and quantization? Explain",
        ("What are sampling and quantization? Explain.",),
        sampling,
    ),
    Topic(
        "storage-formula",
        SECTION,
        "Write the storage requirement formula for an image",
        ("Write the storage requirement formula for an image.",),
        storage,
    ),
    Topic(
        "rgb-model",
        SECTION,
        "Explain RGB color model with example",
        ("Explain RGB color model with example.",),
        rgb,
    ),
)

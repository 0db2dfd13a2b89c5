"""``scanconv practice``: the same seed gives the same bytes; the promised variety is there by
construction (checked over 1,000 seeds) and true of the questions themselves (recomputed from
their numbers and their answers, not from the generator's own tags); nothing degenerate;
every question is one scanconv answers; the worksheet and key are the sheet's.
"""

from __future__ import annotations

import json
import shutil
from fractions import Fraction
from pathlib import Path

import pytest

from scanconv.cli.sheet import answer_questions, read_questions
from scanconv.practice.notes import DIFFICULTIES, TOPICS, practice, question_file
from scanconv.practice.records import octant

from .helpers import assert_refused, run

SEEDS = range(1000)


def _line_numbers(argv: tuple[str, ...]) -> tuple[int, int, int, int]:
    x1, y1, x2, y2 = (int(v) for v in argv[1:5])
    return x1, y1, x2, y2


def _shown(argv: tuple[str, ...]) -> set[str]:
    """The variety a question shows, worked out from its command line alone."""
    found: set[str] = set()
    if argv[0] == "line":
        x1, y1, x2, y2 = _line_numbers(argv)
        dx, dy = x2 - x1, y2 - y1
        found.add(f"octant {octant(dx, dy)}")
        if abs(dy) > abs(dx):
            found.add("steep")
        if dx * dy < 0:
            found.add("negative slope")
        if dx < 0:
            found.add("right to left")
    if argv[0] in ("circle", "ellipse") and "--center" in argv:
        i = argv.index("--center")
        if (int(argv[i + 1]), int(argv[i + 2])) != (0, 0):
            found.add("centre away")
    if argv[0] == "ellipse":
        found.add("tall" if int(argv[2]) > int(argv[1]) else "wide")
    if argv[0] == "bezier":
        values = argv[1 : next(i for i, a in enumerate(argv) if a.startswith("--"))]
        found.add("cubic" if len(values) == 8 else "quadratic")
    return found


def _has_tie(argv: tuple[str, ...]) -> bool:
    """Whether the line's own answer meets a tie: Bresenham's p = 0 at a decision, or a DDA
    coordinate exactly halfway between two pixels."""
    from scanconv import _api as api

    x1, y1, x2, y2 = _line_numbers(argv)
    algo = argv[argv.index("--algo") + 1]
    solution = api.line(x1, y1, x2, y2, algo=algo)
    if algo == "bresenham":
        return any(s.p == 0 and s.decision is not None for s in solution.steps())
    half = Fraction(1, 2)
    return any(
        isinstance(v, Fraction) and v - (v.numerator // v.denominator) == half
        for s in solution.steps()
        for v in s.extra
    )


EXPECTED = {f"octant {i}" for i in range(1, 9)}
EXPECTED |= {"steep", "negative slope", "right to left", "centre away", "tall", "wide"}
EXPECTED |= {"cubic", "quadratic"}


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("difficulty", DIFFICULTIES)
def test_over_1000_seeds_every_promised_variety_appears(difficulty: str) -> None:
    seen: set[str] = set()
    ties = 0
    for seed in SEEDS:
        for q in practice("all", 10, seed, difficulty):
            shown = _shown(q.argv)
            assert shown <= q.features  # the generator's tags are true of the question
            seen |= shown
            if "tie" in q.features and seed % 50 == 0:
                assert _has_tie(q.argv), q.argv
                ties += 1
    assert EXPECTED <= seen, EXPECTED - seen
    assert ties > 0


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("difficulty", DIFFICULTIES)
def test_eight_line_questions_cover_every_octant_and_four_ties(difficulty: str) -> None:
    for seed in range(200):
        questions = practice("line", 8, seed, difficulty)
        octants = {
            octant(x2 - x1, y2 - y1)
            for x1, y1, x2, y2 in map(_line_numbers, (q.argv for q in questions))
        }
        assert octants == set(range(1, 9)), seed
        tied = [q for q in questions if "tie" in q.features]
        assert len(tied) == 4
        if seed % 20 == 0:
            assert all(_has_tie(q.argv) for q in tied)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("difficulty", DIFFICULTIES)
def test_no_question_is_degenerate(difficulty: str) -> None:
    for seed in range(300):
        for q in practice("all", 20, seed, difficulty):
            a = q.argv
            if a[0] == "line":
                x1, y1, x2, y2 = _line_numbers(a)
                dx, dy = abs(x2 - x1), abs(y2 - y1)
                assert dx and dy and dx != dy, a
            elif a[0] == "circle":
                assert int(a[1]) >= 2
            elif a[0] == "ellipse":
                assert int(a[1]) >= 2 and int(a[2]) >= 2 and a[1] != a[2]
            elif a[0] in ("bezier", "bspline"):
                end = next(i for i, v in enumerate(a) if v.startswith("--"))
                values = [int(v) for v in a[1:end]]
                points = list(zip(values[::2], values[1::2], strict=True))
                assert len(set(points)) == len(points), a
                (x0, y0), (xn, yn) = points[0], points[-1]
                assert any((xn - x0) * (y - y0) != (yn - y0) * (x - x0) for x, y in points), a


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_exam_lines_have_6_to_12_steps_and_small_integers() -> None:
    for seed in range(300):
        for q in practice("line", 10, seed, "exam"):
            x1, y1, x2, y2 = _line_numbers(q.argv)
            assert 6 <= max(abs(x2 - x1), abs(y2 - y1)) <= 12
            assert all(0 <= v <= 20 for v in (x1, y1, x2, y2))
            assert q.marks == 14


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_exam_circles_have_6_to_12_rows() -> None:
    sheet = read_questions(question_file(practice("circle", 40, 3, "exam"), "c"))
    for a in answer_questions(sheet.questions):
        steps = sum(1 for _ in a.solution.steps())
        assert 6 <= steps <= 12, (a.question.argv, steps)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("difficulty", DIFFICULTIES)
def test_every_generated_question_is_answered_by_scanconv(difficulty: str) -> None:
    for seed in range(15):
        questions = practice("all", 20, seed, difficulty)
        sheet = read_questions(question_file(questions, "t"), "p")
        answered = answer_questions(sheet.questions, "p")
        assert [a.question.argv for a in answered] == [q.argv for q in questions]


#: The topics whose questions are other commands than the topic's name.
COMMANDS = {
    "attributes": {"linestyle", "thickline"},
    "characters": {"char"},
    "midpoint-line": {"line"},
    "line-methods": {"line"},
    "dither": {"dither", "halftone", "printer"},
    "visible": {"3d"},
}


@pytest.mark.parametrize("topic", TOPICS)
def test_each_topic_gives_only_its_own_questions(topic: str) -> None:
    assert {q.argv[0] for q in practice(topic, 12, 9)} == COMMANDS.get(topic, {topic})


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_same_seed_gives_byte_identical_files(tmp_path: Path) -> None:
    outputs = []
    for n in range(2):
        d = tmp_path / str(n)
        d.mkdir()
        r = run(
            "practice", "--seed", "42", "--count", "12", "-o", str(d / "w.md"),
            "--key", str(d / "k.tex"), "--questions", str(d / "q.txt"),
        )  # fmt: skip
        assert r.code == 0 and r.out == "" and r.err == "", r.err
        outputs.append([(d / name).read_bytes() for name in ("w.md", "k.tex", "q.txt")])
    assert outputs[0] == outputs[1]
    other = run("practice", "--seed", "43", "--count", "12", "--format", "json")
    assert other.out.encode() != outputs[0][0]
    assert run("practice", "--seed", "42", "--count", "12").out.encode() == outputs[0][0]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_the_worksheet_and_key_are_the_sheets_of_the_question_file(tmp_path: Path) -> None:
    q, k = tmp_path / "q.txt", tmp_path / "k.md"
    r = run(
        "practice",
        "--topic",
        "line",
        "-n",
        "3",
        "--seed",
        "5",
        "--key",
        str(k),
        "--questions",
        str(q),
    )
    assert r.code == 0, r.err
    assert run("sheet", str(q), "--worksheet").out == r.out
    assert run("sheet", str(q)).out == k.read_text()
    assert r.out.startswith("# Practice: line, exam, seed 5\n\nWorksheet: 3 questions, 42 marks.")


def test_without_a_seed_it_says_which_seed_it_chose() -> None:
    r = run("practice", "--count", "1", "--format", "json")
    assert r.code == 0
    seed = int(r.err.split("--seed ")[1].split(" ")[0])
    assert run("practice", "--count", "1", "--format", "json", "--seed", str(seed)).out == r.out
    assert json.loads(r.out)["kind"] == "worksheet"


def test_bad_practice_input(tmp_path: Path) -> None:
    assert_refused(run("practice", "--count", "0", "--seed", "1"), "--count must be 1 to 200")
    assert_refused(
        run("practice", "--topic", "lines", "--seed", "1"), "'lines'", "did you mean 'line'?"
    )
    assert_refused(run("practice", "--seed", "1", "--key", str(tmp_path / "k.docx")), ".docx")
    assert_refused(run("practice", "--seed", "1", "--key", ""), "--key needs a file name")
    assert list(tmp_path.iterdir()) == []


def test_unwritable_key_is_exit_1(tmp_path: Path) -> None:
    r = run("practice", "--seed", "1", "-n", "1", "--key", str(tmp_path / "no" / "k.md"))
    assert r.code == 1 and "cannot write" in r.err and r.err.count("\n") == 1


@pytest.mark.external
def test_practice_typesets_the_worksheet_and_the_key(tmp_path: Path) -> None:
    if not shutil.which("pdflatex"):
        pytest.skip("pdflatex not installed")
    w, k = tmp_path / "w.pdf", tmp_path / "k.pdf"
    r = run("practice", "--seed", "3", "-n", "4", "--pdf", str(w), "--key", str(k))
    assert r.code == 0 and r.out == "", r.err
    assert w.read_bytes().startswith(b"%PDF") and k.read_bytes().startswith(b"%PDF")
    assert w.read_bytes() != k.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["k.pdf", "w.pdf"]

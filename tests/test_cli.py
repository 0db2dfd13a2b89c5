"""The CLI: every format, terminal detection, colour, errors, files and pipes."""

from __future__ import annotations

import csv
import io
import json
import os
import pty
import re
import select
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from scanconv.answers.methods import methods_of
from scanconv.render import formats

from .helpers import assert_refused, run, run_process

ANSI = re.compile(r"\x1b\[")
COLOUR = re.compile(r"\x1b\[[0-9;]*(3[0-7]|38;|9[0-7])[0-9;]*m")
BOX = re.compile(r"[\u2500-\u257f]")
LINE = ("line", "2", "2", "10", "6", "--algo", "bresenham")
FORMATS = formats("answer")
"""Every format of a single answer, from the format table (a new one is walked here at once)."""


PAIR = re.compile(r"\((-?\d+), (-?\d+)\)")


def _pairs(text: str) -> list[tuple[int, int]]:
    return [(int(x), int(y)) for x, y in PAIR.findall(text)]


def _plotted(out: str) -> list[tuple[int, int]]:
    """The pixels listed under "Pixels plotted (N)", N checked (markdown, latex, plain, rich)."""
    rest = out.partition("Pixels plotted (")[2]
    assert rest, out
    count = int(rest.split(")", 1)[0])
    lines = rest.splitlines()[1:]
    start = next(i for i, ln in enumerate(lines) if PAIR.search(ln))
    listed = []
    for ln in lines[start:]:
        if not PAIR.search(ln):
            break
        listed += _pairs(ln)
    assert len(listed) == count
    return listed


def _table_pixels(out: str, fmt: str) -> list[tuple[int, int]]:
    """The pixel of each step-table row: the one ``(x, y)`` cell of the row."""
    if fmt == "markdown":
        rows = [ln for ln in out.splitlines() if ln.startswith("|") and PAIR.search(ln)]
    elif fmt == "latex":
        rows = [ln for ln in out.splitlines() if ln.endswith("\\\\") and PAIR.search(ln)]
    else:  # plain and rich: the rows between the table's heading and "Pixels plotted"
        table = out.split("Step table", 1)[1].split("Pixels plotted", 1)[0]
        rows = [ln for ln in table.splitlines() if PAIR.search(ln)]
    assert all(len(_pairs(row)) == 1 for row in rows), rows
    return [_pairs(row)[0] for row in rows]


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("algo", [m for m in methods_of("line") if m != "wu"])  # wu: intensities
def test_every_format_and_algorithm(fmt, algo):
    """Each format, parsed, gives the solution's own pixels: JSON ``pixels`` and each step's
    ``pixel``, the CSV rows' x and y, the table rows and the list of pixels plotted."""
    from scanconv import _api

    solution = _api.line(2, 2, 10, 6, algo)  # what the command shows
    pixels = list(solution.pixels())
    steps = [s.pixel for s in solution.steps()]
    r = run("line", "2", "2", "10", "6", "--algo", algo, "--format", fmt)
    assert r.code == 0 and r.err == ""
    assert not ANSI.search(r.out)
    if fmt != "rich":
        assert not BOX.search(r.out)
    if fmt == "json":
        doc = json.loads(r.out)
        assert [tuple(p) for p in doc["pixels"]] == pixels
        assert [tuple(s["pixel"]) for s in doc["steps"]] == steps
    elif fmt == "csv":
        header, *rows = list(csv.reader(io.StringIO(r.out)))
        px, py = ("plot_x", "plot_y") if "plot_x" in header else ("x", "y")  # the pixel's
        x, y = header.index(px), header.index(py)
        assert [(int(row[x]), int(row[y])) for row in rows] == steps
        # every row's pixel is plotted (a pixel repeated by consecutive rows once: the DDAs')
        once = [p for i, p in enumerate(steps) if i == 0 or p != steps[i - 1]]
        assert pixels[len(pixels) - len(once) :] == once
    elif fmt == "html":
        drawn = re.findall(
            r'<rect class="sc-px" data-i="\d+" data-x="(-?\d+)" data-y="(-?\d+)"', r.out
        )
        assert [(int(x), int(y)) for x, y in drawn] == pixels
        assert r.out.count("<tr data-pos=") == len(steps)
    elif fmt in ("rich", "markdown", "latex", "plain"):
        assert _plotted(r.out) == pixels
        assert _table_pixels(r.out, fmt) == steps
    else:
        pytest.fail(f"no reader here for the format {fmt}: add one")


def test_plain_is_ascii():
    for algo in ("bresenham", "dda", "basic"):
        r = run(
            "line",
            "-3",
            "7",
            "4",
            "-1.5",
            "--algo",
            algo if algo != "bresenham" else "dda",
            "-f",
            "plain",
        )
        assert r.code == 0
        assert r.out.isascii(), [c for c in r.out if not c.isascii()]


def test_json_shape():
    r = run(*LINE, "--format", "json")
    doc = json.loads(r.out)
    assert doc["primitive"] == "line" and doc["algorithm"] == "bresenham"
    assert doc["derived"]["p0"] == 0 and doc["given"]["P1"] == [2, 2]
    # the notes' layout: row k plots (x_k, y_k), row 0 the start point
    assert doc["steps"][0] == {"k": 0, "p": 0, "decision": "NE", "pixel": [2, 2], "p_next": -8}
    assert doc["pixels"][0] == [2, 2] and doc["pixels"][-1] == [10, 6]
    assert [s["pixel"] for s in doc["steps"]] == doc["pixels"]


def test_json_dda_has_no_p_and_numbers_are_numbers():
    doc = json.loads(run("line", "2", "2", "5", "10", "--algo", "dda", "-f", "json").out)
    step = doc["steps"][1]
    assert "p" not in step and "decision" not in step
    assert step["x"] == 2.375 and step["y"] == 3 and isinstance(step["y"], int)
    assert doc["derived"]["x_inc"] == 0.375


def test_csv_is_the_table_only():
    rows = list(csv.reader(io.StringIO(run(*LINE, "-f", "csv").out)))
    assert rows[0] == ["k", "p", "decision", "x", "y", "p_next"]
    assert rows[1] == ["0", "0", "NE", "2", "2", "-8"]  # row 0: the start point
    assert len(rows) == 10


def test_markdown_table_and_math():
    out = run(*LINE, "-f", "markdown").out
    assert out.startswith("## Bresenham")
    assert re.search(r"^\| +\$k\$ \| +\$p_k\$ \|", out, re.M)
    assert "$p_0 = 2\\Delta y - \\Delta x = 2 \\cdot 4 - 8 = 0$" in out
    assert "```text\n" in out


def test_latex_fragment_escapes_text_and_sets_numbers_in_math():
    out = run(*LINE, "-f", "latex").out
    assert "\\toprule" in out and "\\bottomrule" in out
    assert "$-8$" in out
    assert "\\$" not in out  # tabulate's latex_booktabs trap: math must not be escaped
    assert "≥" not in out and "→" not in out


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_auto_is_markdown_when_piped():
    r = run_process(*LINE)
    assert r.code == 0
    assert r.out.startswith("## ")
    assert not ANSI.search(r.out) and not BOX.search(r.out)


def _tty_output(args: list[str], env: dict[str, str]) -> str:
    master, slave = pty.openpty()
    proc = subprocess.Popen(
        [sys.executable, "-m", "scanconv", *args],
        stdout=slave,
        stderr=slave,
        env={**{k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "TERM")}, **env},
    )
    os.close(slave)
    chunks = []
    while True:
        ready, _, _ = select.select([master], [], [], 30)
        if not ready:
            break
        try:
            data = os.read(master, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    proc.wait(timeout=30)
    os.close(master)
    return b"".join(chunks).decode("utf-8", "replace")


@pytest.mark.slow  # a real process on a pseudo-terminal
def test_auto_is_rich_on_a_terminal_and_honours_no_color():
    coloured = _tty_output(list(LINE), {"TERM": "xterm-256color", "COLUMNS": "120"})
    assert BOX.search(coloured) and COLOUR.search(coloured)
    plain = _tty_output(list(LINE), {"TERM": "xterm-256color", "COLUMNS": "120", "NO_COLOR": "1"})
    assert BOX.search(plain)  # still the rich format
    assert not COLOUR.search(plain)


BAD = [
    (["line", "a", "2", "3", "4"], "'a' is not a number"),
    (["line", "nan", "2", "3", "4"], "not a finite number"),
    (["line", "1", "inf", "3", "4"], "not a finite number"),
    (["line", "1", "2", "3", "-Infinity"], "not a finite number"),
    (["line", "", "2", "3", "4"], "empty"),
    (["line", "1", "2", "3"], "Missing argument"),
    (["line", "1", "2", "3", "4", "5"], "unexpected extra argument"),
    (["line", "2.5", "2", "3", "4", "--algo", "bresenham"], "integer end points"),
    (["line", "1", "2", "3", "4", "--algo", "xiaolin"], "'xiaolin' is not one of"),
    (["line", "1", "2", "3", "4", "--format", "docx"], "'docx' is not one of"),
    (["line", "1", "2", "3", "4", "--origin", "middle"], "'middle' is not one of"),
    (["line", "1", "2", "3", "4", "--bogus"], "--bogus"),
    (["line", "1e999", "2", "3", "4"], "out of range"),
    (["line", "1/0", "2", "3", "4"], "divides by zero"),
    (["line", "9" * 60, "2", "3", "4"], "longer than"),
    (["nope"], "No such command"),
]


@pytest.mark.parametrize(("args", "message"), BAD, ids=[" ".join(a)[:40] for a, _ in BAD])
def test_bad_input_is_one_line_exit_2(args, message):
    assert_refused(run(*args), message)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_bad_input_in_a_real_process():
    r = run_process("line", "x", "1", "2", "3")
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1


def test_output_file_is_written_atomically(tmp_path: Path):
    target = tmp_path / "answer.md"
    r = run(*LINE, "--output", str(target))
    assert r.code == 0 and r.out == ""
    assert target.read_text().startswith("## Bresenham")
    assert [p.name for p in tmp_path.iterdir()] == ["answer.md"]


def test_unwritable_output_is_exit_1_and_leaves_the_old_file(tmp_path: Path):
    missing = tmp_path / "no" / "such" / "dir" / "a.md"
    r = run(*LINE, "--output", str(missing))
    assert r.code == 1 and r.err.count("\n") == 1 and "cannot write" in r.err
    existing = tmp_path / "keep.md"
    existing.write_text("precious")
    r = run("line", "x", "1", "2", "3", "--output", str(existing))
    assert r.code == 2 and existing.read_text() == "precious"


def test_bad_input_never_truncates_an_existing_file(tmp_path: Path):
    existing = tmp_path / "keep.md"
    existing.write_text("precious")
    r = run("line", "2.5", "1", "2", "3", "--output", str(existing))
    assert r.code == 2 and existing.read_text() == "precious"
    assert [p.name for p in tmp_path.iterdir()] == ["keep.md"]


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_broken_pipe_is_quiet():
    proc = subprocess.run(
        f"{sys.executable} -m scanconv line 0 0 1000000 3 --format csv | head -1",
        shell=True,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.stdout == "k,p,decision,x,y,p_next\n"
    assert "Error" not in proc.stderr and "Traceback" not in proc.stderr


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_ctrl_c_during_a_long_stream_exits_130_quietly():
    proc = subprocess.Popen(
        [sys.executable, "-m", "scanconv", "line", "0", "0", "1999999", "1", "-f", "csv"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None
    assert proc.stdout.readline() == "k,p,decision,x,y,p_next\n"  # streaming has started
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_grid_too_large_is_a_note_on_stderr():
    r = run("line", "0", "0", "500", "3", "-f", "markdown")
    assert r.code == 0
    assert "grid left out" in r.err and r.err.count("\n") == 1
    assert "```text" not in r.out and "(500, 3)" in r.out


def test_no_grid_and_top_left():
    assert " | " not in run(*LINE, "-f", "plain", "--no-grid").out
    up = run("line", "0", "0", "3", "3", "-f", "plain").out
    down = run("line", "0", "0", "3", "3", "-f", "plain", "--origin", "top-left").out
    up_rows = [ln for ln in up.splitlines() if " | " in ln]
    down_rows = [ln for ln in down.splitlines() if " | " in ln]
    assert up_rows == down_rows[::-1]
    assert "y down" in down


def test_negative_coordinates_are_arguments_not_options():
    r = run("line", "-2", "-3", "4", "5", "-f", "csv")
    assert r.code == 0
    rows = list(csv.DictReader(io.StringIO(r.out)))
    assert (rows[0]["x"], rows[0]["y"]) == ("-2", "-3")
    assert (rows[-1]["x"], rows[-1]["y"]) == ("4", "5") and len(rows) == 9


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_python_dash_m_and_version():
    r = run_process("--version")
    assert r.code == 0 and r.out.startswith("scanconv ")
    assert run_process("line", "--help").out.startswith("Usage: scanconv line")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@pytest.mark.parametrize("fmt", FORMATS)
def test_typer_cli_runner_every_format(fmt):
    from typer.testing import CliRunner

    from scanconv.cli import app

    result = CliRunner().invoke(app, [*LINE, "--format", fmt], prog_name="scanconv")
    assert result.exit_code == 0, result.output
    assert "(9, 6)" in result.stdout or "9,6" in result.stdout or "[9, 6]" in result.stdout
    assert not ANSI.search(result.stdout)


# --- errors name the command's flag; the library names its parameter ---------------------------


@pytest.mark.parametrize(
    ("args", "api_name", "param", "flag"),
    [
        (("circle", "5", "-m", "trig"), "circle", "rounding", "--rounding: "),
        (("circle", "5"), "circle", "xc", "--center: "),  # one option, two parameters
        (("circle", "5"), "circle", "r", ""),  # a positional argument: no flag
        (("bezier", "0", "0", "1", "1"), "bezier", "samples", "--samples: "),
        (("bezier", "0", "0", "1", "1", "--at", "1"), "bezier", "t", "--at: "),
        (("sample", "x", "--size", "4", "--levels", "4"), "sample", "m", "--size: "),
        (("quantize", "--bits", "2"), "quantize", "integer", "--input: "),
        (("storage", "8", "8", "--bits", "2"), "storage", "m", ""),  # storage M N: positional
        (("line", "0", "0", "1", "1"), "line", None, ""),
    ],
)
def test_an_input_error_names_the_flag_of_its_parameter(monkeypatch, args, api_name, param, flag):
    from scanconv import _api
    from scanconv.core.checks import InputError

    def refuse(*args, **kwargs):
        raise InputError("the value is wrong\n(on two lines)", param)

    monkeypatch.setattr(_api, api_name, refuse)
    r = run(*args)
    assert_refused(r)
    assert r.err == f"scanconv: error: {flag}the value is wrong (on two lines)\n"


def test_a_flag_already_in_the_message_is_not_repeated(monkeypatch):
    from scanconv import _api
    from scanconv.core.checks import InputError

    def refuse(*args, **kwargs):
        raise InputError("--rounding applies to the float methods", "rounding")

    monkeypatch.setattr(_api, "circle", refuse)
    assert run("circle", "5").err == "scanconv: error: --rounding applies to the float methods\n"


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (("line", "--bogus", "1", "2", "3"), "--bogus"),
        (("line", "1", "2", "3", "-Q"), "-Q"),
        (("circle", "5", "--center", "-q", "0"), "-q"),
        (("parametric", "circle", "--radius", "-q"), "-q"),
        (("bezier", "0", "0", "1", "1", "--bogus"), "--bogus"),
        (("continuity", "0", "0", "1", "1", ":", "-q", "1", "2", "2"), "-q"),
    ],
)
def test_an_option_where_a_number_belongs_is_no_such_option(args, name):
    """``ignore_unknown_options`` hands ``--bogus`` to the number parser, which says what
    click says of an unknown option (the library only says the text is not a number)."""
    assert_refused(run(*args), f"No such option: {name}")


def test_the_library_says_not_a_number_without_naming_options():
    from scanconv.core.numeric import parse_number

    with pytest.raises(ValueError, match="'--bogus' is not a number"):
        parse_number("--bogus")


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_shared_options_are_declared_once_and_added_by_answers():
    """The drawing commands get --svg and --png; storage and quantize no grid; sample keeps
    its own --origin help (and reads the option itself)."""
    import typer

    from scanconv.cli import app

    group = typer.main.get_command(app)
    names = {
        cmd: {p.name: p for p in group.commands[cmd].params}  # type: ignore[attr-defined]
        for cmd in ("line", "storage", "sample", "local-control")
    }
    assert {"fmt", "grid", "origin", "output", "explain", "svg", "png"} <= set(names["line"])
    assert {"fmt", "output", "explain"} <= set(names["storage"])
    assert not {"grid", "origin", "svg", "png"} & set(names["storage"])
    assert "svg" not in names["local-control"] and "origin" in names["local-control"]
    assert "Row 0 is the top" in (names["sample"]["origin"].help or "")
    assert list(names["line"])[:5] == ["x1", "y1", "x2", "y2", "algo"]


# --- what students type ---------------------------------------------------------------------------


@pytest.mark.parametrize("group", [(), ("parametric",), ("compare",), ("image",)])
def test_a_group_without_a_command_prints_its_help(group: tuple[str, ...]) -> None:
    r = run(*group)
    assert r.code == 0 and r.err == ""
    assert r.out.startswith("Usage: scanconv") and "\n\n" in r.out


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
def test_help_groups_the_commands_by_topic_with_examples() -> None:
    out = run("--help").out
    for panel in ("Lines, circles and ellipses:", "Curves:", "Image representation:"):
        assert panel in out
    assert "Comparisons:" in out and "Examples:" in out
    panels = out.split("Lines, circles and ellipses:")[1].split("Examples:")[0]
    assert not re.search(r"\w\.\.\.?$", panels, re.M), "a command's sentence cut short"


@pytest.mark.parametrize("points", [("2,2", "10,6"), ("(2,2)", "(10,6)"), ("(2, 2)", "(10, 6)")])
def test_points_as_students_write_them(points: tuple[str, ...]) -> None:
    base = run("line", "2", "2", "10", "6", "-f", "json").out
    assert run("line", *points, "-f", "json").out == base


def test_storage_takes_a_size_written_with_x() -> None:
    base = run("storage", "1024", "768", "--levels", "256", "-f", "json").out
    assert run("storage", "1024x768", "--levels", "256", "-f", "json").out == base


@pytest.mark.parametrize(
    ("short", "long"), [("md", "markdown"), ("tex", "latex"), ("txt", "plain")]
)
def test_format_short_names(short: str, long: str) -> None:
    assert (
        run("line", "2", "2", "10", "6", "-f", short).out
        == run("line", "2", "2", "10", "6", "-f", long).out
    )


def test_parametric_circle_takes_the_radius_as_circle_does() -> None:
    base = run("parametric", "circle", "--radius", "5", "-f", "json").out
    assert run("parametric", "circle", "5", "-f", "json").out == base
    assert_refused(run("parametric", "circle", "5", "--radius", "4"), "already given as 4")


def test_an_unknown_flag_is_no_such_option() -> None:
    assert_refused(run("line", "2", "2", "10", "6", "--bogus"), "No such option: --bogus")


def test_a_close_method_name_is_suggested() -> None:
    assert_refused(run("circle", "5", "--method", "dda"), "did you mean 'symmetric-dda'?")


@pytest.mark.parametrize(
    ("name", "start"),
    [("a.tex", "% scanconv answer"), ("a.csv", "k,p,decision"), ("a.json", "{"), ("a.md", "## ")],
)
def test_output_format_from_the_extension(tmp_path: Path, name: str, start: str) -> None:
    r = run("line", "2", "2", "10", "6", "-o", str(tmp_path / name))
    assert r.code == 0, r.err
    assert (tmp_path / name).read_text(encoding="utf-8").startswith(start)


def test_output_extension_contradicting_format_is_refused(tmp_path: Path) -> None:
    assert_refused(run("line", "2", "2", "10", "6", "-f", "json", "-o", str(tmp_path / "a.csv")))
    assert not list(tmp_path.iterdir())


def test_markdown_answers_appended_stay_apart() -> None:
    out = run("line", "2", "2", "10", "6", "-f", "markdown").out
    assert out.endswith("```\n\n")

"""``check`` marks the syllabus methods whose tables are not a pixel walk
(scanconv.marking.tables, scanconv.marking.table_models): for each, a right table, a
table with one slip (charged once) and a table that carries a slip on (follow-through).

The students' tables are written here by hand (the numbers in each docstring), not taken
from scanconv's own output.
"""

from __future__ import annotations

from fractions import Fraction as F
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from scanconv.marking.tables import canon
from scanconv.questions.marking import check

from .helpers import run


def _mark(tmp_path: Path, text: str, question: str, name: str = "s.csv") -> dict:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return check(path, question).data


CB_Q = "clip line 30 60 60 25 --window 10 10 50 50 --method cyrus-beck"
CB_RIGHT = """edge,N.D,N.(P0 - E),t,type,tE,tL
V1V2,1400,-2000,10/7,leaving,0,1
V2V3,1200,-800,2/3,leaving,0,2/3
V3V4,-1400,400,2/7,entering,2/7,2/3
V4V1,-1200,-800,-2/3,entering,2/7,2/3
"""


def test_cyrus_beck_right_slip_and_follow_through(tmp_path: Path) -> None:
    """Outward normals of the window (10, 10)-(50, 50), D = (30, -35): N·D = 1400, 1200,
    -1400, -1200; t = N·(P0 - E)/(-N·D) = 10/7, 2/3, 2/7, -2/3."""
    right = _mark(tmp_path, CB_RIGHT, CB_Q)
    assert (right["score"], right["out_of"]) == (4, 4)
    # one slip not carried on: tL written 0.7 in row 2, the next rows as the answer's
    slip = CB_RIGHT.replace("V2V3,1200,-800,2/3,leaving,0,2/3", "V2V3,1200,-800,2/3,leaving,0,0.7")
    data = _mark(tmp_path, slip, CB_Q)
    assert (data["score"], data["out_of"]) == (3, 4)
    assert data["first_error"].startswith("Row 2")
    # N·(P0 - E) = -900 in row 2: t = 900/1200 = 3/4 follows, and tL = 3/4 carried down
    carried = CB_RIGHT.replace(
        "V2V3,1200,-800,2/3,leaving,0,2/3", "V2V3,1200,-900,3/4,leaving,0,3/4"
    ).replace("entering,2/7,2/3", "entering,2/7,3/4")
    data = _mark(tmp_path, carried, CB_Q)
    assert (data["score"], data["out_of"]) == (3, 4)


NLL_Q = "clip line 30 60 60 25 --window 10 10 50 50 --method nicholl-lee-nicholl"
NLL_RIGHT = """k,compare,value,relation,with,value
1,y2,25,<,ymax,50
2,m',-6/7,<,m'_TL,2
3,m',-6/7,>,m'_TR,-2
4,m',-6/7,<,m'_BL,2/5
5,m',-6/7,<,m'_BR,-2/5
6,x2,60,>,xmax,50
"""


def test_nll_right_slip_and_follow_through(tmp_path: Path) -> None:
    """The Mumbai line: m' = 30/(-35) = -6/7 against 2, -2, 2/5, -2/5."""
    data = _mark(tmp_path, NLL_RIGHT, NLL_Q)
    assert (data["score"], data["out_of"]) == (6, 6)
    # m' worked as -5/7 and used in every comparison: wrong once, then followed through
    carried = NLL_RIGHT.replace("-6/7", "-5/7")
    data = _mark(tmp_path, carried, NLL_Q)
    assert (data["score"], data["out_of"]) == (5, 6)
    assert data["first_error"].startswith("Row 2")
    # a relation that contradicts the row's own numbers is wrong
    data = _mark(tmp_path, NLL_RIGHT.replace("-6/7,>,m'_TR", "-6/7,<,m'_TR"), NLL_Q)
    assert (data["score"], data["out_of"]) == (5, 6)


DITHER_Q = "dither ordered --image '10 200; 130 90' --top 255 --matrix 2"


def test_ordered_dither_slip_charged_once(tmp_path: Path) -> None:
    """The 2 x 2 Bayer matrix (0 2 / 3 1) at top 255: T = 0, 127.5, 191.25, 63.75; on when
    the value is above T."""
    right = "i,j,value,threshold,output\n0,0,10,0,1\n0,1,200,127.5,1\n1,0,130,191.25,0\n1,1,90,63.75,1\n"
    assert _mark(tmp_path, right, DITHER_Q)["score"] == 4
    # T written 100 for (1, 0): wrong once; its output 1 follows from the student's own T
    slip = right.replace("1,0,130,191.25,0", "1,0,130,100,1")
    data = _mark(tmp_path, slip, DITHER_Q)
    assert (data["score"], data["out_of"]) == (3, 4)
    # an output against the row's own numbers is wrong
    assert (
        _mark(tmp_path, right.replace("0,1,200,127.5,1", "0,1,200,127.5,0"), DITHER_Q)["score"] == 3
    )


def _fs(image: list[list[int]], top: int, slip: tuple[int, F] | None = None) -> list[tuple]:
    """An independent Floyd-Steinberg (raster order, exact, on when value >= top/2); ``slip``
    replaces the error the student writes at one step."""
    rows, cols = len(image), len(image[0])
    got = [[F(0)] * cols for _ in range(rows)]
    out = []
    k = 0
    for i in range(rows):
        for j in range(cols):
            value = image[i][j] + got[i][j]
            o = top if value >= F(top, 2) else 0
            err = value - o
            if slip is not None and slip[0] == k:
                err = slip[1]
            for di, dj, w in (
                (0, 1, F(7, 16)),
                (1, -1, F(3, 16)),
                (1, 0, F(5, 16)),
                (1, 1, F(1, 16)),
            ):
                if 0 <= i + di < rows and 0 <= j + dj < cols:
                    got[i + di][j + dj] += err * w
            out.append((i, j, got[i][j], value, o, err))
            k += 1
    return out


def _fs_csv(rows: list[tuple]) -> str:
    lines = ["i,j,received,value,output,error"]
    lines += [",".join(str(v) for v in r) for r in rows]
    return "\n".join(lines) + "\n"


def test_floyd_steinberg_follow_through(tmp_path: Path) -> None:
    q = "dither floyd-steinberg --image '100 100; 100 100' --top 255"
    assert _mark(tmp_path, _fs_csv(_fs([[100, 100], [100, 100]], 255)), q)["score"] == 4
    # the first error written 90 (not 100): every later pixel receives the student's shares
    data = _mark(tmp_path, _fs_csv(_fs([[100, 100], [100, 100]], 255, (0, F(90)))), q)
    assert (data["score"], data["out_of"]) == (3, 4)
    assert data["first_error"].startswith("Row 1")


MID_Q = "clip line 7 9 11 4 --window 4 4 10 8 --method midpoint-subdivision"


def test_midpoint_subdivision_and_follows_the_codes(tmp_path: Path) -> None:
    right = run(*MID_Q.split(), "--format", "csv").out
    assert _mark(tmp_path, right, MID_Q)["score"] == 9
    # row 1's code of (11, 4) miswritten 0110: its AND 0000 and "split" follow from it
    slip = right.replace('0,"(7, 9) to (11, 4)",1000,0010', '0,"(7, 9) to (11, 4)",1000,0110', 1)
    data = _mark(tmp_path, slip, MID_Q)
    assert (data["score"], data["out_of"]) == (8, 9)


def test_line_style_and_frame_buffer(tmp_path: Path) -> None:
    q = "linestyle 0 0 6 2 --mask 110"
    # the mask's bit (scanconv's heading "bit" is its index, "value" the bit)
    right = (
        "bit,value,action\n0,1,draw\n1,1,draw\n2,0,skip\n0,1,draw\n1,1,draw\n2,0,skip\n0,1,draw\n"
    )
    assert _mark(tmp_path, right, q)["score"] == 7
    # a bit misread as 1 with "draw": the bit wrong once, its action follows
    assert _mark(tmp_path, right.replace("2,0,skip", "2,1,draw", 1), q)["score"] == 6
    # "draw" for a 0 bit is wrong
    assert _mark(tmp_path, right.replace("2,0,skip", "2,0,draw", 1), q)["score"] == 6
    fb = "framebuffer 1280 1024 8"
    right = "unit,size\nbits,10485760\nbytes,1310720\nKB,1310.72\nMB,1.31072\nKiB,1280\nMiB,1.25\n"
    assert _mark(tmp_path, right, fb)["score"] == 6
    # bytes = bits / 4 by mistake (2621440): KB and MB follow from it
    carried = (
        right.replace("1310720", "2621440")
        .replace("1310.72", "2621.44")
        .replace("1.31072", "2.62144")
    )
    data = _mark(tmp_path, carried, fb)
    assert (data["score"], data["out_of"]) == (5, 6)  # KB, MB follow; KiB, MiB the answer's
    assert data["first_error"].startswith("Row 2")


def test_canon_reads_cells_as_written() -> None:
    assert canon("−6/7") == F(-6, 7) and canon("(38.5, 50)") == (F(77, 2), 50)
    assert canon("Leaving") == "leaving" and canon("") is None


def test_cli_check_and_batch(tmp_path: Path) -> None:
    (tmp_path / "a.csv").write_text(NLL_RIGHT, encoding="utf-8")
    (tmp_path / "b.csv").write_text(NLL_RIGHT.replace("-6/7", "-5/7"), encoding="utf-8")
    r = run("check", str(tmp_path / "a.csv"), "--", *NLL_Q.split(), "--format", "json")
    assert r.code == 0 and '"score": 6' in r.out
    r = run("check", "--batch", str(tmp_path), "--", *NLL_Q.split())
    assert r.code == 0 and "a.csv,6,6" in r.out and "b.csv,5,6" in r.out


def test_a_table_with_no_column_of_the_answer_is_refused(tmp_path: Path) -> None:
    (tmp_path / "x.csv").write_text("foo,bar\n1,2\n", encoding="utf-8")
    r = run("check", str(tmp_path / "x.csv"), "--", *NLL_Q.split())
    assert r.code == 2 and r.out == "" and "no column to mark" in r.err


@pytest.mark.parametrize(
    "question",
    [CB_Q, NLL_Q, DITHER_Q, MID_Q, "thickline 0 0 8 3 --width 3", "char bitmap A",
     "inside 0 0 8 0 8 8 --points 1 1", "dither threshold --image '10 200; 130 90' --top 255 --at 128",
     "halftone 2", "halftone 4", "char stroke A", "char storage 96 5 7"],
)  # fmt: skip
def test_scanconv_own_table_scores_full(tmp_path: Path, question: str) -> None:
    import shlex

    out = run(*shlex.split(question), "--format", "csv").out
    data = _mark(tmp_path, out, question)
    assert data["score"] == data["out_of"] > 0


CELLS = st.one_of(
    st.integers(-(10**6), 10**6).map(str),
    st.sampled_from(["", "-", "1/0", "(1, 2)", "entering", "0110", "1e30", "nan", "−3/4", "x"]),
    st.text(max_size=6),
)


@pytest.mark.slow  # over 50 ms a case: outside the inner loop
@settings(deadline=None, max_examples=60)
@given(
    question=st.sampled_from([CB_Q, NLL_Q, MID_Q, DITHER_Q, "framebuffer 1280 1024 8",
                              "dither floyd-steinberg --image '100 100; 100 100' --top 255"]),
    rows=st.lists(st.lists(CELLS, min_size=7, max_size=7), min_size=1, max_size=8),
)  # fmt: skip
def test_any_cells_are_marked_or_refused_in_one_line(question: str, rows: list) -> None:
    """Whatever a student writes in the answer's columns, the marking ends with a score or an
    InputError naming the problem, never another exception."""
    import csv
    import io
    import shlex
    import tempfile

    from scanconv.core.checks import InputError
    from scanconv.marking.tables import table_model_for
    from scanconv.questions import parse, solve

    solution = solve(parse(shlex.split(question)))
    model = table_model_for(solution)
    assert model is not None
    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["k", *model.marked, "x"][:7])
    w.writerows(rows)
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "s.csv"
        path.write_text(out.getvalue(), encoding="utf-8")
        try:
            data = check(path, question).data
        except InputError:
            return
    assert 0 <= data["score"] <= data["out_of"]


def test_midpoint_line_half_scale_follows_through(tmp_path: Path) -> None:
    """(2, 2) to (10, 6) with d = F(M) unscaled: d0 = dy - dx/2 = 0, E adds dy = 4, NE adds
    dy - dx = -4. The student writes the next d at (4, 3) as -3 and carries it on (-3, 1, -3,
    ...): the same pixels; that row is wrong once, the rest right by follow-through."""
    q = "line 2 2 10 6 --algo midpoint --scale half"
    rows = [
        (0, "NE", 2, 2, -4), (-4, "E", 3, 3, 0), (0, "NE", 4, 3, -3), (-3, "E", 5, 4, 1),
        (1, "NE", 6, 4, -3), (-3, "E", 7, 5, 1), (1, "NE", 8, 5, -3), (-3, "E", 9, 6, 1),
        (1, "NE", 10, 6, -3),
    ]  # fmt: skip
    text = "k,d_k,decision,x,y,d_{k+1}\n" + "".join(
        f"{k},{d},{m},{x},{y},{n}\n" for k, (d, m, x, y, n) in enumerate(rows)
    )
    data = _mark(tmp_path, text, q)
    assert (data["score"], data["out_of"]) == (7, 8)
    right = "k,d_k,decision,x,y,d_{k+1}\n" + "".join(
        f"{k},{d},{'NE' if d == 0 else 'E'},{x},{y},{-4 if d == 0 else 0}\n"
        for k, (d, x, y) in enumerate(
            [(0, 2, 2), (-4, 3, 3), (0, 4, 3), (-4, 5, 4), (0, 6, 4), (-4, 7, 5), (0, 8, 5),
             (-4, 9, 6), (0, 10, 6)]
        )
    )  # fmt: skip
    assert _mark(tmp_path, right, q)["score"] == 8


INSIDE_Q = "inside 0 0 8 0 8 8 4 3 0 8 --points 1 1 4 5 6 2"


def test_inside_verdicts_follow_the_students_counts(tmp_path: Path) -> None:
    """The concave polygon (0,0) (8,0) (8,8) (4,3) (0,8): the ray from (1, 1) crosses BC
    only (1 crossing, winding +1: inside by both rules); from (4, 5) it crosses BC (up) and
    CD (down): 2, winding 0, outside; from (6, 2) BC: 1, +1, inside."""
    right = (
        "point,crossings,even-odd,winding number,nonzero\n"
        "P1,1,inside,1,inside\nP2,2,outside,0,outside\nP3,1,inside,1,inside\n"
    )
    assert _mark(tmp_path, right, INSIDE_Q)["score"] == 3
    # P2's crossings counted as 3 and called inside: the count is wrong once, the verdict
    # follows from it
    data = _mark(tmp_path, right.replace("P2,2,outside", "P2,3,inside"), INSIDE_Q)
    assert (data["score"], data["out_of"]) == (2, 3)
    assert data["first_error"].startswith("Row 2")
    # a verdict against the row's own count is wrong
    assert _mark(tmp_path, right.replace("P3,1,inside", "P3,1,outside"), INSIDE_Q)["score"] == 2


def test_one_point_edge_table_is_chosen_by_its_headings(tmp_path: Path) -> None:
    q = "inside 0 0 8 0 8 8 --points 1 1"
    edges = run(*q.split(), "--format", "csv").out
    assert _mark(tmp_path, edges, q)["score"] == 3  # the edge tests, not the verdicts
    verdict = "point,crossings,even-odd,winding number,nonzero\nP1,1,inside,1,inside\n"
    assert _mark(tmp_path, verdict, q)["score"] == 1


def test_halftone_patterns_and_font_storage_one_slip_costs_one_row(tmp_path: Path) -> None:
    """Rows that stand alone (each level's pattern; each packing's sizes): a wrong pattern or a
    wrong byte count costs its own row and nothing else."""
    right = "level,pattern,on\n0,0 0 / 0 0,0\n1,1 0 / 0 0,1\n2,1 0 / 0 1,2\n3,1 1 / 0 1,3\n4,1 1 / 1 1,4\n"
    assert _mark(tmp_path, right, "halftone 2")["score"] == 5
    data = _mark(tmp_path, right.replace("2,1 0 / 0 1,2", "2,1 1 / 0 0,2"), "halftone 2")
    assert (data["score"], data["out_of"]) == (4, 5) and data["first_error"].startswith("Row 3")
    storage = "packing,glyph,bits,bytes\nrows,56,5376,672\ncolumns,40,3840,480\nbits,35,3360,420\n"
    assert _mark(tmp_path, storage, "char storage 96 5 7")["score"] == 3
    data = _mark(tmp_path, storage.replace("5376,672", "5376,5376"), "char storage 96 5 7")
    assert (data["score"], data["out_of"]) == (2, 3) and data["first_error"].startswith("Row 1")


def test_cox_de_boor_triangle_follows_the_students_lower_degree(tmp_path: Path) -> None:
    """N_{0,2} = 5/4·N_{0,1} + 1/4·N_{1,1} at t = 2.5 on knots 0..5 (span 2): with the
    student's N_{1,1} = 1/4 (a slip), N_{0,2} = 1/16 follows and is right."""
    q = "bspline --basis --degree 2 --knots 0,1,2,3,4,5 --at 2.5"
    right = "d,i,N\n1,1,0.5\n1,2,0.5\n2,0,0.125\n2,1,0.75\n2,2,0.125\n"
    assert _mark(tmp_path, right, q)["score"] == 5
    slip = right.replace("1,1,0.5", "1,1,0.25")
    data = _mark(tmp_path, slip, q)
    assert (data["score"], data["out_of"]) == (4, 5) and data["first_error"].startswith("Row 1")
    # N_{0,2} and N_{1,2} as the slip gives them: 1/16 and 9/16 (= 3/4·1/4 + 3/4·1/2)
    carried = slip.replace("2,0,0.125", "2,0,0.0625").replace("2,1,0.75", "2,1,0.5625")
    data = _mark(tmp_path, carried, q)
    assert (data["score"], data["out_of"]) == (4, 5)
    # a wrong N_{2,2} that follows from nothing is charged
    assert _mark(tmp_path, right.replace("2,2,0.125", "2,2,0.5"), q)["score"] == 4

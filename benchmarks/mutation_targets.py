"""What benchmarks/mutate.py mutates and how each module is tested: the targets (module ->
its tests), the mutations of the mutation report always run, and the mutants proved
equivalent (left out of the ratio, each with its reasoning)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Target:
    """A module to mutate: its tests, its golden topic, and what in it to mutate."""

    tests: tuple[str, ...]
    golden: str = ""
    #: Only these functions (and module-level assignments named here) are mutated; all if empty.
    only: tuple[str, ...] = ()
    #: Only these kinds of mutation (see :class:`Mutant`); all if empty.
    kinds: tuple[str, ...] = ()
    #: Escapers: call drops and string mutations are tried.
    escaper: bool = False


MARK_TESTS = (
    "tests/test_marking_hand_tables.py",
    "tests/test_marking_hand_edges.py",
    "tests/test_marking_roundtrip.py",
    "tests/test_marking_layouts.py",
    "tests/test_marking_tables.py",
    "tests/test_marking_first_error.py",
    "tests/test_marking_glyph_tables.py",
    "tests/test_marking_steps.py",
    "tests/test_marking_windows_addresses.py",
    "tests/test_marking_conventions.py",
    "tests/test_check.py",
    "tests/test_check_batch.py",
    "tests/test_check_student_words.py",
)
#: The marking modules (all of scanconv/marking/ but its constants): each is tested by
#: :data:`MARK_TESTS` and the golden answers of ``check``.
MARKING = tuple(
    f"scanconv/marking/{m}.py"
    for m in (
        "mark",
        "rows",
        "table_models",
        "tables",
        "student_table",
        "models",
        "diagnose",
        "words",
        "table_head",
    )
)
ESCAPE_TESTS = ("tests/test_escaping.py", "tests/test_escaping_readers.py")

#: module -> its tests (the mutation report's groups, the marking tests written by hand added).
TARGETS: dict[str, Target] = {
    "scanconv/algorithms/lines.py": Target(
        ("tests/test_lines.py", "tests/test_conventions.py", "tests/test_compare.py"),
        "lines or compare",
    ),
    "scanconv/algorithms/midpoint_line.py": Target(
        ("tests/test_lines.py", "tests/test_conventions.py"), "midpoint"
    ),
    "scanconv/algorithms/circles.py": Target(
        ("tests/test_circles.py", "tests/test_circles_xstep.py", "tests/test_conventions.py"),
        "circle",
    ),
    "scanconv/algorithms/ellipses.py": Target(
        ("tests/test_ellipses.py", "tests/test_conventions.py"), "ellipse"
    ),
    "scanconv/algorithms/bezier.py": Target(("tests/test_curves.py",), "curves or bezier"),
    "scanconv/algorithms/bspline.py": Target(
        ("tests/test_curves.py", "tests/test_curves_bspline_basis.py"), "curves or bspline"
    ),
    "scanconv/algorithms/clipping.py": Target(
        ("tests/test_clipping.py", "tests/test_midpoint_clip.py"), "clip"
    ),
    "scanconv/algorithms/cyrus_beck.py": Target(("tests/test_cyrus_beck.py",), "cyrus"),
    "scanconv/algorithms/nll.py": Target(
        ("tests/test_nll.py", "tests/test_published_dither_inside.py"), "nll"
    ),
    "scanconv/algorithms/polygon.py": Target(
        ("tests/test_polygon.py", "tests/test_fill.py"), "polygon or fill"
    ),
    "scanconv/algorithms/seedfill.py": Target(("tests/test_fill.py",), "fill or seed"),
    "scanconv/algorithms/dither.py": Target(("tests/test_dither.py",), "dither"),
    "scanconv/algorithms/wu.py": Target(
        ("tests/test_antialias_wu.py", "tests/test_antialias.py"), "wu or antialias"
    ),
    "scanconv/algorithms/transform.py": Target(
        ("tests/test_transform.py",), "transform or viewport"
    ),
    "scanconv/algorithms/weiler_atherton.py": Target(("tests/test_weiler_atherton.py",), "weiler"),
    "scanconv/core/numeric.py": Target(
        ("tests/test_numeric.py", "tests/test_lines.py", "tests/test_circles.py"),
        "lines or circle or ellipse",
    ),
    **{path: Target(MARK_TESTS, "check") for path in MARKING},
    "scanconv/render/mappings/text.py": Target(
        ("tests/test_streaming.py", *ESCAPE_TESTS),
        "md",
        only=("table_lines", "md_cell", "_md_heading", "md_text", "note_md", "prose_md", "md_code"),
        escaper=True,
    ),
    "scanconv/core/tex_escape.py": Target(
        ("tests/test_tex_escape.py", *ESCAPE_TESTS), "tex", escaper=True
    ),
    "scanconv/render/documents/gift.py": Target(
        ("tests/test_lms_escaping.py", "tests/test_lms.py", *ESCAPE_TESTS),
        only=("_SPECIAL", "gift_plain", "gift_text"),
        escaper=True,
    ),
    "scanconv/render/documents/moodle.py": Target(
        ("tests/test_lms_escaping.py", "tests/test_lms.py", *ESCAPE_TESTS),
        only=("_XML_ILLEGAL", "moodle_text", "cdata", "_CLOZE_SPECIAL", "_cloze_answer"),
        escaper=True,
    ),
    "scanconv/render/mappings/html.py": Target(
        ("tests/test_html.py", *ESCAPE_TESTS), kinds=("call",), escaper=True
    ),
}

#: Mutants proved equivalent, each with its proof. They are run all the same (a survivor
#: only is taken as equivalent) and listed, but left out of the ratio.
EQUIVALENT: dict[tuple[str, str, str], str] = {
    # (module, the mutant's line and the two after it, stripped, the mutated text in ⟦ ⟧ (a
    # part of them), the replacement) -> the proof
    (
        "scanconv/algorithms/lines.py",
        "if ⟦(dy if steep else dx) < 0⟧:",
        "((dy if steep else dx) <= 0)",
    ): (
        "orient(): the major delta is 0 only for a single point (not steep means |dy| <= |dx| "
        "= 0), where swapping the two equal end points and negating dx = dy = 0 changes nothing."
    ),
    ("scanconv/algorithms/midpoint_line.py", "extra=(halve(s.extra[⟦0⟧]),)", "-1"): (
        "bresenham()'s Step.extra is the 1-tuple (p_{k+1},): extra[0] and extra[-1] are the "
        "same element."
    ),
    ("scanconv/algorithms/bspline.py", "s = last_span(kf, n) if t >= kf[n + ⟦1⟧]", "0"): (
        "basis_float(): for u_n <= t < u_{n+1} the span u_n < u_{n+1} is not empty, so "
        "last_span(kf, n) = n = bisect_right(kf, t) - 1: both branches give the same span."
    ),
    ("scanconv/algorithms/wu.py", "if ⟦a2 < a1⟧:", "(a2 <= a1)"): (
        "wu(): a2 = a1 only for a single point (not steep: dx = 0 forces dy = 0; steep needs "
        "|dy| > 0), where swapping the two equal end points changes nothing."
    ),
    ("scanconv/algorithms/transform.py", "for start in vertices[:⟦1⟧]:", "2"): (
        "outline(): with two or more vertices the first edge is (v0, v1) whether closed or "
        "not, and it yields v1 (unless it is v0) right after v0: yielding v1 first changes "
        "nothing; with fewer, vertices[:1] = vertices[:2]."
    ),
    (
        "scanconv/render/mappings/html.py",
        'listed = ⟦esc(", ".join(fmt_pixel(p)',
        '(", ".join(fmt_pixel(p) for p in st.pixels[:MAX_PIXEL_LIST]))',
    ): (
        "_pixels(): fmt_pixel writes integers, parentheses, commas and spaces, so the pixel "
        "list holds no character HTML escapes: esc() is the identity on it."
    ),
    (
        "scanconv/render/mappings/html.py",
        'more = ⟦esc(f", ',
        '(f", \\u2026 ({count - MAX_PIXEL_LIST:,} more)" if count > MAX_PIXEL_LIST else "")',
    ): (
        "_pixels(): ', … (N more)' with N an integer written with commas holds no character "
        "HTML escapes."
    ),
    ("scanconv/render/mappings/html.py", "⟦esc(block.heading)⟧", "(block.heading)"): (
        "question_html(): Question.heading is 'Question N' or 'Question N (M marks)' of two "
        "integers: nothing HTML escapes."
    ),
    (
        "scanconv/algorithms/dither.py",
        "[⟦4 * v + a⟧ for v in row] + [4 * v + b for v in row]\nfor row in d\nfor a, b in [(0, 2)]",
        "(4 * v - a)",
    ): ("bayer(): in the first half a = 0, so 4v + a = 4v - a."),
    ("scanconv/marking/mark.py", "if n == ⟦0⟧:\nbreak", "-1"): (
        "_judged(): the break only ends the search early; n counts wrong fields (n >= 0) "
        "and a later candidate replaces the best only when n < best[0] = 0: never, so "
        "searching on returns the same best."
    ),
    (
        "scanconv/marking/student_table.py",
        'body = s[1:-1] if s.endswith("|") and ⟦len(s) > 1⟧',
        "(len(s) >= 1)",
    ): (
        "_markdown_rows(): s starts with '|', so len(s) >= 1 always; at len(s) == 1, s is "
        "'|' and s[1:-1] = s[1:] = '': both branches give the empty body."
    ),
    (
        "scanconv/marking/table_head.py",
        'end = max(line.rfind(")"), line.rfind("]")) + ⟦1⟧',
        "2",
    ): (
        "unbracketed(): end is one past the last closing bracket; one more takes the character "
        "after it into the part the groups are removed from, and a group must end in a closing "
        "bracket, none of which is there: the same groups go (with no closing bracket at all, "
        "line[:1] is one character, no group)."
    ),
}

#: The hand-made mutations of the mutation report (shared/reference/mutation-report.md) that
#: survived its run, in the modules above: always run, beside the sampled ones.
#: (id, module, the text replaced, once in the module, its replacement)
REPORT: tuple[tuple[str, str, str, str], ...] = (
    ("ML1", "scanconv/algorithms/midpoint_line.py", "extra=(halve(s.extra[0]),)", "extra=s.extra"),
    ("E2", "scanconv/algorithms/ellipses.py", "se = p4 >= t1", "se = p4 > t1"),
    (
        "F2",
        "scanconv/algorithms/seedfill.py",
        "for row in (y + 1, y - 1):",
        "for row in (y - 1, y + 1):",
    ),
    ("MR1", "scanconv/marking/rows.py", "c.places >= 2 and abs", "c.places >= 1 and abs"),
    (
        "MR2",
        "scanconv/marking/rows.py",
        "abs(c.value - v) <= tolerance",
        "abs(c.value - v) < tolerance",
    ),
    (
        "MR3",
        "scanconv/marking/rows.py",
        "and not (got.p_next is None and last)",
        "and not (got.p_next is None)",
    ),
    (
        "TM1",
        "scanconv/marking/table_models.py",
        'int(v > t or (self.compare == ">=" and v == t))',
        'int(v > t or (self.compare == ">" and v == t))',
    ),
    (
        "TM2",
        "scanconv/marking/table_models.py",
        't_enter = _given(prev, "t_enter", answer[i - 1])',
        't_enter = _given({}, "t_enter", answer[i - 1])',
    ),
    (
        "TM3",
        "scanconv/marking/table_models.py",
        'on = value > half or (self.compare == ">=" and value == half)',
        "on = value > half",
    ),
    (
        "NU3",
        "scanconv/core/numeric.py",
        "len(str(float(value))) <= 8",
        "len(str(float(value))) < 8",
    ),
    (
        "R1",
        "scanconv/render/mappings/text.py",
        '" | ".join(escape(c) for c in cells)',
        '" | ".join(c for c in cells)',
    ),
    (
        "R6",
        "scanconv/render/documents/moodle.py",
        """_CLOZE_SPECIAL = re.compile(r\"\"\"[&<>"'{}~#\\\\]\"\"\")""",
        """_CLOZE_SPECIAL = re.compile(r\"\"\"[&<>{}~#\\\\]\"\"\")""",
    ),
)


#: Calls an escaper makes whose dropping is a mutant (``esc(c)`` -> ``c``).
ESCAPING_CALLS = {
    "esc",
    "escape",
    "md_text",
    "md_cell",
    "note_md",
    "tex_text",
    "gift_text",
    "gift_plain",
    "moodle_text",
    "_cloze_answer",
    "visible",
    "cdata",
}

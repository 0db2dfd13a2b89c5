"""The question language: scanconv's own arguments (``line 2 2 10 6 --algo dda``) as a
question, parsed and answered in the library, without the command line.

* :func:`parse` reads a question into a :class:`CommandLine` (the command, its arguments, its
  display options); :func:`solve` answers it; :func:`answer` does both
  (``scanconv.questions.answer("circle 5")``), after :func:`check_budget`, which refuses a
  question beyond the work budget of a format before any work (the one check the command line,
  the site and the MCP server make).
* A question longer than :data:`~.limits.MAX_LINE_CHARS` characters, or a question file's
  text beyond :data:`~.limits.MAX_FILE_BYTES` bytes, is refused before it is read
  (:mod:`.limits`).
* :func:`read_questions` and :func:`read_file` read a question file (:mod:`.files`).
* :func:`check` marks a student's table against a question.

Bad words are a :class:`UsageError`, bad values found while answering an
:class:`~scanconv.core.checks.InputError` (both ``ValueError``), worded as the command line
words them. The grammar (:mod:`.grammar_table`) is generated from the command line's
declarations, and a test keeps the two equal.

>>> from scanconv import questions
>>> questions.parse("circle 5 -c 1 2 --no-grid").arguments["center"]
(Fraction(1, 1), Fraction(2, 1))
>>> questions.answer("line 0 0 3 1").rows()[1]["pixel"]
(1, 0)
"""

from ..core.lazy import attach_stub

__getattr__, __dir__ = attach_stub(__name__, __file__)

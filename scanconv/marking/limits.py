"""The size limits of marking that more than one marking module enforces: kept here, below
them, so that the pixel-walk marker (:mod:`.mark`) and the marker of the other tables
(:mod:`.tables`) read one number without importing each other."""

from __future__ import annotations

__all__ = ["MAX_QUESTION_ROWS"]

MAX_QUESTION_ROWS = 10**4
"""Most rows of a question's table that ``check`` marks against: twice the longest student
table (:data:`~scanconv.marking.student_table.MAX_TABLE_ROWS`); a longer question is refused
before any marking (its table, and each convention's, is held in memory)."""

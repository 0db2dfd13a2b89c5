"""Data shipped with scanconv: the exam book's question file (``exam.txt``)."""

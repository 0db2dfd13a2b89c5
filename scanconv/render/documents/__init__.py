"""Documents of many answers: sheets, worksheets, the exam book and practice sets
(:mod:`.sheet` and its writers :mod:`.sheet_latex`, :mod:`.sheet_html`), quiz files
(:mod:`.lms`, :mod:`.moodle`, :mod:`.gift`) and ``check --batch``'s score sheet (:mod:`.scores`)."""

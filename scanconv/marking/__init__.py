"""Marking a student's table (`scanconv check`), one layer above the answers: reading what
a student wrote (`student_table`, `table_head`), the follow-through marking models of the
stepped methods (`models`) and of the other tables (`table_models`), marking row by row
(`rows`, `tables`), the diagnosis of a whole table (`diagnose`), its words (`words`) and
the entry points (`mark`)."""

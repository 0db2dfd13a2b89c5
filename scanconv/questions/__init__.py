"""The question language: scanconv's own arguments (``line 2 2 10 6 --algo dda``) as a
question, read from a question file (:mod:`.files`) and answered in the library, without the
command line."""

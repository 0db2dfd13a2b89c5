"""Practice questions (`scanconv practice`), one layer above the answers: fresh questions
of the notes' kinds with the numbers drawn at random from a seed (`notes`), and of the
topics beyond the notes (`beyond`)."""

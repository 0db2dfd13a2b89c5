"""The anti-aliasing answers: area sampling and supersampling (`sampling`), Xiaolin Wu's
line (`wu`), sub-pixel rendering, and their shared coverage text (`_shared`)."""

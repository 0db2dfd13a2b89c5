"""scanconv in the browser: a static site that answers questions with scanconv itself, on
Pyodide, with nothing to install (issue 31; ``scanconv site build DIR``, docs/site.md).

* :mod:`.page` runs in the browser: a question in scanconv's own language, answered as the
  HTML step-through page and the JSON data (no numpy, no typer, no rich).
* :mod:`.forms` writes a form per command from the question grammar, for those who do not
  know the syntax.
* :mod:`.build` writes the folder: the pinned Pyodide runtime (fetched once from the npm
  registry, checked against its SHA-256 and cached), the wheels of scanconv and of the
  pure-Python packages the page needs, the page itself and the exam book.
"""

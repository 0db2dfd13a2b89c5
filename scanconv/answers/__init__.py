"""The exam working around the algorithms: each module builds the
:class:`~scanconv.core.records.Solution` of one topic (given, derived values with the numbers
substituted, notes, tables, what to draw). Formats nothing: that is :mod:`scanconv.render`."""

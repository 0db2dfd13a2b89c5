"""Pure algorithms: generators of :class:`~scanconv.core.records.Step` records with exact
values and structured decisions, and the numpy bulk rasterizers. No working, no strings."""

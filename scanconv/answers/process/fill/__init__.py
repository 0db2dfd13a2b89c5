"""The filling answers: the scan-line polygon fill (`scanline`), the seed fills (`seed`)
and the inside-outside tests (`inside`)."""

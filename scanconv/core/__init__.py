"""The bottom layer: exact numbers, the records every algorithm yields and every answer
fills, the safe expression evaluator and the input checks. Imports nothing else of scanconv."""

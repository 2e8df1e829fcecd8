"""Grading returned answer files against the Variants they answer.

answers    the answer form a student fills in, and reading answer files back (formats: the bytes)
reading    one typed answer to a value in the asked unit, safely (a format problem is not a wrong answer)
checks     small pure comparators: numeric, angle, integer, choice
mistakes   naming the mistake behind a wrong answer: template mistakes, then generic slips
marking    the parts of one question, with error carried forward
grade      one sheet, or a directory of answer files (collect: whose file is which)
results    what grading produces; report writes it out (gradebook, feedback, report)
"""

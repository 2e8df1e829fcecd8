"""Stage 3, solving: a template's solver run over drawn values into a derivation of named steps, and
the frozen Variant every output and the grader read."""

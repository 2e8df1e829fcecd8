"""Stage 2, drawing: a seed (from the course secret, or for practice) to given values that are nice,
printed as drawn, and make a machine someone could build."""

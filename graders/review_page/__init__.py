"""`exgen review`: a local page listing what the grader could not settle, where a lecturer decides
each answer; the decisions go to the decisions file (graders.decisions) that `exgen grade` applies."""

"""Issuing an assignment: the assignment file and roster, a sheet per student drawn from the secret,
the files written for students and keys, and the manifest grading checks."""

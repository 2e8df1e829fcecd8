"""Practice mode: a student drills any topic alone, in the terminal (`exgen practice`) or the browser
(`exgen serve`), offline, with progress kept in one SQLite file. It stands on both exgen (templates,
variants, worked solutions, figures) and graders (the marking of answers), as the command line does."""

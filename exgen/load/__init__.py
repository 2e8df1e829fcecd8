"""Stage 1, loading a bank: template files read and checked into frozen Templates (with file, key and
line for every problem), the expressions, domains and texts they hold, the code they name, their
versions, and the shared texts of named mistakes."""

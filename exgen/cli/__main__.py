"""`python -m exgen.cli`: the `exgen` command."""
import sys

from . import main

sys.exit(main())

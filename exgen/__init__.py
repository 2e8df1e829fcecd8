"""exgen: endless, correct, gradeable problems for Mechanics of Machines."""

__version__ = "0.1.0"

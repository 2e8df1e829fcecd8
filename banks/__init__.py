"""The template bank, shipped as package data and found as `exgen.banks` (see pyproject.toml)."""

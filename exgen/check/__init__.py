"""Checking templates: `exgen validate` over many seeds, `exgen solve` for values a user gives, and the
stored unit table rewritten from the bank."""

"""The practice web app: `exgen serve`."""

"""Errors of the 1D profile engine (kept free of any ``surfmet`` import)."""

from __future__ import annotations


class ProfileError(ValueError):
    """Unusable profile input: too short for the cut-off, all NaN, bad spacing, bad fit data."""

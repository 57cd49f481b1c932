"""Errors of the 1D profile engine (kept free of any ``surfmet`` import)."""

from __future__ import annotations


class ProfileError(ValueError):
    """Unusable profile input: too short for the cut-off, all NaN, bad spacing, bad fit data.

    A :class:`ValueError`, so ``except ValueError`` catches it.

    Examples
    --------
    >>> import numpy as np
    >>> from profiles import profile_parameters
    >>> profile_parameters(np.full(10, np.nan), 1e-6)
    Traceback (most recent call last):
    ...
    profiles._errors.ProfileError: the profile has no measured points (all heights are NaN)
    """


class ProfileTooShortError(ProfileError):
    """The profile is shorter than any cut-off the rule could choose (ISO 4288 cannot be
    entered); callers with an automatic cut-off may evaluate the primary profile instead."""

"""profiles: the 1D engine (profile parameters, ISO Gaussian filtering, circle fitting).

Arrays and SI floats in, arrays and small frozen dataclasses out. Never imports surfmet.
"""

from profiles.errors import ProfileError

__all__ = ["ProfileError"]

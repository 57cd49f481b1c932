"""contact: the contact-mechanics engine (materials, Hertz, FFT boundary elements, rolling
resistance, the rotor of Alaci et al. 2022).

Arrays and SI floats in, arrays and small frozen dataclasses out. Never imports surfmet.
"""

from contact.errors import (
    ContactError,
    ContactInputError,
    ConvergenceError,
    EdgeContactError,
    EdgeContactWarning,
)

__all__ = [
    "ContactError",
    "ContactInputError",
    "ConvergenceError",
    "EdgeContactError",
    "EdgeContactWarning",
]

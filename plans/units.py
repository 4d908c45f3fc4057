"""Units at the file boundary: lengths in mm or m, speeds in rpm or rad/s.

Inside the engine everything is SI (m, rad, s, kg, N).
"""

from __future__ import annotations

import math
import re

LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "cm": 1e-2}
_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-zA-Z]*)\s*$")


def parse_length(value: object, default_unit: str) -> float:
    """A number in the file's unit, or a string such as ``"35 mm"`` / ``"0.035 m"``.

    Raises ValueError with the expectation when the value is not a length.
    """
    if isinstance(value, bool):
        raise ValueError("expected a length (number or string like '35 mm')")
    if isinstance(value, int | float):
        if isinstance(value, int) and abs(value) > 10**300:
            raise ValueError(f"expected a length of a sensible size, got an integer of {len(str(abs(value)))} digits")
        if not math.isfinite(value):
            raise ValueError("expected a finite length")
        return float(value) * LENGTH_UNITS[default_unit]
    if isinstance(value, str):
        m = _QUANTITY.match(value)
        if m:
            unit = m.group(2) or default_unit
            if unit in LENGTH_UNITS:
                return float(m.group(1)) * LENGTH_UNITS[unit]
    raise ValueError("expected a length: a number in the file's unit or a string like '35 mm'")


def rpm_to_rad_s(n: float) -> float:
    """ω = π n / 30."""
    return math.pi * n / 30.0

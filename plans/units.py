"""Units at the file boundary: lengths in mm or m, speeds in rpm or rad/s.

Inside the engine everything is SI (m, rad, s, kg, N).
"""

from __future__ import annotations

import math
import re

LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "cm": 1e-2}
#: A length written as text, "35 mm" (compiled by ``re`` when first met: most files give numbers).
_QUANTITY = r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-zA-Z]*)\s*$"


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
        m = re.match(_QUANTITY, value)
        if m:
            unit = m.group(2) or default_unit
            if unit in LENGTH_UNITS:
                return float(m.group(1)) * LENGTH_UNITS[unit]
    raise ValueError("expected a length: a number in the file's unit or a string like '35 mm'")


def rpm_to_rad_s(n: float) -> float:
    """ω = π n / 30."""
    return math.pi * n / 30.0


#: A value within this fraction of its scale is zero up to round-off: written 0, drawn as a point.
DUST = 1e-9


def clean(x: float, scale: float) -> float:
    """``x``, or 0.0 where it is zero up to round-off against ``scale`` (the size of the plan,
    polygon or quantity it belongs to); -0.0 becomes 0.0."""
    return 0.0 if abs(x) <= DUST * abs(scale) else x + 0.0


def percent(read: float, exact: float, ref: float = 0.0) -> float | None:
    """The difference of a reading, %: 100·(read − exact)/max(|exact|, ref), the same in
    ``solve``, on the sheet and in the check report.  None where the exact value is zero up to
    round-off (against ``ref``, or itself when no ref): print the absolute difference instead."""
    den = max(abs(exact), ref)
    if den == 0 or abs(exact) <= DUST * max(ref, abs(read)):
        return None
    return clean(100.0 * (read - exact) / den, 100.0)

#: Longer links than this (metres) no machine of the course has, and faster points than
#: this (m/s): a scene beyond them is warned about (:mod:`plans.plausible`: a unit slip).
LENGTH_WARN = 20.0
SPEED_WARN = 300.0

"""What the force polygons and the lever both draw with: the force scale μF, the ruler a
draftsman reads, and two small vector helpers (over positions)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from plans.kinematics import construction

if TYPE_CHECKING:
    from plans.forces.polygons import ForceAnalysis

C = NDArray[np.complex128]
R = NDArray[np.float64]

#: What a draftsman reads off a ruler, mm (readings are rounded to this).
RULER_MM = 0.5
#: Nice values of K = 1/μ (unit per mm), times powers of ten: consecutive ratios ≤ 1.25,
#: so the longest vector always lands between 80 and 100 mm.
_NICE = (1.0, 1.2, 1.25, 1.5, 1.6, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0)


def nice_scale(longest: float, target_mm: float = 100.0) -> float:
    """μF (mm per N): K a round number from a denser set, the longest vector 80..100 mm."""
    return construction.nice_scale(longest, target_mm, _NICE)


def mu_force(fa: ForceAnalysis, values: list[complex]) -> float:
    """The scene's μF when it gives one, else a nice scale for the longest of ``values``."""
    given = fa.scene.scales.get("force")
    if given:
        return given
    return nice_scale(max((abs(v) for v in values), default=0.0))


def unit_vector(z: C) -> C:
    """z / |z|, and 1 where z = 0."""
    mag = np.abs(z)
    return np.where(mag > 0, z / np.where(mag > 0, mag, 1.0), 1.0 + 0j)


def safe_div(a: R, b: R) -> R:
    """a / b, and 0 where b = 0."""
    return np.where(b != 0, a / np.where(b != 0, b, 1.0), 0.0)

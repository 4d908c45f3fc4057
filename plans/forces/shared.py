"""What the force polygons and the lever both draw with: the force scale μF, the ruler a
draftsman reads, and small vector helpers (over positions): a unit vector, a safe
division, the sum of forces and their moment about a point."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from plans.kinematics import construction
from plans.kinematics.scales import fit
from plans.lines import cross
from plans.scene.model import Scene
from plans.units import DUST

C = NDArray[np.complex128]
R = NDArray[np.float64]

def _all(x: np.ndarray) -> bool:
    """Every element true (non-zero), without ndarray.all's Python wrapper (any shape)."""
    return bool(np.logical_and.reduce(x, axis=None))

#: What a draftsman reads off a ruler, mm (readings are rounded to this).
RULER_MM = 0.5
#: Round values of K = 1/μ (unit per mm), times powers of ten; the longest vector lands
#: between 50 and 100 mm.
_NICE = (1.0, 2.0, 2.5, 4.0, 5.0)  # round both ways: μ and K = 1/μ


def nice_scale(longest: float, target_mm: float = 100.0) -> float:
    """μF (mm per N): K a round number, the longest vector 50..100 mm."""
    return construction.nice_scale(longest, target_mm, _NICE)


class Forces(Protocol):
    """What sets a force scale: the scene and the largest reaction over the positions
    (:class:`plans.forces.polygons.ForceAnalysis`)."""

    @property
    def scene(self) -> Scene: ...

    @property
    def largest_reaction(self) -> float: ...


def mu_force(fa: Forces, values: list[complex]) -> float:
    """The scene's μF when it gives one, else a round scale for the longest of ``values``;
    never from forces that are zero up to round-off (then the cycle's largest sets it)."""
    given = fa.scene.scales.get("force")
    if given:
        return given
    longest = max((abs(v) for v in values), default=0.0)
    cycle = fa.largest_reaction
    if longest <= DUST * cycle:  # zero up to round-off: a point, at the cycle's scale
        longest = cycle
    return nice_scale(longest, 100.0 * fit(fa.scene))


def unit_vector(z: C) -> C:
    """z / |z|, and 1 where z = 0 (divided in real parts: numpy's complex division by a
    subnormal |z| overflows inside)."""
    mag = np.abs(z)
    some = mag > 0
    if _all(some):  # the usual case: no zero to leave out (both parts divided in place)
        out = np.empty(mag.shape, complex)
        np.divide(np.real(z), mag, out=out.real)
        np.divide(np.imag(z), mag, out=out.imag)
        return out
    safe = np.where(some, mag, 1.0)
    return np.where(some, np.real(z) / safe + 1j * (np.imag(z) / safe), 1.0 + 0j)


def safe_div(a: R, b: R) -> R:
    """a / b, and 0 where b = 0."""
    if _all(b):  # the usual case (nothing zero), in one division
        return a / b
    nz = b != 0
    return np.where(nz, a / np.where(nz, b, 1.0), 0.0)


def force_sum(fs: Iterable[Any], n: int) -> C:
    """ΣF of the forces (each ``.F``) over the n positions."""
    out = np.zeros(n, complex)
    for f in fs:
        out = out + f.F  # not in place: a load may carry several cases (a leading axis)
    return out


def moment_about(fs: Iterable[Any], ms: Iterable[Any], P: C, n: int) -> R:
    """ΣM about P of the forces (cross(r − P, F)) and the couples (each ``.M``), ccw+."""
    out = np.zeros(n)
    for f in fs:
        out = out + cross(f.r - P, f.F)
    for m in ms:
        out = out + m.M
    return out
